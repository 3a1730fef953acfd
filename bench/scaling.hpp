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
    bool quick = false;                      ///< --quick: one small run of each scene, 30 steps (CTest smoke test).
    std::vector<std::size_t> rainSizes;      ///< --sizes: sphere-rain counts (default 1000, 4000, 16000, 64000).
    std::vector<std::size_t> pileSizes;      ///< --pile-sizes: box-pile and pyramid counts (default 1000, 4000, 16000).
    /// --steps: steps of a sphere-rain run below kLargeRain spheres: 240 (4 s, the fall and the
    /// first settling) rather than the side-by-side's 600, so that 64k spheres take minutes, not an hour.
    int rainSteps = 240;
    int largeRainSteps = 240;                ///< --large-steps: steps of a rain of kLargeRain spheres or more.
    int pileSteps = 120;                     ///< --pile-steps: steps of a box-pile or pyramid run (2 s, as bench/broadphase).
    std::uint64_t seed = 1;                  ///< --seed: seed of every generated scene.
    /// --scenes: which of sphere-rain, box-pile, pyramids to run (default all three; runs in
    /// parallel processes share a busy machine better than one long run).
    std::vector<std::string> scenes;
    std::optional<std::string> markdownPath; ///< --markdown PATH: the tables as Markdown (docs/benchmarks.md).
};

/// @brief From this many spheres on, a rain runs ScalingOptions::largeRainSteps steps.
inline constexpr std::size_t kLargeRain = 32000;

/// @brief Runs the scaling benchmark and prints its tables; returns the exit code (0, or 1 when the
/// broadphase tracker found a broadphase disagreeing with brute force).
int runScaling(const ScalingOptions& options);

}  // namespace stepwise::bench
