// Kinematic objects: prescribed motion, pushing, never pushed; sphere-box detection.
// Tags: [kinematic], [sphere-box].
#include <catch2/catch.hpp>

#include <cmath>

#include "collision/narrowphase.hpp"
#include "test_support.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;

namespace {

using test::boxGeometry;
using test::kinematicBox;
using test::sphereGeometry;

}  // namespace

TEST_CASE("Sphere-box finds the closest point on a face, an edge and a corner", "[sphere-box]") {
    const Geometry box = boxGeometry(Vec3(0), Vec3(1, 1, 1));
    ContactManifold c;
    SECTION("face") {
        REQUIRE(collideSphereBox(sphereGeometry(Vec3(0, 1.4, 0), 0.5), box, c));
        CHECK_THAT(c.points[0].depth, WithinAbs(0.1, 1e-12));
        CHECK(glm::length(c.normal - Vec3(0, -1, 0)) < 1e-12);
        // The sphere's own deepest point, y = 1.4 − 0.5: friction's lever arm is exactly r.
        CHECK(glm::length(c.points[0].position - Vec3(0, 0.9, 0)) < 1e-12);
    }
    SECTION("edge") {
        const Real d = 0.45;  // distance from the edge (1, 1, z) along the diagonal
        const Vec3 centre = Vec3(1, 1, 0.3) + d * glm::normalize(Vec3(1, 1, 0));
        REQUIRE(collideSphereBox(sphereGeometry(centre, 0.5), box, c));
        CHECK_THAT(c.points[0].depth, WithinAbs(0.05, 1e-12));
        CHECK(glm::length(c.normal + glm::normalize(Vec3(1, 1, 0))) < 1e-12);
    }
    SECTION("corner, just out of reach") {
        const Vec3 centre = Vec3(1, 1, 1) + Real(0.51) * glm::normalize(Vec3(1, 1, 1));
        CHECK_FALSE(collideSphereBox(sphereGeometry(centre, 0.5), box, c));
    }
    SECTION("centre inside: leave through the nearest face") {
        REQUIRE(collideSphereBox(sphereGeometry(Vec3(0.2, 0.1, -0.9), 0.5), box, c));
        CHECK(glm::length(c.normal - Vec3(0, 0, 1)) < 1e-12);  // nearest face is z = −1
        CHECK_THAT(c.points[0].depth, WithinAbs(0.5 + 0.1, 1e-12));
    }
    SECTION("rotated box") {
        // Box turned 45° about z: its corner (√2, 0) now points along +x.
        const Geometry turned = boxGeometry(Vec3(0), Vec3(1, 1, 1), glm::angleAxis(kPi / 4, Vec3(0, 0, 1)));
        REQUIRE(collideSphereBox(sphereGeometry(Vec3(std::sqrt(2.0) + 0.4, 0, 0), 0.5), turned, c));
        CHECK_THAT(c.points[0].depth, WithinAbs(0.1, 1e-12));
        CHECK(glm::length(c.normal - Vec3(-1, 0, 0)) < 1e-12);
    }
}

TEST_CASE("A kinematic body follows its prescribed velocity and is never pushed", "[kinematic]") {
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60, Vec3(0));
    scene.kinematics.push_back(kinematicBox("paddle", Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(1, 0, 0)));
    scene.dynamics.push_back(test::sphere("ball", Vec3(3, 0, 0), Vec3(-4, 0, 0), 0.5, 100, 1));  // heavy, fast
    World world(scene);
    bool hit = false;
    while (world.time() < 2 - 1e-9) {
        world.step();
        hit = hit || !world.contacts().empty();
        const KinematicsObject& paddle = world.kinematics()[0];
        CHECK(glm::length(paddle.position - Vec3(world.time(), 0, 0)) < 1e-12);
        CHECK(glm::length(paddle.velocity - Vec3(1, 0, 0)) == 0);
    }
    CHECK(hit);
}

