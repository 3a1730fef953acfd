// Contact manifolds of boxes: how many points, where, how deep, and their feature ids.
// Every expected value is worked out from the geometry in the comment above it.
// Tags: [contacts].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "collision/box_features.hpp"
#include "collision/clip_polygon.hpp"
#include "collision/narrowphase.hpp"
#include "test_support.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;

namespace {

const Real kSqrt3 = std::sqrt(Real(3));
const Quat kIdentity(1, 0, 0, 0);
constexpr Real kExact = 1e-12;  // a few dozen operations of round-off

Geometry box(Vec3 centre, Vec3 halfExtents, Quat orientation = kIdentity) {
    return test::boxGeometry(centre, halfExtents, orientation);
}

Geometry sphere(Vec3 centre, Real radius) { return test::sphereGeometry(centre, radius); }

/// The floor y = 0, facing up.
Geometry floorPlane() {
    Geometry g;
    g.type = GeometryType::Plane;
    g.centre = Vec3(0);
    g.normal = Vec3(0, 1, 0);
    return g;
}

bool near(const Vec3& x, const Vec3& y, Real tolerance = kExact) { return glm::length(x - y) < tolerance; }

/// True when the manifold's points are exactly @p expected, in any order.
bool samePoints(const ContactManifold& m, const std::vector<Vec3>& expected) {
    if (m.pointCount != static_cast<int>(expected.size())) return false;
    for (const Vec3& e : expected) {
        if (std::none_of(m.points, m.points + m.pointCount, [&](const ContactPoint& p) { return near(p.position, e); }))
            return false;
    }
    return true;
}

std::vector<std::uint32_t> sortedIds(const ContactManifold& m) {
    std::vector<std::uint32_t> ids;
    for (int i = 0; i < m.pointCount; ++i) ids.push_back(m.points[i].featureId);
    std::sort(ids.begin(), ids.end());
    return ids;
}

void checkDepths(const ContactManifold& m, Real depth) {
    for (int i = 0; i < m.pointCount; ++i) CHECK_THAT(m.points[i].depth, WithinAbs(depth, kExact));
}

/// Incoming and outgoing polygon-edge labels of a face contact id (box_features.hpp).
int inEdgeOf(std::uint32_t id) { return static_cast<int>((id >> 6) & 7u); }
int outEdgeOf(std::uint32_t id) { return static_cast<int>((id >> 9) & 7u); }

}  // namespace

TEST_CASE("A box lying flat on a plane touches at its 4 bottom corners", "[contacts]") {
    // Half extents (0.5, 0.25, 1), sunk d = 1 cm: the bottom corners are at
    // (1 ± 0.5, −d, −2 ± 1); each point lies midway, at y = −d/2.
    const Real d = 0.01;
    ContactManifold m;
    REQUIRE(collideBoxPlane(box(Vec3(1, 0.25 - d, -2), Vec3(0.5, 0.25, 1)), floorPlane(), m));
    CHECK(near(m.normal, Vec3(0, -1, 0)));  // from the box towards the plane
    CHECK(samePoints(m, {Vec3(0.5, -d / 2, -3), Vec3(1.5, -d / 2, -3), Vec3(0.5, -d / 2, -1),
                         Vec3(1.5, -d / 2, -1)}));
    checkDepths(m, d);
    // The bottom corners are those with the y bit (bit 1) clear: 0, 1, 4, 5.
    CHECK(sortedIds(m) == std::vector<std::uint32_t>{0, 1, 4, 5});
}

