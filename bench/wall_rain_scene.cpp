/// @file wall_rain_scene.cpp
/// @brief Writes the sphere rain into a box of static walls (wall_rain_scene.hpp).
#include "wall_rain_scene.hpp"

#include "config/scene_writing.hpp"
#include "sphere_rain_scene.hpp"

namespace stepwise::bench {

namespace {

using namespace scene_writing;

constexpr double kJitter = 0.05;       ///< Largest random offset of a sphere from its column, m.
constexpr double kDensity = 1000;      ///< kg/m³ (water): 524 kg per sphere.
constexpr double kElasticity = 0.5;    ///< e = 0.5, spheres and walls alike (combined by product: 0.25).
constexpr double kFriction = 0.5;      ///< μ = 0.5, spheres and walls alike.
constexpr double kHeadroom = 1.0;      ///< How far the walls reach above the top layer, m.
constexpr double kPi = 3.14159265358979323846;

}  // namespace

std::string wallRainSceneText(std::size_t count, std::uint64_t seed) {
    const double r = double(kRainRadius);
    const double side = double(latticeColumns(count)) * kWallRainPitch;  // inside width of the box, m
    const double top = kLatticeClearance + kLatticeLayers * kWallRainPitch;  // the top layer's top, m
    const double height = top + kHeadroom;
    const double mass = kDensity * 4.0 / 3.0 * kPi * r * r * r;
    const double t = kWallThickness;
    SplitMix64 random(seed);

    std::string text;
    append(text,
           "# Wall rain (issue #33): %zu spheres of radius %.1f m into a box %.2f m wide whose floor and walls\n"
           "# are static boxes, seed %llu.\n",
           count, r, side, static_cast<unsigned long long>(seed));
    append(text, "# Written by: stepwise-bench rain-scene --walls boxes --count %zu --seed %llu (bench/wall_rain_scene.cpp).\n",
           count, static_cast<unsigned long long>(seed));
    text += "World, TimeStep=1/60, Duration=10, Sleep=false\n";
    appendStaticContainer(text, side, height, t, kElasticity, kFriction);  // floor top at y = 0, walls around [0, side]²
    appendLattice(count, random, kWallRainPitch, kJitter, [&](std::size_t n, double x, double y, double z, double vx,
                                                              double vz) {
        append(text,
               "DynamicObject, Name=s%zu, Shape=Sphere, Position=(%.4f, %.4f, %.4f), Velocity=(%.3f, 0, %.3f), "
               "Radius=%.1f, Mass=%.2f, Elasticity=%.1f, Friction=%.1f\n",
               n, x, y, z, vx, vz, r, mass, kElasticity, kFriction);
    });
    return text;
}

}  // namespace stepwise::bench
