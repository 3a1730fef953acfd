// Bounding boxes, reaches and inner radii of capsules, cylinders, hulls,
// compounds and meshes, and what the step plan decides for them. Every
// expected value is worked out from the geometry by hand (or, for the
// cylinder, by sampling its rims, which does not use the formula under test).
// Tags: [broadphase] (bounds), [ccd] (inner radii), [plan].
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "collision/aabb.hpp"
#include "collision/continuous.hpp"
#include "shape_fixtures.hpp"
#include "test_support.hpp"
#include "world/step_plan.hpp"
#include "world/world.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;

namespace {

/// m: the boxes are a few products and sums of numbers of order 1, exact up to round-off.
constexpr Real kTolerance = Real(1e-12);
/// Rim points sampled per circle: the sampled extent falls short of the true one by at most
/// r·(1 − cos(π/n)), 9e-8 m for r = 0.3 m and n = 4096.
constexpr int kRimSamples = 4096;
constexpr Real kSampleTolerance = Real(1e-7);

void checkBox(const Aabb& box, const Vec3& centre, const Vec3& extent, Real tolerance = kTolerance) {
    for (int i = 0; i < 3; ++i) {
        CHECK_THAT(box.min[i], WithinAbs(centre[i] - extent[i], tolerance));
        CHECK_THAT(box.max[i], WithinAbs(centre[i] + extent[i], tolerance));
    }
}

/// A turn by @p degrees about the unit @p axis.
Quat turn(Real degrees, const Vec3& axis) { return glm::angleAxis(degrees * kPi / Real(180), axis); }

}  // namespace

TEST_CASE("A capsule's box is its segment's box grown by r", "[broadphase]") {
    // Turned 30° about z, the segment's direction is a = (−sin 30°, cos 30°, 0) = (−1/2, √3/2, 0):
    // the box reaches h·|a_i| + r from the centre on each axis.
    const Vec3 centre(1, 2, 3);
    const Real r = Real(0.2), h = Real(0.5);
    const Aabb box = capsuleAabb(centre, turn(30, Vec3(0, 0, 1)), r, h);
    checkBox(box, centre, Vec3(h * Real(0.5) + r, h * std::sqrt(Real(3)) / 2 + r, r));

    // The same through a body: height is the whole segment (2h)
    DynamicObject body = test::shapedBody("capsule", Shape::Capsule, centre, turn(30, Vec3(0, 0, 1)), r, 2 * h);
    checkBox(shapeAabb(body), centre, Vec3(h * Real(0.5) + r, h * std::sqrt(Real(3)) / 2 + r, r));
    CHECK_THAT(shapeReach(body), WithinAbs(h + r, kTolerance));
}

TEST_CASE("A cylinder's box: h|a_i| + r sqrt(1 - a_i^2) on each axis", "[broadphase]") {
    const Vec3 centre(-1, 0.5, 2);
    const Real r = Real(0.3), h = Real(0.5);
    const Quat q = turn(30, Vec3(0, 0, 1));  // a = (−1/2, √3/2, 0)
    const Aabb box = cylinderAabb(centre, q, r, h);
    const Real s3 = std::sqrt(Real(3));
    SECTION("against the formula worked by hand") {
        // x: h/2 + r·√(3/4); y: h·√3/2 + r·√(1/4); z: 0 + r·1
        checkBox(box, centre, Vec3(h / 2 + r * s3 / 2, h * s3 / 2 + r / 2, r));
    }
    SECTION("against the extremes of points sampled on its two rims") {
        // The cylinder's extreme along any axis is on one of its two rim circles.
        const Vec3 axis = q * Vec3(0, 1, 0);
        const Vec3 u = q * Vec3(1, 0, 0), w = q * Vec3(0, 0, 1);  // the rims' plane
        Vec3 lowest(std::numeric_limits<Real>::max()), highest(std::numeric_limits<Real>::lowest());
        for (const Real end : {-h, h}) {
            for (int k = 0; k < kRimSamples; ++k) {
                const Real angle = Real(2) * kPi * Real(k) / Real(kRimSamples);
                const Vec3 p = centre + end * axis + r * (std::cos(angle) * u + std::sin(angle) * w);
                lowest = glm::min(lowest, p);
                highest = glm::max(highest, p);
            }
        }
        for (int i = 0; i < 3; ++i) {
            CHECK_THAT(box.min[i], WithinAbs(lowest[i], kSampleTolerance));
            CHECK_THAT(box.max[i], WithinAbs(highest[i], kSampleTolerance));
            CHECK(box.min[i] <= lowest[i] + kTolerance);  // never smaller than the shape
            CHECK(box.max[i] >= highest[i] - kTolerance);
        }
    }
    SECTION("upright: the box is r, h, r exactly") {
        checkBox(cylinderAabb(centre, Quat(1, 0, 0, 0), r, h), centre, Vec3(r, h, r));
    }
    DynamicObject body = test::shapedBody("cylinder", Shape::Cylinder, centre, q, r, 2 * h);
    CHECK_THAT(shapeReach(body), WithinAbs(std::sqrt(h * h + r * r), kTolerance));
}

