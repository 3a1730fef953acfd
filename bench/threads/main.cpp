/// @file main.cpp
/// @brief stepwise_bench_threads: what the threaded narrowphase and the continuous-collision stage cost.
///
/// For each scene (generated sphere piles, the 210-box pyramid) and each
/// thread count, the scene is loaded, stepped `--settle` steps untimed (the
/// spheres fall into a heap: that is when the narrowphase has work), then
/// `--steps` steps timed one by one. It prints the median of the
/// narrowphase's time per step and of the whole step's, the speed-up over one
/// thread, and whether the final state is bit-identical to one thread's.
/// A second table times the same runs with ContinuousCollision off, to show
/// what the continuous stage costs when nothing is fast.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "config/scene_generator.hpp"
#include "config/scene_loader.hpp"
#include "world/world.hpp"

using namespace stepwise;

namespace {

constexpr const char* kUsage =
    "Usage: stepwise_bench_threads [--counts LIST] [--threads LIST] [--settle N] [--steps N] [--seed S]\n"
    "  --counts LIST    sphere-pile sizes, comma-separated (default 4096,16384)\n"
    "  --threads LIST   thread counts, comma-separated (default 1,2)\n"
    "  --settle N       untimed steps before timing: the fall (default 120)\n"
    "  --steps N        timed steps (default 60)\n"
    "  --seed S         seed of the generated piles (default 1)\n"
    "  Also runs config/lesson08_pyramid.scene. Prints medians of per-step times.\n";

constexpr double kMillisecondsPerSecond = 1e3;

std::vector<long> splitNumbers(const std::string& text) {
    std::vector<long> values;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = text.find(',', start);
        values.push_back(std::strtol(text.substr(start, comma - start).c_str(), nullptr, 10));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return values;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Measured {
    double narrowphaseMs = 0;  ///< Median narrowphase time per step.
    double continuousMs = 0;   ///< Median continuous-collision stage time per step.
    double stepMs = 0;         ///< Median whole-step time.
    std::size_t pairs = 0;     ///< Candidate pairs in the last step.
    std::vector<DynamicObject> finalState;
};

Measured measure(Scene scene, int threads, bool continuous, int settle, int steps) {
    scene.settings.threads = threads;
    scene.settings.continuousCollision = continuous;
    World world(std::move(scene));
    for (int i = 0; i < settle; ++i) world.step();
    std::vector<double> narrow, sweep, whole;
    using Clock = std::chrono::steady_clock;
    for (int i = 0; i < steps; ++i) {
        const auto start = Clock::now();
        world.step();
        whole.push_back(std::chrono::duration<double>(Clock::now() - start).count() * kMillisecondsPerSecond);
        const StageRecords& records = world.stageRecords();
        narrow.push_back(records[static_cast<std::size_t>(Stage::Narrowphase)].lastSeconds * kMillisecondsPerSecond);
        sweep.push_back(records[static_cast<std::size_t>(Stage::Continuous)].lastSeconds * kMillisecondsPerSecond);
    }
    return {median(narrow), median(sweep), median(whole), world.candidatePairs().size(), world.dynamics()};
}

bool identical(const std::vector<DynamicObject>& a, const std::vector<DynamicObject>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].position != b[i].position || a[i].velocity != b[i].velocity ||
            a[i].orientation != b[i].orientation || a[i].angularMomentum != b[i].angularMomentum) {
            return false;
        }
    }
    return true;
}

void benchScene(const std::string& label, const Scene& scene, const std::vector<long>& threadCounts, int settle,
                int steps) {
    Measured baseline;
    for (std::size_t k = 0; k < threadCounts.size(); ++k) {
        const int threads = static_cast<int>(threadCounts[k]);
        const Measured m = measure(scene, threads, true, settle, steps);
        if (k == 0) baseline = m;
        const bool same = identical(baseline.finalState, m.finalState);
        std::printf("| %-22s | %7zu | %7zu | %7d | %8.3f | %8.3f | %6.2fx | %6.2fx | %9.4f | %-9s |\n", label.c_str(),
                    m.finalState.size(), m.pairs, threads, m.narrowphaseMs, m.stepMs,
                    baseline.narrowphaseMs / m.narrowphaseMs, baseline.stepMs / m.stepMs, m.continuousMs,
                    same ? "yes" : "NO");
    }
    // The continuous stage's cost when nothing is fast: the same run with it switched off.
    const Measured off = measure(scene, static_cast<int>(threadCounts.front()), false, settle, steps);
    std::printf("| %-22s | %7zu | %7zu | %7ld | %8.3f | %8.3f |  (ContinuousCollision=false)  | %-9s |\n",
                label.c_str(), off.finalState.size(), off.pairs, threadCounts.front(), off.narrowphaseMs, off.stepMs,
                identical(baseline.finalState, off.finalState) ? "yes" : "NO");
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<long> counts{4096, 16384};
    std::vector<long> threadCounts{1, 2};
    int settle = 120, steps = 60;
    std::uint64_t seed = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (i + 1 >= argc) {
            std::fprintf(stderr, "%s needs a value\n%s", arg.c_str(), kUsage);
            return 2;
        }
        const std::string value = argv[++i];
        if (arg == "--counts") counts = splitNumbers(value);
        else if (arg == "--threads") threadCounts = splitNumbers(value);
        else if (arg == "--settle") settle = std::atoi(value.c_str());
        else if (arg == "--steps") steps = std::atoi(value.c_str());
        else if (arg == "--seed") seed = std::strtoull(value.c_str(), nullptr, 10);
        else {
            std::fprintf(stderr, "unknown option %s\n%s", arg.c_str(), kUsage);
            return 2;
        }
    }
    std::printf("hardware threads: %u; %d settling steps, then medians of %d timed steps\n\n", autoThreadCount(),
                settle, steps);
    std::printf("| scene                  |  bodies |   pairs | threads | narrow ms | step ms | narrow x | step x | ccd ms | identical |\n");
    std::printf("|------------------------|--------:|--------:|--------:|----------:|--------:|---------:|-------:|-------:|-----------|\n");
    for (long count : counts) {
        GeneratorOptions options;
        options.scene = GeneratedScene::SphereRain;
        options.count = static_cast<std::size_t>(count);
        options.seed = seed;
        benchScene("sphere pile " + std::to_string(count), parseScene(generateSceneText(options), "sphere-rain"),
                   threadCounts, settle, steps);
    }
    benchScene("pyramid (210 boxes)", loadSceneFile(std::string(STEPWISE_CONFIG_DIR) + "/lesson08_pyramid.scene"),
               threadCounts, settle, steps);
    return 0;
}
