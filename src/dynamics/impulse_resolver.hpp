/// @file impulse_resolver.hpp
/// @brief Stage 6 of the step: collision response by impulses.
#pragma once

#include <span>

#include "collision/contact.hpp"
#include "world/body_set.hpp"

namespace stepwise {

/// @brief Restitution of a pair of materials: the product e = e_A · e_B.
///
/// With the product, an object of elasticity 1 (the default for planes and
/// kinematic objects) lets the other object's value decide, which is how
/// the classic assignment format (elasticity on dynamic objects only) reads.
/// Bullet combines restitution the same way.
inline Real combineElasticity(Real a, Real b) { return a * b; }

/// @brief Friction of a pair of materials: the product μ = μ_A · μ_B (same reasoning).
inline Real combineFriction(Real a, Real b) { return a * b; }

/// Contacts approaching slower than the speed their own relative
/// acceleration builds in this many steps do not bounce: that speed is
/// gravity pulling a resting body into its support during one step, not an
/// impact. Without it a resting ball with e > 0 hops forever.
inline constexpr Real kRestingContactSteps = Real(2);

/// @brief What happened at one contact, for tests, traces and debuggers.
struct ImpulseReport {
    Real approachSpeed = 0;       ///< −v_n before the impulse, m/s (> 0 when approaching).
    Real approachAtTouch = 0;     ///< Approach speed reconstructed at the moment of touching, m/s.
    Real restitution = 0;         ///< e used (0 for a resting contact).
    Real normalImpulse = 0;       ///< j, N·s (≥ 0).
    Real frictionImpulse = 0;     ///< |j_t|, N·s (≤ μ·j).
};

/// @brief Applies a normal impulse with restitution, then a Coulomb friction impulse, at each contact in turn.
///
/// For contact normal n (from A to B) and relative velocity
/// v_rel = v_B − v_A, the normal velocity is v_n = v_rel·n (< 0: approaching).
/// The impulse j along n that makes the bodies separate at speed e·v_c is
/// \f[ j = \frac{e\,v_c - v_n}{m_A^{-1} + m_B^{-1}}, \qquad
///     v_A \mathrel{-}= j\,n\,m_A^{-1}, \quad v_B \mathrel{+}= j\,n\,m_B^{-1}, \f]
/// (momentum m_A v_A + m_B v_B is unchanged). With v_c = −v_n this is the
/// textbook j = −(1+e)·v_n / (m_A⁻¹ + m_B⁻¹).
///
/// **Why v_c and not −v_n.** The contact is found only after the step has
/// carried the bodies a depth d into each other. Under their relative normal
/// acceleration a_n = (a_B − a_A)·n the approach speed grew over that
/// distance, v_n² = v_c² − 2·a_n·d, so the speed at the moment of touching is
/// \f[ v_c = \sqrt{\max(0,\; v_n^2 + 2\,a_n\,d)}. \f]
/// Bouncing with the end-of-step speed instead, and then pushing the body
/// back to the surface, adds m·g·d of energy per bounce: the well-known
/// "ball that bounces higher than it fell". With v_c, a ball of
/// restitution e dropped from height h peaks at e²ⁿ·h after n bounces at any
/// time step. (A v_c of zero means the bodies were resting, not colliding.)
///
/// Friction then acts on the tangential part of the relative velocity
/// *after* the normal impulse (the normal impulse sets the friction bound),
/// and is clamped to Coulomb's cone |j_t| ≤ μ·j. Bodies are treated as
/// particles in this stage: impulses change linear velocity only (angular
/// response arrives with inertia tensors).
///
/// References: Millington, *Game Physics Engine Development*, ch. 7;
/// Catto, "Fast and Simple Physics using Sequential Impulses", GDC 2006.
/// @param bodies   the world's objects (dynamic velocities change)
/// @param contacts this step's contacts
/// @param h        time step, s (sets the resting-contact speed)
/// @param reports  optional, one report per contact (size must match), may be empty
void resolveImpulses(const BodySet& bodies, std::span<const Contact> contacts, Real h,
                     std::span<ImpulseReport> reports = {});

/// @brief Stage 7: moves overlapping bodies apart along the contact normal, in proportion to their inverse masses.
///
/// Each contact's depth d is removed in full: A moves by −n·d·m_A⁻¹/(m_A⁻¹+m_B⁻¹)
/// and B by +n·d·m_B⁻¹/(m_A⁻¹+m_B⁻¹), which leaves the centre of mass where it
/// was. Only positions change: no velocity is added, so the correction puts
/// no energy into the system beyond undoing the overlap. Removing all of d
/// (not a fraction, as Baumgarte stabilisation does) is what lets a sphere
/// rest on a plane without sinking: each step's gravity sag of about g·h² is
/// taken back in the same step.
/// @param bodies   the world's objects (dynamic positions change)
/// @param contacts this step's contacts
void correctPositions(const BodySet& bodies, std::span<const Contact> contacts);

}  // namespace stepwise
