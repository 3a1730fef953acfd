/// @file apply_forces.hpp
/// @brief Stage 1 of the step: what accelerates each body.
#pragma once

#include <functional>
#include <span>

#include "objects/game_object.hpp"

namespace stepwise {

/// @brief Computes every body's acceleration from the bodies' current state.
///
/// An integrator that needs the acceleration at a new position (velocity
/// Verlet) calls it again after moving the bodies. Tests pass their own
/// function (a spring, an orbit) to check an integrator against a known
/// solution.
using AccelerationFunction = std::function<void(std::span<DynamicObject>)>;

/// @brief Sets each body's `acceleration` to gravity plus its own constant acceleration.
///
/// Newton's second law with F = m·g + m·a_obj gives a = F/m = g + a_obj:
/// in a uniform field the mass cancels, which is why a feather and a hammer
/// fall together on the Moon.
/// @param bodies  the dynamic bodies (acceleration is written)
/// @param gravity the World's gravitational acceleration, m/s²
void applyUniformForces(std::span<DynamicObject> bodies, const Vec3& gravity);

/// @brief The AccelerationFunction of a World whose only forces are uniform fields.
AccelerationFunction uniformForces(const Vec3& gravity);

}  // namespace stepwise
