/// @file scaling_commands.cpp
/// @brief Parses the options of `stepwise-bench scaling`, `stage-costs`, `bullet` and `rain-scene`.
#include "scaling_commands.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <optional>

#include "scaling.hpp"
#include "stage_costs.hpp"
#include "sphere_rain_scene.hpp"
#include "wall_rain_scene.hpp"
#include "box_pile_scene.hpp"
#ifdef STEPWISE_HAVE_BULLET
#include "bullet/side_by_side.hpp"
#endif

namespace stepwise::bench {

const char* const kScalingUsage =
    "usage: stepwise-bench scaling [--quick] [--sizes 1000,4000,16000,64000] [--pile-sizes 1000,4000,16000]\n"
    "                              [--steps 240] [--large-steps 240] [--pile-steps 120] [--seed 1]\n"
    "                              [--scenes sphere-rain,box-pile,pyramids] [--markdown PATH]\n"
    "\n"
    "  Stepwise's ms per step and µs per body per step on sphere rain (r = 0.5 m into an open box),\n"
    "  box piles and pyramids of growing size, and the broadphase tracker's table of each run.\n"
    "  --steps is the steps of a rain, --large-steps of a rain of 32 000 spheres or more,\n"
    "  --pile-steps of a pile or pyramids; --quick one small run of each (bench_scaling_quick).\n"
    "\n"
    "usage: stepwise-bench stage-costs [--quick] [--sizes 1000,16000,64000] [--settle 300] [--rounds 20]\n"
    "                                  [--seed 1] [--markdown PATH]\n"
    "\n"
    "  The sphere rain at each size, settled for --settle untimed steps, then the sizes stepped in\n"
    "  turn for --rounds rounds in one process (so a shared machine's slow minutes fall on all of\n"
    "  them): each stage's cost in ns per body per step, and the megabytes of each size's arrays.\n"
    "\n"
    "usage: stepwise-bench bullet [--quick] [--sizes 1000,4000,16000] [--steps 600] [--config DIR]\n"
    "                             [--scenarios rain,rain-sweep,stacks,pyramid-sweep,free-box,bounce,incline,\n"
    "                                          reference,wall-rain,box-pile,chain,ragdoll]\n"
    "                             [--markdown PATH] [--sweep-csv PATH] [--ratios-csv PATH]\n"
    "\n"
    "  The same scene files in Stepwise and in Bullet 3, one table per scenario: sphere rain\n"
    "  (--sizes, --steps), the 1k rain's run time against overlap (its runs as CSV: --sweep-csv),\n"
    "  pyramid and tower, the pyramid's run time against its largest displacement, free box, bounce at 1/60 and 1/240 s, incline, and the precision\n"
    "  benchmark's reference problems at 1/60, 1/240 and 1/960 s; then issue #33's scenes: the\n"
    "  wall rain (spheres into a box of static boxes, --sizes, --steps), a pile of 1000 boxes\n"
    "  into static walls, a 100-link chain (config/bench_chain.scene) and a 20-box ragdoll\n"
    "  (config/bench_ragdoll.scene), each with its accuracy beside its speed, and the largest\n"
    "  wall rain and the pile on 1 and 2 threads; then the verdicts on the targets of issues\n"
    "  #7 and #33. --ratios-csv writes each scene's times, speed ratio and accuracy as CSV.\n"
    "  --quick: small versions of each, a smoke test. Needs a build with -DSTEPWISE_WITH_BULLET=ON.\n"
    "\n"
    "usage: stepwise-bench rain-scene --count N [--seed S] [--walls planes|boxes] --out FILE\n"
    "\n"
    "  Writes the sphere-rain scene of N spheres (config/bench_sphere_rain_1k.scene is N = 1000);\n"
    "  --walls boxes writes the wall rain instead: a floor and walls of static boxes, e = 0.5,\n"
    "  columns 1.25 m apart, Sleep=false (issue #33).\n"
    "\n"
    "usage: stepwise-bench pile-scene --count N [--seed S] --out FILE\n"
    "\n"
    "  Writes the box pile of N boxes (edges 0.8 to 1.2 m, turned at random) dropped into a box\n"
    "  of static walls, Sleep=false (issue #33; config/bench_box_pile_1k.scene is N = 1000).\n";

namespace {

constexpr int kExitUsage = 2;

int usage(const std::string& message) {
    std::fprintf(stderr, "stepwise-bench: error: %s\n\n%s", message.c_str(), kScalingUsage);
    return kExitUsage;
}

/// Whole numbers from 1 to 10⁷, or nothing.
std::optional<std::size_t> count(const std::string& text) {
    char* end = nullptr;
    const unsigned long long n = std::strtoull(text.c_str(), &end, 10);
    constexpr unsigned long long kMost = 10'000'000;
    if (text.empty() || *end != '\0' || n < 1 || n > kMost) return std::nullopt;
    return static_cast<std::size_t>(n);
}

std::optional<std::vector<std::size_t>> counts(const std::string& text) {
    std::vector<std::size_t> values;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = text.find(',', start);
        const auto n = count(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (!n) return std::nullopt;
        values.push_back(*n);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return values;
}

/// The comma-separated words of @p text.
std::vector<std::string> names(const std::string& text) {
    std::vector<std::string> words;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = text.find(',', start);
        words.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return words;
}

/// An option's handler that reads a whole number (count()) into @p target; false when it is not one.
std::function<bool(const std::string&)> wholeNumberInto(int& target) {
    return [&target](const std::string& v) {
        const auto n = count(v);
        if (n) target = static_cast<int>(*n);
        return n.has_value();
    };
}

/// An option's handler that reads a scene generator's seed into @p target (as strtoull reads it).
std::function<bool(const std::string&)> seedInto(std::uint64_t& target) {
    return [&target](const std::string& v) {
        target = std::strtoull(v.c_str(), nullptr, 10);
        return true;
    };
}

/// An option's handler that keeps a path (--markdown, --sweep-csv) in @p target.
std::function<bool(const std::string&)> pathInto(std::optional<std::string>& target) {
    return [&target](const std::string& v) {
        target = v;
        return true;
    };
}

/// An option's handler that reads comma-separated whole numbers (counts()) into @p target.
std::function<bool(const std::string&)> wholeNumbersInto(std::vector<std::size_t>& target) {
    return [&target](const std::string& v) {
        const auto n = counts(v);
        if (n) target = *n;
        return n.has_value();
    };
}

/// Walks @p args: flags call their handler; options take the next argument and
/// their handler returns false when it is not valid.
int parse(const std::vector<std::string>& args, const std::map<std::string, std::function<void()>>& flags,
          const std::map<std::string, std::function<bool(const std::string&)>>& options) {
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (const auto flag = flags.find(args[i]); flag != flags.end()) {
            flag->second();
            continue;
        }
        const auto option = options.find(args[i]);
        if (option == options.end()) return usage("unknown option '" + args[i] + "'");
        if (i + 1 >= args.size()) return usage(args[i] + " needs a value");
        if (!option->second(args[i + 1])) return usage("bad value '" + args[i + 1] + "' for " + args[i]);
        ++i;
    }
    return 0;
}

}  // namespace

int scalingCommand(const std::vector<std::string>& args) {
    ScalingOptions o;
    const int status = parse(args, {{"--quick", [&] { o.quick = true; }}},
                             {{"--sizes", wholeNumbersInto(o.rainSizes)},
                              {"--pile-sizes", wholeNumbersInto(o.pileSizes)},
                              {"--steps", wholeNumberInto(o.rainSteps)},
                              {"--large-steps", wholeNumberInto(o.largeRainSteps)},
                              {"--pile-steps", wholeNumberInto(o.pileSteps)},
                              {"--seed", seedInto(o.seed)},
                              {"--scenes", [&](const std::string& v) { o.scenes = names(v); return true; }},
                              {"--markdown", pathInto(o.markdownPath)}});
    return status ? status : runScaling(o);
}

int stageCostsCommand(const std::vector<std::string>& args) {
    StageCostOptions o;
    const int status = parse(args, {{"--quick", [&] { o.quick = true; }}},
                             {{"--sizes", wholeNumbersInto(o.sizes)},
                              {"--settle", wholeNumberInto(o.settleSteps)},
                              {"--rounds", wholeNumberInto(o.rounds)},
                              {"--seed", seedInto(o.seed)},
                              {"--markdown", pathInto(o.markdownPath)}});
    return status ? status : runStageCosts(o);
}

int bulletCommand([[maybe_unused]] const std::vector<std::string>& args) {
#ifdef STEPWISE_HAVE_BULLET
    SideBySideOptions o;
    o.configDir = STEPWISE_CONFIG_DIR;
    const int status = parse(args, {{"--quick", [&] { o.quick = true; }}},
                             {{"--sizes", wholeNumbersInto(o.rainSizes)},
                              {"--config", [&](const std::string& v) { o.configDir = v; return true; }},
                              {"--steps", wholeNumberInto(o.rainSteps)},
                              {"--scenarios", [&](const std::string& v) { o.scenarios = names(v); return true; }},
                              {"--markdown", pathInto(o.markdownPath)},
                              {"--sweep-csv", pathInto(o.sweepCsvPath)},
                              {"--ratios-csv", pathInto(o.ratiosCsvPath)}});
    return status ? status : runSideBySide(o);
#else
    std::fprintf(stderr,
                 "stepwise-bench: built without Bullet: install it (STEPWISE_WITH_BULLET=1 scripts/setup.sh, or\n"
                 "apt-get install libbullet-dev pkg-config) and configure with -DSTEPWISE_WITH_BULLET=ON\n");
    return kExitUsage;
#endif
}

int rainSceneCommand(const std::vector<std::string>& args) {
    std::optional<std::size_t> n;
    std::uint64_t seed = 1;
    std::string out;
    bool boxWalls = false;  // --walls boxes: the wall rain (wall_rain_scene.hpp)
    const int status = parse(args, {},
                             {{"--count", [&](const std::string& v) { n = count(v); return n.has_value(); }},
                              {"--walls", [&](const std::string& v) { boxWalls = v == "boxes"; return v == "boxes" || v == "planes"; }},
                              {"--seed", [&](const std::string& v) { seed = std::strtoull(v.c_str(), nullptr, 10); return true; }},
                              {"--out", [&](const std::string& v) { out = v; return true; }}});
    if (status) return status;
    if (!n || out.empty()) return usage("rain-scene needs --count N and --out FILE");
    std::ofstream file(out);
    file << (boxWalls ? wallRainSceneText(*n, seed) : sphereRainSceneText(*n, seed));
    if (!file) {
        std::fprintf(stderr, "stepwise-bench: cannot write %s\n", out.c_str());
        return 1;
    }
    std::printf("wrote %s: %zu spheres, seed %llu\n", out.c_str(), *n, static_cast<unsigned long long>(seed));
    return 0;
}

int pileSceneCommand(const std::vector<std::string>& args) {
    std::optional<std::size_t> n;
    std::uint64_t seed = 1;
    std::string out;
    const int status = parse(args, {},
                             {{"--count", [&](const std::string& v) { n = count(v); return n.has_value(); }},
                              {"--seed", seedInto(seed)},
                              {"--out", [&](const std::string& v) { out = v; return true; }}});
    if (status) return status;
    if (!n || out.empty()) return usage("pile-scene needs --count N and --out FILE");
    std::ofstream file(out);
    file << boxPileSceneText(*n, seed);
    if (!file) {
        std::fprintf(stderr, "stepwise-bench: cannot write %s\n", out.c_str());
        return 1;
    }
    std::printf("wrote %s: %zu boxes, seed %llu\n", out.c_str(), *n, static_cast<unsigned long long>(seed));
    return 0;
}

}  // namespace stepwise::bench
