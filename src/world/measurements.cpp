/// @file measurements.cpp
/// @brief Energy and momenta summed over the dynamic bodies.
#include "world/measurements.hpp"

#include <cmath>

#include "soft/soft_stages.hpp"  // enclosedVolume()

namespace stepwise {

Energy energyOf(const DynamicObject& body, const Vec3& gravity) {
    Energy energy;
    energy.translational = Real(0.5) * body.mass * glm::dot(body.velocity, body.velocity);
    // ½·ω·L = ½·ωᵀ·I_world·ω: ω and L are kept consistent by updateAngularVelocity().
    energy.rotational = Real(0.5) * glm::dot(body.angularVelocity, body.angularMomentum);
    energy.potential = -body.mass * glm::dot(gravity + body.constantAcceleration, body.position);
    energy.kinetic = energy.translational + energy.rotational;
    return energy;
}

Energy energyOf(const World& world) {
    Energy energy;
    for (const DynamicObject& body : world.dynamics()) {
        const Energy own = energyOf(body, world.settings().gravity);
        energy.translational += own.translational;
        energy.rotational += own.rotational;
        energy.potential += own.potential;
        for (const Attractor& attractor : world.attractors()) {
            energy.potential += attractorPotentialEnergy(attractor, body.mass, body.position);
        }
    }
    for (const Spring& spring : world.springs()) energy.potential += springPotentialEnergy(spring, world.dynamics());
    for (const SoftBody& body : world.softBodies()) {
        const Energy own = energyOf(body, world.settings().gravity);
        energy.translational += own.translational;
        energy.potential += own.potential;
    }
    energy.kinetic = energy.translational + energy.rotational;
    return energy;
}

Energy energyOf(const SoftBody& body, const Vec3& gravity) {
    Energy energy;
    for (std::size_t i = 0; i < body.nodeCount(); ++i) {
        const Real m = Real(1) / body.nodeInverseMasses[i];
        energy.translational += Real(0.5) * m * glm::dot(body.nodeVelocities[i], body.nodeVelocities[i]);
        energy.potential -= m * glm::dot(gravity, body.nodePositions[i]);
    }
    for (const SoftSpring& s : body.springs) {
        const Real stretch = glm::length(body.nodePositions[s.b] - body.nodePositions[s.a]) - s.restLength;
        energy.potential += Real(0.5) * s.stiffness * stretch * stretch;
    }
    // The volume where the nodes are now: body.volume is the pressure stage's, from before the last move
    const Real volume = enclosedVolume(body.nodePositions, body.faces);
    if (body.nRT > 0 && volume > 0) energy.potential -= body.nRT * std::log(volume);
    energy.kinetic = energy.translational;
    return energy;
}

Energy energyOfBody(const World& world, std::size_t index) {
    const DynamicObject& body = world.dynamics()[index];
    Energy energy = energyOf(body, world.settings().gravity);
    for (const Attractor& attractor : world.attractors()) {
        energy.potential += attractorPotentialEnergy(attractor, body.mass, body.position);
    }
    for (const Spring& spring : world.springs()) {
        if (spring.bodyA == index && spring.bodyB == kFixedInWorld) {
            energy.potential += springPotentialEnergy(spring, world.dynamics());
        }
    }
    return energy;
}

Vec3 linearMomentumOf(const World& world) {
    Vec3 momentum(0);
    for (const DynamicObject& body : world.dynamics()) momentum += body.mass * body.velocity;
    for (const SoftBody& body : world.softBodies()) {
        for (std::size_t i = 0; i < body.nodeCount(); ++i) momentum += body.nodeVelocities[i] / body.nodeInverseMasses[i];
    }
    return momentum;
}

Vec3 angularMomentumOf(const World& world) {
    Vec3 momentum(0);
    for (const DynamicObject& body : world.dynamics()) {
        momentum += glm::cross(body.position, body.mass * body.velocity) + body.angularMomentum;
    }
    for (const SoftBody& body : world.softBodies()) {
        for (std::size_t i = 0; i < body.nodeCount(); ++i) {
            momentum += glm::cross(body.nodePositions[i], body.nodeVelocities[i] / body.nodeInverseMasses[i]);
        }
    }
    return momentum;
}

}  // namespace stepwise
