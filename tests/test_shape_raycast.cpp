// Ray casts against capsules, cylinders, hulls, triangle meshes and compound
// bodies, and World::raycast over them. Every expected hit is worked out by
// hand from the geometry, or (hull against box) from a second, independent
// exact routine. Tag: [raycast].
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "collision/raycast.hpp"
#include "shape_fixtures.hpp"
#include "test_support.hpp"
#include "world/world.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;

namespace {

constexpr Real kTolerance = Real(1e-12);  // m: the formulas are exact up to round-off
constexpr Real kFar = std::numeric_limits<Real>::infinity();
const Quat kUpright(1, 0, 0, 0);

void checkVec(const Vec3& actual, const Vec3& expected, Real tolerance = kTolerance) {
    for (int i = 0; i < 3; ++i) CHECK_THAT(actual[i], WithinAbs(expected[i], tolerance));
}

void checkHit(const std::optional<RayShapeHit>& hit, Real distance, const Vec3& normal) {
    REQUIRE(hit);
    CHECK_THAT(hit->distance, WithinAbs(distance, kTolerance));
    checkVec(hit->normal, normal);
}

Quat turn(Real degrees, const Vec3& axis) { return glm::angleAxis(degrees * kPi / Real(180), axis); }

}  // namespace

TEST_CASE("A ray meets a capsule on its round side or on an end ball", "[raycast]") {
    // r = 0.5, segment from y = −1 to y = 1 (halfHeight 1), at the origin
    const Real r = Real(0.5), h = 1;
    auto cast = [&](Vec3 from, Vec3 along, Real reach = kFar) {
        return intersectRayCapsule(from, glm::normalize(along), reach, Vec3(0), kUpright, r, h);
    };
    SECTION("along x at the side: t = distance − r, normal −x") { checkHit(cast({-5, 0.3, 0}, {1, 0, 0}), 4.5, {-1, 0, 0}); }
    SECTION("down the axis: the top ball at y = h + r") { checkHit(cast({0, 5, 0}, {0, -1, 0}), 3.5, {0, 1, 0}); }
    SECTION("along x above the segment's end: the end ball, x = −sqrt(r² − 0.3²) = −0.4") {
        checkHit(cast({-5, 1.3, 0}, {1, 0, 0}), 4.6, {-0.8, 0.6, 0});
    }
    SECTION("past the top ball, pointing away, or short of it: no hit") {
        CHECK_FALSE(cast({-5, 1.51, 0}, {1, 0, 0}));
        CHECK_FALSE(cast({-5, 0, 0}, {-1, 0, 0}));
        CHECK_FALSE(cast({-5, 0, 0}, {1, 0, 0}, Real(4.49)));
    }
    SECTION("from inside: distance 0, normal back along the ray") { checkHit(cast({0.1, 1.2, 0.1}, {0, 0, 1}), 0, {0, 0, -1}); }
    SECTION("lying along x (90° about z), hit from above mid-segment") {
        const auto hit = intersectRayCapsule(Vec3(0.7, 5, 0.2), Vec3(0, -1, 0), kFar, Vec3(0), turn(90, Vec3(0, 0, 1)), r, h);
        // the side at z = 0.2 from the axis: y = sqrt(r² − 0.2²)
        const Real y = std::sqrt(r * r - Real(0.04));
        checkHit(hit, 5 - y, Vec3(0, y, 0.2) / r);
    }
}

TEST_CASE("A ray meets a cylinder on a flat cap or on its round side", "[raycast]") {
    // r = 0.5, length 2 (caps at y = ±1), centred at (1, 2, 3)
    const Vec3 c(1, 2, 3);
    const Real r = Real(0.5), h = 1;
    auto cast = [&](Vec3 from, Vec3 along, const Quat& q = Quat(1, 0, 0, 0)) {
        return intersectRayCylinder(c + from, glm::normalize(along), kFar, c, q, r, h);
    };
    SECTION("down the axis: the top cap at h") { checkHit(cast({0, 5, 0}, {0, -1, 0}), 4, {0, 1, 0}); }
    SECTION("up, off the axis: the bottom cap") { checkHit(cast({0.3, -4, -0.2}, {0, 1, 0}), 3, {0, -1, 0}); }
    SECTION("along x: the side, t = 5 − r") { checkHit(cast({-5, 0.9, 0}, {1, 0, 0}), 4.5, {-1, 0, 0}); }
    SECTION("at 45° down onto the side: it meets x = −r at y = 0.7") {
        checkHit(cast({-3, 3.2, 0}, {1, -1, 0}), 2.5 * std::sqrt(Real(2)), {-1, 0, 0});
    }
    SECTION("at 45° down onto the cap: it meets y = h at x = 0") {
        checkHit(cast({-3, 4, 0}, {1, -1, 0}), 3 * std::sqrt(Real(2)), {0, 1, 0});
    }
    SECTION("just above the cap, parallel to it, or beside the side along the axis: no hit") {
        CHECK_FALSE(cast({-5, 1.01, 0}, {1, 0, 0}));
        CHECK_FALSE(cast({0.51, 5, 0}, {0, -1, 0}));
    }
    SECTION("from inside: distance 0") { checkHit(cast({0.1, -0.9, 0}, {1, 0, 0}), 0, {-1, 0, 0}); }
    SECTION("lying along z (90° about x): down the axis from +z meets the cap at z = h") {
        checkHit(cast({0, 0, 5}, {0, 0, -1}, turn(90, Vec3(1, 0, 0))), 4, {0, 0, 1});
    }
}

