/// @file main.cpp
/// @brief stepwise_bench_walkthrough: the cost of the viewer's S key (src/viewer/stage_walkthrough.hpp).
///
/// For each scene: simulate to t = 1 s, then take the same number of steps
/// twice, on two Simulations of the scene: plainly (the N key), and recorded
/// stage by stage (the S key: World::step() with the StageWalkthrough
/// observer, then leaving the walk-through). Prints the snapshots per step,
/// the bytes the snapshot arrays hold after the recordings, and the time of a
/// plain and of a recorded step. The first recording (which allocates the
/// arrays) is in the average: it is what the first press of S costs.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "viewer/simulation.hpp"

using namespace stepwise;
using namespace stepwise::viewer;

namespace {

/// Simulated time before the measured steps, s: past the drop, bodies in contact.
constexpr double kSettleSeconds = 1.0;
/// Steps measured each way.
constexpr int kSteps = 20;
/// Bytes per kibibyte.
constexpr double kKiB = 1024.0;

double millisecondsPerStep(std::chrono::steady_clock::duration elapsed) {
    return std::chrono::duration<double, std::milli>(elapsed).count() / kSteps;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> scenes(argv + 1, argv + argc);
    if (scenes.empty()) {
        for (const char* name : {"lesson03_bounce", "lesson06_manifold", "viewer_test", "lesson08_tower",
                                 "lesson08_pyramid"}) {
            scenes.push_back(std::string(STEPWISE_CONFIG_DIR) + "/" + name + ".scene");
        }
    }
    std::printf("| scene | bodies | snapshots per step | snapshot memory, KiB | plain step, ms | recorded step, ms |\n");
    std::printf("|-------|-------:|-------------------:|---------------------:|---------------:|------------------:|\n");
    for (const std::string& path : scenes) {
        Simulation plain(path), recorded(path);
        plain.stepTo(kSettleSeconds);
        recorded.stepTo(kSettleSeconds);
        using Clock = std::chrono::steady_clock;
        const Clock::time_point start = Clock::now();
        for (int i = 0; i < kSteps; ++i) plain.stepOnce();
        const Clock::time_point middle = Clock::now();
        for (int i = 0; i < kSteps; ++i) {
            recorded.showStageRun(0);  // S: record a step, show its first stage
            recorded.stepOnce();       // N: leave the walk-through at the end of that step
        }
        const Clock::time_point end = Clock::now();
        const World& world = recorded.world();
        const std::string name = path.substr(path.find_last_of('/') + 1);
        std::printf("| %s | %zu | %zu | %.1f | %.3f | %.3f |\n", name.c_str(),
                    world.dynamics().size() + world.kinematics().size(), recorded.walkthrough().size(),
                    double(recorded.walkthrough().memoryBytes()) / kKiB, millisecondsPerStep(middle - start),
                    millisecondsPerStep(end - middle));
    }
    return 0;
}
