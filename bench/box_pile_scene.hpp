/// @file box_pile_scene.hpp
/// @brief A pile of boxes dropped into a box of static walls, as a user builds a level (issue #33).
///
/// Boxes of edges from kPileSmallestEdge to kPileLargestEdge (each edge drawn
/// on its own, so a few are slabs or sticks), each turned at random, on a
/// jittered lattice 16 layers deep (scene_writing::appendLattice()), dropped
/// into a box whose floor and four walls are static boxes (KinematicsObject
/// with no velocity), as in the wall rain (wall_rain_scene.hpp). Elasticity 0,
/// friction 0.6, density of water, `Sleep=false`: every step solves every
/// contact, and the pile must come to rest by friction alone.
///
/// `stepwise-bench pile-scene --count N --out FILE` writes it
/// (config/bench_box_pile_1k.scene is N = 1000); `stepwise-bench bullet`
/// runs it in both engines.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace stepwise::bench {

/// @brief Shortest edge of a pile box, m.
inline constexpr double kPileSmallestEdge = 0.8;
/// @brief Longest edge of a pile box, m.
inline constexpr double kPileLargestEdge = 1.2;
/// @brief Distance between lattice sites, m: more than a 1.2 m cube's diagonal
/// (√3·1.2 = 2.08 m) less the jitter, so no two boxes touch at the start, whatever their turn.
inline constexpr double kPilePitch = 2.2;

/// @brief The scene file's text for @p count boxes and @p seed (the same text on every machine).
std::string boxPileSceneText(std::size_t count, std::uint64_t seed);

}  // namespace stepwise::bench
