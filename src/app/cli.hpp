/// @file cli.hpp
/// @brief The `stepwise` command line: parsed options and the commands they run.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "config/scene_generator.hpp"
#include "core/exit_codes.hpp"
#include "core/types.hpp"
#include "io/trace_writer.hpp"
#include "io/quantity_table.hpp"
#include "viewer/view_options.hpp"
#include "world/expectations.hpp"
#include "world/scene.hpp"
#include "world/world.hpp"

/// @brief The `stepwise` command-line program (src/app/).
namespace stepwise::cli {

/// @brief Thrown for a malformed command line; the message says what and how to fix it.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// @brief Options of `stepwise run`.
struct RunOptions {
    std::string scenePath;                ///< Scene file; the default scene when not given.
    std::optional<double> duration;       ///< --duration S: simulated seconds (overrides the scene's Duration).
    std::optional<std::uint64_t> steps;   ///< --steps N: number of steps (alternative to --duration).
    std::optional<std::string> csvPath;   ///< --csv PATH: write the trajectory here.
    std::optional<std::string> nodesCsvPath;  ///< --csv-nodes PATH: write every soft body's nodes here.
    std::uint64_t every = 1;              ///< --every K: write a CSV sample every K steps.
    bool explain = false;                 ///< --explain: print the step plan first (with --steps 0, only that).
    std::optional<int> threads;           ///< --threads N: overrides the scene's World Threads (0: one per hardware thread).
    std::optional<double> maxSeconds;     ///< --max-seconds S: wall-clock budget; past it the run stops (exit code 1).
};

/// @brief Parses the arguments after `run`. @throws UsageError.
RunOptions parseRunOptions(const std::vector<std::string>& args, const std::string& defaultScene);

/// @brief `stepwise run`: simulate, print a summary, optionally write CSV. Returns the exit code.
int runCommand(const RunOptions& options);

/// @brief The one-line message for running out of memory in a step of @p world: the step, the
/// bodies, the contacts, and the likely cause (bodies that all overlap).
std::string outOfMemoryMessage(const World& world);

/// @brief Loads the scene at @p path, printing its warnings, or every diagnostic and
/// "nothing was loaded" to stderr; nullptr when it did not load (`run`, `check`, `bench`, `raycast`).
std::unique_ptr<Scene> loadOrReport(const std::string& path);

/// @brief Parses the arguments after `view` (the options are the viewer's). @throws UsageError.
viewer::ViewOptions parseViewOptions(const std::vector<std::string>& args, const std::string& defaultScene);

/// @brief How long `stepwise grade` lets one file run by default, wall-clock seconds: far longer than
/// any assignment needs (they run in well under a second), short enough that one submission that
/// never ends cannot stall a class's grading.
inline constexpr double kDefaultGradeSeconds = 60;

/// @brief Options of `stepwise grade`.
struct GradeOptions {
    std::string folder;                     ///< Folder of scene files (searched recursively).
    std::string glob = "*.scene";           ///< --scene-glob GLOB: which files, matched against the path below the folder.
    std::optional<std::string> expectPath;  ///< --expect FILE: check these Expect records instead of each file's own.
    std::uint64_t maxSteps = 1000000;       ///< --max-steps N: a scene needing more steps is an error row.
    double maxSecondsPerFile = kDefaultGradeSeconds;  ///< --max-seconds S: wall-clock budget of each file's run.
};

/// @brief Parses the arguments after `grade`. @throws UsageError.
GradeOptions parseGradeOptions(const std::vector<std::string>& args);

/// @brief `stepwise grade DIR`: run every scene in a folder, one table row per file. Returns the exit code.
int gradeCommand(const GradeOptions& options);

/// @brief Prints the pass/fail table of a run's expectations (what `stepwise run` shows after its summary).
/// @return true when every expectation passed.
bool printExpectationTable(const std::vector<Expectation>& expectations, const std::vector<ExpectationResult>& results);

/// @brief `stepwise check FILE`: validate and describe a scene. Returns the exit code.
int checkCommand(const std::string& scenePath);

/// @brief Options of `stepwise raycast FILE --from x,y,z --dir x,y,z [--max D] [--at T]`.
struct RaycastOptions {
    std::string scenePath;        ///< Scene file.
    Vec3 from{0};                 ///< --from: the ray's start, m.
    Vec3 direction{0, -1, 0};     ///< --dir: its direction (any usable length; normalised by the command).
    double maxDistance = HUGE_VAL;  ///< --max D: how far the ray reaches, m.
    double at = 0;                ///< --at T: simulated seconds before the ray is cast.
};

/// @brief Parses the arguments after `raycast`. @throws UsageError.
RaycastOptions parseRaycastOptions(const std::vector<std::string>& args);

/// @brief `stepwise raycast`: the first body along a ray. Returns the exit code.
int raycastCommand(const RaycastOptions& options);

/// @brief The most bodies `stepwise generate --count` writes: a million spheres are a 100 MB
/// scene file and still step (the broadphase benchmarks go to 65 536).
inline constexpr std::uint64_t kMaxGeneratedBodies = 1000000;

/// @brief Options of `stepwise generate SCENE --count N --out FILE [--seed S] [--broadphase KIND]`.
struct GenerateOptions {
    GeneratorOptions generator;  ///< Which scene, how many bodies, the seed, the broadphase.
    std::string outPath;         ///< --out FILE ('-': standard output).
};

/// @brief Parses the arguments after `generate`. @throws UsageError.
GenerateOptions parseGenerateOptions(const std::vector<std::string>& args);

/// @brief `stepwise generate`: write a benchmark scene. Returns the exit code.
int generateCommand(const GenerateOptions& options);

/// @brief Options of `stepwise bench broadphase FILE [--steps N | --duration S] [--check-every K]`.
struct BenchOptions {
    std::string scenePath;               ///< Scene file.
    std::optional<double> duration;      ///< --duration S: simulated seconds.
    std::optional<std::uint64_t> steps;  ///< --steps N: steps instead of a duration.
    std::uint64_t checkEvery = 1;        ///< --check-every K: compare with brute force every K-th step.
};

/// @brief Parses the arguments after `bench` (the first must be `broadphase`). @throws UsageError.
BenchOptions parseBenchOptions(const std::vector<std::string>& args);

/// @brief `stepwise bench broadphase`: the broadphase tracker. Returns the exit code (1 when a
/// broadphase disagrees with brute force).
int benchCommand(const BenchOptions& options);

/// @brief Options of `stepwise trace FILE [--steps N] [--from STEP] [--stage NAME] [--object NAME]
/// [--substeps all] [--digits D] [--max-seconds S]`.
struct TraceCommandOptions {
    std::string scenePath;             ///< Scene file.
    TraceOptions trace;                ///< What to print (src/io/trace_writer.hpp).
    std::optional<double> maxSeconds;  ///< --max-seconds S: wall-clock budget (exit code 1 past it).
};

/// @brief Parses the arguments after `trace`. @throws UsageError.
TraceCommandOptions parseTraceOptions(const std::vector<std::string>& args);

/// @brief `stepwise trace`: stage-by-stage lines of what each stage took in and produced. Returns the exit code.
int traceCommand(const TraceCommandOptions& options);

/// @brief Options of `stepwise plot`.
struct PlotOptions {
    std::string scenePath;                       ///< Scene file; the default scene when not given.
    PlotQuantity quantity = PlotQuantity::Position;  ///< --quantity Q: what to draw against time.
    std::vector<std::string> objects;            ///< --object NAME (repeatable, or a,b): the bodies; empty: every dynamic one.
    std::vector<std::string> components;         ///< --component C (repeatable, or x,y): the panels; empty: the defaults.
    std::optional<double> duration;              ///< --duration S: simulated seconds (overrides the scene's Duration).
    std::optional<std::uint64_t> steps;          ///< --steps N: number of steps (alternative to --duration).
    std::uint64_t every = 1;                     ///< --every K: a sample every K steps.
    std::optional<std::string> outPath;          ///< --out FILE.png: the picture, drawn by gnuplot.
    std::optional<std::string> dataPath;         ///< --data FILE: the numbers plotted, as CSV ('-': standard output).
    int width = 800;                             ///< --size WxH: the picture's width, pixels.
    int height = 600;                            ///< --size WxH: the picture's height, pixels.
};

/// @brief Parses the arguments after `plot`. @throws UsageError.
PlotOptions parsePlotOptions(const std::vector<std::string>& args, const std::string& defaultScene);

/// @brief `stepwise plot`: simulate, sample one quantity of chosen bodies, write its numbers and/or
/// draw them with gnuplot. Returns the exit code (1 when gnuplot cannot run or fails).
int plotCommand(const PlotOptions& options);

/// @brief Parses @p args, the arguments after @p command, as that command does, and runs nothing:
/// what the tests and the command-line fuzzer call. @return false for a word with no option parser
/// here (`check`, an unknown command). @throws UsageError for a bad command line.
bool parseCommandOptions(const std::string& command, const std::vector<std::string>& args,
                         const std::string& defaultScene);

/// @brief The usage text printed by `stepwise` and `stepwise --help`.
std::string usageText();

/// @brief What `stepwise COMMAND --help` prints: that command's lines of the usage text ("" for an
/// unknown command); for `view`, the window's controls too.
std::string commandUsageText(const std::string& command);

}  // namespace stepwise::cli
