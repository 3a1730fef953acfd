/// @file options.cpp
/// @brief Parsing and usage text of the command line.
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "app/cli.hpp"

namespace stepwise::cli {

/// `stepwise view`'s lines of the usage text; `stepwise view --help` prints them too.
#define VIEW_USAGE                                                                              \
    "  stepwise view [FILE] [--size WxH] [--log-events PATH]\n"                               \
    "      Open a window onto the scene (H in the window lists the controls);\n"              \
    "      --log-events writes a line per mouse pick, push and release to PATH.\n"            \
    "  stepwise view [FILE] --screenshot PATH [--at T] [--size WxH] [--keys KEYS]\n"          \
    "                [--dump-state PATH] [--stage K]\n"                                      \
    "      Simulate to T seconds (default 0) as 'run --duration T' does, draw one\n"         \
    "      frame into the PNG file PATH and exit; --keys presses window keys first\n"         \
    "      (e.g. CV: contacts and velocities); --dump-state writes the state drawn\n"        \
    "      in the CSV format of --csv; --stage K draws the state after the K-th\n"           \
    "      stage run of the next step (the S key). Without a screen, prefix 'xvfb-run -a'.\n"

const char* usageText() {
    return "Stepwise - a rigid-body physics engine for teaching\n"
           "\n"
           "Usage:\n"
           "  stepwise run [FILE] [--duration S | --steps N] [--csv PATH] [--every K] [--explain]\n"
           "               [--threads N]\n"
           "      Simulate the scene in FILE (the default scene when omitted) and print a\n"
           "      summary: objects, final state, energy, momentum, time per stage.\n"
           "      --duration S  simulated seconds (default: the scene's World Duration)\n"
           "      --steps N     number of time steps instead of a duration\n"
           "      --csv PATH    write the trajectory as CSV: time,name,px,py,pz,vx,vy,vz,\n"
           "                    qw,qx,qy,qz,wx,wy,wz, one row per object per sample,\n"
           "                    starting with the initial state at time 0\n"
           "      --every K     write a CSV sample every K steps (default 1)\n"
           "      --explain     print the step plan first: each stage, whether it runs\n"
           "                    and why (with --steps 0, only the plan)\n"
           "      --threads N   narrowphase threads, overriding the scene's World Threads\n"
           "                    (0: one per hardware thread); the results do not change\n"
           VIEW_USAGE
           "      A scene with Expect records ends with a table: each expectation, PASS or\n"
           "      FAIL, and the value measured.\n"
           "  stepwise check FILE\n"
           "      Validate FILE and print what it contains.\n"
           "  stepwise grade DIR [--scene-glob GLOB] [--expect FILE] [--max-steps N]\n"
           "      Run every scene file below DIR (GLOB, default *.scene, matches the path\n"
           "      below DIR) and print one row per file: PASS, FAIL or ERROR, expectations\n"
           "      passed, the first failure. --expect FILE checks FILE's Expect records\n"
           "      instead of each file's own, and when FILE has MayChange records, fails\n"
           "      any other change against FILE; --max-steps (default 1000000) caps a run.\n"
           "  stepwise raycast FILE --from X,Y,Z --dir X,Y,Z [--max D] [--at T]\n"
           "      The first body the ray from (X,Y,Z) along the direction meets within D m\n"
           "      (default: any distance), after simulating T seconds (default 0): its name,\n"
           "      the distance, the hit point and the surface normal.\n"
           "  stepwise generate sphere-rain|box-pile|pyramids --count N --out FILE\n"
           "                [--seed S] [--broadphase KIND]\n"
           "      Write a benchmark scene of N bodies to FILE ('-': standard output).\n"
           "  stepwise bench broadphase FILE [--steps N | --duration S] [--check-every K]\n"
           "      Run every broadphase on the scene step by step, check each against brute\n"
           "      force (every K-th step, default every step) and rank them by time per step.\n"
           "      Exit code 1 when one differs from brute force (each difference is listed).\n"
           "  stepwise trace FILE [--steps N] [--from STEP] [--stage NAME] [--object NAME]\n"
           "                [--substeps all] [--digits D]\n"
           "      Print, stage by stage, what each stage of each step took in and produced,\n"
           "      with units: forces, velocities before -> after, candidate pairs, contacts,\n"
           "      impulses (effective mass, v_n, j, clamping), constraint errors, sleep;\n"
           "      each contact's line names its index and feature id. Step 1 is the first.\n"
           "      --from STEP first step printed (default 1); --steps N steps printed\n"
           "      (default 1); --stage NAME only that stage (repeat, or a,b,c); --object\n"
           "      NAME only lines about that body (repeatable); --substeps all every\n"
           "      substep, not only the first; --digits D decimals (default 4).\n"
           "      Lines are described in docs/trace.md.\n"
           "  stepwise plot [FILE] --quantity Q [--object NAME]... [--component C]...\n"
           "                [--duration S | --steps N] [--every K] [--out FILE.png]\n"
           "                [--data FILE.csv] [--size WxH]\n"
           "      Simulate the scene and draw one quantity against time with gnuplot, one\n"
           "      panel per component, one line per body. Q: position, velocity,\n"
           "      angular-velocity, momentum or energy. --object NAME the bodies (default:\n"
           "      every dynamic body, and for momentum and energy the whole scene too);\n"
           "      --component C the panels (x, y, z, norm; for energy translational,\n"
           "      rotational, kinetic, potential, total); --every K a sample every K\n"
           "      steps (default 1); --out the PNG picture (--size, default 800x600);\n"
           "      --data the numbers plotted, as CSV. Give --out, --data or both.\n"
           "  stepwise --help\n"
           "\n"
           "Exit codes: 0 success, 1 the simulation failed (non-finite state),\n"
           "            2 bad command line or bad scene file,\n"
           "            3 an expectation failed (run), or a file did not pass (grade).\n"
           "Scene format: docs/config-format.md\n";
}

namespace {

double parsePositiveSeconds(const std::string& option, const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value) || value <= 0) {
        throw UsageError(option + " expects a number of seconds > 0, found '" + text + "'");
    }
    return value;
}

