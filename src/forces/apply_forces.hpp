/// @file apply_forces.hpp
/// @brief Stage 1 of the step: what accelerates and what turns each body.
#pragma once

#include <functional>
#include <span>

#include "objects/game_object.hpp"

namespace stepwise {

/// @brief Computes every body's acceleration and torque from the bodies' current state.
///
/// It writes DynamicObject::acceleration (m/s²) and DynamicObject::torque
/// (N·m, world frame, about the centre of mass) of every body, from nothing:
/// nothing carries over from the previous step. An integrator that needs
/// them at a new position and orientation (velocity Verlet) calls it again
/// after moving the bodies. Tests pass their own
/// function (a spring, an orbit) to check an integrator against a known
/// solution.
using AccelerationFunction = std::function<void(std::span<DynamicObject>)>;

/// @brief Sets each body's `acceleration` to gravity plus its own constant acceleration,
/// and its `torque` to zero.
///
/// Newton's second law with F = m·g + m·a_obj gives a = F/m = g + a_obj:
/// in a uniform field the mass cancels, which is why a feather and a hammer
/// fall together on the Moon. A uniform field acts at the centre of mass, so
/// its torque about the centre is zero: τ = Σ rᵢ × mᵢ·g = (Σ mᵢ·rᵢ) × g = 0,
/// because Σ mᵢ·rᵢ = 0 about the centre of mass. No other torque source
/// exists yet (mouse picking and motors will add them here), but the torque
/// is still reset every step: it is a real output of this stage.
/// @param bodies  the dynamic bodies (acceleration is written)
/// @param gravity the World's gravitational acceleration, m/s²
void applyUniformForces(std::span<DynamicObject> bodies, const Vec3& gravity);

/// @brief The AccelerationFunction of a World whose only forces are uniform fields.
AccelerationFunction uniformForces(const Vec3& gravity);

}  // namespace stepwise
