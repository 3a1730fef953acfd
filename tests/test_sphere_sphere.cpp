// Sphere against sphere: detection, and impulses that conserve momentum.
// Tags: [sphere-sphere].
#include <catch2/catch.hpp>

#include <cmath>

#include "collision/narrowphase.hpp"
#include "test_support.hpp"
#include "world/measurements.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;

namespace {

/// Runs @p world until its first contact has been resolved; returns the contact normal.
Vec3 stepThroughFirstContact(World& world) {
    // Without gravity the velocities change only in the step of the impact.
    // (Not the first step with a contact: the sequential-impulse solver also
    // finds contacts a few millimetres before touching, speculative ones.)
    while (world.time() < 10) {
        const Vec3 before = world.dynamics()[0].velocity;
        world.step();
        if (world.dynamics()[0].velocity != before && !world.contacts().empty()) return world.contacts()[0].normal;
    }
    FAIL("no contact within 10 s");
    return Vec3(0);
}

Scene weightless() { return test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 120, Vec3(0)); }

Real kineticEnergy(const World& world) { return energyOf(world).kinetic; }

}  // namespace

TEST_CASE("Sphere-sphere test finds overlap, normal and contact point", "[sphere-sphere]") {
    Geometry a, b;
    a.radius = 1;
    b.radius = 0.5;
    a.centre = Vec3(0, 0, 0);
    b.centre = Vec3(0, 1.2, 0);
    ContactManifold c;
    REQUIRE(collideSphereSphere(a, b, c));
    CHECK_THAT(c.points[0].depth, WithinAbs(0.3, 1e-12));
    CHECK(glm::length(c.normal - Vec3(0, 1, 0)) < 1e-12);
    CHECK(glm::length(c.points[0].position - Vec3(0, 0.85, 0)) < 1e-12);  // middle of the overlap [0.7, 1.0]

    b.centre = Vec3(1.6, 0, 0);  // 0.1 m apart
    CHECK_FALSE(collideSphereSphere(a, b, c));
}

TEST_CASE("Equal elastic spheres exchange velocities head on", "[sphere-sphere]") {
    // m v_A + m v_B conserved and kinetic energy conserved (e = 1) ⇒ the
    // velocities swap: the moving ball stops, the resting one leaves at 2 m/s.
    Scene scene = weightless();
    scene.dynamics.push_back(test::sphere("a", Vec3(-1, 0, 0), Vec3(2, 0, 0), 0.5, 1, 1));
    scene.dynamics.push_back(test::sphere("b", Vec3(1, 0, 0), Vec3(0), 0.5, 1, 1));
    World world(scene);
    stepThroughFirstContact(world);
    CHECK(glm::length(world.dynamics()[0].velocity - Vec3(0)) < 1e-12);
    CHECK(glm::length(world.dynamics()[1].velocity - Vec3(2, 0, 0)) < 1e-12);
}

TEST_CASE("Oblique impacts conserve momentum and scale the normal approach speed by e", "[sphere-sphere]") {
    // Newton's law of restitution: (v_B − v_A)·n after = −e·(v_B − v_A)·n before;
    // the impulses are equal and opposite, so Σ m v is unchanged.
    for (Real e : {Real(0), Real(0.36), Real(1)}) {
        Scene scene = weightless();
        // Elasticities combine by product: each ball gets sqrt(e).
        scene.dynamics.push_back(test::sphere("light", Vec3(-2, 0.3, 0), Vec3(3, 0, 0.5), 0.5, 1, std::sqrt(e)));
        scene.dynamics.push_back(test::sphere("heavy", Vec3(0, 0, 0), Vec3(-0.5, 0, 0), 0.5, 3, std::sqrt(e)));
        World world(scene);
        const Vec3 p0 = linearMomentumOf(world);
        const Real k0 = kineticEnergy(world);
        const Vec3 relativeBefore = world.dynamics()[1].velocity - world.dynamics()[0].velocity;
        const Vec3 n = stepThroughFirstContact(world);
        const Vec3 relativeAfter = world.dynamics()[1].velocity - world.dynamics()[0].velocity;

        INFO("e = " << e);
        CHECK(glm::length(linearMomentumOf(world) - p0) < 1e-12 * glm::length(p0));
        CHECK_THAT(glm::dot(relativeAfter, n), WithinAbs(-e * glm::dot(relativeBefore, n), 1e-12));
        // Friction (μ = 0.25) only acts on the tangential part; no gravity, so nothing else changed.
        if (e == 1) CHECK(kineticEnergy(world) <= k0 * (1 + 1e-12));
    }
}

TEST_CASE("Frictionless elastic impacts conserve kinetic energy", "[sphere-sphere]") {
    Scene scene = weightless();
    scene.dynamics.push_back(test::sphere("a", Vec3(-2, 0.4, 0.1), Vec3(3, 0, 0), 0.5, 2, 1, 0));
    scene.dynamics.push_back(test::sphere("b", Vec3(0, 0, 0), Vec3(-1, 0.2, 0), 0.7, 5, 1, 0));
    World world(scene);
    const Real k0 = kineticEnergy(world);
    stepThroughFirstContact(world);
    CHECK_THAT(kineticEnergy(world), WithinAbs(k0, 1e-12 * k0));
}

TEST_CASE("A box of bouncing spheres keeps its momentum through many collisions", "[sphere-sphere]") {
    // No gravity, no walls: only sphere-sphere impulses act, and each one
    // conserves momentum, so the total must hold to round-off after hundreds.
    Scene scene = weightless();
    int index = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const Vec3 position(i * 1.2, j * 1.2, 0);
            const Vec3 velocity(std::sin(index * 1.7), std::cos(index * 2.3), 0);
            scene.dynamics.push_back(test::sphere("s" + std::to_string(index), position, velocity, 0.5,
                                                  1 + index % 3, 0.9));
            ++index;
        }
    // Converge them on the centre so they collide many times.
    for (DynamicObject& b : scene.dynamics) b.velocity += (Vec3(1.8, 1.8, 0) - b.position) * Real(0.8);
    World world(scene);
    const Vec3 p0 = linearMomentumOf(world);
    std::size_t contacts = 0;
    while (world.time() < 5) {
        world.step();
        contacts += world.contacts().size();
    }
    CHECK(contacts > 20);
    CHECK(glm::length(linearMomentumOf(world) - p0) < 1e-10);
}

TEST_CASE("Spheres that touch exactly at the end of a step collide in that step", "[sphere-sphere]") {
    // Gap 1 m closed at 2 m/s: they touch at t = 0.5 s, a step boundary at
    // h = 1/120 (step 60). Round-off leaves the gap at ±1e-15 m; it must count
    // as touching, so the swap happens there, with no overlap: the left ball
    // stops at x = −1 and the right one reaches 0 + 2·(3 − 0.5) = 5 m at t = 3 s.
    Scene scene = weightless();
    scene.dynamics.push_back(test::sphere("left", Vec3(-2, 0, 0), Vec3(2, 0, 0), 0.5, 1, 1, 0));
    scene.dynamics.push_back(test::sphere("right", Vec3(0, 0, 0), Vec3(0), 0.5, 1, 1, 0));
    World world(scene);
    while (world.time() < 3 - 1e-9) world.step();
    CHECK_THAT(world.dynamics()[0].position.x, WithinAbs(-1.0, 1e-9));
    CHECK_THAT(world.dynamics()[1].position.x, WithinAbs(5.0, 1e-9));
}