TEST_CASE("A hull's box is its turned vertices' box: a hull cube's equals the box's", "[broadphase]") {
    const Vec3 half(Real(0.5), Real(0.25), Real(1));
    const auto hull = test::cubeHull(half);
    const Vec3 centre(3, -1, 0.5);
    for (const Quat& q : {Quat(1, 0, 0, 0), turn(45, Vec3(0, 1, 0)), turn(37, glm::normalize(Vec3(1, 2, 3)))}) {
        const Aabb expected = boxAabb(centre, q, half);
        checkBox(hullAabb(centre, q, *hull), expected.centre(), Real(0.5) * (expected.max - expected.min));
    }
    // 45° about y by hand: x and z reach (e_x + e_z)/√2, y stays e_y
    const Real diagonal = (half.x + half.z) / std::sqrt(Real(2));
    checkBox(hullAabb(centre, turn(45, Vec3(0, 1, 0)), *hull), centre, Vec3(diagonal, half.y, diagonal));

    DynamicObject body = test::shapedBody("hull", Shape::Hull, centre);
    body.hull = hull;
    checkBox(shapeAabb(body), centre, half);
    CHECK_THAT(shapeReach(body), WithinAbs(glm::length(half), kTolerance));
}

TEST_CASE("A compound's box holds all its parts, and a mesh's is its root box turned", "[broadphase]") {
    SECTION("two unit boxes side by side, stood on end by 90° about z: a 1 x 2 x 1 bar") {
        DynamicObject body = test::shapedBody("bar", Shape::Compound, Vec3(0, 1, 0), turn(90, Vec3(0, 0, 1)));
        body.compound = test::twoBoxCompound();
        checkBox(shapeAabb(body), Vec3(0, 1, 0), Vec3(0.5, 1, 0.5));
        CHECK_THAT(shapeReach(body), WithinAbs(std::sqrt(Real(1.5)), kTolerance));
    }
    SECTION("a 2 m square: flat, then turned 90° about x into the plane z = const") {
        KinematicsObject floor = test::kinematicBox("floor", Vec3(1, 2, 3), Vec3(1));
        floor.shape = Shape::Mesh;
        floor.mesh = test::squareMesh(1);
        checkBox(shapeAabb(floor), Vec3(1, 2, 3), Vec3(1, 0, 1));
        floor.orientation = turn(90, Vec3(1, 0, 0));  // (x, 0, z) → (x, −z, 0)
        checkBox(shapeAabb(floor), Vec3(1, 2, 3), Vec3(1, 1, 0));
        CHECK_THAT(shapeReach(floor), WithinAbs(std::sqrt(Real(2)), kTolerance));  // the corner (1, 0, 1)
        floor.mesh = [] {  // no hierarchy: the vertices themselves
            auto flat = std::make_shared<TriangleMesh>(*test::squareMesh(1));
            flat->nodes.clear();
            return flat;
        }();
        checkBox(shapeAabb(floor), Vec3(1, 2, 3), Vec3(1, 1, 0));
    }
    SECTION("the broadphase grows the exact box by kSpeculativeDistance + sweep") {
        DynamicObject body = test::shapedBody("capsule", Shape::Capsule, Vec3(0), Quat(1, 0, 0, 0), Real(0.25), 1);
        body.sweep = Real(0.1);
        checkBox(broadphaseBounds(body), Vec3(0), Vec3(0.25, 0.75, 0.25) + Vec3(kSpeculativeDistance + Real(0.1)));
    }
    SECTION("a plane's geometry, and a compound's (which carries no parts), are unbounded") {
        const Real inf = std::numeric_limits<Real>::infinity();
        Geometry plane;
        plane.type = GeometryType::Plane;
        CHECK(geometryAabb(plane).max.x == inf);
        Geometry compound;
        compound.type = GeometryType::Count;
        CHECK(geometryAabb(compound).min.y == -inf);
    }
}

TEST_CASE("Inner radii: the largest ball about the centre each shape holds", "[ccd]") {
    // A capsule: r (the centre is on the segment); a cylinder: min(r, h/2); a hull: its nearest
    // face; a compound: its thinnest part (continuous.hpp says why).
    CHECK(innerRadius(test::shapedBody("c", Shape::Capsule, Vec3(0), Quat(1, 0, 0, 0), Real(0.2), 3)) == Real(0.2));
    CHECK(innerRadius(test::shapedBody("squat", Shape::Cylinder, Vec3(0), Quat(1, 0, 0, 0), Real(0.5), Real(0.4))) ==
          Real(0.2));
    CHECK(innerRadius(test::shapedBody("tall", Shape::Cylinder, Vec3(0), Quat(1, 0, 0, 0), Real(0.3), 4)) == Real(0.3));
    DynamicObject hull = test::shapedBody("hull", Shape::Hull, Vec3(0));
    hull.hull = test::cubeHull(Vec3(0.5, 0.1, 2));
    CHECK(innerRadius(hull) == Real(0.1));
    DynamicObject bar = test::shapedBody("bar", Shape::Compound, Vec3(0));
    bar.compound = test::twoBoxCompound(Real(0.6));
    CHECK(innerRadius(bar) == Real(0.3));
}

TEST_CASE("The plan lets every shape but a sphere turn, and takes no capsule for a ball", "[plan]") {
    // Frictionless bodies with no spin, springs or joints: only spheres can be kept from turning.
    for (const Shape shape : {Shape::Capsule, Shape::Cylinder, Shape::Hull, Shape::Compound}) {
        Scene scene = test::emptyScene();
        scene.settings.fastPath = true;
        scene.planes = {test::ground()};
        scene.planes[0].friction = 0;
        DynamicObject body = test::shapedBody("body", shape, Vec3(0, 2, 0));
        body.friction = 0;
        if (shape == Shape::Hull) body.hull = test::cubeHull();
        if (shape == Shape::Compound) body.compound = test::twoBoxCompound();
        scene.dynamics = {body};
        const StepPlan plan = World(std::move(scene)).plan();
        INFO(toString(shape));
        CHECK(plan.rotation.runs);
        CHECK_FALSE(plan.fastPath.runs);  // no ball: the fast path's round contacts are spheres only
        CHECK_FALSE(plan.boxBoxSat.runs);
    }
}
