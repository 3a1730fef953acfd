/// @file main.cpp
/// @brief Entry point of the `stepwise` program: picks the command.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "app/cli.hpp"
#ifdef STEPWISE_HAVE_VIEWER
#include "viewer/viewer.hpp"
#endif

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

/// `stepwise view`: the viewer when it was built, otherwise how to build it.
int viewCommand(const std::vector<std::string>& args) {
    using namespace stepwise::cli;
    const stepwise::viewer::ViewOptions options = parseViewOptions(args, defaultScenePath());
    if (options.help) {
        std::fputs(viewUsageText().c_str(), stdout);
        return stepwise::kExitOk;
    }
#ifdef STEPWISE_HAVE_VIEWER
    return stepwise::viewer::runViewer(options);
#else
    std::fprintf(stderr,
                 "stepwise: the viewer was not built into this program (CMake option STEPWISE_VIEWER is OFF,\n"
                 "  or freeglut/OpenGL were not found when it was configured). To build it, install the\n"
                 "  packages (scripts/setup.sh does: freeglut3-dev) and configure again with\n"
                 "    cmake --preset release -DSTEPWISE_VIEWER=ON && cmake --build --preset release\n");
    return stepwise::kExitUsageError;
#endif
}

}  // namespace

namespace {

/// The command named by the first of @p args, run; its exit code.
int runCommandLine(const std::vector<std::string>& args) {
    using namespace stepwise::cli;
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::fputs(usageText(), stdout);
        return stepwise::kExitOk;
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
        if (command == "view") return viewCommand(rest);
        if (command == "grade") return gradeCommand(parseGradeOptions(rest));
        if (command == "raycast") return raycastCommand(rest);
        if (command == "generate") return generateCommand(rest);
        if (command == "bench") return benchCommand(rest);
        if (command == "trace") return traceCommand(rest);
        throw UsageError("unknown command '" + command +
                         "' (commands: run, check, view, grade, raycast, generate, bench, trace)");
    } catch (const UsageError& error) {
        std::fprintf(stderr, "stepwise: error: %s\nRun 'stepwise --help' for usage.\n", error.what());
        return stepwise::kExitUsageError;
    } catch (const std::exception& error) {
        // Whatever a command did not report itself (an unwritten student stage, memory that ran out):
        // one line naming it, never an abort. The commands report the simulation's own errors.
        std::fprintf(stderr, "stepwise: error: %s\n", error.what());
        return stepwise::kExitSimulationError;
    }
}

}  // namespace

/// @brief Runs the command named by the first argument (`run`, `check`, `view`, `grade`, `raycast`, `generate`,
/// `bench`, `trace`, `--help`).
/// @return the exit code: 0 success, 1 simulation failure, 2 bad command line or scene,
///         3 an expectation failed (`run`) or a graded file did not pass (`grade`).
int main(int argc, char** argv) {
    const int code = runCommandLine(std::vector<std::string>(argv + 1, argv + argc));
    // What the command printed must have reached standard output (a full disk, a closed pipe): say so.
    errno = 0;
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::fprintf(stderr, "stepwise: error: cannot write standard output: %s\n", std::strerror(errno ? errno : EIO));
        return code == stepwise::kExitOk ? stepwise::kExitSimulationError : code;
    }
    return code;
}
