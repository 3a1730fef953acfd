/// @file random_force.cpp
/// @brief Effect=RandomForce: a hash of (seed, step, body) → a direction on the sphere and a size.
#include "forces/random_force.hpp"

#include <cmath>
#include <numbers>

namespace stepwise {

namespace {

/// SplitMix64's output function: a bijection of 64-bit words that mixes every input bit into every output bit.
std::uint64_t mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/// The top 53 bits of a word as a number in [0, 1): every double of that form is equally likely.
Real unit(std::uint64_t bits) { return Real(bits >> 11) * Real(0x1.0p-53); }

}  // namespace

Vec3 randomForce(std::uint64_t seed, std::uint64_t step, std::uint32_t bodyIndex, Real strength) {
    const std::uint64_t key = mix(mix(seed) ^ step) ^ bodyIndex;
    const Real u = unit(mix(key));
    const Real v = unit(mix(key + 1));
    const Real w = unit(mix(key + 2));
    // Archimedes' hat-box theorem: z uniform in [−1, 1] and an angle uniform in [0, 2π) give a
    // direction uniform over the sphere (the band between z and z + dz has area 2π·dz).
    const Real z = 2 * u - 1;
    const Real angle = 2 * std::numbers::pi_v<Real> * v;
    const Real across = std::sqrt(std::max(Real(0), 1 - z * z));
    return strength * w * Vec3(across * std::cos(angle), across * std::sin(angle), z);
}

void addRandomForce(DynamicObject& body, std::uint32_t bodyIndex, const Region& region, std::uint64_t step) {
    body.acceleration += randomForce(region.seed, step, bodyIndex, region.strength) * body.inverseMass;
}

}  // namespace stepwise
