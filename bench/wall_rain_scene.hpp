/// @file wall_rain_scene.hpp
/// @brief The sphere rain as a user builds a level: a floor and four walls of static boxes, not planes.
///
/// The scene of issue #33. A real level has no infinite planes: its floor and
/// walls are boxes that do not move (KinematicsObject with no velocity). This
/// rain is built that way, as a new user would build it: spheres of radius
/// 0.5 m in columns 1.25 m apart, 16 layers deep, e = 0.5 against each other
/// and the walls, and `Sleep=false`, so every step solves every contact.
/// The floor is a slab under the lattice and the walls stand on it; the walls
/// reach a metre above the top layer, so no sphere can leave the box.
///
/// `stepwise-bench rain-scene --walls boxes --count N --out FILE` writes it;
/// `stepwise-bench bullet` runs it at 1k, 4k and 16k spheres.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace stepwise::bench {

/// @brief Distance between the centres of neighbouring columns of the wall rain, m.
inline constexpr double kWallRainPitch = 1.25;
/// @brief Thickness of the floor slab and of each wall of the wall rain, m.
inline constexpr double kWallThickness = 1.0;

/// @brief The scene file's text for @p count spheres and @p seed (the same text on every machine).
std::string wallRainSceneText(std::size_t count, std::uint64_t seed);

}  // namespace stepwise::bench
