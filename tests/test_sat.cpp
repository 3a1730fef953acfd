// Box against box by the separating-axis test: which axis, which normal, how deep.
// Every expected value is worked out from the geometry in the comment above it.
// Tags: [sat].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "collision/box_features.hpp"
#include "collision/closest_points.hpp"
#include "collision/narrowphase.hpp"
#include "config/scene_loader.hpp"
#include "test_support.hpp"
#include "world/world.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;

namespace {

const Real kSqrt2 = std::sqrt(Real(2));
const Real kSqrt3 = std::sqrt(Real(3));
const Quat kIdentity(1, 0, 0, 0);

/// Positions and depths below are exact up to round-off in a few dozen operations.
constexpr Real kExact = 1e-12;

Geometry box(Vec3 centre, Vec3 halfExtents, Quat orientation = kIdentity) {
    return test::boxGeometry(centre, halfExtents, orientation);
}

/// The interval a box's corners cover along @p axis, by projecting all 8
/// corners: a brute-force check that does not use the |u·L| formula of box_box.cpp.
std::pair<Real, Real> shadow(const Geometry& g, const Vec3& axis) {
    const OrientedBox b = orientedBoxOf(g);
    Real low = glm::dot(cornerOf(b, 0), axis);
    Real high = low;
    for (int k = 1; k < 8; ++k) {
        const Real x = glm::dot(cornerOf(b, k), axis);
        low = std::min(low, x);
        high = std::max(high, x);
    }
    return {low, high};
}

/// How much the shadows of two boxes overlap along @p axis (negative: a gap).
Real shadowOverlap(const Geometry& a, const Geometry& b, const Vec3& axis) {
    const auto [lowA, highA] = shadow(a, axis);
    const auto [lowB, highB] = shadow(b, axis);
    return std::min(highA, highB) - std::max(lowA, lowB);
}

bool near(const Vec3& x, const Vec3& y, Real tolerance = kExact) { return glm::length(x - y) < tolerance; }

/// True when the manifold's points are exactly @p expected, in any order.
bool samePoints(const ContactManifold& m, const std::vector<Vec3>& expected) {
    if (m.pointCount != static_cast<int>(expected.size())) return false;
    for (const Vec3& e : expected) {
        const bool found = std::any_of(m.points, m.points + m.pointCount,
                                       [&](const ContactPoint& p) { return near(p.position, e); });
        if (!found) return false;
    }
    return true;
}

// The edge–edge scene of the tests below. A (above): a unit cube turned 45°
// about z, so its lowest feature is the edge along z through
// (xA, yA − √2/2, ·). B (below, at the origin): half extents (1, ½, ½)
// turned 45° about x, so its highest feature is the edge along x through
// (·, √2/2, 0). The two edges cross at right angles; their common
// perpendicular is y = z × x, which is neither box's face normal
// (A's are (1,1,0)/√2, (−1,1,0)/√2, z; B's are x, (0,1,1)/√2, (0,−1,1)/√2).
// The edges overlap by gap-free depth d when yA = √2 − d.
const Quat kEdgeDownA = glm::angleAxis(kPi / 4, Vec3(0, 0, 1));
const Quat kEdgeUpB = glm::angleAxis(kPi / 4, Vec3(1, 0, 0));
const Vec3 kEdgeHalfB(1, 0.5, 0.5);

Geometry crossedUpper(Real depth) { return box(Vec3(0.1, kSqrt2 - depth, -0.05), Vec3(0.5), kEdgeDownA); }
Geometry crossedLower() { return box(Vec3(0), kEdgeHalfB, kEdgeUpB); }

}  // namespace

TEST_CASE("Boxes apart along a face axis do not collide", "[sat]") {
    ContactManifold m;
    // Unit cubes 1.2 m apart on x: a 0.2 m gap between A's +x face and B's −x face.
    CHECK_FALSE(collideBoxBox(box(Vec3(0), Vec3(0.5)), box(Vec3(1.2, 0, 0), Vec3(0.5)), m));
    // B turned 10° about y reaches 0.5·(cos 10° + sin 10°) = 0.579 m along x:
    // its nearest point is at x = 0.621 > 0.5, still a gap on A's x axis.
    const Quat turned = glm::angleAxis(glm::radians(Real(10)), Vec3(0, 1, 0));
    CHECK_FALSE(collideBoxBox(box(Vec3(0), Vec3(0.5)), box(Vec3(1.2, 0.3, -0.2), Vec3(0.5), turned), m));
    // And with the roles swapped.
    CHECK_FALSE(collideBoxBox(box(Vec3(1.2, 0.3, -0.2), Vec3(0.5), turned), box(Vec3(0), Vec3(0.5)), m));
}

