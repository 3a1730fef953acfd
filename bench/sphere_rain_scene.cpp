/// @file sphere_rain_scene.cpp
/// @brief Writes the sphere-rain scene (sphere_rain_scene.hpp).
#include "sphere_rain_scene.hpp"

#include <cmath>
#include <cstdio>

#include "config/scene_writing.hpp"

namespace stepwise::bench {

namespace {

using namespace scene_writing;

constexpr double kGap = 0.1;            ///< Free space between neighbouring lattice sites, m.
constexpr double kJitter = 0.05;        ///< Largest random offset of a sphere from its site, m (< kGap/2: no overlap at start).
constexpr double kDensity = 1000;       ///< kg/m³ (water): 524 kg per sphere.
constexpr double kElasticity = 0.3;     ///< Some bounce, so the impacts matter; combined with the walls' 1 by product.
constexpr double kFriction = 0.5;       ///< Combined with the walls' 1 by product.
constexpr double kPi = 3.14159265358979323846;

}  // namespace

std::string sphereRainSceneText(std::size_t count, std::uint64_t seed) {
    const double r = double(kRainRadius);
    const double pitch = 2 * r + kGap;
    const double side = double(latticeColumns(count)) * pitch;
    const double mass = kDensity * 4.0 / 3.0 * kPi * r * r * r;
    SplitMix64 random(seed);

    std::string text;
    append(text, "# Sphere rain (issue #7): %zu spheres of radius %.1f m into an open box %.1f m wide, seed %llu.\n",
           count, r, side, static_cast<unsigned long long>(seed));
    append(text, "# Written by: stepwise-bench rain-scene --count %zu --seed %llu (bench/sphere_rain_scene.cpp).\n",
           count, static_cast<unsigned long long>(seed));
    text += "# stepwise-bench scaling and stepwise-bench bullet run it for 600 steps (10 s) and report the\n"
            "# time per step, the deepest overlap and how many spheres left the box (docs/benchmarks.md).\n";
    text += "World, TimeStep=1/60, Duration=10\n";
    appendContainer(text, side);
    appendLattice(count, random, pitch, kJitter, [&](std::size_t n, double x, double y, double z, double vx, double vz) {
        append(text,
               "DynamicObject, Name=s%zu, Shape=Sphere, Position=(%.4f, %.4f, %.4f), Velocity=(%.3f, 0, %.3f), "
               "Radius=%.1f, Mass=%.2f, Elasticity=%.1f, Friction=%.1f\n",
               n, x, y, z, vx, vz, r, mass, kElasticity, kFriction);
    });
    return text;
}

}  // namespace stepwise::bench
