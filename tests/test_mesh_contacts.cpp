/// @file test_mesh_contacts.cpp
/// @brief Convex shapes against triangle meshes: the hierarchy's query, the pair tests, the
/// active-edge rule, and bodies rolling and sliding across many triangles as on a plane.
/// Tags: [mesh] (all), [narrowphase] (the pair tests).
///
/// Every expected value is worked out here from the geometry or from the mechanics of a
/// body on a plane (a ball rolls at constant speed, or at 5/7·g·sinθ down a slope; a box
/// slides to rest at μ·g); none is copied from the engine's output.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <vector>

#include "collision/mesh_contacts.hpp"
#include "config/scene_loader.hpp"
#include "expectation_runner.hpp"
#include "mesh_fixtures.hpp"
#include "collision/mesh_query.hpp"
#include "objects/inertia.hpp"
#include "objects/triangle_mesh.hpp"
#include "shape_fixtures.hpp"
#include "test_support.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// Closest points and clipping are a few products and sums: round-off only.
constexpr Real kRoundOff = 1e-9;

/// A flat grid of n × n square cells of side @p cell in the plane y = 0, from the origin
/// towards +x and +z (test::heightGrid(), mesh_fixtures.hpp): 2n² triangles.
TriangleMesh flatGrid(std::uint32_t n, Real cell) {
    return test::heightGrid(n, cell, 0, 0, [](Real, Real) { return Real(0); });
}

Geometry meshGeometry(const TriangleMesh& mesh, Vec3 centre = Vec3(0), Quat orientation = Quat(1, 0, 0, 0)) {
    Geometry g;
    g.type = GeometryType::Mesh;
    g.centre = centre;
    g.orientation = orientation;
    g.mesh = &mesh;
    return g;
}

Geometry capsuleGeometry(Vec3 centre, Quat orientation, Real radius, Real halfHeight) {
    Geometry g;
    g.type = GeometryType::Capsule;
    g.centre = centre;
    g.orientation = orientation;
    g.radius = radius;
    g.halfHeight = halfHeight;
    return g;
}

/// Every contact point of @p found, with its manifold's normal.
struct FoundPoint {
    Vec3 normal;
    ContactPoint point;
};
std::vector<FoundPoint> pointsOf(const MeshContacts& found) {
    std::vector<FoundPoint> points;
    for (int m = 0; m < found.count; ++m) {
        for (int i = 0; i < found.manifolds[m].pointCount; ++i) points.push_back({found.manifolds[m].normal, found.manifolds[m].points[i]});
    }
    return points;
}

/// The triangles of @p mesh whose boxes overlap @p box (mesh frame), one by one: what the query must find.
std::set<std::uint32_t> bruteForce(const TriangleMesh& mesh, const Aabb& box) {
    std::set<std::uint32_t> found;
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        Aabb own{Vec3(1e30), Vec3(-1e30)};
        for (const std::uint32_t v : mesh.triangles[t]) {
            own.min = glm::min(own.min, mesh.vertices[v]);
            own.max = glm::max(own.max, mesh.vertices[v]);
        }
        if (own.overlaps(box)) found.insert(t);
    }
    return found;
}

/// The query's answer, each triangle counted: a triangle found twice fails the test.
std::multiset<std::uint32_t> queried(const TriangleMesh& mesh, const Aabb& box) {
    std::multiset<std::uint32_t> found;
    std::uint32_t t = 0;
    for (TrianglesInBox query(mesh, box); query.next(t);) found.insert(t);
    return found;
}

std::set<std::uint32_t> asSet(const std::multiset<std::uint32_t>& m) { return {m.begin(), m.end()}; }

