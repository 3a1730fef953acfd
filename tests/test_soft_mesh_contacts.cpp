/// @file test_soft_mesh_contacts.cpp
/// @brief Soft bodies against triangle meshes (src/soft/node_mesh_contacts.cpp): a node meets a
/// mesh through the mesh's hierarchy and is pushed out once; a soft ball rests on a mesh floor
/// as on a plane, rolls down a mesh ramp as down a tilted plane, stays inside a mesh bowl, and
/// rides a moving mesh. Tags: [soft][mesh].
///
/// The references are the plane, which the soft bodies' tests already check against physics,
/// and the geometry of the mesh itself; no number is copied from the engine's output.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "objects/soft_mesh.hpp"
#include "mesh_fixtures.hpp"
#include "objects/triangle_mesh.hpp"
#include "soft/soft_stages.hpp"
#include "test_support.hpp"
#include "world/world.hpp"

using namespace stepwise;

namespace {

/// Closest points and a clip are a few products and sums: round-off only, m.
constexpr Real kRoundOff = 1e-12;

/// A grid of n × n square cells of side @p cell over y = height(x, z), centred on the origin
/// (test::heightGrid(), mesh_fixtures.hpp): 2n² triangles.
template <class Height>
TriangleMesh grid(std::uint32_t n, Real cell, Height height) {
    const Real half = Real(n) * cell / 2;
    return test::heightGrid(n, cell, -half, -half, height);
}

TriangleMesh flatGrid(std::uint32_t n, Real cell) {
    return grid(n, cell, [](Real, Real) { return Real(0); });
}

/// A kinematic object of @p mesh at @p position turned by @p orientation, with the given materials.
KinematicsObject meshObject(const TriangleMesh& mesh, Real friction, Real elasticity, Vec3 position = Vec3(0),
                            Quat orientation = Quat(1, 0, 0, 0)) {
    KinematicsObject k;
    k.name = "mesh";
    k.shape = Shape::Mesh;
    k.mesh = std::make_shared<const TriangleMesh>(mesh);
    k.position = position;
    k.orientation = orientation;
    k.friction = friction;
    k.elasticity = elasticity;
    return k;
}

/// A plane through @p position along @p normal, with the given materials.
CollisionPlane plane(Real friction, Real elasticity, Vec3 normal = Vec3(0, 1, 0), Vec3 position = Vec3(0)) {
    CollisionPlane p = test::ground();
    p.normal = normal;
    p.position = position;
    p.friction = friction;
    p.elasticity = elasticity;
    return p;
}

/// A soft ball of radius 0.5 m (the gas inflates it to about 0.6 m) and 1 kg, 162 nodes, held up by
/// its gas; its springs' dampers, the bending springs' among them, let it settle in a few seconds.
SoftBody softBall(Vec3 position, Real friction = Real(0.8), Real elasticity = Real(0), Vec3 velocity = Vec3(0)) {
    SoftBodyMaking making;
    making.resolution = 2;
    making.position = position;
    making.velocity = velocity;
    making.radius = Real(0.5);
    making.mass = 1;
    making.stiffness = 60;
    making.damping = Real(0.2);
    making.bendStiffness = 10;
    making.nRT = 60;
    SoftBody body;
    body.name = "ball";
    buildSoftBody(making, body);
    body.friction = friction;
    body.elasticity = elasticity;
    return body;
}

/// Steps of 1/60 s in 8 substeps under standard gravity, holding @p body.
Scene softScene(const SoftBody& body) {
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.settings.substeps = 8;
    scene.softBodies.push_back(body);
    return scene;
}

Geometry nodeAt(Vec3 centre, Real radius) { return test::sphereGeometry(centre, radius); }

Geometry meshGeometry(const TriangleMesh& mesh) {
    Geometry g;
    g.type = GeometryType::Mesh;
    g.mesh = &mesh;
    return g;
}

}  // namespace

