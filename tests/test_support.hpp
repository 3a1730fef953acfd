// Helpers shared by the tests: build small scenes in code, run them, watch them.
#pragma once

#include <string>

#include "collision/narrowphase.hpp"
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

/// The geometry of an oriented box, as the pair tests see it (half edge lengths).
inline Geometry boxGeometry(Vec3 centre, Vec3 halfExtents, Quat orientation = Quat(1, 0, 0, 0)) {
    Geometry g;
    g.type = GeometryType::Box;
    g.centre = centre;
    g.halfExtents = halfExtents;
    g.orientation = orientation;
    return g;
}

/// The geometry of a sphere, as the pair tests see it.
inline Geometry sphereGeometry(Vec3 centre, Real radius) {
    Geometry g;
    g.type = GeometryType::Sphere;
    g.centre = centre;
    g.radius = radius;
    return g;
}

/// A kinematic box with full edge lengths @p size moving at @p velocity.
inline KinematicsObject kinematicBox(const std::string& name, Vec3 position, Vec3 size, Vec3 velocity = Vec3(0)) {
    KinematicsObject box;
    box.name = name;
    box.shape = Shape::Box;
    box.position = position;
    box.scale = size;
    box.velocity = velocity;
    return box;
}

/// A dynamic solid box with full edge lengths @p size, no bounce.
inline DynamicObject dynamicBox(const std::string& name, Vec3 position, Vec3 size, Real mass, Real friction) {
    DynamicObject box;
    box.name = name;
    box.shape = Shape::Box;
    box.position = position;
    box.scale = size;
    box.setMass(mass);
    box.elasticity = 0;
    box.friction = friction;
    return box;
}

/// Every integrator, for tests that must hold for all of them.
inline constexpr IntegratorKind kAllIntegrators[] = {IntegratorKind::ExplicitEuler, IntegratorKind::SymplecticEuler,
                                                     IntegratorKind::Verlet};

}  // namespace stepwise::test