TEST_CASE("A tilted box on a plane touches only at the corners below it", "[contacts]") {
    ContactManifold m;
    SECTION("on an edge: 2 points") {
        // A unit cube turned 30° about z. Corner (−½, −½, ±½) goes to
        // x = −½cos30° + ½sin30° = (1 − √3)/4, y = −½sin30° − ½cos30° = −(1 + √3)/4,
        // the lowest; the next, (½, −½, ±½), is at y = (1 − √3)/4, 0.5 m higher.
        const Real d = 0.005;
        const Real lowest = (1 + kSqrt3) / 4;
        REQUIRE(collideBoxPlane(box(Vec3(0, lowest - d, 0), Vec3(0.5), glm::angleAxis(kPi / 6, Vec3(0, 0, 1))),
                                floorPlane(), m));
        const Real x = (1 - kSqrt3) / 4;
        CHECK(samePoints(m, {Vec3(x, -d / 2, -0.5), Vec3(x, -d / 2, 0.5)}));
        checkDepths(m, d);
        CHECK(sortedIds(m) == std::vector<std::uint32_t>{0, 4});  // x and y bits clear
    }
    SECTION("on a corner: 1 point") {
        // Body diagonal turned to vertical (see test_sat.cpp): corner 0 hangs √3/2 below the centre.
        const Quat onCorner = glm::angleAxis(std::acos(1 / kSqrt3), glm::normalize(Vec3(-1, 0, 1)));
        const Real d = 0.02;
        REQUIRE(collideBoxPlane(box(Vec3(0.4, kSqrt3 / 2 - d, 0.7), Vec3(0.5), onCorner), floorPlane(), m));
        CHECK(samePoints(m, {Vec3(0.4, -d / 2, 0.7)}));
        checkDepths(m, d);
        CHECK(m.points[0].featureId == 0);
    }
    SECTION("1 mm above: 4 speculative points with depth -1 mm; beyond kSpeculativeDistance: none") {
        REQUIRE(collideBoxPlane(box(Vec3(0, 0.501, 0), Vec3(0.5)), floorPlane(), m));
        REQUIRE(m.pointCount == 4);
        checkDepths(m, -0.001);
        CHECK_FALSE(collideBoxPlane(box(Vec3(0, 0.5 + kSpeculativeDistance + 1e-4, 0), Vec3(0.5)), floorPlane(), m));
    }
}

TEST_CASE("A box sunk past its centre keeps its 4 deepest corners", "[contacts]") {
    // Cube turned 30° about z as above, centre 0.3 m below the floor. Its
    // corners' heights are −0.3 ± (1+√3)/4 and −0.3 ± (√3−1)/4, i.e. −0.98
    // (corners 0, 4), −0.48 (1, 5), −0.12 (2, 6) and +0.38 (3, 7): six are
    // below, and the 4 deepest are 0, 1, 4, 5.
    ContactManifold m;
    REQUIRE(collideBoxPlane(box(Vec3(0, -0.3, 0), Vec3(0.5), glm::angleAxis(kPi / 6, Vec3(0, 0, 1))), floorPlane(),
                            m));
    CHECK(m.pointCount == kMaxManifoldPoints);
    CHECK(sortedIds(m) == std::vector<std::uint32_t>{0, 1, 4, 5});
    for (int i = 0; i < m.pointCount; ++i) {
        const Real expected = m.points[i].featureId == 0 || m.points[i].featureId == 4 ? 0.3 + (1 + kSqrt3) / 4
                                                                                        : 0.3 + (kSqrt3 - 1) / 4;
        CHECK_THAT(m.points[i].depth, WithinAbs(expected, kExact));
    }
}

TEST_CASE("A box lying flat on a larger box touches at its 4 corners", "[contacts]") {
    // A: half extents (0.5, 0.25, 0.5) at (0.3, 0.75 − d, 0.2); B: slab with top y = 0.5.
    const Real d = 0.004;
    ContactManifold m;
    REQUIRE(collideBoxBox(box(Vec3(0.3, 0.75 - d, 0.2), Vec3(0.5, 0.25, 0.5)), box(Vec3(0), Vec3(2, 0.5, 2)), m));
    CHECK(near(m.normal, Vec3(0, -1, 0)));
    const Real y = 0.5 - d / 2;
    CHECK(samePoints(m, {Vec3(-0.2, y, -0.3), Vec3(0.8, y, -0.3), Vec3(-0.2, y, 0.7), Vec3(0.8, y, 0.7)}));
    checkDepths(m, d);
}

