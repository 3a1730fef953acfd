/// @file spring.hpp
/// @brief A Hooke spring with a damper between two anchor points: the record and its force law.
///
/// A spring joins a point of dynamic body A to a point of dynamic body B, or
/// to a fixed point of the world. Its anchors are given where a student can
/// measure them: on a body, in that body's own frame (metres from its centre,
/// before its rotation), so the anchor turns with the body; a world end is a
/// world point. The force acts *at the anchors*, so a spring hooked off the
/// centre both pulls a body and turns it.
///
/// References: Millington, *Game Physics Engine Development*, §6.1 (Hooke's
/// law, springs as force generators) and §10.3 (forces at a point give
/// torque); Baraff & Witkin, *Physically Based Modeling* (SIGGRAPH 2001),
/// "Particle System Dynamics", §4 (damped springs).
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string>

#include "objects/game_object.hpp"

namespace stepwise {

/// @brief Spring::bodyB of a spring whose second end is fixed in the world at Spring::anchorB.
inline constexpr std::size_t kFixedInWorld = std::numeric_limits<std::size_t>::max();

/// @brief A linear spring and a linear damper, side by side, between two anchor points.
///
/// With d = p_B − p_A from anchor A to anchor B, l = |d| and n = d/l,
/// \f[ F_A = \big(k\,(l - L_0) + c\,(v_B - v_A)\cdot n\big)\,n, \qquad F_B = -F_A , \f]
/// where v_A, v_B are the velocities of the anchor points (v + ω × r). A
/// stretched spring (l > L₀) pulls A towards B; the damper resists the rate
/// at which the anchors separate, never their sideways motion.
struct Spring {
    std::string name;                 ///< Unique within a scene; used in warnings and output.
    std::size_t bodyA = 0;            ///< Index of body A among the World's dynamic bodies.
    std::size_t bodyB = kFixedInWorld;///< Index of body B, or kFixedInWorld: then anchorB is a world point.
    Vec3 anchorA{0, 0, 0};            ///< Where the spring holds A: in A's body frame, m from A's centre.
    Vec3 anchorB{0, 0, 0};            ///< In B's body frame, m; a world point, m, when bodyB is kFixedInWorld.
    Real stiffness = 0;               ///< Hooke constant k, N/m; ≥ 0.
    Real damping = 0;                 ///< Damper constant c, N·s/m; ≥ 0.
    Real restLength = 0;              ///< Length L₀ at which the spring pulls on nothing, m; ≥ 0.
};

/// @brief Where a body-frame point of @p body is in the world: x + R·r, m.
inline Vec3 anchorInWorld(const DynamicObject& body, const Vec3& localAnchor) {
    return body.position + body.orientation * localAnchor;
}

/// @brief The two anchor points of a spring, in world space.
struct SpringEnds {
    Vec3 a{0, 0, 0};  ///< Anchor on body A, m.
    Vec3 b{0, 0, 0};  ///< Anchor on body B, or the fixed world point, m.
};

/// @brief World positions of @p spring's anchors for the bodies' current poses.
SpringEnds springEnds(const Spring& spring, std::span<const DynamicObject> bodies);

/// @brief Adds every spring's force to the accelerations (F/m) and torques (r × F) of its bodies.
///
/// Run after applyUniformForces(), which starts each step's accelerations and
/// torques from gravity and zero: springs *add* to them. Anchors closer than
/// kMinSpringLength have no direction to pull along, and give no force.
/// @param bodies  the World's dynamic bodies (acceleration and torque are added to)
/// @param springs indices in them must be valid (World checks them once)
void applySprings(std::span<DynamicObject> bodies, std::span<const Spring> springs);

/// @brief Elastic energy ½·k·(l − L₀)² stored in @p spring, J.
Real springPotentialEnergy(const Spring& spring, std::span<const DynamicObject> bodies);

/// @brief The mass the spring feels along its own line, kg.
///
/// The same effective mass as a contact's (src/dynamics/impulse_resolver.hpp):
/// \f[ \frac{1}{m_\text{eff}} = \sum_{\text{ends on bodies}}
///     \left(\frac{1}{m} + (r\times n)\cdot I_\text{world}^{-1}\,(r\times n)\right), \f]
/// with r from a body's centre to its anchor. A fixed end adds nothing; an
/// off-centre anchor makes the body lighter along n (it can also turn), so
/// the spring oscillates faster. With ω = √(k/m_eff) the spring's angular
/// frequency, it decides the stable time step (spring_stability.hpp).
/// The bodies' inverse inertia (DynamicObject::inverseInertiaBody) must be set
/// (initialiseMassProperties()). When the anchors coincide, n is taken along x.
Real springEffectiveMass(const Spring& spring, std::span<const DynamicObject> bodies);

/// @brief Anchors closer than this, m, have no direction to pull along: the spring gives no force.
inline constexpr Real kMinSpringLength = Real(1e-9);

}  // namespace stepwise