TEST_CASE("A node over a shared edge or corner of a flat mesh is pushed out once, by its depth", "[soft][mesh]") {
    // Four cells of 1 m: the node sinks 0.01 m into the floor at a cell's middle (one triangle),
    // on a diagonal (two), on an edge between cells (two) and at a corner where six meet. The
    // floor is y = 0 everywhere, so the overlap is r − y and the push straight up, once.
    const TriangleMesh floor = flatGrid(2, 1);
    const Real r = Real(0.05);
    const Real y = Real(0.04);
    for (const Vec3 at : {Vec3(-0.3, y, -0.6), Vec3(-0.5, y, -0.5), Vec3(0, y, -0.25), Vec3(0, y, 0)}) {
        INFO("node at " << at.x << ", " << at.z);
        ContactManifold found;
        REQUIRE(collideNodeMesh(nodeAt(at, r), meshGeometry(floor), found));
        REQUIRE(found.pointCount == 1);
        CHECK(found.normal.y == Approx(-1).margin(kRoundOff));
        CHECK(found.points[0].depth == Approx(r - y).margin(kRoundOff));
    }
    // Just clear of the floor, and below it (behind every triangle: a mesh pushes towards its front only).
    ContactManifold found;
    CHECK_FALSE(collideNodeMesh(nodeAt(Vec3(0.3, r + Real(1e-6), 0.3), r), meshGeometry(floor), found));
    CHECK_FALSE(collideNodeMesh(nodeAt(Vec3(0.3, -Real(0.01), 0.3), r), meshGeometry(floor), found));
}

TEST_CASE("A node in a concave crease is pushed out of the deeper face only", "[soft][mesh]") {
    // A V-shaped valley along z: two faces at ±45° meeting at x = 0. A node on the valley's
    // floor right of the axis overlaps the right face more than the left; the push is the
    // right face's normal (−1, 1, 0)/√2, by that face's own depth.
    const std::vector<Vec3> vertices{{-1, 1, -1}, {-1, 1, 1}, {0, 0, -1}, {0, 0, 1}, {1, 1, -1}, {1, 1, 1}};
    const TriangleMesh valley = buildTriangleMesh(vertices, {{0, 1, 2}, {2, 1, 3}, {2, 3, 4}, {4, 3, 5}});
    const Real r = Real(0.1);
    const Vec3 centre(0.02, 0.1, 0);
    ContactManifold found;
    REQUIRE(collideNodeMesh(nodeAt(centre, r), meshGeometry(valley), found));
    const Real s = std::sqrt(Real(0.5));
    const Vec3 rightOut(-s, s, 0);  // out of the right face x − y = 0 (towards smaller x, larger y)
    CHECK(glm::length(-found.normal - rightOut) < 1e-9);
    CHECK(found.points[0].depth == Approx(r - glm::dot(centre, rightOut)).margin(kRoundOff));
}

TEST_CASE("A soft ball comes to rest on a flat mesh floor where it rests on a plane", "[soft][mesh]") {
    // The same surface y = 0, the same materials: a plane's sphere test and a mesh's closest point
    // both find the overlap r − y along +y, and a floor that does not move takes no impulse, so
    // the two runs differ by round-off in the depth alone, which the resting ball, a damped
    // system, does not amplify. 1 µm is a millionth of the ball's diameter and a thirtieth of a
    // thousandth of its node radius (about 0.03 m); it holds at every step, not only at rest.
    constexpr Real kSameRest = 1e-6;
    const SoftBody ball = softBall(Vec3(0.1, 1.2, 0.05));
    Scene onPlane = softScene(ball);
    onPlane.planes.push_back(plane(Real(0.8), Real(0.5)));
    Scene onMesh = softScene(ball);
    onMesh.kinematics.push_back(meshObject(flatGrid(8, Real(0.5)), Real(0.8), Real(0.5)));
    World a(std::move(onPlane));
    World b(std::move(onMesh));
    Real lowest = 1;  // the lowest node centre seen on the mesh, m
    Real apart = 0;   // the largest difference in the centre's height, m
    const int settle = 480, average = 120;  // 8 s: the drop, the bounces and the settling; then 2 s
    Real meanHeight = 0, lowestCentre = 1, highestCentre = 0;  // over the last 2 s, m
    for (int i = 0; i < settle + average; ++i) {
        a.step();
        b.step();
        for (const Vec3& x : b.softBodies()[0].nodePositions) lowest = std::min(lowest, x.y);
        apart = std::max(apart, std::abs(b.softBodies()[0].position.y - a.softBodies()[0].position.y));
        if (i + 1 <= settle) continue;
        const Real y = a.softBodies()[0].position.y;
        meanHeight += y / average;
        lowestCentre = std::min(lowestCentre, y);
        highestCentre = std::max(highestCentre, y);
    }
    const SoftBody& pa = a.softBodies()[0];
    const SoftBody& pb = b.softBodies()[0];
    // Settled but for a bob on its gas (about ±2 cm at 2 Hz after 8 s: the dampers act along the
    // springs and hardly touch that mode), and flattened: its centre is below its inflated radius.
    CHECK(highestCentre - lowestCentre < 0.05);
    CHECK(meanHeight < Real(0.57));
    CHECK(apart < kSameRest);
    CHECK(std::abs(pb.volume - pa.volume) < kSameRest * pa.volume);
    // No node centre went through the floor: a node that sinks in a substep is put back at once,
    // so its centre ends every step at least its radius above the floor, less round-off.
    CHECK(lowest >= pb.nodeRadius - kRoundOff);
}