TEST_CASE("A ray meets a hull where it enters the last face plane (Ericson 5.3.8)", "[raycast]") {
    const Vec3 half(Real(0.5), Real(0.25), Real(1));
    const auto hull = test::cubeHull(half);
    SECTION("the fixture's loops are counter-clockwise seen from outside") {
        for (const HullFace& face : hull->faces) {
            const Vec3& v0 = hull->vertices[hull->faceIndices[face.firstIndex]];
            const Vec3& v1 = hull->vertices[hull->faceIndices[face.firstIndex + 1]];
            const Vec3& v2 = hull->vertices[hull->faceIndices[face.firstIndex + 2]];
            CHECK(glm::dot(glm::cross(v1 - v0, v2 - v0), face.normal) > 0);
            CHECK_THAT(glm::dot(face.normal, v0), WithinAbs(face.offset, kTolerance));
        }
    }
    SECTION("by hand: along x onto the −x face, down onto the top") {
        checkHit(intersectRayHull(Vec3(-5, 0.1, 0.2), Vec3(1, 0, 0), kFar, Vec3(0), kUpright, *hull), 4.5, {-1, 0, 0});
        checkHit(intersectRayHull(Vec3(0.2, 3, -0.7), Vec3(0, -1, 0), kFar, Vec3(0), kUpright, *hull), 2.75, {0, 1, 0});
        CHECK_FALSE(intersectRayHull(Vec3(-5, 0.3, 0), Vec3(1, 0, 0), kFar, Vec3(0), kUpright, *hull));
        checkHit(intersectRayHull(Vec3(0.1, 0, 0), Vec3(0, 0, 1), kFar, Vec3(0), kUpright, *hull), 0, {0, 0, -1});
    }
    SECTION("the same hits as the box's slab test, for 500 random rays at a turned cube") {
        // Two exact routines written from different maths (face planes, slabs) must agree.
        std::mt19937 random(20240601);
        std::uniform_real_distribution<Real> unit(-1, 1);
        const Vec3 centre(0.3, -0.2, 0.1);
        const Quat q = turn(37, glm::normalize(Vec3(1, 2, 3)));
        int hits = 0;
        for (int k = 0; k < 500; ++k) {
            const Vec3 from = Real(4) * Vec3(unit(random), unit(random), unit(random));
            const Vec3 target = centre + Vec3(unit(random), unit(random), unit(random));
            const Vec3 d = glm::normalize(target - from);
            const auto byFaces = intersectRayHull(from, d, kFar, centre, q, *hull);
            const auto bySlabs = intersectRayBox(from, d, kFar, centre, q, half);
            REQUIRE(byFaces.has_value() == bySlabs.has_value());
            if (!byFaces) continue;
            ++hits;
            CHECK_THAT(byFaces->distance, WithinAbs(bySlabs->distance, kTolerance));
            checkVec(byFaces->normal, bySlabs->normal, Real(1e-9));  // a ray through an edge may pick either face
        }
        CHECK(hits > 100);  // the rays aim at the cube: most of them hit
    }
}

