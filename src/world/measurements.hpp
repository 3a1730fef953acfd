/// @file measurements.hpp
/// @brief Conserved quantities of a World: what a summary reports and tests check.
#pragma once

#include "world/world.hpp"

namespace stepwise {

/// @brief Energies of the dynamic bodies, J.
struct Energy {
    Real kinetic = 0;    ///< Σ ½·m·|v|².
    Real potential = 0;  ///< Σ −m·(g + a_obj)·x: potential of the uniform fields, zero at the origin.
    /// @brief Kinetic plus potential, J.
    Real total() const { return kinetic + potential; }
};

/// @brief Translational kinetic energy and the potential energy of the uniform fields.
///
/// A uniform acceleration g has potential U = −m·g·x per body (for g = (0,−9.81,0)
/// that is m·9.81·y, the familiar m·g·h). Rotational energy is not yet
/// counted: until inertia tensors arrive, spin is constant and carries no exchange.
Energy energyOf(const World& world);

/// @brief Total linear momentum Σ m·v of the dynamic bodies, kg·m/s.
Vec3 linearMomentumOf(const World& world);

}  // namespace stepwise