TEST_CASE("A soft ball rolls down a mesh ramp as down a tilted plane", "[soft][mesh]") {
    // A 20° slope of 16 × 16 cells, and a plane with the same normal through the same point.
    // The ball starts just above it and rolls down. The two runs see one surface, so their
    // paths agree to round-off (1 µm, as on the flat floor) after 1 s. And it rolls: a thin shell
    // (I = ⅔·m·r², as the nodes are) rolling without slipping goes ½·(3/5)·g·sin20°·t² = 1.007 m
    // in 1 s, where a free slide would go 1.68 m; within 10 % of the first, as the ball lands,
    // squashes and breathes on its way down.
    const Real angle = glm::radians(Real(20));
    const Quat tilt = glm::angleAxis(angle, Vec3(0, 0, 1));  // the slope falls towards −x
    const Vec3 normal = tilt * Vec3(0, 1, 0);
    const Vec3 downhill = tilt * Vec3(-1, 0, 0);
    const SoftBody ball = softBall(tilt * Vec3(2, 0, 0) + Real(0.6) * normal);  // 0.1 m clear of the slope
    Scene onPlane = softScene(ball);
    onPlane.planes.push_back(plane(Real(0.8), Real(0.3), normal));
    Scene onMesh = softScene(ball);
    onMesh.kinematics.push_back(meshObject(flatGrid(16, Real(0.5)), Real(0.8), Real(0.3), Vec3(0), tilt));
    World a(std::move(onPlane));
    World b(std::move(onMesh));
    const Vec3 start = a.softBodies()[0].position;
    Real lowest = 1;  // lowest node height above the slope, m
    for (int i = 0; i < 60; ++i) {
        a.step();
        b.step();
        for (const Vec3& x : b.softBodies()[0].nodePositions) lowest = std::min(lowest, glm::dot(x, normal));
    }
    const Vec3 pa = a.softBodies()[0].position;
    const Vec3 pb = b.softBodies()[0].position;
    const Real rolled = Real(0.5) * Real(0.6) * kStandardGravity * std::sin(angle);
    CHECK(glm::dot(pa - start, downhill) == Approx(rolled).epsilon(0.1));
    CHECK(glm::length(pb - pa) < 1e-6);
    CHECK(lowest >= b.softBodies()[0].nodeRadius - 1e-9);
}