TEST_CASE("Boxes apart only along an edge-edge axis do not collide", "[sat]") {
    // The crossed edges 1 cm apart (d = −0.01): only y = a_z × b_x shows the gap.
    const Geometry a = crossedUpper(-0.01);
    const Geometry b = crossedLower();
    const OrientedBox oa = orientedBoxOf(a);
    const OrientedBox ob = orientedBoxOf(b);
    // Brute force over the corners: every face axis overlaps (by 0.34 m at least),
    // so a test of face axes alone would report a collision…
    for (int i = 0; i < 3; ++i) {
        CHECK(shadowOverlap(a, b, oa.axes[i]) > 0.3);
        CHECK(shadowOverlap(a, b, ob.axes[i]) > 0.3);
    }
    // …while along y the shadows are 1 cm apart.
    CHECK_THAT(shadowOverlap(a, b, Vec3(0, 1, 0)), WithinAbs(-0.01, kExact));

    ContactManifold m;
    CHECK_FALSE(collideBoxBox(a, b, m));
    CHECK_FALSE(collideBoxBox(b, a, m));
}

TEST_CASE("Boxes touching at distance 0 collide with depth 0, and a gap gives speculative points up to 1 cm", "[sat]") {
    // A unit cube on a 4 x 1 x 4 slab whose top is y = 0.5: A's bottom at 1.0 − 0.5 = 0.5.
    const Geometry slab = box(Vec3(0), Vec3(2, 0.5, 2));
    ContactManifold m;
    REQUIRE(collideBoxBox(box(Vec3(0.2, 1.0, -0.1), Vec3(0.5)), slab, m));
    CHECK(near(m.normal, Vec3(0, -1, 0)));
    REQUIRE(m.pointCount == 4);
    for (int i = 0; i < m.pointCount; ++i) CHECK_THAT(m.points[i].depth, WithinAbs(0, kExact));

    // A 2 mm gap: the same four points, speculative, with depth −2 mm (contact.hpp says why).
    REQUIRE(collideBoxBox(box(Vec3(0.2, 1.0 + 2e-3, -0.1), Vec3(0.5)), slab, m));
    REQUIRE(m.pointCount == 4);
    for (int i = 0; i < m.pointCount; ++i) CHECK_THAT(m.points[i].depth, WithinAbs(-2e-3, kExact));
    // Beyond kSpeculativeDistance the face axis separates them: no contact.
    CHECK_FALSE(collideBoxBox(box(Vec3(0.2, 1.0 + kSpeculativeDistance + 1e-4, -0.1), Vec3(0.5)), slab, m));
}

TEST_CASE("Face-face: a turned cube resting on a slab", "[sat]") {
    // Unit cube turned 30° about y, sunk d = 2 cm into the slab's top (y = 0.5).
    // Turning (x, z) = (±½, ±½) by 30° about y (x' = x cos + z sin, z' = −x sin + z cos)
    // gives the bottom corners at offsets ±((√3+1)/4, (√3−1)/4) and
    // ±((√3−1)/4, −(√3+1)/4): all inside the slab's top.
    const Real d = 0.02;
    const Vec3 centre(0.3, 1.0 - d, -0.2);
    const Geometry cube = box(centre, Vec3(0.5), glm::angleAxis(kPi / 6, Vec3(0, 1, 0)));
    const Geometry slab = box(Vec3(0), Vec3(2, 0.5, 2));
    const Real big = (kSqrt3 + 1) / 4;
    const Real small = (kSqrt3 - 1) / 4;
    const Real y = 0.5 - d / 2;  // midway between the cube's bottom (0.5 − d) and the slab's top
    const std::vector<Vec3> corners = {centre + Vec3(big, 0, small), centre + Vec3(small, 0, -big),
                                       centre + Vec3(-small, 0, big), centre + Vec3(-big, 0, -small)};
    std::vector<Vec3> expected;
    for (const Vec3& c : corners) expected.push_back(Vec3(c.x, y, c.z));

    ContactManifold m;
    REQUIRE(collideBoxBox(cube, slab, m));
    CHECK(near(m.normal, Vec3(0, -1, 0)));  // from the cube (A) down into the slab (B)
    CHECK(samePoints(m, expected));
    for (int i = 0; i < m.pointCount; ++i) {
        CHECK_THAT(m.points[i].depth, WithinAbs(d, kExact));
        // A's bottom face and B's top face overlap equally: A's face is the reference.
        CHECK(featureKind(m.points[i].featureId) == BoxContactKind::FaceOfA);
    }

    SECTION("with the roles swapped the normal flips and the points stay") {
        ContactManifold swapped;
        REQUIRE(collideBoxBox(slab, cube, swapped));
        CHECK(near(swapped.normal, Vec3(0, 1, 0)));
        CHECK(samePoints(swapped, expected));
        for (int i = 0; i < swapped.pointCount; ++i) CHECK_THAT(swapped.points[i].depth, WithinAbs(d, kExact));
    }
}

