/// @file sphere_rain_scene.hpp
/// @brief The benchmark's sphere rain: N spheres of radius 0.5 m falling into an open box.
///
/// The scene of issue #7 (the same in Stepwise and in Bullet): spheres of
/// radius 0.5 m on a jittered lattice of 16 layers, dropped into a box of five
/// planes (a floor and four walls, open at the top) whose floor grows with N,
/// so the pile is about as deep at 1k as at 64k; dt = 1/60 s, 600 steps.
/// `stepwise-bench rain-scene --count N --out FILE` writes it;
/// config/bench_sphere_rain_1k.scene is the 1000-sphere one, for students to
/// open; the larger ones are generated from the seed when the benchmark runs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/types.hpp"

namespace stepwise::bench {

/// @brief Radius of every sphere of the rain, m.
inline constexpr Real kRainRadius = Real(0.5);
/// @brief Steps of a sphere-rain run: 10 s at 1/60 s, the fall (about 2 s) and the settling.
inline constexpr int kRainSteps = 600;

/// @brief The scene file's text for @p count spheres and @p seed (the same text on every machine).
std::string sphereRainSceneText(std::size_t count, std::uint64_t seed);

}  // namespace stepwise::bench