TEST_CASE("A ray meets a triangle mesh from either side, through its hierarchy or without one", "[raycast]") {
    SECTION("one triangle (Moller-Trumbore): inside, on the far side, outside") {
        const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);  // normal +z
        checkHit(intersectRayTriangle(Vec3(0.2, 0.3, 2), Vec3(0, 0, -1), kFar, a, b, c), 2, {0, 0, 1});
        checkHit(intersectRayTriangle(Vec3(0.2, 0.3, -3), Vec3(0, 0, 1), kFar, a, b, c), 3, {0, 0, -1});
        CHECK_FALSE(intersectRayTriangle(Vec3(0.6, 0.6, 2), Vec3(0, 0, -1), kFar, a, b, c));  // u + v > 1
        CHECK_FALSE(intersectRayTriangle(Vec3(0.2, 0.3, 2), Vec3(1, 0, 0), kFar, a, b, c));   // in a parallel plane
    }
    for (const bool twoLeaves : {false, true}) {
        DYNAMIC_SECTION("a 2 m square, " << (twoLeaves ? "a root over two leaves" : "one leaf")) {
            const auto mesh = test::squareMesh(1, twoLeaves);
            const Vec3 c(0, -1, 0);
            // Each half of the square: (0.5, −0.4) is in triangle 1 (x > z), (−0.5, 0.4) in triangle 0
            checkHit(intersectRayMesh(Vec3(0.5, 4, -0.4), Vec3(0, -1, 0), kFar, c, kUpright, *mesh), 5, {0, 1, 0});
            checkHit(intersectRayMesh(Vec3(-0.5, 4, 0.4), Vec3(0, -1, 0), kFar, c, kUpright, *mesh), 5, {0, 1, 0});
            checkHit(intersectRayMesh(Vec3(-0.5, -3, 0.4), Vec3(0, 1, 0), kFar, c, kUpright, *mesh), 2, {0, -1, 0});
            CHECK_FALSE(intersectRayMesh(Vec3(1.5, 4, 0), Vec3(0, -1, 0), kFar, c, kUpright, *mesh));
            CHECK_FALSE(intersectRayMesh(Vec3(0.5, 4, -0.4), Vec3(0, -1, 0), Real(4.9), c, kUpright, *mesh));
            // Turned 90° about x: (x, 0, z) → (x, −z, 0), the normal +y → +z
            checkHit(intersectRayMesh(Vec3(0.2, -1.1, 5), Vec3(0, 0, -1), kFar, c, turn(90, Vec3(1, 0, 0)), *mesh), 5,
                     {0, 0, 1});
        }
    }
    SECTION("without nodes: every triangle is tried") {
        auto flat = std::make_shared<TriangleMesh>(*test::squareMesh(1));
        flat->nodes.clear();
        checkHit(intersectRayMesh(Vec3(0.5, 4, -0.4), Vec3(0, -1, 0), kFar, Vec3(0), kUpright, *flat), 4, {0, 1, 0});
    }
}

TEST_CASE("World::raycast finds capsules, cylinders, hulls, compounds and meshes", "[raycast]") {
    Scene scene = test::emptyScene();
    // A bar of two unit boxes stood on end: from y = 0 to y = 2 at x = 0
    DynamicObject bar = test::shapedBody("bar", Shape::Compound, Vec3(0, 1, 0), turn(90, Vec3(0, 0, 1)));
    bar.compound = test::twoBoxCompound();
    DynamicObject capsule = test::shapedBody("capsule", Shape::Capsule, Vec3(5, 1, 0), kUpright, Real(0.5), 1);
    DynamicObject cylinder = test::shapedBody("cylinder", Shape::Cylinder, Vec3(-5, 1, 0), kUpright, Real(0.5), 2);
    DynamicObject hull = test::shapedBody("hull", Shape::Hull, Vec3(0, 1, 5));
    hull.hull = test::cubeHull();
    scene.dynamics = {bar, capsule, cylinder, hull};
    KinematicsObject floor = test::kinematicBox("floor", Vec3(0, -1, 0), Vec3(1));
    floor.shape = Shape::Mesh;
    floor.mesh = test::squareMesh(20, true);
    scene.kinematics = {floor};
    const World world(std::move(scene));

    auto cast = [&](Vec3 from, Vec3 along) { return world.raycast(from, along, kFar); };
    SECTION("the compound: from above, its upper part; from the side low down, its lower part") {
        auto hit = cast({0, 10, 0}, {0, -1, 0});
        REQUIRE(hit);
        CHECK(hit->body.kind == BodyKind::Dynamic);
        CHECK(hit->body.index == 0);
        CHECK_THAT(hit->distance, WithinAbs(8, kTolerance));
        checkVec(hit->normal, {0, 1, 0});
        hit = cast({-2, 0.25, 0.1}, {1, 0, 0});
        REQUIRE(hit);
        CHECK(hit->body.index == 0);
        CHECK_THAT(hit->distance, WithinAbs(1.5, kTolerance));
        checkVec(hit->normal, {-1, 0, 0});
    }
    SECTION("capsule, cylinder and hull from above: y = 1 + 0.5 + 0.5, 1 + 1, 1 + 0.5") {
        const struct {
            Vec3 from;
            std::uint32_t index;
            Real distance;
        } cases[] = {{{5, 10, 0}, 1, 8}, {{-5, 10, 0}, 2, 8}, {{0.1, 10, 5.2}, 3, 8.5}};
        for (const auto& c : cases) {
            const auto hit = cast(c.from, {0, -1, 0});
            REQUIRE(hit);
            CHECK(hit->body.index == c.index);
            CHECK_THAT(hit->distance, WithinAbs(c.distance, kTolerance));
            checkVec(hit->normal, {0, 1, 0});
            checkVec(hit->point, c.from - Vec3(0, c.distance, 0));
        }
    }
    SECTION("the mesh floor, between the bodies") {
        const auto hit = cast({2.5, 3, 2.5}, {0, -1, 0});
        REQUIRE(hit);
        CHECK(hit->body.kind == BodyKind::Kinematic);
        CHECK_THAT(hit->distance, WithinAbs(4, kTolerance));
        checkVec(hit->normal, {0, 1, 0});
    }
}
