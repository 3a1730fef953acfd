/// @file main.cpp
/// @brief `stepwise-bench`: the benchmark programs behind docs/benchmarks.md.
///
///     stepwise-bench precision [--quick] [--repeats N] [--csv PATH] [--markdown PATH]
///                              [--config DIR] [--problems a,b,...]
///     stepwise-bench stress [--quick] [--markdown PATH] [--config DIR] [--cases a,b,...]
///
///     stepwise-bench scaling | stage-costs | bullet | rain-scene | pile-scene ...   (scaling_commands.cpp)
///     stepwise-bench narrowphase [--quick] [--pairs N] [--repeats N] [--seed S]   (narrowphase_bench.cpp)
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "precision.hpp"
#include "stress.hpp"
#include "scaling_commands.hpp"
#include "soak.hpp"
#include "narrowphase_bench.hpp"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;

const char* const kUsage =
    "stepwise-bench: the benchmarks behind docs/benchmarks.md (scripts/bench.sh runs them)\n"
    "\n"
    "  precision     each integrator's error and cost on the reference problems\n"
    "  stress        the stress cases, each judged pass or fail\n"
    "  scaling       the cost per body from 1k to 64k bodies\n"
    "  stage-costs   the settled rain's cost per body, stage by stage\n"
    "  bullet        the same scene files in Stepwise and in Bullet 3\n"
    "  soak          random valid scenes of every kind for a million steps\n"
    "  narrowphase   SAT, GJK+EPA and MPR on the same shape pairs: ns per pair, iterations\n"
    "  rain-scene    writes a sphere-rain scene file\n"
    "  pile-scene    writes a box-pile scene file (boxes into a box of static walls)\n"
    "\n"
    "usage: stepwise-bench precision [--quick] [--repeats N] [--csv PATH] [--markdown PATH] [--config DIR]\n"
    "                                [--problems a,b,...]\n"
    "\n"
    "  Runs every reference problem (config/reference_*.scene) with every integrator\n"
    "  at time steps 1/30 ... 1/1920 s and prints each run's errors against the exact\n"
    "  solution and its cost in nanoseconds per step (median of the repetitions).\n"
    "\n"
    "  --quick           two time steps, one repetition: a smoke test\n"
    "  --repeats N       timed repetitions per point (default 5)\n"
    "  --csv PATH        write every measurement as CSV (one row per metric)\n"
    "  --markdown PATH   write the tables as Markdown (for docs/benchmarks.md)\n"
    "  --config DIR      where the scene files are (default: the source tree's config/)\n"
    "  --problems LIST   comma-separated problem names, e.g. spring,bounce\n"
    "\n"
    "usage: stepwise-bench stress [--quick] [--markdown PATH] [--config DIR] [--cases a,b,...]\n"
    "\n"
    "  Runs the stress cases (deep stacks, a 1000-body elastic gas, a bullet at a thin\n"
    "  wall, springs at and past their stability limit, a 1/15 s step, 10 km from the\n"
    "  origin, masses from 1 g to 10 t, random scenes) and judges each against its\n"
    "  criterion; exit code 1 when one fails.\n"
    "\n"
    "  --quick           shorter runs, fewer bodies (the CTest test bench_stress_quick)\n"
    "  --markdown PATH   write the table as Markdown (for docs/benchmarks.md)\n"
    "  --config DIR      where the scene files are (default: the source tree's config/)\n"
    "  --cases LIST      comma-separated case names, e.g. tower,random\n"
    "\n";

int usageError(const std::string& message) {
    std::fprintf(stderr, "stepwise-bench: error: %s\n\n%s", message.c_str(), kUsage);
    return kExitUsage;
}

std::vector<std::string> splitCommas(const std::string& text) {
    std::vector<std::string> parts;
    std::istringstream in(text);
    std::string part;
    while (std::getline(in, part, ',')) {
        if (!part.empty()) parts.push_back(part);
    }
    return parts;
}

/// `stepwise-bench stress …`: its options, then the suite (bench/stress.cpp).
int runStressCommand(const std::vector<std::string>& args) {
    stepwise::bench::StressOptions options;
    options.configDir = STEPWISE_CONFIG_DIR;
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "--quick") {
            options.quick = true;
        } else if (arg == "--markdown" || arg == "--config" || arg == "--cases") {
            if (i + 1 >= args.size()) return usageError(arg + " needs a value");
            const std::string& v = args[++i];
            if (arg == "--markdown") options.markdownPath = v;
            else if (arg == "--config") options.configDir = v;
            else options.only = splitCommas(v);
        } else {
            return usageError("unknown option '" + arg + "' for stress");
        }
    }
    return stepwise::bench::runStress(options);
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h") {
        std::fputs(kUsage, args.empty() ? stderr : stdout);
        std::fputs(stepwise::bench::kScalingUsage, args.empty() ? stderr : stdout);
        std::fputs(stepwise::bench::kSoakUsage, args.empty() ? stderr : stdout);
        std::fputs(stepwise::bench::kNarrowphaseUsage, args.empty() ? stderr : stdout);
        return args.empty() ? kExitUsage : kExitOk;
    }
    if (args[0] == "stress") return runStressCommand(args);
    if (args[0] == "scaling") return stepwise::bench::scalingCommand({args.begin() + 1, args.end()});
    if (args[0] == "stage-costs") return stepwise::bench::stageCostsCommand({args.begin() + 1, args.end()});
    if (args[0] == "bullet") return stepwise::bench::bulletCommand({args.begin() + 1, args.end()});
    if (args[0] == "rain-scene") return stepwise::bench::rainSceneCommand({args.begin() + 1, args.end()});
    if (args[0] == "pile-scene") return stepwise::bench::pileSceneCommand({args.begin() + 1, args.end()});
    if (args[0] == "soak") return stepwise::bench::soakCommand({args.begin() + 1, args.end()});
    if (args[0] == "narrowphase") return stepwise::bench::narrowphaseCommand({args.begin() + 1, args.end()});
    if (args[0] != "precision") return usageError("unknown subcommand '" + args[0] + "'");

    stepwise::bench::PrecisionOptions options;
    options.configDir = STEPWISE_CONFIG_DIR;
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& arg = args[i];
        const auto value = [&]() -> const std::string* { return i + 1 < args.size() ? &args[++i] : nullptr; };
        if (arg == "--quick") {
            options.quick = true;
        } else if (arg == "--repeats" || arg == "--csv" || arg == "--markdown" || arg == "--config" ||
                   arg == "--problems") {
            const std::string* v = value();
            if (!v) return usageError(arg + " needs a value");
            if (arg == "--repeats") {
                char* end = nullptr;
                const long n = std::strtol(v->c_str(), &end, 10);
                if (end == v->c_str() || *end != '\0' || n < 1 || n > 1000) {
                    return usageError("--repeats expects a whole number from 1 to 1000, found '" + *v + "'");
                }
                options.repeats = static_cast<int>(n);
            } else if (arg == "--csv") {
                options.csvPath = *v;
            } else if (arg == "--markdown") {
                options.markdownPath = *v;
            } else if (arg == "--config") {
                options.configDir = *v;
            } else {
                options.only = splitCommas(*v);
            }
        } else {
            return usageError("unknown option '" + arg + "'");
        }
    }
    return stepwise::bench::runPrecision(options);
}
