/// @file main.cpp
/// @brief stepwise_bench_broadphase: how each broadphase's cost grows with the number of bodies.
///
/// For each scene (sphere rain, box pile, pyramids) and each body count, the
/// scene is generated exactly as `stepwise generate` writes it, loaded, and
/// simulated for a fixed number of steps. Every step, the broadphase tracker
/// runs all four broadphases on the same bodies (brute force only every K-th
/// step: at 64k bodies it takes seconds), so every broadphase is timed on
/// identical states. Since they all return the same pairs, a World running
/// broadphase X would spend (the other stages' time) + (X's time) per step.
///
/// Prints one scaling table per scene, then the tracker's table for every run.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "collision/broadphase_tracker.hpp"
#include "config/scene_generator.hpp"
#include "config/scene_loader.hpp"
#include "io/broadphase_table.hpp"
#include "world/world.hpp"

using namespace stepwise;

namespace {

constexpr const char* kUsage =
    "Usage: stepwise_bench_broadphase [--scenes LIST] [--counts LIST] [--steps N] [--check-every K] [--seed S]\n"
    "  --scenes LIST     comma-separated: sphere-rain,box-pile,pyramids (default: all three)\n"
    "  --counts LIST     comma-separated body counts (default: 1024,4096,16384,65536)\n"
    "  --steps N         steps simulated per run (default 120: 2 s, the fall and the first settling)\n"
    "  --check-every K   run brute force and compare every K-th step (default 20)\n"
    "  --seed S          seed of the generated scenes (default 1)\n";

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = text.find(',', start);
        parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return parts;
}

/// One run: its tracker totals and the World's own stage times.
struct Run {
    std::size_t bodies = 0;
    double otherStagesSeconds = 0;  ///< Per step, every stage but the broadphase.
    std::vector<TrackedBroadphase> tracked;
    BroadphaseChoice autoChoice;
};

Run runScene(const GeneratorOptions& options, std::uint64_t steps, std::uint64_t checkEvery) {
    World world(parseScene(generateSceneText(options), toString(options.scene)));
    world.timeStages(true);  // the other stages' time is read below
    const BodySet initial{world.dynamics(), world.kinematics(), world.planes()};
    Run run;
    run.bodies = world.dynamics().size();
    run.autoChoice = chooseBroadphase(initial);

    BroadphaseTracker tracker;
    for (std::uint64_t i = 0; i < steps; ++i) {
        world.step();
        const BodySet bodies{world.dynamics(), world.kinematics(), world.planes()};
        tracker.observe(bodies, world.stepCount(), world.stepCount() % checkEvery == 0);
    }
    for (std::size_t s = 0; s < kStageCount; ++s) {
        if (static_cast<Stage>(s) == Stage::Broadphase) continue;
        run.otherStagesSeconds += world.stageRecords()[s].totalSeconds;
    }
    run.otherStagesSeconds /= double(world.stepCount());
    run.tracked = tracker.results();

    std::printf("\n%s, %zu bodies, seed %llu:\n", toString(options.scene), run.bodies,
                static_cast<unsigned long long>(options.seed));
    writeBroadphaseTable(stdout, tracker, {world.dynamics(), world.kinematics(), world.planes()});
    std::fflush(stdout);
    if (!tracker.agrees()) {
        std::fprintf(stderr, "stepwise_bench_broadphase: a broadphase differs from brute force\n");
        std::exit(1);
    }
    return run;
}

void printScaling(GeneratedScene scene, const std::vector<Run>& runs) {
    std::printf("\nScaling, %s: time per step in ms, and per body in us (broadphase alone | whole step)\n",
                toString(scene));
    std::printf("  %7s %12s", "bodies", "other stages");
    for (const BroadphaseKind kind : kAllBroadphases) std::printf(" %26s", toString(kind));
    std::printf("   Auto\n");
    for (const Run& run : runs) {
        std::printf("  %7zu %9.2f ms", run.bodies, 1e3 * run.otherStagesSeconds);
        for (const BroadphaseKind kind : kAllBroadphases) {
            for (const TrackedBroadphase& t : run.tracked) {
                if (t.kind != kind) continue;
                const double perStep = t.secondsPerStep();
                std::printf(" %8.2f ms %5.2f|%6.2f us", 1e3 * perStep, 1e6 * perStep / double(run.bodies),
                            1e6 * (perStep + run.otherStagesSeconds) / double(run.bodies));
            }
        }
        std::printf("   %s\n", toString(run.autoChoice.kind));
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> scenes = {"sphere-rain", "box-pile", "pyramids"};
    std::vector<std::string> counts = {"1024", "4096", "16384", "65536"};
    std::uint64_t steps = 120;
    std::uint64_t checkEvery = 20;
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
        if (arg == "--scenes") scenes = split(value);
        else if (arg == "--counts") counts = split(value);
        else if (arg == "--steps") steps = std::strtoull(value.c_str(), nullptr, 10);
        else if (arg == "--check-every") checkEvery = std::strtoull(value.c_str(), nullptr, 10);
        else if (arg == "--seed") seed = std::strtoull(value.c_str(), nullptr, 10);
        else {
            std::fprintf(stderr, "unknown option %s\n%s", arg.c_str(), kUsage);
            return 2;
        }
    }
    if (steps == 0 || checkEvery == 0) {
        std::fprintf(stderr, "--steps and --check-every must be > 0\n");
        return 2;
    }

    std::printf("stepwise_bench_broadphase: %llu steps per run, brute force and the comparison every %llu steps\n",
                static_cast<unsigned long long>(steps), static_cast<unsigned long long>(checkEvery));
    std::vector<std::pair<GeneratedScene, std::vector<Run>>> results;
    for (const std::string& name : scenes) {
        const std::optional<GeneratedScene> scene = generatedSceneNamed(name);
        if (!scene) {
            std::fprintf(stderr, "unknown scene '%s'\n%s", name.c_str(), kUsage);
            return 2;
        }
        std::vector<Run> runs;
        for (const std::string& count : counts) {
            GeneratorOptions options;
            options.scene = *scene;
            options.count = std::strtoull(count.c_str(), nullptr, 10);
            options.seed = seed;
            if (options.count == 0) {
                std::fprintf(stderr, "bad count '%s'\n", count.c_str());
                return 2;
            }
            runs.push_back(runScene(options, steps, checkEvery));
        }
        results.emplace_back(*scene, std::move(runs));
    }
    for (const auto& [scene, runs] : results) printScaling(scene, runs);
    return 0;
}
