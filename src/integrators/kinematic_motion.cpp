/// @file kinematic_motion.cpp
/// @brief Stage 3: prescribed motion of kinematic bodies, and the shared rotation update.
///
/// A kinematic body's velocity is given, not computed: it is not pushed by
/// anything, so its motion is exact for any step size: x(t+h) = x(t) + h·v.
#include <cmath>

#include "integrators/integrators.hpp"

namespace stepwise {

/// Below this angle (rad) a step's rotation is treated as none: the axis
/// ω/|ω| of a zero angular velocity is undefined.
constexpr Real kNegligibleRotationAngle = Real(1e-15);

Quat rotateByAngularVelocity(const Quat& orientation, const Vec3& omega, Real h) {
    const Real speed = glm::length(omega);  // rad/s
    const Real angle = speed * h;           // rad turned this step
    if (angle < kNegligibleRotationAngle) return orientation;
    // World-frame angular velocity: the step's rotation multiplies on the left.
    const Quat turn = glm::angleAxis(angle, omega / speed);
    return glm::normalize(turn * orientation);
}

void moveKinematics(std::span<KinematicsObject> bodies, Real h) {
    for (KinematicsObject& body : bodies) {
        body.position += h * body.velocity;
        body.orientation = rotateByAngularVelocity(body.orientation, body.angularVelocity, h);
    }
}

}  // namespace stepwise
