/// @file kinematic_motion.hpp
/// @brief Stage 3: kinematic bodies along their prescribed motion.
#pragma once

#include <span>

#include "objects/game_object.hpp"

namespace stepwise {

/// @brief Stage 3: moves kinematic bodies along their prescribed constant velocities.
///
/// A kinematic body's velocity is given, not computed: it is not pushed by
/// anything, so its motion is exact for any step size: x(t+h) = x(t) + h·v,
/// and it turns by the exact rotation of ω·h (rotateByAngularVelocity()).
void moveKinematics(std::span<KinematicsObject> bodies, Real h);

}  // namespace stepwise