std::uint64_t parsePositiveCount(const std::string& option, const std::string& text) {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value == 0) {
        throw UsageError(option + " expects a whole number > 0, found '" + text + "'");
    }
    return value;
}

/// Most threads --threads accepts: far more than any machine this runs on,
/// small enough that a typo (--threads 10000) is an error, not 10 000 threads.
constexpr int kMaxThreads = 256;

/// "--threads N": 0 (one per hardware thread) to kMaxThreads.
int parseThreadCount(const std::string& option, const std::string& text) {
    int value = -1;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 0 || value > kMaxThreads) {
        throw UsageError(option + " expects a whole number from 0 (one per hardware thread) to " +
                         std::to_string(kMaxThreads) + ", found '" + text + "'");
    }
    return value;
}

/// "WxH", each from 16 to 8192 pixels.
void parseSize(const std::string& text, int& width, int& height) {
    const std::size_t x = text.find('x');
    int w = 0, h = 0;
    const auto parse = [](std::string_view part, int& value) {
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        return !part.empty() && error == std::errc() && end == part.data() + part.size();
    };
    if (x == std::string::npos || !parse(std::string_view(text).substr(0, x), w) ||
        !parse(std::string_view(text).substr(x + 1), h) || w < 16 || h < 16 || w > 8192 || h > 8192) {
        throw UsageError("--size expects WIDTHxHEIGHT in pixels, each 16 to 8192, e.g. 800x500; found '" + text + "'");
    }
    width = w;
    height = h;
}

}  // namespace

std::string viewUsageText() {
    std::string text = "Usage:\n" VIEW_USAGE "\nIn the window:\n";
    for (const char* line : viewer::kViewerControls) text += std::string("  ") + line + "\n";
    return text;
}

viewer::ViewOptions parseViewOptions(const std::vector<std::string>& args, const std::string& defaultScene) {
    viewer::ViewOptions options;
    bool sceneGiven = false;
    bool atGiven = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(arg + " needs a value");
            return args[++i];
        };
        if (arg == "--help" || arg == "-h") {
            options.help = true;
        } else if (arg == "--screenshot") {
            options.screenshotPath = value();
        } else if (arg == "--at") {
            const std::string& text = value();
            char* end = nullptr;
            options.at = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0' || !std::isfinite(options.at) || options.at < 0) {
                throw UsageError("--at expects a number of seconds >= 0, found '" + text + "'");
            }
            atGiven = true;
        } else if (arg == "--size") {
            parseSize(value(), options.width, options.height);
        } else if (arg == "--dump-state") {
            options.dumpStatePath = value();
        } else if (arg == "--keys") {
            options.keys = value();
        } else if (arg == "--log-events") {
            options.logEventsPath = value();
        } else if (arg == "--stage") {
            const std::string& text = value();
            char* end = nullptr;
            const long k = std::strtol(text.c_str(), &end, 10);
            if (text.empty() || *end != '\0' || k < 1) {
                throw UsageError("--stage expects a stage run number >= 1, found '" + text + "'");
            }
            options.stage = static_cast<std::size_t>(k);
        } else if (arg.size() > 1 && arg[0] == '-') {
            throw UsageError("unknown option '" + arg + "' for 'view'");
        } else if (sceneGiven) {
            throw UsageError("'view' takes one scene file, got '" + options.scenePath + "' and '" + arg + "'");
        } else {
            options.scenePath = arg;
            sceneGiven = true;
        }
    }
    if (!options.screenshotPath && (atGiven || options.dumpStatePath || !options.keys.empty() || options.stage)) {
        throw UsageError("--at, --dump-state, --keys and --stage go with --screenshot PATH");
    }
    if (options.screenshotPath && options.logEventsPath) {
        throw UsageError("--log-events records what the mouse does in the window; a --screenshot has no mouse");
    }
    if (!sceneGiven) options.scenePath = defaultScene;
    return options;
}

