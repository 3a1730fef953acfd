// GJK, EPA and MPR against distances and depths worked out by hand, and against SAT.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "collision/epa.hpp"
#include "collision/gjk.hpp"
#include "collision/mpr.hpp"
#include "convex_fixtures.hpp"

using namespace stepwise;
using namespace stepwise::test;
using Catch::Matchers::WithinAbs;

namespace {

/// Polytopes and points: GJK ends on the exact closest feature, so only round-off is left.
constexpr Real kRoundOff = 1e-9;

GjkResult gjkOf(const Geometry& a, const Geometry& b, std::vector<Simplex>* record = nullptr) {
    return gjk(convexShapeOf(a), convexShapeOf(b), record);
}

Quat aboutAxis(Real angle, const Vec3& axis) { return glm::angleAxis(angle, glm::normalize(axis)); }

}  // namespace

TEST_CASE("GJK: two spheres are apart by the distance of their centres less the radii", "[gjk]") {
    const GjkResult r = gjkOf(sphereAt(Vec3(0), 0.5), sphereAt(Vec3(1, 2, 2), 0.25));
    REQUIRE_FALSE(r.overlap);
    CHECK_THAT(r.distance, WithinAbs(3 - 0.75, kRoundOff));  // |(1,2,2)| = 3
    CHECK_THAT(glm::length(r.normal - Vec3(1, 2, 2) / Real(3)), WithinAbs(0, kRoundOff));
    CHECK_THAT(glm::length(r.onA - Vec3(1, 2, 2) / Real(6)), WithinAbs(0, kRoundOff));
    CHECK(r.iterations <= 2);  // two points: one support query each, then w repeats
    // Radii that overlap but centres that do not: a negative distance, still a direction.
    const GjkResult close = gjkOf(sphereAt(Vec3(0), 0.5), sphereAt(Vec3(0.8, 0, 0), 0.5));
    REQUIRE_FALSE(close.overlap);
    CHECK_THAT(close.distance, WithinAbs(-0.2, kRoundOff));
}

TEST_CASE("GJK: boxes facing each other are apart by the gap between the faces", "[gjk]") {
    const Geometry a = boxAt(Vec3(0), Vec3(0.5));
    const Geometry b = boxAt(Vec3(2.3, 0.1, -0.2), Vec3(0.5));
    std::vector<Simplex> record;
    const GjkResult r = gjkOf(a, b, &record);
    REQUIRE_FALSE(r.overlap);
    CHECK_THAT(r.distance, WithinAbs(1.3, kRoundOff));
    CHECK_THAT(glm::length(r.normal - Vec3(1, 0, 0)), WithinAbs(0, kRoundOff));
    CHECK_THAT(r.onA.x, WithinAbs(0.5, kRoundOff));
    CHECK_THAT(r.onB.x, WithinAbs(1.8, kRoundOff));
    // The record has one simplex per point added, each no farther from the origin than the last.
    REQUIRE(!record.empty());
    CHECK(static_cast<int>(record.size()) <= r.iterations);
    for (std::size_t i = 1; i < record.size(); ++i) {
        CHECK(glm::length(record[i].closest) <= glm::length(record[i - 1].closest) + kRoundOff);
    }
    CHECK_THAT(glm::length(record.back().closest), WithinAbs(1.3, kRoundOff));
}

TEST_CASE("GJK: capsules crossing and parallel are apart by their axes' distance less the radii", "[gjk]") {
    // Along y through the origin, and along z through x = 1: the axes cross at distance 1.
    const Geometry a = roundAt(GeometryType::Capsule, Vec3(0), 0.2, 1);
    const Geometry crossing = roundAt(GeometryType::Capsule, Vec3(1, 0.3, 0), 0.1, 1, aboutAxis(kPi / 2, Vec3(1, 0, 0)));
    const GjkResult r = gjkOf(a, crossing);
    REQUIRE_FALSE(r.overlap);
    CHECK_THAT(r.distance, WithinAbs(1 - 0.3, kRoundOff));
    CHECK_THAT(glm::length(r.onA - Vec3(0.2, 0.3, 0)), WithinAbs(0, kRoundOff));
    // Parallel, side by side, overlapping half their length: every point of the overlap is closest.
    const Geometry parallel = roundAt(GeometryType::Capsule, Vec3(0.75, 1, 0), 0.1, 1);
    const GjkResult p = gjkOf(a, parallel);
    REQUIRE_FALSE(p.overlap);
    CHECK_THAT(p.distance, WithinAbs(0.75 - 0.3, kRoundOff));
    CHECK_THAT(glm::length(p.normal - Vec3(1, 0, 0)), WithinAbs(0, kRoundOff));
}

