// Helpers shared by the tests: build small scenes in code, run them, watch them.
#pragma once

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "collision/broadphase.hpp"
#include "collision/narrowphase.hpp"
#include "config/scene_loader.hpp"
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

/// Every contact among @p bodies, as the World's collision stages find them (all pairs tested, one thread).
inline std::vector<Contact> contactsOf(const BodySet& bodies) {
    std::vector<CandidatePair> pairs;
    Broadphase().findPairs(BroadphaseKind::BruteForce, bodies, pairs);
    ThreadPool pool(1);
    NarrowphaseWorkspace workspace;
    std::vector<Contact> contacts;
    findContacts(bodies, pairs, contacts, false, kSpeculativeDistance, pool, workspace);
    return contacts;
}

/// Checks that the scene @p text is refused, with a diagnostic that contains @p words.
inline void checkRefused(const char* text, const char* words) {
    try {
        (void)parseScene(text, "bad.scene");
        FAIL_CHECK("loaded: " << text);
    } catch (const ConfigError& error) {
        CHECK_THAT(error.what(), Catch::Contains(words));
    }
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

/// Every quantity of two Worlds' states, compared with ==: two roads through the same step (the
/// plan on and off, the fast path and the plain one) must not differ by one bit (== also lets +0
/// equal −0, the one difference a skipped I⁻¹·0 could make). Contacts' impulses too.
inline void requireSameState(const World& planned, const World& unplanned) {
    REQUIRE(planned.time() == unplanned.time());
    REQUIRE(planned.candidatePairs().size() == unplanned.candidatePairs().size());
    REQUIRE(planned.contacts().size() == unplanned.contacts().size());
    REQUIRE(planned.dynamics().size() == unplanned.dynamics().size());
    for (std::size_t i = 0; i < planned.dynamics().size(); ++i) {
        const DynamicObject& a = planned.dynamics()[i];
        const DynamicObject& b = unplanned.dynamics()[i];
        INFO(a.name << " at step " << planned.stepCount());
        REQUIRE(a.position == b.position);
        REQUIRE(a.velocity == b.velocity);
        REQUIRE(a.orientation == b.orientation);
        REQUIRE(a.angularVelocity == b.angularVelocity);
        REQUIRE(a.angularMomentum == b.angularMomentum);
        REQUIRE(a.asleep == b.asleep);
    }
    for (std::size_t i = 0; i < planned.kinematics().size(); ++i) {
        REQUIRE(planned.kinematics()[i].position == unplanned.kinematics()[i].position);
        REQUIRE(planned.kinematics()[i].orientation == unplanned.kinematics()[i].orientation);
    }
    for (std::size_t i = 0; i < planned.joints().size(); ++i) {
        REQUIRE(planned.joints()[i].broken == unplanned.joints()[i].broken);
    }
    REQUIRE(planned.impulses().size() == unplanned.impulses().size());
    for (std::size_t c = 0; c < planned.impulses().size(); ++c) {
        INFO("contact " << c << " at step " << planned.stepCount());
        REQUIRE(planned.impulses()[c].normalImpulse == unplanned.impulses()[c].normalImpulse);
        REQUIRE(planned.impulses()[c].frictionImpulse == unplanned.impulses()[c].frictionImpulse);
    }
}

}  // namespace stepwise::test