namespace {

/// "a,b,c" appended to @p list, each part non-empty.
void appendCommaList(const std::string& option, const std::string& text, std::vector<std::string>& list) {
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (part.empty()) throw UsageError(option + " expects a name or a comma-separated list of names, found '" + text + "'");
        list.push_back(part);
        if (comma == std::string::npos) return;
        start = comma + 1;
    }
}

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

PlotOptions parsePlotOptions(const std::vector<std::string>& args, const std::string& defaultScene) {
    PlotOptions options;
    bool sceneGiven = false;
    bool quantityGiven = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(arg + " needs a value");
            return args[++i];
        };
        if (arg == "--quantity") {
            const std::string& text = value();
            if (quantityGiven) throw UsageError("--quantity is given twice: one plot draws one quantity");
            if (!parsePlotQuantity(text, options.quantity)) {
                throw UsageError("--quantity expects one of " + plotQuantityWords() + ", found '" + text + "'");
            }
            quantityGiven = true;
        } else if (arg == "--object") {
            appendCommaList(arg, value(), options.objects);
        } else if (arg == "--component") {
            appendCommaList(arg, value(), options.components);
        } else if (arg == "--duration") {
            options.duration = parsePositiveSeconds(arg, value());
        } else if (arg == "--steps") {
            options.steps = parsePositiveCount(arg, value());
        } else if (arg == "--every") {
            options.every = parsePositiveCount(arg, value());
        } else if (arg == "--out") {
            const std::string& path = value();
            if (!endsWith(path, ".png") || path.size() == 4) {
                throw UsageError("--out expects the name of a .png file (gnuplot draws a PNG), found '" + path + "'");
            }
            options.outPath = path;
        } else if (arg == "--data") {
            const std::string& path = value();
            if (path.empty()) throw UsageError("--data expects a file name ('-': standard output)");
            options.dataPath = path;
        } else if (arg == "--size") {
            parseSize(value(), options.width, options.height);
        } else if (arg.size() > 1 && arg[0] == '-') {
            throw UsageError("unknown option '" + arg + "' for 'plot'");
        } else if (sceneGiven) {
            throw UsageError("'plot' takes one scene file, got '" + options.scenePath + "' and '" + arg + "'");
        } else {
            options.scenePath = arg;
            sceneGiven = true;
        }
    }
    if (!quantityGiven) throw UsageError("'plot' needs --quantity Q, one of " + plotQuantityWords());
    if (!options.outPath && !options.dataPath) {
        throw UsageError("'plot' needs --out FILE.png (the picture), --data FILE.csv (the numbers), or both");
    }
    if (options.duration && options.steps) throw UsageError("give --duration or --steps, not both");
    if (options.outPath && options.dataPath && *options.outPath == *options.dataPath) {
        throw UsageError("--out and --data name the same file, '" + *options.outPath + "'");
    }
    if (!sceneGiven) options.scenePath = defaultScene;
    return options;
}

RunOptions parseRunOptions(const std::vector<std::string>& args, const std::string& defaultScene) {
    RunOptions options;
    bool sceneGiven = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(arg + " needs a value");
            return args[++i];
        };
        if (arg == "--duration") {
            options.duration = parsePositiveSeconds(arg, value());
        } else if (arg == "--steps") {
            const std::string& text = value();
            options.steps = text == "0" ? 0 : parsePositiveCount(arg, text);  // 0: with --explain, only the plan
        } else if (arg == "--explain") {
            options.explain = true;
        } else if (arg == "--csv") {
            options.csvPath = value();
        } else if (arg == "--every") {
            options.every = parsePositiveCount(arg, value());
        } else if (arg == "--threads") {
            options.threads = parseThreadCount(arg, value());
        } else if (arg.size() > 1 && arg[0] == '-') {
            throw UsageError("unknown option '" + arg + "' for 'run'");
        } else if (sceneGiven) {
            throw UsageError("'run' takes one scene file, got '" + options.scenePath + "' and '" + arg + "'");
        } else {
            options.scenePath = arg;
            sceneGiven = true;
        }
    }
    if (options.duration && options.steps) throw UsageError("give --duration or --steps, not both");
    if (options.steps == std::uint64_t(0) && !options.explain) {
        throw UsageError("--steps expects a whole number > 0, found '0' (--steps 0 goes with --explain)");
    }
    if (!sceneGiven) options.scenePath = defaultScene;
    return options;
}

}  // namespace stepwise::cli