TEST_CASE("GJK: a point's distance from a hull cube is its distance from the nearest face, edge or corner", "[gjk]") {
    const auto cube = cubeHull(Vec3(Real(0.5)));
    const Geometry hull = hullAt(*cube, Vec3(0));
    // Beyond a face: 2 − 0.5. Beyond an edge: |(0.5, 0.5)|. Beyond a corner: |(0.5, 0.5, 0.5)|.
    CHECK_THAT(gjkOf(sphereAt(Vec3(2, 0.2, 0.1), 0), hull).distance, WithinAbs(1.5, kRoundOff));
    CHECK_THAT(gjkOf(sphereAt(Vec3(1, 1, 0.3), 0), hull).distance, WithinAbs(std::sqrt(0.5), kRoundOff));
    CHECK_THAT(gjkOf(sphereAt(Vec3(1, 1, 1), 0), hull).distance, WithinAbs(std::sqrt(0.75), kRoundOff));
    // Turned 45° about y, the cube's edge points along x at distance √2/2 from its centre.
    const Geometry turned = hullAt(*cube, Vec3(0), aboutAxis(kPi / 4, Vec3(0, 1, 0)));
    CHECK_THAT(gjkOf(sphereAt(Vec3(2, 0, 0), 0), turned).distance, WithinAbs(2 - std::sqrt(0.5), kRoundOff));
    CHECK(gjkOf(sphereAt(Vec3(0.1, 0.2, 0.3), 0), hull).overlap);
}

TEST_CASE("GJK: a cylinder's distance converges on its curved side within the iteration cap", "[gjk]") {
    // A cylinder (r 0.5, half length 1, along y) and a point at 45° across its axis, 2 m out.
    const Geometry cylinder = roundAt(GeometryType::Cylinder, Vec3(0), 0.5, 1);
    const GjkResult r = gjkOf(sphereAt(Vec3(std::sqrt(2.0), 0.3, std::sqrt(2.0)), 0.1), cylinder);
    REQUIRE_FALSE(r.overlap);
    // The side is curved: GJK approaches it in steps and stops within kGjkRelativeTolerance of the
    // distance; 1e-6 m allows for the bound being on |v|² rather than |v|.
    CHECK_THAT(r.distance, WithinAbs(2 - 0.5 - 0.1, 1e-6));
    CHECK(r.iterations < kMaxGjkIterations);
}

TEST_CASE("EPA: overlapping boxes give the face overlap as depth, the face normal, and witness points", "[epa]") {
    const Geometry a = boxAt(Vec3(0), Vec3(0.5));
    const Geometry b = boxAt(Vec3(0.9, 0.05, 0.1), Vec3(0.5));
    const ConvexShape sa = convexShapeOf(a);
    const ConvexShape sb = convexShapeOf(b);
    const GjkResult g = gjk(sa, sb);
    REQUIRE(g.overlap);
    const EpaResult e = epa(sa, sb, g.simplex);
    REQUIRE(e.valid);
    // Polytopes: EPA ends on the exact face of A − B, so round-off is the only error.
    CHECK_THAT(e.depth, WithinAbs(0.1, kRoundOff));
    CHECK_THAT(glm::length(e.normal - Vec3(1, 0, 0)), WithinAbs(0, kRoundOff));
    CHECK_THAT(glm::length(e.onA - e.onB - e.depth * e.normal), WithinAbs(0, kRoundOff));
    CHECK_THAT(e.onA.x, WithinAbs(0.5, kRoundOff));
    CHECK_THAT(e.onB.x, WithinAbs(0.4, kRoundOff));
    CHECK(e.iterations >= 1);
}

TEST_CASE("EPA: spheres whose centres overlap get depth r_A + r_B - d along the centres' line", "[epa]") {
    // Cores are single points, so GJK never overlaps for spheres apart: put one centre inside a box.
    const Geometry ball = sphereAt(Vec3(0.45, 0, 0), 0.2);
    const Geometry box = boxAt(Vec3(0), Vec3(0.5));
    const ConvexShape sa = convexShapeOf(ball);
    const ConvexShape sb = convexShapeOf(box);
    const GjkResult g = gjk(sa, sb);
    REQUIRE(g.overlap);
    const EpaResult e = epa(sa, sb, g.simplex);
    REQUIRE(e.valid);
    // The way out is through the +x face: 0.05 to the face plus the radius. The sphere is curved,
    // so EPA stops within kEpaAbsoluteTolerance + kEpaRelativeTolerance·depth of it.
    CHECK_THAT(e.depth, WithinAbs(0.25, 1e-7 + 1e-4 * 0.25));
    CHECK(e.normal.x < -0.999);  // from the ball (A) into the box (B): −x
}

TEST_CASE("MPR: boxes in line give the face overlap, a sphere pair its depth", "[mpr]") {
    const MprResult boxes = mpr(convexShapeOf(boxAt(Vec3(0), Vec3(0.5))), convexShapeOf(boxAt(Vec3(0.9, 0, 0), Vec3(0.5))));
    REQUIRE(boxes.overlap);
    // The ray between the centres meets the face square on: the portal is that face exactly.
    CHECK_THAT(boxes.depth, WithinAbs(0.1, kRoundOff));
    CHECK_THAT(glm::length(boxes.normal - Vec3(1, 0, 0)), WithinAbs(0, kRoundOff));
    const MprResult balls = mpr(convexShapeOf(sphereAt(Vec3(0), 0.5)), convexShapeOf(sphereAt(Vec3(0.6, 0.8, 0), 0.6)));
    REQUIRE(balls.overlap);
    // A curved boundary: the portal's plane lies within kMprTolerance-ish of it; 1e-6 m allows for the last portal's sag.
    CHECK_THAT(balls.depth, WithinAbs(0.1, 1e-6));
    CHECK_THAT(glm::length(balls.normal - Vec3(0.6, 0.8, 0)), WithinAbs(0, 1e-3));
    CHECK_FALSE(mpr(convexShapeOf(sphereAt(Vec3(0), 0.5)), convexShapeOf(sphereAt(Vec3(1.2, 0, 0), 0.6))).overlap);
}