TEST_CASE("Edge-edge: two crossed boxes meet at one point between their edges", "[sat]") {
    // Depth d = 3 cm. A's edge is the line (0.1, √2 − d − √2/2, z), z ∈ [−0.55, 0.45];
    // B's is (x, √2/2, 0), x ∈ [−1, 1]. Their closest points are (0.1, √2/2 − d, 0)
    // and (0.1, √2/2, 0); the contact point is midway. The best face axis
    // overlaps by 0.34 m (B's (0,−1,1)/√2), far more than d.
    const Real d = 0.03;
    ContactManifold m;
    REQUIRE(collideBoxBox(crossedUpper(d), crossedLower(), m));
    CHECK(near(m.normal, Vec3(0, -1, 0)));  // z × x = y, signed from A (above) to B (below)
    REQUIRE(m.pointCount == 1);
    CHECK(near(m.points[0].position, Vec3(0.1, kSqrt2 / 2 - d / 2, 0)));
    CHECK_THAT(m.points[0].depth, WithinAbs(d, kExact));
    // A's lowest edge runs along its z axis (axis 2) at −x, −y (bits clear): edge 8.
    // B's highest edge runs along its x axis (axis 0) at +y (bit 0), −z (bit 1 clear): edge 1.
    CHECK(m.points[0].featureId == edgeFeatureId(8, 1));

    SECTION("with the roles swapped") {
        ContactManifold swapped;
        REQUIRE(collideBoxBox(crossedLower(), crossedUpper(d), swapped));
        CHECK(near(swapped.normal, Vec3(0, 1, 0)));
        REQUIRE(swapped.pointCount == 1);
        CHECK(near(swapped.points[0].position, Vec3(0.1, kSqrt2 / 2 - d / 2, 0)));
        CHECK_THAT(swapped.points[0].depth, WithinAbs(d, kExact));
        CHECK(swapped.points[0].featureId == edgeFeatureId(1, 8));
    }
}

TEST_CASE("Vertex-face: a cube balanced on its corner touches at that corner only", "[sat]") {
    // Turn the cube so its body diagonal (1,1,1)/√3 points up: about the axis
    // (1,1,1) × y ∝ (−1, 0, 1) by acos(1/√3). Corner 0, (−½,−½,−½), then hangs
    // √3/2 straight below the centre.
    const Quat onCorner = glm::angleAxis(std::acos(1 / kSqrt3), glm::normalize(Vec3(-1, 0, 1)));
    const Real d = 0.01;
    const Vec3 centre(0.2, 0.5 + kSqrt3 / 2 - d, 0.1);
    const Geometry cube = box(centre, Vec3(0.5), onCorner);
    REQUIRE(near(cornerOf(orientedBoxOf(cube), 0), Vec3(0.2, 0.5 - d, 0.1)));  // the set-up is right

    ContactManifold m;
    REQUIRE(collideBoxBox(cube, box(Vec3(0), Vec3(2, 0.5, 2)), m));
    CHECK(near(m.normal, Vec3(0, -1, 0)));  // the slab's face normal, from the cube to the slab
    REQUIRE(m.pointCount == 1);
    // The corner's neighbours are 1/√3 = 0.58 m higher: only the corner is below the face.
    CHECK(near(m.points[0].position, Vec3(0.2, 0.5 - d / 2, 0.1)));
    CHECK_THAT(m.points[0].depth, WithinAbs(d, kExact));
    CHECK(featureKind(m.points[0].featureId) == BoxContactKind::FaceOfB);  // the slab's top is the reference
}

