/// @file integrators.hpp
/// @brief Stage 2 of the step: the time integrators, one file each.
///
/// Each integrator advances every dynamic body from time t to t + h, given
/// the accelerations a(t) that the apply-forces stage wrote into
/// DynamicObject::acceleration. They differ in *which* velocity moves the
/// position:
///
/// | integrator        | position update                 | velocity update            | global error | energy on an oscillator |
/// |-------------------|---------------------------------|----------------------------|--------------|-------------------------|
/// | explicit Euler    | x + h·v(t)                      | v + h·a(t)                 | O(h)         | grows every step        |
/// | symplectic Euler  | x + h·v(t+h)                    | v + h·a(t)                 | O(h)         | bounded (oscillates)    |
/// | velocity Verlet   | x + h·v(t) + ½h²·a(t)           | v + ½h·(a(t) + a(t+h))     | O(h²)        | bounded (oscillates)    |
///
/// Rotation is integrated alongside, from the torque τ the apply-forces stage
/// wrote into DynamicObject::torque. The rotational state is the world-frame
/// angular momentum L (τ = dL/dt, the rotational twin of m·v), not ω: the
/// orientation turns, and ω = I_world⁻¹·L follows (src/objects/inertia.hpp):
///
/// | integrator        | angular momentum                   | orientation                               | ‖L‖ (τ = 0) | rotational energy (τ = 0) |
/// |-------------------|------------------------------------|-------------------------------------------|-------------|---------------------------|
/// | explicit Euler    | L + h·τ(t)                         | turn by ω(t)·h, ω from the old q and L    | exact       | drifts, error O(h)        |
/// | symplectic Euler  | L + h·τ(t), first                  | free-body splitting for h, with the new L | exact       | bounded, O(h²)            |
/// | velocity Verlet   | + ½h·τ(t) before, + ½h·τ(t+h) after | free-body splitting for h                 | exact       | bounded, O(h²)            |
///
/// The free-body splitting (rotateTorqueFree(), free_rotation.cpp) is shared
/// by the last two. Why L and not ω is the state: differentiate
/// L = R·I_body·Rᵀ·ω and you get Euler's equations, I·ω̇ + ω×(I·ω) = τ in the
/// body frame; the gyroscopic term ω×(I·ω) that makes a tumbling box wobble
/// and flip is carried by R turning inside I_world. With L stored, a
/// torque-free body keeps L to the last bit, and only the orientation needs
/// an integrator. See lectures/04-inertia-and-rotation.md.
///
/// Every update ends with the quaternion normalised: rounding in each
/// product moves it off the unit sphere, and |q| ≠ 1 would scale the body.
///
/// **How each integrator meets collision impulses.** Collisions act *after*
/// integration: the narrowphase finds the overlaps the step produced and the
/// impulse stage changes velocities directly. An *impact* (a ball hitting
/// the floor) is instantaneous, so its impulse bypasses the integrator. A
/// *resting* contact (a box on a slope) is really a continuous support force,
/// and each integrator would have moved the body by its own share of the
/// velocity change Δv that force causes over the step:
///
/// | integrator        | x_{n+1} − x_n − h·v_n | share of h·Δv (positionShareOfVelocityChange) |
/// |-------------------|-----------------------|-----------------------------------------------|
/// | explicit Euler    | 0                     | 0: the position never sees this step's Δv      |
/// | symplectic Euler  | h·Δv                  | 1: the position moves with the new velocity    |
/// | velocity Verlet   | ½h²·a = ½h·Δv         | ½: the position moves with the mean velocity   |
///
/// The position-correction stage moves supported bodies by that share of
/// their support impulses' Δv (src/dynamics/impulse_resolver.hpp), so a body
/// at rest on a slope neither sinks nor creeps, with every integrator.
/// See lectures/01–03.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "forces/apply_forces.hpp"
#include "objects/game_object.hpp"
#include "core/world_settings.hpp"

