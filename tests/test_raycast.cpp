// Ray casts against spheres, boxes and planes, and World::raycast: every
// expected hit is worked out by hand from the geometry. Tag: [raycast].
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "collision/raycast.hpp"
#include "test_support.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;

namespace {

constexpr Real kTolerance = Real(1e-12);  // m: the formulas are exact up to round-off
constexpr Real kFar = std::numeric_limits<Real>::infinity();

void checkVec(const Vec3& actual, const Vec3& expected) {
    for (int i = 0; i < 3; ++i) CHECK_THAT(actual[i], WithinAbs(expected[i], kTolerance));
}

}  // namespace

TEST_CASE("A ray meets a sphere where |o + t d - c| = r", "[raycast]") {
    const Vec3 centre(1, 2, 3);
    SECTION("head on: t = distance to the centre - r, normal against the ray") {
        const auto hit = intersectRaySphere(Vec3(-4, 2, 3), Vec3(1, 0, 0), kFar, centre, 1);
        REQUIRE(hit);
        CHECK_THAT(hit->distance, WithinAbs(4, kTolerance));
        checkVec(hit->normal, Vec3(-1, 0, 0));
    }
    SECTION("off centre by b = 0.5: enters at x = -sqrt(r^2 - b^2)") {
        const auto hit = intersectRaySphere(Vec3(-4, 2.5, 3), Vec3(1, 0, 0), kFar, centre, 1);
        REQUIRE(hit);
        const Real x = std::sqrt(Real(0.75));
        CHECK_THAT(hit->distance, WithinAbs(5 - x, kTolerance));
        checkVec(hit->normal, Vec3(-x, 0.5, 0));
    }
    SECTION("passing by, pointing away, or beyond the reach: no hit") {
        CHECK_FALSE(intersectRaySphere(Vec3(-4, 3.01, 3), Vec3(1, 0, 0), kFar, centre, 1));
        CHECK_FALSE(intersectRaySphere(Vec3(-4, 2, 3), Vec3(-1, 0, 0), kFar, centre, 1));
        CHECK_FALSE(intersectRaySphere(Vec3(-4, 2, 3), Vec3(1, 0, 0), Real(3.99), centre, 1));
        CHECK(intersectRaySphere(Vec3(-4, 2, 3), Vec3(1, 0, 0), Real(4), centre, 1));
    }
    SECTION("from inside: distance 0, normal back along the ray") {
        const auto hit = intersectRaySphere(Vec3(1.2, 2, 3), Vec3(0, 0, 1), kFar, centre, 1);
        REQUIRE(hit);
        CHECK(hit->distance == 0);
        checkVec(hit->normal, Vec3(0, 0, -1));
    }
}

TEST_CASE("A ray meets an oriented box on the face it crosses first", "[raycast]") {
    SECTION("axis-aligned box, straight down onto the top face") {
        const auto hit = intersectRayBox(Vec3(0.3, 5, -0.2), Vec3(0, -1, 0), kFar, Vec3(0), Quat(1, 0, 0, 0),
                                         Vec3(1, 0.5, 1));
        REQUIRE(hit);
        CHECK_THAT(hit->distance, WithinAbs(4.5, kTolerance));
        checkVec(hit->normal, Vec3(0, 1, 0));
    }
    SECTION("a box turned 30 degrees about z, hit from above: its top face n = (-sin 30, cos 30, 0)") {
        // The top face is the plane n.x = 1 (half height 1); the ray x = (0, 5 - t, 0)
        // meets it at cos30 (5 - t) = 1, so t = 5 - 1/cos30.
        const Real angle = kPi / 6;
        const Quat turn = glm::angleAxis(angle, Vec3(0, 0, 1));
        const auto hit = intersectRayBox(Vec3(0, 5, 0), Vec3(0, -1, 0), kFar, Vec3(0), turn, Vec3(2, 1, 1));
        REQUIRE(hit);
        CHECK_THAT(hit->distance, WithinAbs(5 - 1 / std::cos(angle), kTolerance));
        checkVec(hit->normal, Vec3(-std::sin(angle), std::cos(angle), 0));
    }
    SECTION("a diagonal ray enters through the face whose slab it enters last") {
        // Unit cube at the origin, ray from (-3, -2, 0.25) along (1, 1, 0)/sqrt2:
        // it enters the x slab at t = 2 sqrt2, the y slab at t = sqrt2, so the x face.
        const Vec3 d = glm::normalize(Vec3(1, 1, 0));
        const auto hit = intersectRayBox(Vec3(-3, -2, 0.25), d, kFar, Vec3(0), Quat(1, 0, 0, 0), Vec3(1));
        REQUIRE(hit);
        CHECK_THAT(hit->distance, WithinAbs(2 * std::sqrt(Real(2)), kTolerance));
        checkVec(hit->normal, Vec3(-1, 0, 0));
    }
    SECTION("parallel to a face: outside the slab misses, inside it hits") {
        CHECK_FALSE(intersectRayBox(Vec3(-5, 1.5, 0), Vec3(1, 0, 0), kFar, Vec3(0), Quat(1, 0, 0, 0), Vec3(1)));
        const auto hit = intersectRayBox(Vec3(-5, 0.5, 0), Vec3(1, 0, 0), kFar, Vec3(0), Quat(1, 0, 0, 0), Vec3(1));
        REQUIRE(hit);
        CHECK_THAT(hit->distance, WithinAbs(4, kTolerance));
    }
    SECTION("behind the ray, or beyond its reach: no hit; from inside: distance 0") {
        CHECK_FALSE(intersectRayBox(Vec3(5, 0, 0), Vec3(1, 0, 0), kFar, Vec3(0), Quat(1, 0, 0, 0), Vec3(1)));
        CHECK_FALSE(intersectRayBox(Vec3(-5, 0, 0), Vec3(1, 0, 0), 3, Vec3(0), Quat(1, 0, 0, 0), Vec3(1)));
        const auto inside = intersectRayBox(Vec3(0.5, 0, 0), Vec3(1, 0, 0), kFar, Vec3(0), Quat(1, 0, 0, 0), Vec3(1));
        REQUIRE(inside);
        CHECK(inside->distance == 0);
        checkVec(inside->normal, Vec3(-1, 0, 0));
    }
}

