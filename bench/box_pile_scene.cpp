/// @file box_pile_scene.cpp
/// @brief Writes the box pile into a box of static walls (box_pile_scene.hpp).
#include "box_pile_scene.hpp"

#include "config/scene_writing.hpp"
#include "wall_rain_scene.hpp"

namespace stepwise::bench {

namespace {

using namespace scene_writing;

constexpr double kJitter = 0.05;      ///< Largest random offset of a box from its site, m.
constexpr double kDensity = 1000;     ///< kg/m³ (water): 1000 kg for a 1 m cube.
constexpr double kElasticity = 0.0;   ///< No bounce: a pile settles.
constexpr double kFriction = 0.6;     ///< Boxes and walls alike (combined by product: 0.36).
constexpr double kHeadroom = 1.0;     ///< How far the walls reach above the top layer, m.
constexpr double kFullTurn = 360;     ///< Degrees: each Rotation component is drawn in [0, 360).

}  // namespace

std::string boxPileSceneText(std::size_t count, std::uint64_t seed) {
    const double side = double(latticeColumns(count)) * kPilePitch;  // inside width of the box, m
    const double top = kLatticeClearance + kLatticeLayers * kPilePitch;
    const double height = top + kHeadroom;
    const double t = kWallThickness;
    SplitMix64 random(seed);

    std::string text;
    append(text,
           "# Box pile (issue #33): %zu boxes with edges of %.1f to %.1f m, turned at random, dropped into a box\n"
           "# %.2f m wide whose floor and walls are static boxes, seed %llu.\n",
           count, kPileSmallestEdge, kPileLargestEdge, side, static_cast<unsigned long long>(seed));
    append(text, "# Written by: stepwise-bench pile-scene --count %zu --seed %llu (bench/box_pile_scene.cpp).\n", count,
           static_cast<unsigned long long>(seed));
    text += "World, TimeStep=1/60, Duration=10, Sleep=false\n";
    appendStaticContainer(text, side, height, t, kElasticity, kFriction);  // floor top at y = 0, walls around [0, side]²
    appendLattice(count, random, kPilePitch, kJitter, [&](std::size_t n, double x, double y, double z, double vx,
                                                          double vz) {
        // One draw per statement: the order of a call's arguments is unspecified.
        const double sx = random.uniform(kPileSmallestEdge, kPileLargestEdge);
        const double sy = random.uniform(kPileSmallestEdge, kPileLargestEdge);
        const double sz = random.uniform(kPileSmallestEdge, kPileLargestEdge);
        const double rx = random.uniform(0, kFullTurn);
        const double ry = random.uniform(0, kFullTurn);
        const double rz = random.uniform(0, kFullTurn);
        append(text,
               "DynamicObject, Name=b%zu, Shape=Box, Position=(%.4f, %.4f, %.4f), Velocity=(%.3f, 0, %.3f), "
               "Scale=(%.3f, %.3f, %.3f), Rotation=(%.1f, %.1f, %.1f), Mass=%.1f, Elasticity=%.1f, Friction=%.1f\n",
               n, x, y, z, vx, vz, sx, sy, sz, rx, ry, rz, kDensity * sx * sy * sz, kElasticity, kFriction);
    });
    return text;
}

}  // namespace stepwise::bench
