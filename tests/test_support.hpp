// Helpers shared by the tests: build small scenes in code, run them, watch them.
#pragma once

#include <string>

#include "world/scene.hpp"
#include "world/world.hpp"

namespace stepwise::test {

/// A dynamic sphere with the given state and material.
inline DynamicObject sphere(const std::string& name, Vec3 position, Vec3 velocity = Vec3(0), Real radius = 0.5,
                            Real mass = 1, Real elasticity = 0.5, Real friction = 0.5) {
    DynamicObject body;
    body.name = name;
    body.shape = Shape::Sphere;
    body.position = position;
    body.velocity = velocity;
    body.radius = radius;
    body.scale = Vec3(2 * radius);
    body.setMass(mass);
    body.elasticity = elasticity;
    body.friction = friction;
    return body;
}

/// The plane y = 0 facing up.
inline CollisionPlane ground(const std::string& name = "ground") {
    CollisionPlane plane;
    plane.name = name;
    return plane;
}

/// A scene with the given integrator and time step, standard gravity, no objects.
inline Scene emptyScene(IntegratorKind integrator = IntegratorKind::SymplecticEuler, Real h = Real(1) / 60,
                        Vec3 gravity = Vec3(0, -kStandardGravity, 0)) {
    Scene scene;
    scene.settings.integrator = integrator;
    scene.settings.timeStep = h;
    scene.settings.gravity = gravity;
    return scene;
}

/// Every integrator, for tests that must hold for all of them.
inline constexpr IntegratorKind kAllIntegrators[] = {IntegratorKind::ExplicitEuler, IntegratorKind::SymplecticEuler,
                                                     IntegratorKind::Verlet};

}  // namespace stepwise::test
