/// @file main.cpp
/// @brief Entry point of the `stepwise` program: picks the command.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <system_error>
#include <vector>

#include "app/arguments.hpp"
#include "app/cli.hpp"
#ifdef STEPWISE_HAVE_VIEWER
#include "viewer/viewer.hpp"
#endif

#ifndef STEPWISE_DEFAULT_SCENE
/// Path of the default scene; CMake passes the absolute path in the source tree.
#define STEPWISE_DEFAULT_SCENE "config/default.scene"
#endif
#ifndef STEPWISE_SCENES_FROM_PROGRAM
/// Path from the installed program's folder to the installed scenes' folder; CMake passes it
/// (bin/ to share/stepwise/config/ is "../share/stepwise/config").
#define STEPWISE_SCENES_FROM_PROGRAM "../share/stepwise/config"
#endif

namespace {

/// True when @p path names a file this program can open.
bool readable(const std::string& path) {
    if (std::FILE* f = std::fopen(path.c_str(), "r")) {
        std::fclose(f);
        return true;
    }
    return false;
}

/// The folder of the running program, from Linux's /proc/self/exe ("" when it cannot be read).
std::filesystem::path programFolder() {
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : program.parent_path();
}

/// The default scene, the first of these that exists:
///  1. the installed copy, found from the program's own folder (PREFIX/bin/stepwise opens
///     PREFIX/share/stepwise/config/default.scene), so an installed program opens its own
///     scene under any prefix, even where the source tree it was built from is gone or has changed;
///  2. the copy in the source tree this program was built from (a program in the build tree);
///  3. config/default.scene below the current directory (the name is then reported as missing there).
std::string defaultScenePath() {
    const std::filesystem::path folder = programFolder();
    if (!folder.empty()) {
        const std::string installed =
            (folder / STEPWISE_SCENES_FROM_PROGRAM / "default.scene").lexically_normal().string();
        if (readable(installed)) return installed;
    }
    if (readable(STEPWISE_DEFAULT_SCENE)) return STEPWISE_DEFAULT_SCENE;
    return "config/default.scene";
}

/// `stepwise view`: the viewer when it was built, otherwise how to build it.
int viewCommand(const std::vector<std::string>& args) {
    using namespace stepwise::cli;
    const stepwise::viewer::ViewOptions options = parseViewOptions(args, defaultScenePath());
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
        std::fputs(usageText().c_str(), stdout);
        return stepwise::kExitOk;
    }
    const std::string& command = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    // `stepwise COMMAND --help`: that command's usage, whatever else the line holds.
    if (const std::string usage = commandUsageText(command); !usage.empty() && asksForHelp(rest)) {
        std::fputs(usage.c_str(), stdout);
        return stepwise::kExitOk;
    }
    try {
        if (command == "run") return runCommand(parseRunOptions(rest, defaultScenePath()));
        if (command == "check") {
            if (rest.size() != 1) throw UsageError("'check' takes exactly one scene file");
            if (!rest[0].empty() && rest[0][0] == '-') throw UsageError("unknown option '" + rest[0] + "' for 'check'");
            return checkCommand(rest[0]);
        }
        if (command == "view") return viewCommand(rest);
        if (command == "grade") return gradeCommand(parseGradeOptions(rest));
        if (command == "raycast") return raycastCommand(parseRaycastOptions(rest));
        if (command == "generate") return generateCommand(parseGenerateOptions(rest));
        if (command == "bench") return benchCommand(parseBenchOptions(rest));
        if (command == "trace") return traceCommand(parseTraceOptions(rest));
        if (command == "plot") return plotCommand(parsePlotOptions(rest, defaultScenePath()));
        throw UsageError("unknown command '" + command +
                         "' (commands: run, check, view, grade, raycast, generate, bench, trace, plot)");
    } catch (const UsageError& error) {
        std::fprintf(stderr, "stepwise: error: %s\nRun 'stepwise --help' for usage.\n", error.what());
        return stepwise::kExitUsageError;
    } catch (const std::bad_alloc&) {
        // The commands name what they were building when they can (World::step's stages); this is the rest.
        std::fprintf(stderr, "stepwise: error: out of memory running '%s'\n", command.c_str());
        return stepwise::kExitSimulationError;
    } catch (const std::exception& error) {
        // Whatever a command did not report itself (an unwritten student stage, memory that ran out):
        // one line naming it, never an abort. The commands report the simulation's own errors.
        std::fprintf(stderr, "stepwise: error: %s\n", error.what());
        return stepwise::kExitSimulationError;
    }
}

}  // namespace

/// @brief Runs the command named by the first argument (`run`, `check`, `view`, `grade`, `raycast`, `generate`,
/// `bench`, `trace`, `plot`, `--help`).
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
