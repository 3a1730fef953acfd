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
/// what the continuous stage costs when nothing is fast. A third times the
/// continuous stage alone on a layer of n resting spheres with many fast
/// ones arriving: each fast body tested against every other body (the O(n)
/// reference, stopFastBodiesAtImpactBruteForce()) against the candidate
/// index (stopFastBodiesAtImpact(), continuous_candidates.hpp).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "collision/continuous.hpp"
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
    "  --ccd-counts LIST  layer sizes of the continuous-stage table (default 1024,4096,16384; 0: skip it)\n"
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
    world.timeStages(true);  // the narrowphase's and the continuous stage's times are read below
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
    // A row of its own (ContinuousCollision=false in the scene column), as many cells as the others.
    std::printf("| %-22s | %7zu | %7zu | %7ld | %8.3f | %8.3f | %7s | %6s | %9s | %-9s |\n",
                (label + ", ContinuousCollision=false").c_str(), off.finalState.size(), off.pairs, threadCounts.front(),
                off.narrowphaseMs, off.stepMs, "", "", "off", identical(baseline.finalState, off.finalState) ? "yes" : "NO");
}

/// The continuous stage's scene: n spheres of radius kLayerRadius resting in a
/// square layer on the floor, and @p fast spheres above it that moved
/// kFastDrop m straight down this step, ending half-way into the layer.
constexpr Real kLayerRadius = Real(0.05);     ///< m
constexpr Real kLayerSpacing = Real(0.12);    ///< centre to centre, m: 2 cm gaps
constexpr Real kFastDrop = Real(1);           ///< m in one step: 20 radii, surely fast
constexpr int kContinuousRepeats = 21;        ///< timed calls per case; the median is printed

struct SweepCase {
    std::vector<DynamicObject> bodies;
    std::vector<Vec3> starts;
};

SweepCase sweepCase(std::size_t layer, std::size_t fast, std::uint64_t seed) {
    SweepCase c;
    const std::size_t side = static_cast<std::size_t>(std::ceil(std::sqrt(double(layer))));
    auto sphere = [](Vec3 position) {
        DynamicObject body;
        body.shape = Shape::Sphere;
        body.radius = kLayerRadius;
        body.scale = Vec3(2 * kLayerRadius);
        body.position = position;
        return body;
    };
    for (std::size_t i = 0; i < layer; ++i) {
        const Vec3 p(Real(i % side) * kLayerSpacing, kLayerRadius, Real(i / side) * kLayerSpacing);
        c.bodies.push_back(sphere(p));
        c.starts.push_back(p);
    }
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<Real> across(0, Real(side) * kLayerSpacing);
    for (std::size_t i = 0; i < fast; ++i) {
        const Vec3 end(across(random), kLayerRadius, across(random));
        c.bodies.push_back(sphere(end));
        c.starts.push_back(end + Vec3(0, kFastDrop, 0));
    }
    return c;
}

/// Median ms of one call of @p stage on fresh copies of the case; the last copy's result in @p result.
template <class StageFunction>
double timeSweep(const SweepCase& c, StageFunction stage, std::vector<DynamicObject>& result) {
    SweepWorkspace workspace;
    workspace.startPositions = c.starts;
    std::vector<double> times;
    using Clock = std::chrono::steady_clock;
    for (int r = 0; r < kContinuousRepeats; ++r) {
        result = c.bodies;  // outside the timing: the stage moves bodies back
        const auto start = Clock::now();
        stage(BodySet{result, {}, {}}, workspace);
        times.push_back(std::chrono::duration<double>(Clock::now() - start).count() * kMillisecondsPerSecond);
    }
    return median(times);
}

/// Median ms of building the candidate index alone (the stage's O(n) part in a step with a fast body).
double timeIndexBuild(const SweepCase& c) {
    std::vector<std::uint8_t> fast(c.bodies.size());
    for (std::size_t i = 0; i < fast.size(); ++i) fast[i] = c.bodies[i].position != c.starts[i] ? 1 : 0;
    std::vector<DynamicObject> bodies = c.bodies;
    SweptBoxIndex index;
    std::vector<double> times;
    using Clock = std::chrono::steady_clock;
    for (int r = 0; r < kContinuousRepeats; ++r) {
        const auto start = Clock::now();
        index.build(BodySet{bodies, {}, {}}, c.starts, fast);
        times.push_back(std::chrono::duration<double>(Clock::now() - start).count() * kMillisecondsPerSecond);
    }
    return median(times);
}

void benchContinuous(const std::vector<long>& layers, std::uint64_t seed) {
    std::printf("\nThe continuous stage alone: n spheres resting in a layer, fast ones arriving from %.0f m above\n"
                "(median of %d calls; brute force: each fast body against all n, the old stage)\n\n",
                double(kFastDrop), kContinuousRepeats);
    std::printf("|  bodies |  fast | brute force ms | brute us per fast | index ms | of which build ms | index us per fast (after build) | speed-up | identical |\n");
    std::printf("|--------:|------:|---------------:|------------------:|---------:|------------------:|--------------------------------:|---------:|-----------|\n");
    for (long layer : layers) {
        for (std::size_t fast : {std::size_t(64), static_cast<std::size_t>(layer) / 8}) {
            const SweepCase c = sweepCase(static_cast<std::size_t>(layer), fast, seed);
            std::vector<DynamicObject> brute, indexed;
            const double bruteMs = timeSweep(c, stopFastBodiesAtImpactBruteForce, brute);
            const double indexMs = timeSweep(c, stopFastBodiesAtImpact, indexed);
            bool same = brute.size() == indexed.size();
            for (std::size_t i = 0; same && i < brute.size(); ++i) same = brute[i].position == indexed[i].position;
            const double buildMs = timeIndexBuild(c);
            std::printf("| %7zu | %5zu | %14.3f | %17.2f | %8.3f | %17.3f | %31.2f | %7.1fx | %-9s |\n",
                        c.bodies.size(), fast, bruteMs, 1e3 * bruteMs / double(fast), indexMs, buildMs,
                        1e3 * (indexMs - buildMs) / double(fast), bruteMs / indexMs, same ? "yes" : "NO");
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<long> counts{4096, 16384};
    std::vector<long> threadCounts{1, 2};
    int settle = 120, steps = 60;
    std::uint64_t seed = 1;
    std::vector<long> ccdCounts{1024, 4096, 16384};
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
        else if (arg == "--ccd-counts") ccdCounts = splitNumbers(value);
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
    if (!(ccdCounts.size() == 1 && ccdCounts.front() == 0)) benchContinuous(ccdCounts, seed);
    return 0;
}
