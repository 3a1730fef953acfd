/// @file apply_forces.cpp
/// @brief Stage 1: forces → accelerations and torques.
#include "forces/apply_forces.hpp"

namespace stepwise {

void applyUniformForces(std::span<DynamicObject> bodies, const Vec3& gravity) {
    for (DynamicObject& body : bodies) {
        body.acceleration = gravity + body.constantAcceleration;
        // A uniform field pulls every mass element alike, so it acts at the
        // centre of mass and has no torque about it. Torques are recomputed
        // from nothing every step, like accelerations: springs (spring.cpp)
        // add theirs after this.
        body.torque = Vec3(0);
    }
}

AccelerationFunction uniformForces(const Vec3& gravity) {
    return [gravity](std::span<DynamicObject> bodies) { applyUniformForces(bodies, gravity); };
}

void SceneForces::operator()(std::span<DynamicObject> bodies) const {
    applyUniformForces(bodies, gravity);  // sets a = g + a_obj and τ = 0
    applySprings(bodies, springs);        // adds F/m and r × F at each anchor (spring.cpp)
    applyAttractors(bodies, attractors);  // adds −μ·r̂/r² (attractor.cpp)
    applyRegions(bodies, regions);        // adds drag, wind, buoyancy, ... on the bodies inside (region.cpp)
}

}  // namespace stepwise
