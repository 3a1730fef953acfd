/// @file apply_forces.cpp
/// @brief Stage 1: forces → accelerations and torques.
#include "forces/apply_forces.hpp"

namespace stepwise {

void applyUniformForces(std::span<DynamicObject> bodies, const Vec3& gravity) {
    for (DynamicObject& body : bodies) {
        body.acceleration = gravity + body.constantAcceleration;
        // A uniform field pulls every mass element alike, so it acts at the
        // centre of mass and has no torque about it. Torques are recomputed
        // from nothing every step, like accelerations: mouse picking and
        // motors will add theirs here.
        body.torque = Vec3(0);
    }
}

AccelerationFunction uniformForces(const Vec3& gravity) {
    return [gravity](std::span<DynamicObject> bodies) { applyUniformForces(bodies, gravity); };
}

}  // namespace stepwise
