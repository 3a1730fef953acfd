/// @file soak.hpp
/// @brief `stepwise-bench soak`: random valid scenes of every kind, run for a million steps in all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace stepwise::bench {

/// @brief Options of `stepwise-bench soak`.
struct SoakOptions {
    std::uint64_t totalSteps = 1000000;  ///< --steps N: steps over all scenes.
    std::uint64_t stepsPerScene = 2000;  ///< --steps-per-scene N.
    std::uint64_t seed = 1;              ///< --seed S: the first scene's seed; scene k has seed S + k.
    std::string failureDir = ".";        ///< --keep DIR: where a failing scene's text is written.
    bool quick = false;                  ///< --quick: 30 scenes of 300 steps (the CTest test bench_soak_quick).
};

/// @brief The usage lines of `stepwise-bench soak`.
extern const char* const kSoakUsage;

/// @brief Parses the arguments after `soak` and runs it; the exit code (0: every scene clean,
/// 1: a scene failed, 2: a bad argument).
int soakCommand(const std::vector<std::string>& args);

/// @brief The text of soak scene @p seed: a closed box of planes holding spheres and boxes,
/// kinematic bodies, springs, attractors and joints of every kind, with a random solver.
/// @param elastic an isolated elastic gas instead: no gravity, e = 1, μ = 0, spheres only.
std::string soakSceneText(std::uint64_t seed, bool elastic, std::uint64_t steps);

}  // namespace stepwise::bench
