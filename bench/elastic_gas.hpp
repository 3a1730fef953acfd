/// @file elastic_gas.hpp
/// @brief The elastic gas: spheres with e = 1 and no friction in a closed box without gravity,
/// and the measure of how near its speeds are to Maxwell–Boltzmann's.
///
/// Used by the stress case `elastic-gas` (stress.cpp) and by the tests that hold the gas to
/// physics (tests/test_elastic_gas.cpp): its kinetic energy stays what it was, and collisions
/// spread the start's uniform velocities into Maxwell–Boltzmann's distribution.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>

#include "world/scene.hpp"
#include "world/world.hpp"

namespace stepwise::bench {

/// @brief Largest velocity component at the start, m/s: each component is uniform in [−2, 2).
inline constexpr double kGasSpeed = 2;

/// @brief Closes a generated box (floor and four walls) with a ceiling 1 m above its highest body's centre.
void addCeiling(Scene& scene);

/// @brief A velocity with each component uniform in [−speed, speed), m/s: drawn from the raw 64-bit
/// output of mt19937_64, whose sequence the C++ standard fixes (its distributions it does not), so a
/// seed gives the same scene everywhere.
Vec3 randomVelocity(std::mt19937_64& random, double speed);

/// @brief @p count spheres of the generated sphere rain (seed @p seed), every one with e = 1,
/// μ = 0 and a velocity drawn uniformly from the cube [−kGasSpeed, kGasSpeed)³, in the rain's
/// box closed by a ceiling; no gravity, no sleep. The planes have e = μ = 1, so each pair's
/// product is the sphere's: e = 1, μ = 0.
Scene elasticGasScene(std::size_t count, std::uint64_t seed);

/// @brief The Kolmogorov–Smirnov distance between the bodies' kinetic energies and the
/// Maxwell–Boltzmann distribution of the same mean.
///
/// In equilibrium at temperature T each body's kinetic energy ε = ½mv² follows the gamma
/// distribution of shape 3/2 and scale kT, whatever its mass (three squared Gaussian velocity
/// components of variance kT/m): F(ε) = P(3/2, ε/kT) = erf(√x) − 2√(x/π)·e^(−x), x = ε/kT.
/// kT is fixed by the total: E = (3/2)·N·kT. Returns D = sup |F_N(ε) − F(ε)| over the sample.
double maxwellBoltzmannDistance(const World& world);

/// @brief The Kolmogorov–Smirnov critical distance for @p n samples at the 1 % level:
/// 1.628/√n (the asymptotic value; a sample of Maxwell–Boltzmann's own exceeds it 1 time in 100).
double kolmogorovSmirnovCritical1Percent(std::size_t n);

}  // namespace stepwise::bench