TEST_CASE("A soft ball dropped into a mesh bowl stays inside it and rolls to and fro across the bottom", "[soft][mesh]") {
    // A bowl y = (x² + z²)/(2·R_b), R_b = 2 m, 3 m across (rim 0.56 m up), of 24 × 24 cells.
    // Dropped off-centre, the ball rolls down, past the bottom and up the other side; with
    // losses in its springs and in its bounces it never rises higher than it started.
    const Real bowlRadius = 2;
    const auto height = [bowlRadius](Real x, Real z) { return (x * x + z * z) / (2 * bowlRadius); };
    const std::uint32_t n = 24;
    const Real cell = Real(0.125);
    const TriangleMesh bowl = grid(n, cell, height);
    Scene scene = softScene(softBall(Vec3(0.5, 1.0, 0)));
    scene.kinematics.push_back(meshObject(bowl, Real(0.8), Real(0.3)));
    World world(std::move(scene));
    const Real startHeight = world.softBodies()[0].position.y;
    const Real half = Real(n) * cell / 2;
    Real mostLeft = 0, mostRight = 0, highest = 0, clearance = 1;
    for (int i = 0; i < 240; ++i) {  // 4 s, more than a swing there and back (2π·√(1.4·1.5 m/g) = 2.9 s)
        world.step();
        const SoftBody& b = world.softBodies()[0];
        mostLeft = std::min(mostLeft, b.position.x);
        mostRight = std::max(mostRight, b.position.x);
        if (i > 30) highest = std::max(highest, b.position.y);  // after the first landing
        for (const Vec3& x : b.nodePositions) {
            if (std::abs(x.x) > half || std::abs(x.z) > half) continue;  // beyond the mesh
            // A node on the mesh has its centre its radius from the triangle it rests on, and at
            // least that far above it vertically (more on a slope); the triangles are chords of
            // the convex paraboloid, so they lie on or above it.
            clearance = std::min(clearance, x.y - height(x.x, x.z));
        }
    }
    const SoftBody& b = world.softBodies()[0];
    CHECK(mostLeft < -0.1);                        // it rolled past the bottom and up the other side
    CHECK(mostRight <= Real(0.5) + Real(1e-3));  // never pushed out towards the rim it came from
    CHECK(highest < startHeight);                  // no energy gained
    CHECK(std::abs(b.position.x) < half - Real(0.5));  // inside the bowl
    // 0.1 mm: what a node in a crease may keep of its overlap with the shallower face until the next substep
    CHECK(clearance >= b.nodeRadius - Real(1e-4));
}

TEST_CASE("A soft ball on a rising mesh platform rides up with it", "[soft][mesh]") {
    // The platform rises at 0.5 m/s and the ball starts with the same upward velocity: in the
    // platform's frame that is the ball dropped on a still floor, but for one thing: a kinematic
    // body moves once a step, 8.3 mm, and the nodes in h/8 substeps, so the floor comes up in
    // jumps under them. Averaged over the last 2 s of 10 (the bob on the gas left then, ±1 cm at
    // 2 Hz, averages out over four bobs), the ball rests on it at the still ball's height within
    // 5 mm, a jump's worth, and its centre rises at the platform's speed within 2 %, measured from
    // its mean height in each of the two seconds. (Not from its velocity: the floor's jumps push
    // the nodes out by a projection, which moves them without changing their velocity.)
    const Real rise = Real(0.5);
    Scene still = softScene(softBall(Vec3(0, 0.7, 0)));
    still.kinematics.push_back(meshObject(flatGrid(8, Real(0.5)), Real(0.8), Real(0.3)));
    Scene moving = softScene(softBall(Vec3(0, 0.7, 0), Real(0.8), Real(0), Vec3(0, rise, 0)));
    moving.kinematics.push_back(meshObject(flatGrid(8, Real(0.5)), Real(0.8), Real(0.3)));
    moving.kinematics[0].velocity = Vec3(0, rise, 0);
    World a(std::move(still));
    World b(std::move(moving));
    const int settle = 480, average = 120;  // 8 s to settle, then 2 s averaged
    Real heightOnStill = 0, heightOnMoving = 0, firstSecond = 0, secondSecond = 0;
    for (int i = 0; i < settle + average; ++i) {
        a.step();
        b.step();
        if (i + 1 <= settle) continue;
        heightOnStill += a.softBodies()[0].position.y / average;
        heightOnMoving += (b.softBodies()[0].position.y - b.kinematics()[0].position.y) / average;
        (i + 1 <= settle + average / 2 ? firstSecond : secondSecond) += b.softBodies()[0].position.y / (average / 2);
    }
    const Real meanSpeed = (secondSecond - firstSecond) / (Real(average / 2) / 60);
    CHECK(b.kinematics()[0].position.y == Approx(rise * 10).epsilon(1e-9));
    CHECK(meanSpeed == Approx(rise).epsilon(0.02));
    CHECK(std::abs(heightOnMoving - heightOnStill) < 5e-3);
}
