/// @file drag.hpp
/// @brief Drag: the resistance of a fluid to a body moving through it (Effect=Drag).
///
/// Two laws cover the range of a physics course (Taylor, *Classical
/// Mechanics*, §2.1–2.4):
/// - **linear**, F = −c·v: the viscous drag of slow, small bodies (Stokes:
///   c = 6π·η·r for a ball in a fluid of viscosity η);
/// - **quadratic**, F = −c·|v|·v: the pressure drag of fast or large ones,
///   c = ½·ρ·C_d·A (fluid density, drag coefficient, frontal area).
///
/// A body falling from rest under gravity reaches the speed where drag and
/// weight balance, the terminal speed: v_t = m·g/c (linear) and
/// v_t = √(m·g/c) (quadratic). Under the linear law the approach is
/// exponential, v(t) = v_t·(1 − e^(−c·t/m)); the tests check both.
///
/// Turning is resisted the same way, τ = −c_ω·ω or −c_ω·|ω|·ω.
#pragma once

#include "forces/region.hpp"

namespace stepwise {

/// @brief The drag force on a body moving at @p relativeVelocity through the fluid, N.
/// @param law         linear or quadratic
/// @param coefficient c: N·s/m (linear) or kg/m (quadratic); ≥ 0
/// @param relativeVelocity the body's velocity minus the fluid's, m/s
Vec3 dragForce(DragLaw law, Real coefficient, const Vec3& relativeVelocity);

/// @brief The drag torque on a body turning at @p angularVelocity, N·m (same laws, c_ω in N·m·s).
Vec3 dragTorque(DragLaw law, Real angularCoefficient, const Vec3& angularVelocity);

/// @brief Adds drag in a fluid moving at @p fluidVelocity to @p body's acceleration and torque.
///
/// @p share scales both (buoyancy passes the submerged fraction of the body).
/// The force is explicit: it is worked out from the velocity at the start of
/// the substep and held through it. Once c·h/m > 2 an explicit drag would
/// overshoot, reverse the velocity and grow (the instability of explicit
/// Euler on v' = −(c/m)·v), so the force is capped at what stops the body,
/// relative to the fluid, within one substep of @p substepTime: m·|v_rel|/h.
/// The cap only bites when a substep is longer than m/c.
void addDrag(DynamicObject& body, const Region& region, const Vec3& fluidVelocity, Real share, Real substepTime);

}  // namespace stepwise
