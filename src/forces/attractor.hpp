/// @file attractor.hpp
/// @brief A fixed point that pulls every dynamic body by Newton's inverse-square law.
///
/// An Attractor is a planet or a sun that does not move: the central force
/// behind the Kepler orbits of the reference problems (bench/, config/
/// reference_kepler_*.scene). Its strength is the gravitational parameter
/// μ = G·M (m³/s²) rather than a mass, because μ is what orbits measure
/// (Kepler's third law, T² = 4π²·a³/μ) and is known far more precisely than
/// G or M alone: μ_Earth = 3.986004418·10¹⁴ m³/s².
///
/// References: Goldstein, Poole & Safko, *Classical Mechanics*, ch. 3 (the
/// central-force problem); Murray & Dermott, *Solar System Dynamics*, ch. 2.
#pragma once

#include <span>
#include <string>

#include "objects/game_object.hpp"

namespace stepwise {

/// @brief Below this distance from an Attractor, m, it pulls like a uniform ball of this radius.
///
/// Outside, a = −μ·r̂/r², the field of a point mass (or of any spherical
/// body: Newton's shell theorem). At r = 0 that is infinite and r̂ has no
/// direction, so a body passing through the centre would be flung out with
/// NaN or huge speed. Inside kAttractorCoreRadius the mass is taken as spread
/// uniformly through a ball of that radius: by the shell theorem only the
/// mass inside r pulls, a = −μ·r/r_c³, linear in r, zero at the centre and
/// equal to the point-mass value at r = r_c (so the field is continuous).
/// 1 mm is far inside any orbit a scene would set up, so orbits see the exact
/// inverse-square law.
inline constexpr Real kAttractorCoreRadius = Real(1e-3);

/// @brief A fixed point mass: a = −μ·(x − p)/|x − p|³ on every dynamic body.
struct Attractor {
    std::string name;          ///< Unique within a scene.
    Vec3 position{0, 0, 0};    ///< Where it is, world space, m; it never moves.
    Real mu = 0;               ///< Gravitational parameter μ = G·M, m³/s²; > 0.
};

/// @brief Acceleration the attractor gives a body at @p point, m/s² (independent of the body's mass).
Vec3 attractorAcceleration(const Attractor& attractor, const Vec3& point);

/// @brief Adds every attractor's pull to every body's acceleration.
///
/// The pull acts at the centre of mass and adds no torque: the tidal torque
/// of a non-uniform field on an extended body, of order μ·I/r³, is left out.
/// Run after applyUniformForces(), which starts the step's accelerations.
void applyAttractors(std::span<DynamicObject> bodies, std::span<const Attractor> attractors);

/// @brief Potential energy of a body of mass @p mass at @p point in the attractor's field, J.
///
/// U = −μ·m/r outside the core (zero far away), and the uniform ball's
/// U = −μ·m·(3r_c² − r²)/(2r_c³) inside it, so U is continuous and its
/// gradient is the force of attractorAcceleration().
Real attractorPotentialEnergy(const Attractor& attractor, Real mass, const Vec3& point);

}  // namespace stepwise