/// A kinematic object of @p mesh at @p position turned by @p orientation.
KinematicsObject meshObject(std::shared_ptr<const TriangleMesh> mesh, Vec3 position = Vec3(0),
                            Quat orientation = Quat(1, 0, 0, 0)) {
    KinematicsObject k;
    k.name = "floor";
    k.shape = Shape::Mesh;
    k.mesh = std::move(mesh);
    k.position = position;
    k.orientation = orientation;
    k.friction = 1;  // friction combines by product: the body's own value is the one that acts
    return k;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The query

TEST_CASE("Mesh query: the hierarchy finds exactly the triangles whose boxes overlap, each once", "[mesh]") {
    const TriangleMesh mesh = flatGrid(10, 1);  // 200 triangles, cells of 1 m
    // Inside cell (2, 3): its two triangles only. Over a corner where 4 cells meet: 8 triangles.
    // Across the whole grid: all 200. Beside it: none.
    const Aabb inCell{Vec3(2.3, -0.1, 3.3), Vec3(2.6, 0.1, 3.6)};
    const Aabb overCorner{Vec3(4.9, -0.1, 4.9), Vec3(5.1, 0.1, 5.1)};
    const Aabb everything{Vec3(-1, -1, -1), Vec3(11, 1, 11)};
    const Aabb beside{Vec3(12, -1, 0), Vec3(13, 1, 1)};
    CHECK(queried(mesh, inCell).size() == 2);
    CHECK(queried(mesh, overCorner).size() == 8);
    CHECK(queried(mesh, everything).size() == 200);
    CHECK(queried(mesh, beside).empty());
    for (const Aabb& box : {inCell, overCorner, everything, beside}) {
        const std::multiset<std::uint32_t> found = queried(mesh, box);
        CHECK(asSet(found).size() == found.size());  // none twice
        CHECK(asSet(found) == bruteForce(mesh, box));
    }
    // A small box visits a few nodes on the way down, not the 2·50 − 1 = 99 nodes of the tree
    // (50 leaves of at most kMeshLeafSize = 4 triangles): at most two paths of about log₂ 50 ≈ 6.
    TrianglesInBox query(mesh, inCell);
    std::uint32_t t = 0;
    while (query.next(t)) {
    }
    CHECK(query.nodesVisited() < 30);
}

TEST_CASE("Mesh query: a moved and turned mesh is searched in its own frame", "[mesh]") {
    const TriangleMesh mesh = flatGrid(10, 1);
    // The mesh turned by 90° about y and moved: its cell (2, 3) (x 2–3, z 3–4 in its frame) is
    // then at world x = t.x + z, z = t.z − x. A world box over that cell's middle must find it.
    const Vec3 t(5, 1, -2);
    const Quat turn = glm::angleAxis(Real(kPi / 2), Vec3(0, 1, 0));
    const Vec3 cellMiddle = t + turn * Vec3(2.5, 0, 3.5);
    const Aabb world{cellMiddle - Vec3(0.1), cellMiddle + Vec3(0.1)};
    const Aabb local = meshFrameBox(world, t, turn);
    // A quarter turn maps axes onto axes: the box in the mesh frame is exact.
    CHECK(glm::length(local.centre() - Vec3(2.5, 0, 3.5)) < kRoundOff);
    CHECK(glm::length((local.max - local.min) - Vec3(0.2)) < kRoundOff);
    CHECK(queried(mesh, local).size() == 2);
    // Turned by 45° the box is held by one √2 times as wide (|Rᵀ|·e), never a smaller one.
    const Quat eighth = glm::angleAxis(Real(kPi / 4), Vec3(0, 1, 0));
    const Aabb wide = meshFrameBox(world, t, eighth);
    CHECK_THAT(double(wide.max.x - wide.min.x), WithinAbs(0.2 * std::sqrt(2.0), kRoundOff));
    CHECK_THAT(double(wide.max.y - wide.min.y), WithinAbs(0.2, kRoundOff));
}

TEST_CASE("Mesh query: a hierarchy deeper than its stack still yields every triangle once", "[mesh]") {
    // A chain: each inner node has a leaf of one triangle and another inner node below it,
    // 100 levels deep, beyond kMeshQueryStack = 64. Triangle k lies in cell k of a strip.
    constexpr std::uint32_t kCount = 100;
    auto mesh = std::make_shared<TriangleMesh>();
    for (std::uint32_t k = 0; k < kCount; ++k) {
        const auto base = static_cast<std::uint32_t>(mesh->vertices.size());
        const Real x = Real(k);
        mesh->vertices.insert(mesh->vertices.end(), {{x, 0, 0}, {x, 0, 1}, {x + 1, 0, 0}});
        mesh->triangles.push_back({base, base + 1, base + 2});
        mesh->order.push_back(k);
        mesh->activeEdges.push_back({true, true, true});
    }
    // Node 2k is inner (children 2k + 1: leaf of triangle k, 2k + 2: the rest); the last node is a leaf.
    for (std::uint32_t k = 0; k + 1 < kCount; ++k) {
        mesh->nodes.push_back(MeshNode{Vec3(Real(k), 0, 0), Vec3(Real(kCount), 0, 1), 2 * k + 1, 0});
        mesh->nodes.push_back(MeshNode{Vec3(Real(k), 0, 0), Vec3(Real(k + 1), 0, 1), k, 1});
    }
    mesh->nodes.push_back(MeshNode{Vec3(Real(kCount - 1), 0, 0), Vec3(Real(kCount), 0, 1), kCount - 1, 1});
    const Aabb all{Vec3(-1), Vec3(Real(kCount) + 1, 1, 2)};
    const std::multiset<std::uint32_t> found = queried(*mesh, all);
    CHECK(found.size() == kCount);
    CHECK(asSet(found).size() == kCount);
    // Only the far end: triangles 89.5 < x: 89 (x 89–90) to 99.
    const Aabb farEnd{Vec3(89.5, -1, 0), Vec3(200, 1, 1)};
    CHECK(asSet(queried(*mesh, farEnd)) == bruteForce(*mesh, farEnd));
    CHECK(queried(*mesh, farEnd).size() == 11);
}

// ---------------------------------------------------------------------------------------------
// The pair tests

TEST_CASE("A sphere resting on one triangle: the depth is its radius less its height, the normal the face's", "[mesh][narrowphase]") {
    // One triangle in the plane through (0, 0, 0), (4, 0, 0), (0, 3, 4): normal (a × b)/|a × b| with
    // a = (4, 0, 0), b = (0, 3, 4): (0, −16, 12)/20 = (0, −0.8, 0.6). Corners wound so it faces there.
    const std::vector<Vec3> corners = {{0, 0, 0}, {4, 0, 0}, {0, 3, 4}};
    const TriangleMesh mesh = buildTriangleMesh(corners, {{0, 1, 2}});
    const Vec3 faceNormal(0, -0.8, 0.6);
    const Vec3 foot = (corners[0] + corners[1] + corners[2]) / Real(3);  // inside: the face region
    const Real r = 0.5, height = 0.45;
    const Geometry ball = test::sphereGeometry(foot + height * faceNormal, r);
    MeshContacts found;
    REQUIRE(meshContacts(ball, meshGeometry(mesh), kSpeculativeDistance, found));
    REQUIRE(found.count == 1);
    REQUIRE(found.manifolds[0].pointCount == 1);
    CHECK(glm::length(found.manifolds[0].normal + faceNormal) < kRoundOff);  // from the ball towards the triangle
    CHECK_THAT(double(found.manifolds[0].points[0].depth), WithinAbs(r - height, kRoundOff));
    // Midway through the overlap: between the ball's lowest point (height − r) and the face (0).
    const Vec3 expected = foot + Real(0.5) * (height - r) * faceNormal;
    CHECK(glm::length(found.manifolds[0].points[0].position - expected) < kRoundOff);

    // The same mesh moved by t and turned by R: everything moves with it.
    const Vec3 t(1, 2, 3);
    const Quat turn = glm::angleAxis(Real(0.7), glm::normalize(Vec3(1, 2, -1)));
    const Geometry movedBall = test::sphereGeometry(t + turn * ball.centre, r);
    REQUIRE(meshContacts(movedBall, meshGeometry(mesh, t, turn), kSpeculativeDistance, found));
    REQUIRE(found.count == 1);
    CHECK(glm::length(found.manifolds[0].normal + turn * faceNormal) < kRoundOff);
    CHECK_THAT(double(found.manifolds[0].points[0].depth), WithinAbs(r - height, kRoundOff));
    CHECK(glm::length(found.manifolds[0].points[0].position - (t + turn * expected)) < kRoundOff);

    // Behind the triangle (the centre on its back side) it is not touched: a mesh is one-sided.
    CHECK_FALSE(meshContacts(test::sphereGeometry(foot - Real(0.2) * faceNormal, r), meshGeometry(mesh),
                             kSpeculativeDistance, found));
    // 2 cm above (beyond kSpeculativeDistance = 1 cm): nothing; 5 mm above: a speculative point.
    CHECK_FALSE(meshContacts(test::sphereGeometry(foot + Real(r + 0.02) * faceNormal, r), meshGeometry(mesh),
                             kSpeculativeDistance, found));
    REQUIRE(meshContacts(test::sphereGeometry(foot + Real(r + 0.005) * faceNormal, r), meshGeometry(mesh),
                         kSpeculativeDistance, found));
    CHECK_THAT(double(found.manifolds[0].points[0].depth), WithinAbs(-0.005, kRoundOff));
}

TEST_CASE("A box on a two-triangle square gives its 4 bottom corners under one normal", "[mesh][narrowphase]") {
    // The square's diagonal runs under the box: each triangle holds two of its corners (and
    // the points where the diagonal crosses the box's edges), gathered into one manifold of 4.
    const auto square = test::squareMesh(1);
    const Real half = 0.25, sunk = 0.01;
    const Geometry box = test::boxGeometry(Vec3(0.1, half - sunk, -0.05), Vec3(half));
    for (const GeometryType type : {GeometryType::Box, GeometryType::Hull}) {
        Geometry a = box;
        const auto cube = test::cubeHull(Vec3(half));
        if (type == GeometryType::Hull) {
            a.type = GeometryType::Hull;
            a.hull = cube.get();
        }
        INFO((type == GeometryType::Box ? "box" : "hull cube"));
        MeshContacts found;
        REQUIRE(meshContacts(a, meshGeometry(*square), kSpeculativeDistance, found));
        REQUIRE(found.count == 1);
        const ContactManifold& m = found.manifolds[0];
        CHECK(glm::length(m.normal - Vec3(0, -1, 0)) < kRoundOff);
        REQUIRE(m.pointCount == 4);
        std::set<std::uint32_t> ids;
        for (int i = 0; i < m.pointCount; ++i) {
            const Vec3 p = m.points[i].position;
            CHECK_THAT(double(m.points[i].depth), WithinAbs(sunk, kRoundOff));
            CHECK_THAT(double(std::abs(p.x - 0.1)), WithinAbs(half, kRoundOff));     // a corner: ±half from the centre
            CHECK_THAT(double(std::abs(p.z + 0.05)), WithinAbs(half, kRoundOff));
            CHECK_THAT(double(p.y), WithinAbs(-sunk / 2, kRoundOff));                 // midway through the overlap
            ids.insert(m.points[i].featureId);
        }
        CHECK(ids.size() == 4);  // each point its own id: warm starting tells them apart
    }
}

TEST_CASE("A capsule lying across or beside an inner edge is pushed straight up, never sideways", "[mesh][narrowphase]") {
    // test::squareMesh: the diagonal from (−1, 0, −1) to (1, 0, 1) is shared by its two triangles
    // and flat, so inactive. Tested alone, the triangle a shape does not lie over sees it beside
    // its edge and would push it sideways (the file comment of mesh_contacts.hpp); the rule must
    // turn every such push to the face normal (0, 1, 0), so the normal from A is exactly (0, −1, 0).
    const auto square = test::squareMesh(1);
    const Real r = 0.1, sunk = 0.002;
    const Quat alongX = glm::angleAxis(Real(-kPi / 2), Vec3(0, 0, 1));          // local y → world x
    const Quat parallel = glm::angleAxis(Real(-kPi / 4), Vec3(0, 1, 0)) * alongX;  // x → (1, 0, 1)/√2, the diagonal
    struct Case {
        const char* what;
        Geometry capsule;
        int expectedPoints;
    };
    const Case cases[] = {
        // Across the diagonal (along x at z = 0.1): the parts over each triangle are clipped, the
        // crossing point met from both sides is one point: the two ends and the crossing.
        {"across", capsuleGeometry(Vec3(0.1, r - sunk, 0.1 + 0.05), alongX, r, 0.3), 3},
        // Beside it, parallel, 3 cm from it over the x > z triangle: the other triangle's closest
        // points are on the diagonal, √(0.03² + 0.098²) = 0.1025 m from the axis, within reach.
        {"beside", capsuleGeometry(Vec3(0.2, r - sunk, 0.2) + Real(0.03) * glm::normalize(Vec3(1, 0, -1)), parallel, r, 0.3), 2},
    };
    for (const Case& c : cases) {
        INFO(c.what);
        MeshContacts found;
        REQUIRE(meshContacts(c.capsule, meshGeometry(*square), kSpeculativeDistance, found));
        const std::vector<FoundPoint> points = pointsOf(found);
        CHECK(found.count == 1);
        CHECK(static_cast<int>(points.size()) == c.expectedPoints);
        for (const FoundPoint& p : points) {
            CHECK(p.normal.x == 0);  // exactly: no sideways part at all
            CHECK(p.normal.z == 0);
            CHECK_THAT(double(p.normal.y), WithinAbs(-1, kRoundOff));
            CHECK_THAT(double(p.point.depth), WithinAbs(sunk, kRoundOff));
        }
    }
    // A ball beside the diagonal likewise: one point, straight under its centre.
    const Vec3 centre = Vec3(0.3, 0.2 - 0.001, 0.3) + Real(0.03) * glm::normalize(Vec3(-1, 0, 1));
    MeshContacts found;
    REQUIRE(meshContacts(test::sphereGeometry(centre, 0.2), meshGeometry(*square), kSpeculativeDistance, found));
    const std::vector<FoundPoint> points = pointsOf(found);
    REQUIRE(points.size() == 1);
    CHECK(glm::length(points[0].normal - Vec3(0, -1, 0)) < kRoundOff);
    CHECK(glm::length(points[0].point.position - Vec3(centre.x, -0.0005, centre.z)) < kRoundOff);
}

TEST_CASE("A ball over the mesh's border edge, which is active, is pushed outwards from it", "[mesh][narrowphase]") {
    // test::squareMesh(1) ends at x = 1, an edge no triangle shares: active. A ball of radius
    // 0.5 centred at (1.3, 0.1, 0) is nearest to (1, 0, 0) on it, at d = (0.3, 0.1, 0),
    // |d| = √0.1: the push on the ball is along d/|d|, up and outwards, the depth 0.5 − √0.1.
    const auto square = test::squareMesh(1);
    const Vec3 centre(1.3, 0.1, 0);
    MeshContacts found;
    REQUIRE(meshContacts(test::sphereGeometry(centre, 0.5), meshGeometry(*square), kSpeculativeDistance, found));
    const std::vector<FoundPoint> points = pointsOf(found);
    REQUIRE(points.size() == 1);
    const Vec3 d(0.3, 0.1, 0);
    CHECK(glm::length(points[0].normal + d / glm::length(d)) < kRoundOff);
    CHECK_THAT(double(points[0].point.depth), WithinAbs(0.5 - std::sqrt(0.1), kRoundOff));
    // A box hanging half over that edge is held by its part over the square: face points, pushed up.
    const Geometry box = test::boxGeometry(Vec3(1, 0.25 - 0.01, 0), Vec3(0.25));
    REQUIRE(meshContacts(box, meshGeometry(*square), kSpeculativeDistance, found));
    for (const FoundPoint& p : pointsOf(found)) {
        CHECK(glm::length(p.normal - Vec3(0, -1, 0)) < kRoundOff);
        CHECK(p.point.position.x <= 1 + kRoundOff);  // only what lies over the square
    }
}

TEST_CASE("The dispatch table's Mesh column holds a test for every convex shape", "[mesh][narrowphase]") {
    const auto square = test::squareMesh(1);
    const GeometryType convex[] = {GeometryType::Sphere, GeometryType::Box, GeometryType::Capsule, GeometryType::Cylinder,
                                   GeometryType::Hull};
    const auto cube = test::cubeHull(Vec3(Real(0.25)));
    for (const GeometryType type : convex) {
        REQUIRE(pairTestFor(type, GeometryType::Mesh) != nullptr);
        // Each shape, its lowest point 1 mm into the square (a capsule and a cylinder standing
        // upright: half height 0.25 plus radius 0.25, or half height 0.25), touches it with normal −y.
        Geometry a = test::boxGeometry(Vec3(0.2, 0, 0.1), Vec3(0.25));
        a.type = type;
        a.radius = 0.25;
        a.halfHeight = 0.25;
        a.hull = cube.get();
        const Real lowest = type == GeometryType::Capsule ? Real(0.5) : Real(0.25);
        a.centre.y = lowest - Real(0.001);
        ContactManifold m;
        INFO("shape " << int(type));
        REQUIRE(pairTestFor(type, GeometryType::Mesh)(a, meshGeometry(*square), m));
        CHECK(glm::length(m.normal - Vec3(0, -1, 0)) < kRoundOff);
        for (int i = 0; i < m.pointCount; ++i) CHECK_THAT(double(m.points[i].depth), WithinAbs(0.001, 1e-6));
    }
    CHECK(pairTestFor(GeometryType::Mesh, GeometryType::Sphere) == nullptr);  // a mesh is never A
}

// ---------------------------------------------------------------------------------------------
// Motion across many triangles, against the plane's analytic answers

TEST_CASE("A ball rolling across a flat mesh of 200 triangles keeps its speed, as on a plane", "[mesh]") {
    // On a plane a ball rolling without slipping keeps its speed: gravity and the normal force
    // cancel, and the friction force is zero (the contact point is at rest). Over 3 s it crosses
    // about 15 edges and diagonals of the 1 m cells; a snag at any of them would show as a
    // change of speed (0.5 % allowed) or a hop (vertical speed above 1 mm/s).
    const Real r = 0.25, speed = 2;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.kinematics.push_back(meshObject(std::make_shared<const TriangleMesh>(flatGrid(10, 1))));
    const Vec3 direction = glm::normalize(Vec3(1, 0, 0.3));
    const Vec3 v = speed * direction;
    DynamicObject ball = test::sphere("ball", Vec3(1, r, 2), v, r, 1, 0, 0.5);
    ball.angularVelocity = glm::cross(Vec3(0, 1, 0), v) / r;  // rolling: v + ω × (−r·y) = 0
    scene.dynamics.push_back(ball);
    World world(scene);
    Real worstVertical = 0, worstSpeedChange = 0;
    while (world.time() < 3 - 1e-9) {
        world.step();
        const DynamicObject& b = world.dynamics()[0];
        worstVertical = std::max(worstVertical, std::abs(b.velocity.y));
        worstSpeedChange = std::max(worstSpeedChange, std::abs(glm::length(b.velocity) - speed) / speed);
    }
    const DynamicObject& b = world.dynamics()[0];
    INFO("travelled to " << b.position.x << ", " << b.position.z << "; worst speed change " << worstSpeedChange
                         << ", worst vertical speed " << worstVertical << " m/s");
    CHECK(b.position.x > 6.5);  // it did cross the grid: 1 + 3 s · 2 m/s · 0.958 = 6.75
    CHECK(worstSpeedChange < 0.005);
    CHECK(worstVertical < 0.001);
    CHECK_THAT(double(b.position.y), WithinAbs(r, 0.001));
}

TEST_CASE("A box sliding across a flat mesh of 200 triangles slows at mu g, as on a plane", "[mesh]") {
    // A box sliding on a plane: the normal force is m·g, friction μ·m·g against the motion,
    // so the speed falls at μ·g until it stops (the box neither tips nor turns).
    const Real mu = 0.3, v0 = 3;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.kinematics.push_back(meshObject(std::make_shared<const TriangleMesh>(flatGrid(10, 1))));
    DynamicObject box = test::dynamicBox("box", Vec3(1.3, 0.25, 2.4), Vec3(0.5), 1, mu);
    box.velocity = Vec3(v0, 0, 0.5);
    scene.dynamics.push_back(box);
    World world(scene);
    // Settle for a few steps: the first contact's push-out is not sliding friction.
    const Real start = 0.1, end = 0.7;  // it stops at v/(μg) ≈ 1.03 s
    while (world.time() < start - 1e-9) world.step();
    const Real speedStart = glm::length(world.dynamics()[0].velocity);
    while (world.time() < end - 1e-9) world.step();
    const Real speedEnd = glm::length(world.dynamics()[0].velocity);
    const Real deceleration = (speedStart - speedEnd) / (end - start);
    INFO("speed " << speedStart << " → " << speedEnd << " m/s at " << world.dynamics()[0].position.x);
    CHECK_THAT(double(deceleration), WithinRel(double(mu * kStandardGravity), 0.01));
}

TEST_CASE("A ball rolls down a 20 degree mesh ramp at 5/7 g sin(theta), across its triangles' edges", "[mesh]") {
    // Rolling without slipping on an incline: m·a = m·g·sinθ − F, I·α = F·r, a = α·r, I = ⅖·m·r²,
    // so a = g·sinθ / (1 + ⅖) = 5/7·g·sinθ (the lesson-7 result on a plane). The ramp is a flat
    // grid of 0.5 m cells (20 × 8 cells, 320 triangles) on a kinematic object turned by 20°
    // about z, so the query also works in a turned frame. Each 0.5 s window, with several edge
    // and diagonal crossings in it, must show that acceleration to 1 %.
    const Real theta = 20 * kPi / 180, r = 0.2;
    const Quat tilt = glm::angleAxis(-theta, Vec3(0, 0, 1));  // +x of the grid turns down the slope
    const Vec3 up = tilt * Vec3(0, 1, 0);
    const Vec3 down = tilt * Vec3(1, 0, 0);
    std::vector<Vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    {
        const TriangleMesh grid = flatGrid(20, Real(0.5));  // 10 m × 10 m
        vertices = grid.vertices;
        triangles = grid.triangles;
    }
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.kinematics.push_back(meshObject(std::make_shared<const TriangleMesh>(buildTriangleMesh(vertices, triangles)),
                                          Vec3(0), tilt));
    // Start touching, over the grid point (0.5, 0, 2.3) of the mesh frame: off the cells' lines.
    scene.dynamics.push_back(test::sphere("ball", tilt * Vec3(0.5, 0, 2.3) + r * up, Vec3(0), r, 1, 0, 0.5));
    World world(scene);
    const Real expected = Real(5) / 7 * kStandardGravity * std::sin(theta);
    Real previousSpeed = 0, previousTime = 0;
    for (const Real until : {Real(0.5), Real(1), Real(1.5), Real(2)}) {
        Real worstLift = 0;
        while (world.time() < until - 1e-9) {
            world.step();
            worstLift = std::max(worstLift, std::abs(glm::dot(world.dynamics()[0].velocity, up)));
        }
        const Real speed = glm::dot(world.dynamics()[0].velocity, down);
        INFO("window to " << until << " s: down the slope " << speed << " m/s, off it " << worstLift << " m/s");
        CHECK_THAT(double((speed - previousSpeed) / (world.time() - previousTime)), WithinRel(double(expected), 0.01));
        CHECK(worstLift < 0.01);
        previousSpeed = speed;
        previousTime = world.time();
    }
    CHECK(glm::dot(world.dynamics()[0].position, down) > 4);  // 5/7·g·sin20°·(2 s)²/2 = 4.8 m: many cells
}

TEST_CASE("The mesh ramp scene passes its Expect records: 5/7 g sin20 on an OBJ ramp", "[mesh]") {
    // config/mesh_ramp.scene: a ball on the 32 triangles of config/models/ramp.obj, its
    // speed expected at a·t (a = 5/7·g·sin20° = 2.3966 m/s²) at 0.75 s and 1.5 s, each within 1 %.
    const Scene scene = loadSceneFile(STEPWISE_SOURCE_DIR "/config/mesh_ramp.scene");
    REQUIRE(scene.expectations.size() == 2);
    const Real a = Real(5) / 7 * kStandardGravity * std::sin(Real(20) * kPi / 180);
    CHECK_THAT(double(scene.expectations[0].target), WithinRel(double(a * 0.75), 1e-4));  // the file's numbers are a·t
    CHECK_THAT(double(scene.expectations[1].target), WithinRel(double(a * 1.5), 1e-4));
    const test::ExpectationOutcome outcome = test::runExpectations(scene);
    CHECK(outcome.passed() == 2);
}

TEST_CASE("Fast bodies dropped onto a mesh floor stop on it, as on a plane", "[mesh][ccd]") {
    // The continuous stage sweeps bodies against convex shapes, not against a mesh; a mesh gets
    // what a plane gets instead: contacts looked for as far as the body can move in the step
    // (its sweep), so the solver stops it at the surface. A ball of 0.1 m and a box of 0.2 m
    // thrown down at 40 m/s cross 0.67 m a step, several times their own size: without the full
    // reach they would pass through the 1 mm-thin floor. They must end resting on it (1 cm).
    for (const bool box : {false, true}) {
        Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
        scene.kinematics.push_back(meshObject(std::make_shared<const TriangleMesh>(flatGrid(4, 1))));
        DynamicObject body = box ? test::dynamicBox("box", Vec3(2, 1, 2), Vec3(0.2), 1, 0.5)
                                 : test::sphere("ball", Vec3(2, 1, 2), Vec3(0), 0.1, 1, 0, 0.5);
        body.velocity = Vec3(0, -40, 0);
        initialiseMassProperties(body);
        scene.dynamics.push_back(body);
        World world(scene);
        Real lowest = 1;
        while (world.time() < 2) {
            world.step();
            lowest = std::min(lowest, world.dynamics()[0].position.y);
        }
        INFO((box ? "box" : "ball") << ": lowest centre " << lowest << " m, final " << world.dynamics()[0].position.y);
        CHECK(lowest > 0);
        CHECK_THAT(double(world.dynamics()[0].position.y), WithinAbs(0.1, 0.01));
    }
}
