/// @file measurements.cpp
#include "world/measurements.hpp"

namespace stepwise {

Energy energyOf(const World& world) {
    Energy energy;
    const Vec3& gravity = world.settings().gravity;
    for (const DynamicObject& body : world.dynamics()) {
        energy.kinetic += Real(0.5) * body.mass * glm::dot(body.velocity, body.velocity);
        energy.potential -= body.mass * glm::dot(gravity + body.constantAcceleration, body.position);
    }
    return energy;
}

Vec3 linearMomentumOf(const World& world) {
    Vec3 momentum(0);
    for (const DynamicObject& body : world.dynamics()) momentum += body.mass * body.velocity;
    return momentum;
}

}  // namespace stepwise
