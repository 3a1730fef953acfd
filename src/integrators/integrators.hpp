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
/// Collisions act *after* integration: the narrowphase finds the overlaps
/// the step produced and the impulse stage changes velocities directly
/// (an impulse is an instantaneous change of momentum, not a force), so all
/// three integrators meet contacts the same way. See lectures/01 and 02.
#pragma once

#include <span>

#include "forces/apply_forces.hpp"
#include "objects/game_object.hpp"

namespace stepwise {

/// @brief Explicit (forward) Euler: x ← x + h·v, v ← v + h·a, both from the old state.
void integrateExplicitEuler(std::span<DynamicObject> bodies, Real h);

/// @brief Symplectic (semi-implicit) Euler: v ← v + h·a, then x ← x + h·v with the new v.
void integrateSymplecticEuler(std::span<DynamicObject> bodies, Real h);

/// @brief Velocity Verlet: x ← x + h·v + ½h²·a, a_new = a(x_new), v ← v + ½h·(a + a_new).
/// @param accelerations recomputes DynamicObject::acceleration at the new positions.
void integrateVerlet(std::span<DynamicObject> bodies, Real h, const AccelerationFunction& accelerations);

/// @brief Rotates @p orientation by a constant angular velocity @p omega (world frame, rad/s) for @p h seconds.
///
/// Exact for constant ω: q ← exp(½·h·ω̂)·q, i.e. a rotation by angle |ω|·h
/// about ω/|ω|, applied in the world frame. Until rigid-body rotation
/// arrives (inertia tensors and torques), angular velocity is constant,
/// which is the exact torque-free motion of a sphere.
Quat rotateByAngularVelocity(const Quat& orientation, const Vec3& omega, Real h);

/// @brief Stage 3: moves kinematic bodies along their prescribed constant velocities.
void moveKinematics(std::span<KinematicsObject> bodies, Real h);

}  // namespace stepwise