TEST_CASE("Face axes win near-ties: a resting box keeps A's face as reference", "[sat]") {
    // Equal cubes stacked flush: A's −y face, B's +y face and the edge axes
    // aₓ × b_z = −y and a_z × bₓ = y all overlap by exactly d. The bias keeps A's face.
    // A is 0.3 µm off to the side, less than the 1 µm touch tolerance.
    const Real d = 0.001;
    const Real off = 3e-7;
    ContactManifold m;
    REQUIRE(collideBoxBox(box(Vec3(off, 1 - d, off), Vec3(0.5)), box(Vec3(0), Vec3(0.5)), m));
    REQUIRE(m.pointCount == 4);
    for (int i = 0; i < 4; ++i) {
        CHECK(featureKind(m.points[i].featureId) == BoxContactKind::FaceOfA);
        CHECK_THAT(m.points[i].depth, WithinAbs(d, kExact));
    }
    // B's top corners, each just outside or on A's side planes: kept whole as
    // incident corners rather than cut 0.3 µm inwards (which, with round-off,
    // would make the points and their ids change from step to step).
    CHECK(samePoints(m, {Vec3(0.5, 0.5 - d / 2, 0.5), Vec3(-0.5, 0.5 - d / 2, 0.5), Vec3(0.5, 0.5 - d / 2, -0.5),
                         Vec3(-0.5, 0.5 - d / 2, -0.5)}));
}

TEST_CASE("Nearly equal faces: A's face stays the reference", "[sat]") {
    // Equal unit cubes, A on top turned α = 2° about z, its lowest edge d = 1 mm
    // into B. Along B's y: overlap d. Along A's tilted y: |t·a_y| = y_A cos α
    // instead of y_A, so the overlap is d + y_A(1 − cos α) = d + 0.6 mm.
    // B's face is better by only 0.6 mm, less than the bias (5 % of 1.6 mm
    // plus 1 % of 0.5 m = 5 mm): A's bottom face is the reference, and the
    // normal is A's −y axis, (sin α, −cos α, 0). Without the bias the choice
    // would be B's face, or the edge axis a_z × bₓ = y that ties with it exactly.
    const Real alpha = glm::radians(Real(2));
    const Real d = 0.001;
    const Real yA = 0.5 - d + 0.5 * (std::sin(alpha) + std::cos(alpha));  // lowest corner at 0.5 − d
    ContactManifold m;
    REQUIRE(collideBoxBox(box(Vec3(0, yA, 0), Vec3(0.5), glm::angleAxis(alpha, Vec3(0, 0, 1))),
                          box(Vec3(0), Vec3(0.5)), m));
    CHECK(near(m.normal, Vec3(std::sin(alpha), -std::cos(alpha), 0)));
    // Only B's top along A's low (−x) edge is inside A: B's top edge corners
    // are cut off by A's −x side plane −aₓ·(p − c_A) = ½, which crosses y = ½ at
    // x = (−½ − (½ − y_A) sin α)/cos α. There the surface is d/cos α below A's
    // tilted bottom (d above the low edge, along A's side face); the points sit
    // midway, half that along the normal.
    const Real depth = d / std::cos(alpha);
    const Real x = (-0.5 - (0.5 - yA) * std::sin(alpha)) / std::cos(alpha) + 0.5 * depth * std::sin(alpha);
    const Real y = 0.5 - 0.5 * depth * std::cos(alpha);
    CHECK(samePoints(m, {Vec3(x, y, 0.5), Vec3(x, y, -0.5)}));
    for (int i = 0; i < m.pointCount; ++i) {
        CHECK(featureKind(m.points[i].featureId) == BoxContactKind::FaceOfA);
        CHECK_THAT(m.points[i].depth, WithinAbs(depth, kExact));
    }
}

TEST_CASE("Closest points of two segments", "[sat]") {
    // Crossing skew segments: x axis at y = 0 and a z-parallel segment at (0.3, 1, z).
    SegmentClosestPoints c = closestPointsOfSegments(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 1, -1), Vec3(0.3, 1, 1));
    CHECK(near(c.onFirst, Vec3(0.3, 0, 0)));
    CHECK(near(c.onSecond, Vec3(0.3, 1, 0)));
    CHECK_THAT(c.s, WithinAbs(0.65, kExact));
    CHECK_THAT(c.t, WithinAbs(0.5, kExact));
    // The second segment starts past the first one's end: both ends are clamped.
    c = closestPointsOfSegments(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 1, 0.5), Vec3(2, 1, 3));
    CHECK(near(c.onFirst, Vec3(1, 0, 0)));
    CHECK(near(c.onSecond, Vec3(2, 1, 0.5)));
    // Parallel segments: s = 0, and the second's nearest point to the first's start.
    c = closestPointsOfSegments(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(2, 1, 0));
    CHECK(near(c.onFirst, Vec3(0.5, 0, 0)));  // clamped t = 0 → s recomputed for (0.5, 1, 0)
    CHECK(near(c.onSecond, Vec3(0.5, 1, 0)));
}

