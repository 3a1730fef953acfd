/// @file measurements.hpp
/// @brief Conserved quantities of a World: what a summary reports and tests check.
#pragma once

#include "world/world.hpp"

namespace stepwise {

/// @brief Energies of the dynamic bodies, J.
struct Energy {
    Real translational = 0;  ///< Σ ½·m·|v|²: motion of the centres of mass.
    Real rotational = 0;     ///< Σ ½·ω·L: spin about the centres of mass.
    Real kinetic = 0;        ///< translational + rotational (energyOf() fills all three).
    /// Potential energy: Σ −m·(g + a_obj)·x of the uniform fields (zero at the origin),
    /// plus ½·k·(l − L₀)² per spring and −μ·m/r per body and attractor (zero far away).
    Real potential = 0;
    /// @brief Kinetic plus potential, J.
    Real total() const { return kinetic + potential; }
};

/// @brief Kinetic energy, split into translational and rotational, and the potential energy of every force.
///
/// By König's theorem the kinetic energy of a rigid body is that of its
/// centre of mass plus that of its spin about it:
/// \f[ T = \tfrac12 m\,|v|^2 + \tfrac12\,\omega\cdot L, \qquad L = I_\text{world}\,\omega . \f]
/// A uniform acceleration g has potential U = −m·g·x per body (for g = (0,−9.81,0)
/// that is m·9.81·y, the familiar m·g·h); a spring stores ½·k·(l − L₀)²
/// (springPotentialEnergy()), an attractor gives −μ·m/r (attractorPotentialEnergy()).
/// A soft body adds its nodes' ½·m·|v|² (translational), their −m·g·x, its springs' ½·k·(l − L₀)²
/// and its gas's −nRT·ln(V / 1 m³) (potential: the gas's force is −∂/∂x of it, pressure_forces.cpp;
/// only its changes mean anything).
Energy energyOf(const World& world);

/// @brief The same energies for one body in a uniform field @p gravity (energyOf(world) sums these).
Energy energyOf(const DynamicObject& body, const Vec3& gravity);

/// @brief A soft body's energies in a uniform field @p gravity, J (energyOf(world) adds these).
///
/// The nodes' Σ ½·m·|v|² (translational: a node has no spin), and as potential their
/// Σ −m·g·x, the springs' Σ ½·k·(l − L₀)², and the gas's −nRT·ln(V / 1 m³). The gas's force on
/// the nodes is −∂/∂x of that (pressure_forces.cpp), so springs, gas and gravity together
/// conserve the total in free flight, up to the integrator's error; only its changes mean anything.
Energy energyOf(const SoftBody& body, const Vec3& gravity);

/// @brief The energy that belongs to the dynamic body number @p index alone, J.
///
/// Its kinetic energy and its potential energy in the uniform fields (energyOf(body, gravity)),
/// plus −μ·m/r for each attractor and ½·k·(l − L₀)² for each spring whose other end is fixed in
/// the world: those springs and attractors act on this body only. A spring between two bodies
/// belongs to the pair, not to either body: energyOf(world) counts it, this does not. So the
/// sum of energyOfBody() over the bodies is energyOf(world) less the springs between bodies.
/// `stepwise plot FILE --quantity energy` draws it per body.
Energy energyOfBody(const World& world, std::size_t index);

/// @brief Total linear momentum Σ m·v of the dynamic bodies and the soft bodies' nodes, kg·m/s.
Vec3 linearMomentumOf(const World& world);

/// @brief Total angular momentum of the dynamic bodies and the soft bodies' nodes about the world origin, kg·m²/s.
///
/// Each body contributes the moment of its centre's momentum plus its own
/// spin: \f[ L_O = \sum_k \left( x_k \times m_k v_k + L_k \right). \f]
/// With no external torque it is conserved; gravity (a torque x × m·g about
/// the origin) and contacts with planes and kinematic bodies change it.
Vec3 angularMomentumOf(const World& world);

}  // namespace stepwise
