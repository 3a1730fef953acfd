/// @file random_force.hpp
/// @brief Random pushes that repeat bit for bit (Effect=RandomForce): jitter, turbulence, a shaken tray.
///
/// Each step, each body inside gets a force of a random direction, uniform
/// over the sphere of directions, and a random size, uniform between 0 and
/// Strength; it holds through the step's substeps and acts at the centre.
///
/// The numbers come from a counter-based generator: the force is a hash of
/// (seed, step number, body index), SplitMix64 (Steele, Lea & Flood, "Fast
/// splittable pseudorandom number generators", OOPSLA 2014), not the next
/// draw of a generator that is carried along. So the force a body feels does
/// not depend on which other bodies were inside, nor on the order they are
/// visited or on how many threads run: the same seed gives the same run, bit
/// for bit, and a different seed a different one.
#pragma once

#include <cstdint>

#include "forces/region.hpp"

namespace stepwise {

/// @brief The random force on body @p bodyIndex at step @p step, N: |F| ≤ strength.
Vec3 randomForce(std::uint64_t seed, std::uint64_t step, std::uint32_t bodyIndex, Real strength);

/// @brief Adds the region's random force for this step to @p body's acceleration.
void addRandomForce(DynamicObject& body, std::uint32_t bodyIndex, const Region& region, std::uint64_t step);

}  // namespace stepwise