namespace stepwise {

/// @brief Does @p body skip its angular update this step? Only when the step
/// plan says nothing can turn it (DynamicObject::canTurn is false, src/world/step_plan.hpp),
/// and it is a sphere whose L, ω and τ are exactly zero.
///
/// For a sphere the three moments are equal, so the full update with L = 0
/// and τ = 0 turns the orientation by a zero angle (rotateByAngularVelocity()
/// returns it unchanged), keeps L + h·0 = L and sets ω = I_world⁻¹·0 = 0:
/// skipping it leaves the same state, without turning the inertia tensor
/// into the world frame (a 3×3 rotation and two products) or the free-body
/// rotation. The test is exact and made per body, so a body that something
/// did push off its centre (the viewer's mouse, the rounding of a lever arm)
/// still gets the full update.
inline bool skipsRotation(const DynamicObject& body) {
    return !body.canTurn && body.shape == Shape::Sphere && body.angularMomentum == Vec3(0) &&
           body.angularVelocity == Vec3(0) && body.torque == Vec3(0);
}

/// @brief Explicit (forward) Euler: x ← x + h·v, v ← v + h·a, q ← turn(ω·h), L ← L + h·τ, all from the old state.
void integrateExplicitEuler(std::span<DynamicObject> bodies, Real h);

/// @brief Symplectic (semi-implicit) Euler: v ← v + h·a, then x ← x + h·v with the new v;
/// L ← L + h·τ, then the orientation by rotateTorqueFree() with the new L.
void integrateSymplecticEuler(std::span<DynamicObject> bodies, Real h);

/// @brief Velocity Verlet: x ← x + h·v + ½h²·a, a_new = a(x_new), v ← v + ½h·(a + a_new);
/// for rotation L ← L + ½h·τ, rotateTorqueFree() for h, τ_new = τ(q_new), L ← L + ½h·τ_new.
/// @param accelerations recomputes DynamicObject::acceleration and DynamicObject::torque
///        at the new positions and orientations.
void integrateVerlet(std::span<DynamicObject> bodies, Real h, const AccelerationFunction& accelerations);

/// @brief Advances @p bodies by @p h with @p integrator, the scene's `Integrator`: one of the three above.
/// @param forces recomputes the accelerations at new positions (used by Verlet only).
void integrateBodies(IntegratorKind integrator, std::span<DynamicObject> bodies, Real h,
                     const AccelerationFunction& forces);

/// @brief Rotates @p orientation by a constant angular velocity @p omega (world frame, rad/s) for @p h seconds.
///
/// Exact for constant ω: q ← exp(½·h·ω̂)·q, i.e. a rotation by angle |ω|·h
/// about ω/|ω|, applied in the world frame (multiplied on the left). That is
/// the motion of a kinematic body, and of a torque-free body whose three
/// moments of inertia are equal; explicit Euler also uses it for one step of
/// any body, with the ω of the step's start.
Quat rotateByAngularVelocity(const Quat& orientation, const Vec3& omega, Real h);

/// @brief Turns @p orientation by the small angle |@p omega|·@p h about @p omega (world frame):
/// q ← normalise(q + ½·h·(0, ω)⊗q), Catto's rotation update in Box2D (b2IntegrateRotation).
///
/// A turn by 2·atan(|ω|·h/2) instead of |ω|·h: short of the exact
/// rotateByAngularVelocity() by (|ω|·h)³/12 rad, 10⁻¹⁰ rad for a turn of
/// 10⁻³ rad. Cheaper (a quaternion product, no series), so used where the
/// angle is a correction of that size: the drift of a box by the solver's Δω
/// (dynamics/velocity_change_drift.hpp). Not for free flight, whose whole rotation it
/// would make slightly slow, step after step.
Quat turnBySmallAngle(const Quat& orientation, const Vec3& omega, Real h);

/// @brief The torque-free motion of a rigid body for @p h seconds: the orientation
/// after the symmetric splitting 1(h/2) 2(h/2) 3(h) 2(h/2) 1(h/2) of the free-body energy.
///
/// Each sub-flow spins the body about its principal body axis e_i by the angle
/// (Π_i/I_i)·Δt, with Π = Rᵀ·L recomputed before each one; L in the world is
/// fixed throughout. Second order, keeps |L| exactly and the energy within a
/// bounded O(h²). A body with three equal moments is turned exactly, by |ω|·h
/// about ω = L/I. The derivation is in free_rotation.cpp.
/// @param orientation        body-to-world rotation at the start of the step
/// @param angularMomentum    L, world frame, kg·m²/s (constant over the step)
/// @param inverseInertiaBody 1/I₁, 1/I₂, 1/I₃ about the principal body axes, 1/(kg·m²)
/// @param h                  step, s
/// @return the orientation at the end of the step, normalised
Quat rotateTorqueFree(const Quat& orientation, const Vec3& angularMomentum, const Vec3& inverseInertiaBody, Real h);

/// @brief The fraction of a step's velocity change Δv that @p integrator lets
/// move the position within the same step: x_{n+1} = x_n + h·v_n + share·h·Δv.
/// (0 for explicit Euler, 1 for symplectic Euler, ½ for velocity Verlet.)
Real positionShareOfVelocityChange(IntegratorKind integrator);

}  // namespace stepwise
