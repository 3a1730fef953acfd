/// @file apply_forces.cpp
/// @brief Stage 1: forces → accelerations.
#include "forces/apply_forces.hpp"

namespace stepwise {

void applyUniformForces(std::span<DynamicObject> bodies, const Vec3& gravity) {
    for (DynamicObject& body : bodies) {
        body.acceleration = gravity + body.constantAcceleration;
    }
}

AccelerationFunction uniformForces(const Vec3& gravity) {
    return [gravity](std::span<DynamicObject> bodies) { applyUniformForces(bodies, gravity); };
}

}  // namespace stepwise