TEST_CASE("A ray meets a plane at t = height / (-n.d)", "[raycast]") {
    const Vec3 d = glm::normalize(Vec3(1, -1, 0));
    const auto hit = intersectRayPlane(Vec3(0, 2, 0), d, kFar, Vec3(0), Vec3(0, 1, 0));
    REQUIRE(hit);
    CHECK_THAT(hit->distance, WithinAbs(2 * std::sqrt(Real(2)), kTolerance));
    checkVec(hit->normal, Vec3(0, 1, 0));
    CHECK_FALSE(intersectRayPlane(Vec3(0, 2, 0), Vec3(0, 1, 0), kFar, Vec3(0), Vec3(0, 1, 0)));  // away
    CHECK_FALSE(intersectRayPlane(Vec3(0, 2, 0), Vec3(1, 0, 0), kFar, Vec3(0), Vec3(0, 1, 0)));  // parallel
    CHECK_FALSE(intersectRayPlane(Vec3(0, 2, 0), d, 2, Vec3(0), Vec3(0, 1, 0)));                 // too short
    const auto behind = intersectRayPlane(Vec3(0, -1, 0), Vec3(0, 1, 0), kFar, Vec3(0), Vec3(0, 1, 0));
    REQUIRE(behind);
    CHECK(behind->distance == 0);
}

TEST_CASE("World::raycast returns the nearest body along the ray", "[raycast][world]") {
    // Along +x from the origin at height 1: a sphere at x = 5 (r 0.5), a kinematic
    // box at x = 8 (1 m x 1 m x 2 m), and a wall plane at x = 10 facing back.
    Scene scene = test::emptyScene();
    scene.dynamics.push_back(test::sphere("ball", Vec3(5, 1, 0), Vec3(0), 0.5));
    scene.kinematics.push_back(test::kinematicBox("crate", Vec3(8, 1, 0), Vec3(1, 1, 2)));
    CollisionPlane wall = test::ground("wall");
    wall.position = Vec3(10, 0, 0);
    wall.normal = Vec3(-1, 0, 0);
    scene.planes.push_back(wall);
    scene.planes.push_back(test::ground("floor"));
    const World world(scene);

    const auto hit = world.raycast(Vec3(0, 1, 0), Vec3(2, 0, 0), kFar);  // any length of direction
    REQUIRE(hit);
    CHECK(hit->body.kind == BodyKind::Dynamic);
    CHECK(hit->body.index == 0);
    CHECK_THAT(hit->distance, WithinAbs(4.5, kTolerance));
    checkVec(hit->point, Vec3(4.5, 1, 0));
    checkVec(hit->normal, Vec3(-1, 0, 0));

    // Passing above the ball (y = 1.6) the crate (top at 1.5) is missed too: the wall.
    const auto high = world.raycast(Vec3(0, 1.6, 0), Vec3(1, 0, 0), kFar);
    REQUIRE(high);
    CHECK(high->body.kind == BodyKind::Plane);
    CHECK(high->body.index == 0);
    CHECK_THAT(high->distance, WithinAbs(10, kTolerance));

    // Beside the ball (z = 0.45 reaches it; z = 0.6 does not) the crate is first, at x = 7.5.
    const auto beside = world.raycast(Vec3(0, 1, 0.6), Vec3(1, 0, 0), kFar);
    REQUIRE(beside);
    CHECK(beside->body.kind == BodyKind::Kinematic);
    CHECK_THAT(beside->distance, WithinAbs(7.5, kTolerance));

    // Straight down: the floor, 1 m below; nothing within 0.9 m.
    const auto down = world.raycast(Vec3(2, 1, 0), Vec3(0, -1, 0), kFar);
    REQUIRE(down);
    CHECK(down->body.index == 1);
    CHECK_THAT(down->distance, WithinAbs(1, kTolerance));
    CHECK_FALSE(world.raycast(Vec3(2, 1, 0), Vec3(0, -1, 0), Real(0.9)));

    CHECK_THROWS_AS(world.raycast(Vec3(0), Vec3(0), kFar), std::invalid_argument);
    CHECK_THROWS_AS(world.raycast(Vec3(0), Vec3(1, 0, 0), -1), std::invalid_argument);
}
