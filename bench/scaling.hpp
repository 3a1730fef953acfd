/// @file scaling.hpp
/// @brief `stepwise-bench scaling`: Stepwise's time per step and per body as scenes grow (issue #6).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stepwise::bench {

/// @brief What `stepwise-bench scaling` runs.
struct ScalingOptions {
    bool quick = false;                      ///< --quick: one small run of each scene, 60 steps (CTest smoke test).
    std::vector<std::size_t> rainSizes;      ///< --sizes: sphere-rain counts (default 1000, 4000, 16000, 64000).
    std::vector<std::size_t> pileSizes;      ///< --pile-sizes: box-pile and pyramid counts (default 1000, 4000, 16000).
    int rainSteps = 600;                     ///< --steps: steps of a sphere-rain run below kLargeRain spheres.
    int largeRainSteps = 300;                ///< --large-steps: steps from kLargeRain spheres on (64k: 600 take too long).
    int pileSteps = 300;                     ///< --pile-steps: steps of a box-pile or pyramid run.
    std::uint64_t seed = 1;                  ///< --seed: seed of every generated scene.
    std::optional<std::string> markdownPath; ///< --markdown PATH: the tables as Markdown (docs/benchmarks.md).
};

/// @brief From this many spheres on, a rain runs ScalingOptions::largeRainSteps steps.
inline constexpr std::size_t kLargeRain = 32000;

/// @brief Runs the scaling benchmark and prints its tables; returns the exit code (0, or 1 when the
/// broadphase tracker found a broadphase disagreeing with brute force).
int runScaling(const ScalingOptions& options);

}  // namespace stepwise::bench
