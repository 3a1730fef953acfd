/// @file main.cpp
/// @brief Entry point of the `stepwise` program: picks the command.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "app/cli.hpp"

#ifndef STEPWISE_DEFAULT_SCENE
/// Path of the default scene; CMake passes the absolute path in the source tree.
#define STEPWISE_DEFAULT_SCENE "config/default.scene"
#endif

namespace {

/// The default scene: the copy in the source tree this program was built
/// from, or config/default.scene below the current directory.
std::string defaultScenePath() {
    if (std::FILE* f = std::fopen(STEPWISE_DEFAULT_SCENE, "r")) {
        std::fclose(f);
        return STEPWISE_DEFAULT_SCENE;
    }
    return "config/default.scene";
}

}  // namespace

/// @brief Runs the command named by the first argument (`run`, `check`, `--help`).
/// @return the exit code: 0 success, 1 simulation failure, 2 bad command line or scene.
int main(int argc, char** argv) {
    using namespace stepwise::cli;
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::fputs(usageText(), stdout);
        return kExitOk;
    }
    const std::string& command = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    try {
        if (command == "run") return runCommand(parseRunOptions(rest, defaultScenePath()));
        if (command == "check") {
            if (rest.size() != 1) throw UsageError("'check' takes exactly one scene file");
            if (!rest[0].empty() && rest[0][0] == '-') throw UsageError("unknown option '" + rest[0] + "' for 'check'");
            return checkCommand(rest[0]);
        }
        throw UsageError("unknown command '" + command + "' (commands: run, check)");
    } catch (const UsageError& error) {
        std::fprintf(stderr, "stepwise: error: %s\nRun 'stepwise --help' for usage.\n", error.what());
        return kExitUsageError;
    }
}