TEST_CASE("A moving kinematic wall returns an elastic ball at 2u - v", "[kinematic]") {
    // In the wall's frame the ball arrives at v − u and leaves at −(v − u);
    // back in the ground frame that is 2u − v. Here u = +2, v = −1: 5 m/s.
    Scene scene = test::emptyScene(IntegratorKind::Verlet, Real(1) / 120, Vec3(0));
    scene.kinematics.push_back(kinematicBox("wall", Vec3(0, 0, 0), Vec3(1, 4, 4), Vec3(2, 0, 0)));
    scene.dynamics.push_back(test::sphere("ball", Vec3(3, 0, 0), Vec3(-1, 0, 0), 0.5, 1, 1, 0));
    World world(scene);
    while (world.time() < 2) world.step();
    CHECK_THAT(world.dynamics()[0].velocity.x, WithinAbs(5.0, 1e-12));
}

TEST_CASE("A sphere rests on a kinematic table within 1 mm", "[kinematic]") {
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.kinematics.push_back(kinematicBox("table", Vec3(0, 0.5, 0), Vec3(2, 1, 2)));
    scene.dynamics.push_back(test::sphere("ball", Vec3(0.3, 1.25, 0), Vec3(0), 0.25, 1, 0.5));
    World world(scene);
    Real worst = 0;
    while (world.time() < 10) {
        world.step();
        worst = std::max(worst, std::abs(world.dynamics()[0].position.y - Real(1.25)));
    }
    CHECK(worst < 1e-3);
}

TEST_CASE("A platform pulled from under a ball leaves it rolling at 2/7 of the platform's speed", "[kinematic][friction]") {
    // Friction J at the contact (a lever arm R below the centre) gives the ball
    // v = J/m and ω = J·R/I. It stops slipping when its contact point moves with
    // the platform, v + ω·R = u, so J·(1/m + R²/I) = u and, with I = ⅖·m·R²,
    // v = u / (1 + 5/2) = 2u/7: the ball rolls backwards relative to the platform.
    // Tolerance 1e-6: once rolling nothing changes; the transient is a few kinetic-friction steps.
    const Real u = 0.5;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 120);
    scene.kinematics.push_back(kinematicBox("platform", Vec3(0, -0.5, 0), Vec3(40, 1, 4), Vec3(u, 0, 0)));
    scene.dynamics.push_back(test::sphere("ball", Vec3(0, 0.5, 0), Vec3(0), 0.5, 1, 0, 0.5));
    World world(scene);
    while (world.time() < 2) world.step();
    const DynamicObject& ball = world.dynamics()[0];
    CHECK_THAT(ball.velocity.x, Catch::Matchers::WithinRel(double(2 * u / 7), 1e-6));
    // Rolling without slipping on the platform: v + ω × r at the contact equals u.
    const Vec3 contactVelocity = ball.velocity + glm::cross(ball.angularVelocity, Vec3(0, -0.5, 0));
    CHECK_THAT(contactVelocity.x, WithinAbs(u, 1e-6 * u));
}

TEST_CASE("An elastic ball glances off a fixed kinematic sphere with its speed kept", "[kinematic][sphere-sphere]") {
    // A fixed obstacle has infinite mass: with e = 1 and no friction the ball's
    // velocity is reflected about the contact normal, v' = v − 2(v·n)n, so
    // its speed is unchanged and the angle of incidence equals the angle of reflection.
    Scene scene = test::emptyScene(IntegratorKind::Verlet, Real(1) / 240, Vec3(0));
    KinematicsObject post;
    post.name = "post";
    post.shape = Shape::Sphere;
    post.radius = 0.5;
    scene.kinematics.push_back(post);
    scene.dynamics.push_back(test::sphere("ball", Vec3(-3, 0.5, 0), Vec3(2, 0, 0), 0.5, 1, 1, 0));
    World world(scene);
    Vec3 normal(0);
    while (world.time() < 3) {
        world.step();
        // The normal of the contact that pushed (a contact may be found a
        // step early, still a gap apart, and push nothing in that step).
        if (!world.contacts().empty() && world.impulses()[0].normalImpulse > 0 && normal == Vec3(0)) {
            normal = world.contacts()[0].normal;
        }
    }
    REQUIRE(normal != Vec3(0));
    const Vec3 expected = Vec3(2, 0, 0) - 2 * glm::dot(Vec3(2, 0, 0), normal) * normal;
    CHECK(glm::length(world.dynamics()[0].velocity - expected) < 1e-12);
    CHECK_THAT(glm::length(world.dynamics()[0].velocity), WithinAbs(2.0, 1e-12));
    CHECK(world.kinematics()[0].position == Vec3(0));
}
