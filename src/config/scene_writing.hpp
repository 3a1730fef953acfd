/// @file scene_writing.hpp
/// @brief What the programs that write scene files share: a seeded random
/// source, formatted lines, an open box and a jittered lattice of bodies.
///
/// `stepwise generate` (scene_generator.cpp) and `stepwise-bench rain-scene`
/// (bench/sphere_rain_scene.cpp) both write their scenes with these, so the
/// same seed gives the same file on every machine.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace stepwise::scene_writing {

/// @brief SplitMix64 (Steele, Lea and Flood 2014): a tiny generator whose output is
/// fixed by the algorithm, so a seed gives the same scene everywhere
/// (std::uniform_real_distribution may differ between standard libraries).
class SplitMix64 {
public:
    /// @brief Starts the sequence at @p seed: the same seed, the same numbers.
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    /// @brief The next 64 random bits.
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// @brief Uniform in [lo, hi): the top 53 bits as a fraction of 2⁵³.
    double uniform(double lo, double hi) {
        constexpr double kUnit = 1.0 / 9007199254740992.0;  // 2^-53
        return lo + (hi - lo) * double(next() >> 11) * kUnit;
    }

private:
    std::uint64_t state_;
};

/// @brief Appends printf-style @p format with @p values to @p text (one line is under 512 characters).
///
/// Every caller passes a string literal as @p format; clang cannot see that through the
/// template, and would warn that a format that is not a literal might be unsafe.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-security"
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
void append(std::string& text, const char* format, auto... values) {
    char line[512];
    std::snprintf(line, sizeof line, format, values...);
    text += line;
}
#pragma GCC diagnostic pop

/// @brief Lattice layers (bodies per column): the box's floor grows with the
/// count, so the pile is about as deep at 1k bodies as at 64k.
inline constexpr double kLatticeLayers = 16;
/// @brief Height of the lowest lattice layer's bottom above the floor, m.
inline constexpr double kLatticeClearance = 0.5;
/// @brief Largest initial horizontal speed of a lattice body, m/s (so the pile is not a lattice).
inline constexpr double kLatticeDropSpeed = 0.5;

/// @brief Columns per side of the lattice for @p count bodies: ⌈√(count / kLatticeLayers)⌉.
inline std::size_t latticeColumns(std::size_t count) {
    return static_cast<std::size_t>(std::ceil(std::sqrt(double(count) / kLatticeLayers)));
}

/// @brief A box of side @p side, m, open at the top: a floor and four walls facing in.
inline void appendContainer(std::string& text, double side) {
    append(text, "CollisionPlane, Name=floor, Position=(0, 0, 0), Normal=(0, 1, 0), Color=(0.5, 0.5, 0.5)\n");
    append(text, "CollisionPlane, Name=wall_x0, Position=(0, 0, 0), Normal=(1, 0, 0)\n");
    append(text, "CollisionPlane, Name=wall_x1, Position=(%.4f, 0, 0), Normal=(-1, 0, 0)\n", side);
    append(text, "CollisionPlane, Name=wall_z0, Position=(0, 0, 0), Normal=(0, 0, 1)\n");
    append(text, "CollisionPlane, Name=wall_z1, Position=(0, 0, %.4f), Normal=(0, 0, -1)\n", side);
}

/// @brief A floor and four walls of static boxes (KinematicsObject at rest), as a level is built: the
/// floor's top face at y = 0 and the walls standing on it around the square [0, @p side]², each
/// @p thickness thick and the walls @p height tall (m), all of elasticity @p elasticity and friction @p friction.
inline void appendStaticContainer(std::string& text, double side, double height, double thickness, double elasticity,
                                  double friction) {
    const double t = thickness;
    const auto box = [&](const char* name, double x, double y, double z, double sx, double sy, double sz) {
        append(text,
               "KinematicsObject, Name=%s, Shape=Box, Position=(%.4f, %.4f, %.4f), Scale=(%.4f, %.4f, %.4f), "
               "Color=(0.5, 0.5, 0.5), Elasticity=%.1f, Friction=%.1f\n",
               name, x, y, z, sx, sy, sz, elasticity, friction);
    };
    box("floor", side / 2, -t / 2, side / 2, side + 2 * t, t, side + 2 * t);
    box("wall_x0", -t / 2, height / 2, side / 2, t, height, side + 2 * t);
    box("wall_x1", side + t / 2, height / 2, side / 2, t, height, side + 2 * t);
    box("wall_z0", side / 2, height / 2, -t / 2, side, height, t);
    box("wall_z1", side / 2, height / 2, side + t / 2, side, height, t);
}

/// @brief @p count bodies on a lattice of columns × columns × kLatticeLayers sites of
/// pitch @p pitch (m), each jittered by up to @p jitter (m) and given a random horizontal
/// velocity; `body(n, x, y, z, vx, vz)` writes body n.
///
/// One random draw per statement, in the order x, y, z, vx, vz: the order in
/// which a call's arguments are evaluated is unspecified in C++.
void appendLattice(std::size_t count, SplitMix64& random, double pitch, double jitter, auto&& body) {
    const std::size_t columns = latticeColumns(count);
    for (std::size_t n = 0; n < count; ++n) {
        const std::size_t layer = n / (columns * columns);
        const std::size_t i = n % columns;
        const std::size_t j = (n / columns) % columns;
        const double x = (double(i) + 0.5) * pitch + random.uniform(-jitter, jitter);
        const double y = kLatticeClearance + (double(layer) + 0.5) * pitch + random.uniform(-jitter, jitter);
        const double z = (double(j) + 0.5) * pitch + random.uniform(-jitter, jitter);
        const double vx = random.uniform(-kLatticeDropSpeed, kLatticeDropSpeed);
        const double vz = random.uniform(-kLatticeDropSpeed, kLatticeDropSpeed);
        body(n, x, y, z, vx, vz);
    }
}

}  // namespace stepwise::scene_writing