TEST_CASE("A small box on a larger one turned 45 degrees: clipping keeps the small box's corners", "[contacts]") {
    // B (2 × ½ × 2 half extents) turned 45° about y: its top is a square
    // standing on a corner, |x| + |z| ≤ 2√2. A unit cube at the origin fits
    // well inside, so its footprint corners (±½, ±½) are the contacts.
    const Real d = 0.01;
    const Real y = 0.5 - d / 2;
    const std::vector<Vec3> corners = {Vec3(0.5, y, 0.5), Vec3(-0.5, y, 0.5), Vec3(0.5, y, -0.5), Vec3(-0.5, y, -0.5)};
    const Geometry small = box(Vec3(0, 1 - d, 0), Vec3(0.5));
    const Geometry turnedSlab = box(Vec3(0), Vec3(2, 0.5, 2), glm::angleAxis(kPi / 4, Vec3(0, 1, 0)));
    ContactManifold m;

    SECTION("small box is A: its own face is the reference; B's face is cut down to it") {
        REQUIRE(collideBoxBox(small, turnedSlab, m));
        CHECK(near(m.normal, Vec3(0, -1, 0)));
        CHECK(samePoints(m, corners));
        checkDepths(m, d);
        // Every point is a corner of the reference face: made by two side planes (labels 4–7).
        for (int i = 0; i < m.pointCount; ++i) {
            CHECK(featureKind(m.points[i].featureId) == BoxContactKind::FaceOfA);
            CHECK(inEdgeOf(m.points[i].featureId) >= 4);
            CHECK(outEdgeOf(m.points[i].featureId) >= 4);
        }
    }
    SECTION("large box is A: its face is the reference; the small face is inside it whole") {
        REQUIRE(collideBoxBox(turnedSlab, small, m));
        CHECK(near(m.normal, Vec3(0, 1, 0)));
        CHECK(samePoints(m, corners));
        checkDepths(m, d);
        // Every point is a corner of the incident face: two incident edges (labels 0–3).
        for (int i = 0; i < m.pointCount; ++i) {
            CHECK(inEdgeOf(m.points[i].featureId) < 4);
            CHECK(outEdgeOf(m.points[i].featureId) < 4);
        }
    }
}

TEST_CASE("A box hanging half over an edge touches only over its support", "[contacts]") {
    // Unit cube A at x ∈ [0.5, 1.5], z ∈ [−0.25, 0.75]; support B's top is
    // x, z ∈ [−1, 1]. The overlap of the two squares is x ∈ [0.5, 1],
    // z ∈ [−0.25, 0.75]: its corners are the contacts, at y = 0.5 − d/2.
    const Real d = 0.002;
    const Real y = 0.5 - d / 2;
    const std::vector<Vec3> expected = {Vec3(0.5, y, -0.25), Vec3(0.5, y, 0.75), Vec3(1, y, -0.25),
                                        Vec3(1, y, 0.75)};
    const Geometry hanging = box(Vec3(1, 1 - d, 0.25), Vec3(0.5));
    const Geometry support = box(Vec3(0), Vec3(1, 0.5, 1));
    ContactManifold m;
    SECTION("hanging box is A") {
        REQUIRE(collideBoxBox(hanging, support, m));
        CHECK(near(m.normal, Vec3(0, -1, 0)));
        CHECK(samePoints(m, expected));
        checkDepths(m, d);
    }
    SECTION("support is A") {
        REQUIRE(collideBoxBox(support, hanging, m));
        CHECK(near(m.normal, Vec3(0, 1, 0)));
        CHECK(samePoints(m, expected));
        checkDepths(m, d);
    }
}

TEST_CASE("Clipping can leave 8 points and the manifold keeps 4 spread out", "[contacts]") {
    // A unit cube (B) turned 45° about y on an equal cube (A) that is not
    // turned. A's top square |x|, |z| ≤ ½ (the reference) cuts B's bottom, the
    // diamond |x| + |z| ≤ √2/2, into a regular octagon: its 8 corners lie on a
    // square side and a diamond side at once, at radius r with
    // r² = ½² + (√2/2 − ½)² = 1 − √2/2. All are at depth d. The 4 kept are
    // every other corner (the deepest — all tie, the first — then the one
    // opposite, then one on each side): a square of area 2r² = 2 − √2, the
    // most any 4 of the corners can span.
    const Real d = 0.01;
    ContactManifold m;
    REQUIRE(collideBoxBox(box(Vec3(0), Vec3(0.5)),
                          box(Vec3(0, 1 - d, 0), Vec3(0.5), glm::angleAxis(kPi / 4, Vec3(0, 1, 0))), m));
    CHECK(near(m.normal, Vec3(0, 1, 0)));
    REQUIRE(m.pointCount == 4);
    checkDepths(m, d);
    std::vector<Vec3> ring;
    for (int i = 0; i < 4; ++i) {
        const Vec3 p = m.points[i].position;
        CHECK_THAT(p.y, WithinAbs(0.5 - d / 2, kExact));
        CHECK_THAT(std::max(std::abs(p.x), std::abs(p.z)), WithinAbs(0.5, kExact));           // on a square side
        CHECK_THAT(std::abs(p.x) + std::abs(p.z), WithinAbs(std::sqrt(0.5), kExact));          // on a diamond side
        ring.push_back(p);
    }
    // Area of the kept quadrilateral (shoelace, corners sorted by angle about y).
    std::sort(ring.begin(), ring.end(),
              [](const Vec3& a, const Vec3& b) { return std::atan2(a.z, a.x) < std::atan2(b.z, b.x); });
    Real area = 0;
    for (int i = 0; i < 4; ++i) area += ring[i].x * ring[(i + 1) % 4].z - ring[(i + 1) % 4].x * ring[i].z;
    CHECK_THAT(std::abs(area) / 2, WithinAbs(2 - std::sqrt(2.0), kExact));
}

