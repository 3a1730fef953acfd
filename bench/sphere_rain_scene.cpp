/// @file sphere_rain_scene.cpp
/// @brief Writes the sphere-rain scene (sphere_rain_scene.hpp).
#include "sphere_rain_scene.hpp"

#include <cmath>
#include <cstdio>

namespace stepwise::bench {

namespace {

constexpr double kLayers = 16;          ///< Lattice layers: the pile is about this deep whatever N.
constexpr double kGap = 0.1;            ///< Free space between neighbouring lattice sites, m.
constexpr double kJitter = 0.05;        ///< Largest random offset of a sphere from its site, m (< kGap/2: no overlap at start).
constexpr double kClearance = 0.5;      ///< Height of the lowest layer's bottom above the floor, m.
constexpr double kDropSpeed = 0.5;      ///< Largest initial horizontal speed, m/s (so the spheres do not stack in columns).
constexpr double kDensity = 1000;       ///< kg/m³ (water): 524 kg per sphere.
constexpr double kElasticity = 0.3;     ///< Some bounce, so the impacts matter; combined with the walls' 1 by product.
constexpr double kFriction = 0.5;       ///< Combined with the walls' 1 by product.
constexpr double kPi = 3.14159265358979323846;

/// SplitMix64 (Steele, Lea and Flood 2014): the same numbers from a seed on
/// every machine, unlike std::uniform_real_distribution.
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    /// Uniform in [lo, hi): the top 53 bits as a fraction of 2⁵³.
    double uniform(double lo, double hi) {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        constexpr double kUnit = 1.0 / 9007199254740992.0;  // 2^-53
        return lo + (hi - lo) * double(z >> 11) * kUnit;
    }

private:
    std::uint64_t state_;
};

void append(std::string& text, const char* format, auto... values) {
    char line[512];
    std::snprintf(line, sizeof line, format, values...);
    text += line;
}

}  // namespace

std::string sphereRainSceneText(std::size_t count, std::uint64_t seed) {
    const double r = double(kRainRadius);
    const double pitch = 2 * r + kGap;
    const auto columns = static_cast<std::size_t>(std::ceil(std::sqrt(double(count) / kLayers)));
    const double side = double(columns) * pitch;
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
    text += "CollisionPlane, Name=floor, Position=(0, 0, 0), Normal=(0, 1, 0), Color=(0.5, 0.5, 0.5)\n";
    text += "CollisionPlane, Name=wall_x0, Position=(0, 0, 0), Normal=(1, 0, 0)\n";
    append(text, "CollisionPlane, Name=wall_x1, Position=(%.4f, 0, 0), Normal=(-1, 0, 0)\n", side);
    text += "CollisionPlane, Name=wall_z0, Position=(0, 0, 0), Normal=(0, 0, 1)\n";
    append(text, "CollisionPlane, Name=wall_z1, Position=(0, 0, %.4f), Normal=(0, 0, -1)\n", side);
    for (std::size_t n = 0; n < count; ++n) {
        const std::size_t layer = n / (columns * columns);
        const std::size_t i = n % columns;
        const std::size_t j = (n / columns) % columns;
        // One draw per statement: argument evaluation order is unspecified in C++.
        const double x = (double(i) + 0.5) * pitch + random.uniform(-kJitter, kJitter);
        const double y = kClearance + (double(layer) + 0.5) * pitch + random.uniform(-kJitter, kJitter);
        const double z = (double(j) + 0.5) * pitch + random.uniform(-kJitter, kJitter);
        const double vx = random.uniform(-kDropSpeed, kDropSpeed);
        const double vz = random.uniform(-kDropSpeed, kDropSpeed);
        append(text,
               "DynamicObject, Name=s%zu, Shape=Sphere, Position=(%.4f, %.4f, %.4f), Velocity=(%.3f, 0, %.3f), "
               "Radius=%.1f, Mass=%.2f, Elasticity=%.1f, Friction=%.1f\n",
               n, x, y, z, vx, vz, r, mass, kElasticity, kFriction);
    }
    return text;
}

}  // namespace stepwise::bench
