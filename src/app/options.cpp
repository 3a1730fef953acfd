/// @file options.cpp
/// @brief The usage text of the command line, and each command's option parser.
///
/// Every parser reads its arguments through one Arguments reader (arguments.hpp),
/// so every command refuses a missing value, an option taken as a value, a
/// repeated option and a badly written number the same way, and only parses:
/// files are opened and scenes loaded by the command itself.
#include <algorithm>
#include <string_view>

#include "app/arguments.hpp"
#include "app/cli.hpp"
#include "config/scene_records.hpp"
#include "config/spelling.hpp"
#include "core/limits.hpp"
#include "core/quoted_text.hpp"

namespace stepwise::cli {

namespace {

/// One command's lines of the usage text: `stepwise COMMAND --help` prints them alone.
struct CommandUsage {
    std::string_view command;
    const char* text;
};

constexpr CommandUsage kUsage[] = {
    {"run",
     "  stepwise run [FILE] [--duration S | --steps N] [--csv PATH] [--every K] [--explain]\n"
     "               [--threads N] [--max-seconds S] [--csv-nodes PATH]\n"
     "      Simulate the scene in FILE (the default scene when omitted) and print a\n"
     "      summary: objects, final state, energy, momentum, time per stage.\n"
     "      --duration S  simulated seconds (default: the scene's World Duration)\n"
     "      --steps N     number of time steps instead of a duration\n"
     "      --csv PATH    write the trajectory as CSV: time,name,px,py,pz,vx,vy,vz,\n"
     "                    qw,qx,qy,qz,wx,wy,wz, one row per object per sample,\n"
     "                    starting with the initial state at time 0; a soft body's row\n"
     "                    adds its volume and pressure\n"
     "      --csv-nodes PATH  write every soft body's nodes as CSV:\n"
     "                    time,body,node,px,py,pz,vx,vy,vz, sampled as --csv\n"
     "      --every K     write a CSV sample every K steps (default 1)\n"
     "      --explain     print the step plan first: each stage, whether it runs\n"
     "                    and why (with --steps 0, only the plan)\n"
     "      --threads N   threads of the narrowphase and the contact passes,\n"
     "                    overriding the scene's World Threads\n"
     "                    (0: one per hardware thread); the results do not change\n"
     "      --max-seconds S  stop after S seconds of wall-clock time, report the steps\n"
     "                    done, exit code 1\n"
     "      A scene with Expect records ends with a table: each expectation, PASS or\n"
     "      FAIL, and the value measured.\n"},
    {"view",
     "  stepwise view [FILE] [--size WxH] [--log-events PATH]\n"
     "      Open a window onto the scene (H in the window lists the controls);\n"
     "      --log-events writes a line per mouse pick, push and release to PATH.\n"
     "  stepwise view [FILE] --screenshot PATH [--at T] [--size WxH] [--keys KEYS]\n"
     "                [--dump-state PATH] [--stage K]\n"
     "      Simulate to T seconds (default 0) as 'run --duration T' does, draw one\n"
     "      frame into the PNG file PATH and exit; --keys presses window keys first\n"
     "      (e.g. CV: contacts and velocities); --dump-state writes the state drawn\n"
     "      in the CSV format of --csv; --stage K draws the state after the K-th\n"
     "      stage run of the next step (the S key). Without a screen, prefix 'xvfb-run -a'.\n"},
    {"check",
     "  stepwise check FILE\n"
     "      Validate FILE and print what it contains.\n"},
    {"grade",
     "  stepwise grade DIR [--scene-glob GLOB] [--expect FILE] [--max-steps N]\n"
     "                [--max-seconds S]\n"
     "      Run every scene file below DIR (GLOB, default *.scene, matches the path\n"
     "      below DIR) and print one row per file as it finishes: PASS, FAIL or\n"
     "      ERROR, expectations passed, the first failure. --expect FILE checks\n"
     "      FILE's Expect records instead of each file's own, and when FILE has\n"
     "      MayChange records, fails any other change against FILE; --max-steps N\n"
     "      (default 1000000) and --max-seconds S (wall clock, default 60) cap each\n"
     "      file's run: a file past either is a FAIL row that says so.\n"},
    {"raycast",
     "  stepwise raycast FILE --from X,Y,Z --dir X,Y,Z [--max D] [--at T]\n"
     "      The first body the ray from (X,Y,Z) along the direction meets within D m\n"
     "      (default: any distance), after simulating T seconds (default 0): its name,\n"
     "      the distance, the hit point and the surface normal.\n"},
    {"generate",
     "  stepwise generate sphere-rain|box-pile|pyramids --count N --out FILE\n"
     "                [--seed S] [--broadphase KIND]\n"
     "      Write a benchmark scene of N bodies (1 to 1000000) to FILE ('-': standard\n"
     "      output).\n"},
    {"bench",
     "  stepwise bench broadphase FILE [--steps N | --duration S] [--check-every K]\n"
     "      Run every broadphase on the scene step by step, check each against brute\n"
     "      force (every K-th step, default every step) and rank them by time per step.\n"
     "      Exit code 1 when one differs from brute force (each difference is listed).\n"},
    {"trace",
     "  stepwise trace FILE [--steps N] [--from STEP] [--stage NAME] [--object NAME]\n"
     "                [--substeps all] [--digits D] [--max-seconds S]\n"
     "      Print, stage by stage, what each stage of each step took in and produced,\n"
     "      with units: forces, velocities before -> after, candidate pairs, contacts,\n"
     "      impulses (effective mass, v_n, j, clamping), constraint errors, sleep;\n"
     "      each contact's line names its index and feature id. Step 1 is the first.\n"
     "      --from STEP first step printed (default 1); --steps N steps printed\n"
     "      (default 1); --stage NAME only that stage (repeat, or a,b,c); --object\n"
     "      NAME only lines about that body (repeatable); --substeps all every\n"
     "      substep, not only the first; --digits D decimals (default 4);\n"
     "      --max-seconds S stop after S seconds of wall-clock time (exit code 1).\n"
     "      Lines are described in docs/trace.md.\n"},
    {"plot",
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
     "      --data the numbers plotted, as CSV. Give --out, --data or both.\n"},
};

constexpr const char* kUsageEnd =
    "  stepwise --help, stepwise COMMAND --help\n"
    "\n"
    "Numbers on the command line are written as in a scene file: 0.5, 2e-3, 1/60.\n"
    "Exit codes: 0 success, 1 the simulation failed (non-finite state) or ran out of\n"
    "            time or memory, 2 bad command line or bad scene file,\n"
    "            3 an expectation failed (run), or a file did not pass (grade).\n"
    "Scene format: docs/config-format.md\n";

/// "WxH", each from 16 to 8192 pixels.
void parseSize(const std::string& text, int& width, int& height) {
    const std::size_t x = text.find('x');
    try {
        if (x == std::string::npos) throw UsageError("no 'x'");
        width = int(parseWholeNumber("--size", text.substr(0, x), 16, 8192));
        height = int(parseWholeNumber("--size", text.substr(x + 1), 16, 8192));
    } catch (const UsageError&) {
        throw UsageError("--size expects WIDTHxHEIGHT in pixels, each 16 to 8192, e.g. 800x500; found '" +
                         quotable(text) + "'");
    }
}

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

/// The one scene file (or folder) a command takes, refusing a second.
void takeOne(const char* command, const char* what, std::string& slot, bool& given, const std::string& word) {
    if (given) throw UsageError(std::string("'") + command + "' takes one " + what + ", got '" + slot + "' and '" + word + "'");
    slot = word;
    given = true;
}

}  // namespace

std::string usageText() {
    std::string text = "Stepwise - a rigid-body physics engine for teaching\n\nUsage:\n";
    for (const CommandUsage& usage : kUsage) text += usage.text;
    return text + kUsageEnd;
}

std::string commandUsageText(const std::string& command) {
    for (const CommandUsage& usage : kUsage) {
        if (usage.command == command) {
            std::string text = std::string("Usage:\n") + usage.text;
            if (command == "view") {
                text += "\nIn the window:\n";
                for (const char* line : viewer::kViewerControls) text += std::string("  ") + line + "\n";
            }
            return text;
        }
    }
    return "";
}

viewer::ViewOptions parseViewOptions(const std::vector<std::string>& args, const std::string& defaultScene) {
    viewer::ViewOptions options;
    bool sceneGiven = false;
    bool atGiven = false;
    Arguments in(args, "view");
    while (in.next()) {
        if (in.isFlag("--help") || in.isFlag("-h")) {
            options.help = true;
        } else if (in.is("--screenshot")) {
            options.screenshotPath = in.value();
        } else if (in.is("--at")) {
            options.at = parseNonNegative(in.option(), in.value(), "a number of seconds >= 0");
            atGiven = true;
        } else if (in.is("--size")) {
            parseSize(in.value(), options.width, options.height);
        } else if (in.is("--dump-state")) {
            options.dumpStatePath = in.value();
        } else if (in.is("--keys")) {
            options.keys = in.value();
        } else if (in.is("--log-events")) {
            options.logEventsPath = in.value();
        } else if (in.is("--stage")) {
            options.stage = std::size_t(parseWholeNumber(in.option(), in.value(), 1, kMaxSteps));
        } else if (in.isOption()) {
            in.refuseUnknown();
        } else {
            takeOne("view", "scene file", options.scenePath, sceneGiven, in.current());
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

PlotOptions parsePlotOptions(const std::vector<std::string>& args, const std::string& defaultScene) {
    PlotOptions options;
    bool sceneGiven = false;
    bool quantityGiven = false;
    Arguments in(args, "plot");
    while (in.next()) {
        if (in.is("--quantity")) {
            const std::string& text = in.value();
            if (!parsePlotQuantity(text, options.quantity)) {
                throw UsageError("--quantity expects one of " + plotQuantityWords() + ", found '" + text + "'");
            }
            quantityGiven = true;
        } else if (in.isList("--object")) {
            appendCommaList(in.option(), in.value(), options.objects);
        } else if (in.isList("--component")) {
            appendCommaList(in.option(), in.value(), options.components);
        } else if (in.is("--duration")) {
            options.duration = parseSeconds(in.option(), in.value());
        } else if (in.is("--steps")) {
            options.steps = parseWholeNumber(in.option(), in.value(), 1, kMaxSteps);
        } else if (in.is("--every")) {
            options.every = parseWholeNumber(in.option(), in.value(), 1, kMaxSteps);
        } else if (in.is("--out")) {
            const std::string& path = in.value();
            if (!endsWith(path, ".png") || path.size() == 4) {
                throw UsageError("--out expects the name of a .png file (gnuplot draws a PNG), found '" + path + "'");
            }
            options.outPath = path;
        } else if (in.is("--data")) {
            const std::string& path = in.value();
            if (path.empty()) throw UsageError("--data expects a file name ('-': standard output)");
            options.dataPath = path;
        } else if (in.is("--size")) {
            parseSize(in.value(), options.width, options.height);
        } else if (in.isOption()) {
            in.refuseUnknown();
        } else {
            takeOne("plot", "scene file", options.scenePath, sceneGiven, in.current());
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
    Arguments in(args, "run");
    while (in.next()) {
        if (in.is("--duration")) {
            options.duration = parseSeconds(in.option(), in.value());
        } else if (in.is("--steps")) {
            // 0 goes with --explain: only the plan.
            options.steps = parseWholeNumber(in.option(), in.value(), 0, kMaxSteps);
        } else if (in.isFlag("--explain")) {
            options.explain = true;
        } else if (in.is("--csv")) {
            options.csvPath = in.value();
        } else if (in.is("--csv-nodes")) {
            options.nodesCsvPath = in.value();
        } else if (in.is("--every")) {
            options.every = parseWholeNumber(in.option(), in.value(), 1, kMaxSteps);
        } else if (in.is("--threads")) {
            options.threads = int(parseWholeNumber(in.option(), in.value(), 0, kMaxThreads));
        } else if (in.is("--max-seconds")) {
            options.maxSeconds = parseSeconds(in.option(), in.value());
        } else if (in.isOption()) {
            in.refuseUnknown();
        } else {
            takeOne("run", "scene file", options.scenePath, sceneGiven, in.current());
        }
    }
    if (options.duration && options.steps) throw UsageError("give --duration or --steps, not both");
    if (options.steps == std::uint64_t(0) && !options.explain) {
        throw UsageError("--steps expects a whole number > 0, found '0' (--steps 0 goes with --explain)");
    }
    if (!sceneGiven) options.scenePath = defaultScene;
    return options;
}

GradeOptions parseGradeOptions(const std::vector<std::string>& args) {
    GradeOptions options;
    bool folderGiven = false;
    Arguments in(args, "grade");
    while (in.next()) {
        if (in.is("--scene-glob")) {
            options.glob = in.value();
        } else if (in.is("--expect")) {
            options.expectPath = in.value();
        } else if (in.is("--max-steps")) {
            options.maxSteps = parseWholeNumber(in.option(), in.value(), 1, kMaxSteps);
        } else if (in.is("--max-seconds")) {
            options.maxSecondsPerFile = parseSeconds(in.option(), in.value());
        } else if (in.isOption()) {
            in.refuseUnknown();
        } else {
            takeOne("grade", "folder", options.folder, folderGiven, in.current());
        }
    }
    if (!folderGiven) throw UsageError("'grade' needs a folder of scene files, e.g. stepwise grade submissions/");
    return options;
}

TraceCommandOptions parseTraceOptions(const std::vector<std::string>& args) {
    TraceCommandOptions options;
    bool sceneGiven = false;
    Arguments in(args, "trace");
    while (in.next()) {
        if (in.is("--steps")) {
            options.trace.steps = parseWholeNumber(in.option(), in.value(), 1, kMaxSteps);
        } else if (in.is("--from")) {
            options.trace.from = parseWholeNumber(in.option(), in.value(), 1, kMaxSteps);
        } else if (in.isList("--stage")) {
            std::vector<std::string> names;
            appendCommaList(in.option(), in.value(), names);
            for (const std::string& name : names) {
                try {
                    options.trace.stages.push_back(stageFromName(name));
                } catch (const std::invalid_argument& error) {
                    throw UsageError(error.what());
                }
            }
        } else if (in.isList("--object")) {
            options.trace.objects.push_back(in.value());
        } else if (in.is("--substeps")) {
            const std::string& which = in.value();
            if (which != "all" && which != "first") {
                throw UsageError("--substeps expects 'first' (the default) or 'all', found '" + which + "'");
            }
            options.trace.allSubsteps = which == "all";
        } else if (in.is("--digits")) {
            options.trace.digits = int(parseWholeNumber(in.option(), in.value(), 0, kMaxTraceDigits));
        } else if (in.is("--max-seconds")) {
            options.maxSeconds = parseSeconds(in.option(), in.value());
        } else if (in.isOption()) {
            in.refuseUnknown();
        } else {
            takeOne("trace", "scene file", options.scenePath, sceneGiven, in.current());
        }
    }
    if (!sceneGiven) {
        throw UsageError("'trace' needs a scene file: stepwise trace FILE [--steps N] [--from STEP] "
                         "[--stage NAME] [--object NAME] [--substeps all] [--digits D]");
    }
    return options;
}

RaycastOptions parseRaycastOptions(const std::vector<std::string>& args) {
    RaycastOptions options;
    bool sceneGiven = false, fromGiven = false, directionGiven = false;
    Arguments in(args, "raycast");
    while (in.next()) {
        if (in.is("--from")) {
            options.from = parseVector(in.option(), in.value());
            fromGiven = true;
        } else if (in.is("--dir")) {
            options.direction = parseDirection(in.option(), in.value());
            directionGiven = true;
        } else if (in.is("--max")) {
            options.maxDistance = parseNonNegative(in.option(), in.value(), "a distance >= 0 in metres");
        } else if (in.is("--at")) {
            options.at = parseNonNegative(in.option(), in.value(), "a time >= 0 in seconds");
        } else if (in.isOption()) {
            in.refuseUnknown();
        } else {
            takeOne("raycast", "scene file", options.scenePath, sceneGiven, in.current());
        }
    }
    if (!sceneGiven || !fromGiven || !directionGiven) {
        throw UsageError("'raycast' needs a scene file, --from x,y,z and --dir x,y,z");
    }
    return options;
}

GenerateOptions parseGenerateOptions(const std::vector<std::string>& args) {
    GenerateOptions options;
    std::optional<GeneratedScene> scene;
    bool countGiven = false;
    Arguments in(args, "generate");
    while (in.next()) {
        if (in.is("--count")) {
            options.generator.count = std::size_t(parseWholeNumber(in.option(), in.value(), 1, kMaxGeneratedBodies));
            countGiven = true;
        } else if (in.is("--seed")) {
            options.generator.seed = parseWholeNumber(in.option(), in.value(), 0, kMaxSteps);
        } else if (in.is("--out")) {
            options.outPath = in.value();
            if (options.outPath.empty()) throw UsageError("--out expects a file name ('-': standard output)");
        } else if (in.is("--broadphase")) {
            const std::string& value = in.value();
            const auto found = std::find_if(config::kBroadphaseChoices.begin(), config::kBroadphaseChoices.end(),
                                            [&](const auto& choice) { return config::equalsIgnoreCase(choice.word, value); });
            if (found == config::kBroadphaseChoices.end()) {
                throw UsageError("--broadphase expects Auto, BruteForce, SweepAndPrune, AabbTree, Grid or Octree, found '" +
                                 value + "'");
            }
            options.generator.broadphase = found->value;
        } else if (in.isOption()) {
            in.refuseUnknown();
        } else if (scene) {
            throw UsageError("'generate' makes one scene at a time, got a second: '" + in.current() + "'");
        } else {
            scene = generatedSceneNamed(in.current());
            if (!scene) throw UsageError("unknown scene '" + in.current() + "' (scenes: sphere-rain, box-pile, pyramids)");
        }
    }
    if (!scene || !countGiven || options.outPath.empty()) {
        throw UsageError("'generate' needs a scene (sphere-rain, box-pile, pyramids), --count N and --out FILE");
    }
    options.generator.scene = *scene;
    return options;
}

BenchOptions parseBenchOptions(const std::vector<std::string>& args) {
    if (args.empty() || args[0] != "broadphase") {
        throw UsageError("'bench' needs what to measure: 'stepwise bench broadphase FILE'");
    }
    BenchOptions options;
    bool sceneGiven = false;
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    Arguments in(rest, "bench");
    while (in.next()) {
        if (in.is("--steps")) {
            options.steps = parseWholeNumber(in.option(), in.value(), 1, kMaxSteps);
        } else if (in.is("--duration")) {
            options.duration = parseSeconds(in.option(), in.value());
        } else if (in.is("--check-every")) {
            options.checkEvery = parseWholeNumber(in.option(), in.value(), 1, kMaxSteps);
        } else if (in.isOption()) {
            in.refuseUnknown();
        } else {
            takeOne("bench broadphase", "scene file", options.scenePath, sceneGiven, in.current());
        }
    }
    if (!sceneGiven) throw UsageError("'bench broadphase' needs a scene file");
    if (options.duration && options.steps) throw UsageError("give --duration or --steps, not both");
    return options;
}

bool parseCommandOptions(const std::string& command, const std::vector<std::string>& args,
                         const std::string& defaultScene) {
    if (command == "run") parseRunOptions(args, defaultScene);
    else if (command == "view") parseViewOptions(args, defaultScene);
    else if (command == "plot") parsePlotOptions(args, defaultScene);
    else if (command == "grade") parseGradeOptions(args);
    else if (command == "trace") parseTraceOptions(args);
    else if (command == "raycast") parseRaycastOptions(args);
    else if (command == "generate") parseGenerateOptions(args);
    else if (command == "bench") parseBenchOptions(args);
    else return false;
    return true;
}

}  // namespace stepwise::cli