TEST_CASE("Feature ids stay the same when the scene moves by 1 mm", "[contacts]") {
    const Real mm = 0.001;
    const std::vector<Vec3> anyWay = {Vec3(mm, 0, 0), Vec3(0, 0, -mm), Vec3(0, -mm, 0), Vec3(-mm, mm / 2, mm)};
    auto check = [&](auto collide, const Geometry& a, const Geometry& b, const std::vector<Vec3>& shifts) {
        ContactManifold before;
        REQUIRE(collide(a, b, before));
        for (const Vec3& shift : shifts) {
            Geometry moved = a;
            moved.centre += shift;
            ContactManifold after;
            REQUIRE(collide(moved, b, after));
            CHECK(after.pointCount == before.pointCount);
            CHECK(sortedIds(after) == sortedIds(before));
            // And the ids in one manifold are all different.
            const std::vector<std::uint32_t> ids = sortedIds(after);
            CHECK(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
        }
    };
    const Real d = 0.01;
    SECTION("box on a turned box") {
        check(collideBoxBox, box(Vec3(0, 1 - d, 0), Vec3(0.5)),
              box(Vec3(0), Vec3(2, 0.5, 2), glm::angleAxis(kPi / 4, Vec3(0, 1, 0))), anyWay);
    }
    SECTION("box half over an edge") {
        check(collideBoxBox, box(Vec3(1, 1 - d, 0.25), Vec3(0.5)), box(Vec3(0), Vec3(1, 0.5, 1)), anyWay);
    }
    SECTION("equal boxes stacked flush, moved up and down") {
        // Sideways, a flush edge would start to overhang: a real change of features.
        check(collideBoxBox, box(Vec3(0, 1 - d, 0), Vec3(0.5)), box(Vec3(0), Vec3(0.5)),
              {Vec3(0, -mm, 0), Vec3(0, mm, 0)});
    }
    SECTION("box flat on the floor") {
        check(collideBoxPlane, box(Vec3(0, 0.5 - d, 0), Vec3(0.5)), floorPlane(), anyWay);
    }
    SECTION("crossed edges") {
        check(collideBoxBox,
              box(Vec3(0.1, std::sqrt(2.0) - 0.03, -0.05), Vec3(0.5), glm::angleAxis(kPi / 4, Vec3(0, 0, 1))),
              box(Vec3(0), Vec3(1, 0.5, 0.5), glm::angleAxis(kPi / 4, Vec3(1, 0, 0))), anyWay);
    }
}

TEST_CASE("A dynamic box against a sphere goes through the table with the normal flipped", "[contacts]") {
    // Sphere of radius ¼ at (0.1, 0.7, 0) over a unit cube at the origin:
    // closest box point (0.1, 0.5, 0), distance 0.2, depth 0.05.
    const PairTest test = pairTestFor(GeometryType::Box, GeometryType::Sphere);
    REQUIRE(test != nullptr);
    const Geometry cube = box(Vec3(0), Vec3(0.5));
    const Geometry ball = sphere(Vec3(0.1, 0.7, 0), 0.25);
    ContactManifold boxFirst;
    REQUIRE(test(cube, ball, boxFirst));
    CHECK(near(boxFirst.normal, Vec3(0, 1, 0)));  // from the box (A) up to the sphere (B)
    REQUIRE(boxFirst.pointCount == 1);
    CHECK_THAT(boxFirst.points[0].depth, WithinAbs(0.05, kExact));

    // The same pair the other way round: opposite normal, same point and depth.
    ContactManifold sphereFirst;
    REQUIRE(pairTestFor(GeometryType::Sphere, GeometryType::Box)(ball, cube, sphereFirst));
    CHECK(near(sphereFirst.normal, -boxFirst.normal));
    CHECK(near(sphereFirst.points[0].position, boxFirst.points[0].position));
    CHECK_THAT(sphereFirst.points[0].depth, WithinAbs(boxFirst.points[0].depth, kExact));

    ContactManifold none;
    CHECK_FALSE(test(cube, sphere(Vec3(0.1, 0.76, 0), 0.25), none));  // 1 cm above
}

TEST_CASE("Every pair with a dynamic box has a test, and findContacts uses it", "[contacts]") {
    CHECK(pairTestFor(GeometryType::Box, GeometryType::Box) == &collideBoxBox);
    CHECK(pairTestFor(GeometryType::Box, GeometryType::Plane) == &collideBoxPlane);
    CHECK(pairTestFor(GeometryType::Box, GeometryType::Sphere) == &collideBoxSphere);

    // Two dynamic boxes stacked flush with 1 cm overlap, the lower one on the floor.
    std::vector<DynamicObject> dynamics(2);
    for (DynamicObject& body : dynamics) {
        body.shape = Shape::Box;
        body.scale = Vec3(1);
    }
    dynamics[0].position = Vec3(0, 0.5, 0);
    dynamics[1].position = Vec3(0, 1.49, 0);
    std::vector<KinematicsObject> kinematics;
    std::vector<CollisionPlane> planes = {test::ground()};
    const BodySet bodies{dynamics, kinematics, planes};
    const std::vector<CandidatePair> pairs = {{0, {BodyKind::Dynamic, 1}}, {0, {BodyKind::Plane, 0}}};
    std::vector<Contact> contacts;
    findContacts(bodies, pairs, contacts);
    REQUIRE(contacts.size() == 8);  // 4 between the boxes, 4 on the floor
    for (int i = 0; i < 4; ++i) {
        CHECK(contacts[i].b.kind == BodyKind::Dynamic);
        CHECK(near(contacts[i].normal, Vec3(0, 1, 0)));  // from the lower box (A) up to the upper
        CHECK_THAT(contacts[i].depth, WithinAbs(0.01, kExact));
        CHECK(contacts[4 + i].b.kind == BodyKind::Plane);
        CHECK(near(contacts[4 + i].normal, Vec3(0, -1, 0)));
        CHECK_THAT(contacts[4 + i].depth, WithinAbs(0, kExact));
    }
}

TEST_CASE("One Sutherland-Hodgman pass names each new vertex by its edge and the plane", "[contacts]") {
    // The square [0, 2]² (edges labelled 0–3) cut by the plane x ≤ 1 (label 7).
    ClipVertex square[4];
    const Vec3 corners[4] = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0)};
    for (int m = 0; m < 4; ++m) {
        square[m].position = corners[m];
        square[m].inEdge = static_cast<std::uint8_t>((m + 3) % 4);
        square[m].outEdge = static_cast<std::uint8_t>(m);
    }
    ClipVertex out[kMaxClipVertices];
    const int count = clipPolygon(square, 4, Vec3(1, 0, 0), 1, 7, 0, out);
    REQUIRE(count == 4);
    // Walking 3→0→1→2→3: keep (0,0); cross edge 0 at (1,0) going out; cross edge 2 at (1,2) coming in; keep (0,2).
    CHECK(near(out[0].position, Vec3(0, 0, 0)));
    CHECK((out[0].inEdge == 3 && out[0].outEdge == 0));
    CHECK(near(out[1].position, Vec3(1, 0, 0)));
    CHECK((out[1].inEdge == 0 && out[1].outEdge == 7));
    CHECK(near(out[2].position, Vec3(1, 2, 0)));
    CHECK((out[2].inEdge == 7 && out[2].outEdge == 2));
    CHECK(near(out[3].position, Vec3(0, 2, 0)));
    CHECK((out[3].inEdge == 2 && out[3].outEdge == 3));
}