TEST_CASE("collideBoxBoxWithin() reports boxes up to its reach apart, with depth minus the gap", "[sat][narrowphase]") {
    // The cube of the test above, 0.2 m over the slab's top: collideBoxBox() (1 cm) finds nothing,
    // a reach of 0.3 m finds the four corners of the bottom face with depth −0.2 m, 0.1 m nothing.
    const Geometry slab = box(Vec3(0), Vec3(2, 0.5, 2));
    const Geometry cube = box(Vec3(0.2, 1.2, -0.1), Vec3(0.5));
    ContactManifold m;
    CHECK_FALSE(collideBoxBox(cube, slab, m));
    CHECK_FALSE(collideBoxBoxWithin(cube, slab, Real(0.1), m));
    REQUIRE(collideBoxBoxWithin(cube, slab, Real(0.3), m));
    CHECK(near(m.normal, Vec3(0, -1, 0)));
    REQUIRE(m.pointCount == 4);
    for (int i = 0; i < m.pointCount; ++i) {
        CHECK_THAT(m.points[i].depth, WithinAbs(-0.2, kExact));
        // Midway between the corner (y = 0.7) and the slab's face (y = 0.5)
        CHECK_THAT(m.points[i].position.y, WithinAbs(0.6, kExact));
    }
}

/// How deep the deepest corner of box @p a lies inside box @p b, m (0 when none is inside): a corner
/// at b's local coordinates x is inside by min_k (e_k − |x_k|), its distance to b's nearest face.
Real deepestCornerInside(const DynamicObject& a, const DynamicObject& b) {
    Real deepest = 0;
    const Vec3 ea = a.halfExtents(), eb = b.halfExtents();
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 local((corner & 1) ? ea.x : -ea.x, (corner & 2) ? ea.y : -ea.y, (corner & 4) ? ea.z : -ea.z);
        const Vec3 inB = glm::conjugate(b.orientation) * (a.position + a.orientation * local - b.position);
        const Vec3 room = eb - glm::abs(inB);
        deepest = std::max(deepest, std::min({room.x, room.y, room.z}));
    }
    return deepest;
}

TEST_CASE("A box falling fast onto a resting box stops on it", "[sat][narrowphase]") {
    // A 0.6 m cube thrown down at 15 m/s onto a 1 m cube resting on the floor. At 1/60 s it moves
    // 0.25 m a step: less than its half-thickness, so the continuous stage (continuous.hpp) leaves
    // it to the contacts, and a contact found only 1 cm ahead would come a step late, with the
    // cube's corners up to 0.25 m inside the other. Found as far ahead as the two can close, the
    // contact stops it at the other's face: no corner of either more than 1 cm inside the other
    // over the impact and the half second after it.
    const Scene scene = parseScene(
        "World, TimeStep=1/60, Gravity=(0, -9.81, 0), Sleep=false\n"
        "CollisionPlane, Name=floor, Position=(0, 0, 0), Normal=(0, 1, 0)\n"
        "DynamicObject, Name=bottom, Shape=Box, Position=(0, 0.5, 0), Scale=(1, 1, 1), Mass=1, Elasticity=0\n"
        "DynamicObject, Name=top, Shape=Box, Position=(0.1, 3.0, 0), Scale=(0.6, 0.6, 0.6), Mass=1, Elasticity=0,"
        " Velocity=(0, -15, 0)\n",
        "falling_box.scene");
    World world(scene);
    Real worst = 0;
    Real slowest = 15;  // the top cube's downward speed must drop: it hit something
    for (int step = 0; step < 36; ++step) {
        world.step();
        const DynamicObject& bottom = world.dynamics()[0];
        const DynamicObject& top = world.dynamics()[1];
        worst = std::max({worst, deepestCornerInside(top, bottom), deepestCornerInside(bottom, top)});
        slowest = std::min(slowest, -top.velocity.y);
    }
    CHECK(worst < 0.01);
    CHECK(slowest < 1);
}
