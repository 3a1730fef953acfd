/// @file test_mass_properties.cpp
/// @brief Lecture 12's mass properties against closed forms: capsules, cylinders, hulls by the
/// divergence theorem, compounds by the parallel-axis theorem, principal axes by Jacobi.
/// Tags: [inertia]; [hull] for the hulls qhull builds (faces, loops, edges).
///
/// Every expected value is a textbook formula evaluated here, never a number the engine
/// printed. Tolerances: 1e-12 relative where only round-off separates the two sides (a few
/// hundred products of numbers of order 1); where the engine approximates (a prism for a
/// cylinder) the bound is the approximation's own error term, stated at the test.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "config/scene_loader.hpp"
#include "objects/convex_hull.hpp"
#include "objects/inertia.hpp"
#include "objects/mass_properties.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// Round-off only: the two sides are the same sum computed in a different order.
constexpr double kRoundOff = 1e-12;

/// The corners of the box [lo, hi].
std::vector<Vec3> boxCorners(const Vec3& lo, const Vec3& hi) {
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i) {
        corners.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    }
    return corners;
}

/// Element (row, column) of a GLM matrix (GLM stores columns).
Real at(const Mat3& m, int row, int column) { return m[column][row]; }

void checkMatrix(const Mat3& actual, const Mat3& expected, double tolerance) {
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            INFO("element (" << r << ", " << c << ")");
            CHECK_THAT(at(actual, r, c), WithinAbs(at(expected, r, c), tolerance));
        }
    }
}

/// The three moments in increasing order: principal axes come in no particular order.
std::vector<Real> sorted(const Vec3& v) {
    std::vector<Real> s{v.x, v.y, v.z};
    std::sort(s.begin(), s.end());
    return s;
}

void checkSameMoments(const Vec3& actual, const Vec3& expected, double relative) {
    const std::vector<Real> a = sorted(actual);
    const std::vector<Real> e = sorted(expected);
    for (std::size_t i = 0; i < 3; ++i) CHECK_THAT(a[i], WithinRel(e[i], relative));
}

/// The one DynamicObject of @p text, with its mass properties initialised as a World does.
DynamicObject loadedBody(const std::string& text) {
    Scene scene = parseScene(text, "test.scene");
    REQUIRE(scene.dynamics.size() == 1);
    DynamicObject body = scene.dynamics.front();
    initialiseMassProperties(body);
    return body;
}

/// A regular N-gon prism of circumradius r and length h along y: the hull that approximates a cylinder.
std::vector<Vec3> prism(int sides, Real radius, Real height) {
    std::vector<Vec3> points;
    for (int k = 0; k < sides; ++k) {
        const Real angle = 2 * kPi * Real(k) / Real(sides);
        for (const Real y : {-height / 2, height / 2}) points.emplace_back(radius * std::cos(angle), y, radius * std::sin(angle));
    }
    return points;
}

}  // namespace

TEST_CASE("A capsule of height 0 is a ball: 2/5 m r^2 about every axis", "[inertia]") {
    const Vec3 capsule = solidCapsuleInertia(3, Real(0.4), 0);
    const Vec3 ball = solidSphereInertia(3, Real(0.4));
    for (int i = 0; i < 3; ++i) CHECK_THAT(capsule[i], WithinRel(ball[i], kRoundOff));
}

TEST_CASE("A capsule's moments: the cylinder and two hemispheres, each 3r/8 off its face", "[inertia]") {
    // r = 1, h = 2, ρ = 1: cylinder m_c = 2π, hemispheres m_h = 2π/3 each (total 10π/3).
    // Axial: ½·2π·1 + 2·⅖·(2π/3)·1 = π + 8π/15 = 23π/15.
    // Transverse: 2π(3 + 4)/12 + 2·(2π/3)·(⅖ − 9/64 + (1 + 3/8)²) = 7π/6 + (4π/3)·(2/5 + 1 + 3/4)
    //           = 7π/6 + (4π/3)(43/20) = 7π/6 + 43π/15 = 121π/30.
    const Real mass = 10 * kPi / 3;
    const Vec3 moments = solidCapsuleInertia(mass, 1, 2);
    CHECK_THAT(moments.y, WithinRel(23 * kPi / 15, kRoundOff));
    CHECK_THAT(moments.x, WithinRel(121 * kPi / 30, kRoundOff));
    CHECK_THAT(moments.z, WithinRel(121 * kPi / 30, kRoundOff));
}

TEST_CASE("A solid cylinder has I_axis = m r^2/2 and I_across = m(3r^2 + h^2)/12", "[inertia]") {
    const Vec3 moments = solidCylinderInertia(12, 1, 2);  // 6 and 12·(3 + 4)/12 = 7
    CHECK_THAT(moments.y, WithinRel(6.0, kRoundOff));
    CHECK_THAT(moments.x, WithinRel(7.0, kRoundOff));
    CHECK_THAT(moments.z, WithinRel(7.0, kRoundOff));
}

TEST_CASE("A hull cube's faces are 6 squares, counter-clockwise from outside, with 12 edges", "[hull]") {
    const ConvexHull hull = buildConvexHull(boxCorners(Vec3(-1), Vec3(1)));
    CHECK(hull.vertices.size() == 8);
    REQUIRE(hull.faces.size() == 6);
    CHECK(hull.edges.size() == 12);
    CHECK_THAT(hull.volume, WithinRel(8.0, kRoundOff));
    CHECK_THAT(hull.boundingRadius, WithinRel(std::sqrt(3.0), kRoundOff));
    for (const HullFace& face : hull.faces) {
        REQUIRE(face.indexCount == 4);
        CHECK_THAT(glm::length(face.normal), WithinAbs(1.0, kRoundOff));
        CHECK_THAT(face.offset, WithinAbs(1.0, kRoundOff));  // each face is 1 from the centre
        // The loop's turn (v1 - v0) x (v2 - v0) points out, along the normal, at every corner.
        for (std::uint32_t k = 0; k < face.indexCount; ++k) {
            const Vec3& a = hull.vertices[hull.faceIndices[face.firstIndex + k]];
            const Vec3& b = hull.vertices[hull.faceIndices[face.firstIndex + (k + 1) % 4]];
            const Vec3& c = hull.vertices[hull.faceIndices[face.firstIndex + (k + 2) % 4]];
            CHECK(glm::dot(glm::cross(b - a, c - a), face.normal) > 0);
            CHECK_THAT(glm::dot(face.normal, a), WithinAbs(face.offset, kRoundOff));
        }
    }
}

TEST_CASE("Points inside a hull are dropped, and only its corners are vertices", "[hull]") {
    std::vector<Vec3> points = boxCorners(Vec3(0), Vec3(2));
    points.emplace_back(1, 1, 1);
    points.emplace_back(Real(0.5), Real(1.5), 1);
    const ConvexHull hull = buildConvexHull(points);
    CHECK(hull.vertices.size() == 8);
    CHECK(hull.faces.size() == 6);
}

TEST_CASE("A hull refuses too few, non-finite, coplanar, collinear and coincident points", "[hull]") {
    const auto problemOf = [](const std::vector<Vec3>& points) {
        try {
            (void)buildConvexHull(points);
        } catch (const HullError& error) {
            return error.problem();
        }
        FAIL("no HullError");
        return HullProblem::Failed;
    };
    CHECK(problemOf({Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0)}) == HullProblem::TooFewPoints);
    CHECK(problemOf({Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, std::nan(""))}) == HullProblem::NotFinite);
    CHECK(problemOf({Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 3, 0)}) == HullProblem::Flat);
    CHECK(problemOf({Vec3(0), Vec3(1), Vec3(2), Vec3(3)}) == HullProblem::Flat);
    CHECK(problemOf({Vec3(1), Vec3(1), Vec3(1), Vec3(1)}) == HullProblem::Flat);
}

TEST_CASE("A hull cube has the box formula's moments", "[inertia][hull]") {
    // The lecture's 1 × 2 × 3 box of 12 kg: (13, 10, 5) kg·m². Its tensor is diagonal, so Jacobi
    // leaves the axes alone: the body keeps its scene orientation.
    const DynamicObject body = loadedBody("DynamicObject, Name=h, Shape=Hull, Mass=12, Position=(1, 2, 3), "
                                          "Vertices=(-0.5, -1, -1.5), (0.5, -1, -1.5), (-0.5, 1, -1.5), (0.5, 1, -1.5), "
                                          "(-0.5, -1, 1.5), (0.5, -1, 1.5), (-0.5, 1, 1.5), (0.5, 1, 1.5)\n");
    const Vec3 box = solidBoxInertia(12, Vec3(1, 2, 3));
    for (int i = 0; i < 3; ++i) CHECK_THAT(body.inertiaBody[i], WithinRel(box[i], kRoundOff));
    CHECK(body.orientation == Quat(1, 0, 0, 0));
    CHECK_THAT(glm::length(body.position - Vec3(1, 2, 3)), WithinAbs(0.0, kRoundOff));
}

TEST_CASE("A regular tetrahedron has I = m a^2/20 about every axis through its centre", "[inertia][hull]") {
    // Alternate corners of the cube [-1, 1]³: edge a = 2√2, so I = m·8/20 = 0.4·m.
    const std::vector<Vec3> corners{Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
    const ConvexHull hull = buildConvexHull(corners);
    CHECK(hull.faces.size() == 4);
    CHECK(hull.edges.size() == 6);
    const PolyhedronMass unit = polyhedronMassProperties(hull);
    CHECK_THAT(unit.volume, WithinRel(8.0 / 3.0, kRoundOff));  // a cube of 8 less four corners of 4/3
    const Real mass = 5;
    const Mat3 tensor = (mass / unit.volume) * unit.inertia;
    checkMatrix(tensor, Mat3(Real(0.4) * mass * Real(8) / Real(8)), kRoundOff * 10);
}

TEST_CASE("A corner tetrahedron's full tensor: 3m(b^2 + c^2)/80 and products m ab/80", "[inertia]") {
    // Corners 0, a·x, b·y, c·z. About the origin ∫x² = V a²/10 and ∫xy = V ab/20 (Tonon 2004);
    // the centroid (a, b, c)/4 moves them to I_xx = 3m(b² + c²)/80, I_xy = +m·ab/80.
    const Real a = 1, b = 2, c = 3;
    const std::vector<Vec3> vertices{Vec3(0), Vec3(a, 0, 0), Vec3(0, b, 0), Vec3(0, 0, c)};
    const std::vector<std::array<std::uint32_t, 3>> triangles{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    const PolyhedronMass unit = polyhedronMassProperties(vertices, triangles);
    CHECK_THAT(unit.volume, WithinRel(a * b * c / 6, kRoundOff));
    CHECK_THAT(glm::length(unit.centroid - Vec3(a, b, c) / Real(4)), WithinAbs(0.0, kRoundOff));
    const Real m = unit.volume;  // density 1
    Mat3 expected(0);
    expected[0][0] = 3 * m * (b * b + c * c) / 80;
    expected[1][1] = 3 * m * (a * a + c * c) / 80;
    expected[2][2] = 3 * m * (a * a + b * b) / 80;
    expected[1][0] = expected[0][1] = m * a * b / 80;
    expected[2][1] = expected[1][2] = m * b * c / 80;
    expected[2][0] = expected[0][2] = m * a * c / 80;
    checkMatrix(unit.inertia, expected, kRoundOff);
}

TEST_CASE("A prism hull converges to the cylinder's closed form as 1/N^2", "[inertia][hull]") {
    // A regular N-gon inscribed in radius r has area (N/2) r² sin(2π/N) and polar moment per area
    // J/A = r²(2 + cos θ)/6 with θ = 2π/N, which is r²/2 less r²(1 - cos θ)/6 ≈ r²θ²/12: the
    // prism's moments per mass differ from the cylinder's by O(θ²). Bound: θ²/6 relative,
    // twice that leading term; and halving θ divides the error by about 4.
    const Real r = Real(0.5), h = 2, m = 3;
    const Vec3 cylinder = solidCylinderInertia(m, r, h);
    const auto relativeError = [&](int sides) {
        const DynamicObject body = [&] {
            DynamicObject b;
            b.shape = Shape::Hull;
            b.setMass(m);
            auto hull = std::make_shared<ConvexHull>(buildConvexHull(prism(sides, r, h)));
            (void)moveToPrincipalFrame(*hull);
            CHECK(hull->faces.size() == std::size_t(sides + 2));  // two N-gon caps, N rectangles
            b.hull = hull;
            return b;
        }();
        const Vec3 moments = shapeInertia(body);
        return std::max(std::abs(moments.y - cylinder.y) / cylinder.y,
                        std::abs(moments.x - cylinder.x) / cylinder.x);
    };
    for (const int sides : {64, 128, 256}) {
        const Real theta = 2 * kPi / Real(sides);
        INFO(sides << " sides");
        CHECK(relativeError(sides) < theta * theta / 6);
    }
    const Real ratio = relativeError(128) / relativeError(256);
    CHECK_THAT(ratio, WithinAbs(4.0, 0.2));
}

TEST_CASE("Principal axes of a rotated box's tensor give back the box's moments", "[inertia]") {
    const Vec3 moments(13, 10, 5);
    const Quat turn = glm::angleAxis(Real(0.7), glm::normalize(Vec3(1, 2, 3)));
    const Mat3 r = glm::mat3_cast(turn);
    Mat3 d(0);
    d[0][0] = moments.x;
    d[1][1] = moments.y;
    d[2][2] = moments.z;
    const Mat3 tensor = r * d * glm::transpose(r);
    const PrincipalAxes axes = principalAxes(tensor);
    checkSameMoments(axes.moments, moments, kRoundOff);
    const Mat3 p = glm::mat3_cast(axes.rotation);
    CHECK_THAT(glm::determinant(p), WithinAbs(1.0, kRoundOff));  // a rotation, not a reflection
    Mat3 found(0);
    found[0][0] = axes.moments.x;
    found[1][1] = axes.moments.y;
    found[2][2] = axes.moments.z;
    checkMatrix(p * found * glm::transpose(p), tensor, 1e-11);  // R diag Rᵀ rebuilds it (values ~13)
}

TEST_CASE("A hull of a rotated box loads with the box's moments and turns with it", "[inertia][hull]") {
    // The 1 × 2 × 3 box of 12 kg, written already turned 30° about z and placed off the origin:
    // the loader finds its centre and axes, and the body's x axis is the box's.
    const Quat turn = glm::angleAxis(glm::radians(Real(30)), Vec3(0, 0, 1));
    std::string vertices;
    for (const Vec3& corner : boxCorners(Vec3(-0.5, -1, -1.5), Vec3(0.5, 1, 1.5))) {
        const Vec3 p = turn * corner + Vec3(4, 5, 6);
        vertices += (vertices.empty() ? "" : ", ") + std::string("(") + std::to_string(p.x) + ", " +
                    std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
    }
    const DynamicObject body = loadedBody("DynamicObject, Shape=Hull, Mass=12, Vertices=" + vertices + "\n");
    // std::to_string keeps 6 decimals: corners are off by up to 5e-7 m, so moments by ~1e-6 relative.
    checkSameMoments(body.inertiaBody, solidBoxInertia(12, Vec3(1, 2, 3)), 1e-5);
    CHECK_THAT(glm::length(body.position - Vec3(4, 5, 6)), WithinAbs(0.0, 1e-6));
    // The principal axis of the smallest moment (5 kg·m², about the 3 m edge) is the box's z.
    const std::vector<Real> order = sorted(body.inertiaBody);
    int smallest = 0;
    for (int i = 0; i < 3; ++i) {
        if (body.inertiaBody[i] == order[0]) smallest = i;
    }
    Vec3 axis(0);
    axis[smallest] = 1;
    CHECK_THAT(std::abs(glm::dot(body.orientation * axis, Vec3(0, 0, 1))), WithinAbs(1.0, 1e-6));
}

TEST_CASE("A hull off its origin: Position becomes its centre of mass, the vertices centred", "[inertia][hull]") {
    const Scene scene = parseScene("DynamicObject, Shape=Hull, Position=(10, 0, 0), Rotation=(0, 0, 90), "
                                   "Vertices=(0, 0, 0), (2, 0, 0), (0, 2, 0), (2, 2, 0), (0, 0, 2), (2, 0, 2), (0, 2, 2), (2, 2, 2)\n",
                                   "test.scene");
    const DynamicObject& body = scene.dynamics.front();
    // The centre (1, 1, 1) in the scene frame, turned 90° about z: (-1, 1, 1), plus the Position.
    CHECK_THAT(glm::length(body.position - Vec3(9, 1, 1)), WithinAbs(0.0, kRoundOff * 10));
    Vec3 centroid(0);
    for (const Vec3& v : body.hull->vertices) centroid += v;
    CHECK_THAT(glm::length(centroid), WithinAbs(0.0, kRoundOff * 10));
    CHECK_THAT(body.hull->boundingRadius, WithinRel(std::sqrt(3.0), kRoundOff));
}

TEST_CASE("Two unit boxes side by side make one 2 x 1 x 1 box", "[inertia][config]") {
    const DynamicObject body = loadedBody("DynamicObject, Name=pair, Shape=Compound, Mass=2, Position=(0, 3, 0)\n"
                                          "Part, Body=pair, Shape=Box, Position=(0, 0, 0)\n"
                                          "Part, Body=pair, Shape=Box, Position=(1, 0, 0)\n");
    const Vec3 box = solidBoxInertia(2, Vec3(2, 1, 1));
    for (int i = 0; i < 3; ++i) CHECK_THAT(body.inertiaBody[i], WithinRel(box[i], kRoundOff));
    CHECK_THAT(glm::length(body.position - Vec3(0.5, 3, 0)), WithinAbs(0.0, kRoundOff));  // the centre of mass
    REQUIRE(body.compound);
    CHECK(body.compound->parts.size() == 2);
    CHECK_THAT(body.compound->parts[0].mass, WithinRel(1.0, kRoundOff));  // Mass shared by volume
    CHECK_THAT(body.compound->boundingRadius, WithinRel(0.5 + std::sqrt(3.0) / 2, kRoundOff));
}

TEST_CASE("A dumbbell: 2 m (L/2)^2 + 2 (2/5) m r^2 across the rod, 2 (2/5) m r^2 along it", "[inertia][config]") {
    // Two balls of m = 3 kg, r = 0.25 m, at the ends of a massless rod of L = 2 m along x.
    const Real m = 3, r = Real(0.25), L = 2;
    const DynamicObject body = loadedBody("DynamicObject, Name=bell, Shape=Compound\n"
                                          "Part, Body=bell, Shape=Sphere, Radius=0.25, Mass=3, Position=(-1, 0, 0)\n"
                                          "Part, Body=bell, Shape=Sphere, Radius=0.25, Mass=3, Position=(1, 0, 0)\n");
    const Real own = 2 * Real(0.4) * m * r * r;
    CHECK_THAT(body.mass, WithinRel(2 * m, kRoundOff));  // the parts' masses add up
    CHECK_THAT(body.inertiaBody.x, WithinRel(own, kRoundOff));
    CHECK_THAT(body.inertiaBody.y, WithinRel(2 * m * (L / 2) * (L / 2) + own, kRoundOff));
    CHECK_THAT(body.inertiaBody.z, WithinRel(2 * m * (L / 2) * (L / 2) + own, kRoundOff));
}

TEST_CASE("A compound of a capsule, a cylinder and a hull part sums each part's own tensor", "[inertia][config]") {
    // Parts at the origin, unturned: the body's tensor is the sum of the closed forms.
    const DynamicObject body = loadedBody(
        "DynamicObject, Name=c, Shape=Compound\n"
        "Part, Body=c, Shape=Capsule, Radius=0.5, Height=1, Mass=2\n"
        "Part, Body=c, Shape=Cylinder, Radius=0.5, Height=2, Mass=3\n"
        "Part, Body=c, Shape=Hull, Mass=12, Vertices=(-0.5, -1, -1.5), (0.5, -1, -1.5), (-0.5, 1, -1.5), "
        "(0.5, 1, -1.5), (-0.5, -1, 1.5), (0.5, -1, 1.5), (-0.5, 1, 1.5), (0.5, 1, 1.5)\n");
    const Vec3 expected = solidCapsuleInertia(2, Real(0.5), 1) + solidCylinderInertia(3, Real(0.5), 2) +
                          solidBoxInertia(12, Vec3(1, 2, 3));
    for (int i = 0; i < 3; ++i) CHECK_THAT(body.inertiaBody[i], WithinRel(expected[i], kRoundOff));
}

TEST_CASE("Capsule and Cylinder bodies take Height and get the closed forms", "[inertia][config]") {
    const DynamicObject capsule = loadedBody("DynamicObject, Shape=Capsule, Radius=0.2, Height=1, Mass=2\n");
    CHECK(capsule.shape == Shape::Capsule);
    CHECK(capsule.height == 1);
    const Vec3 expected = solidCapsuleInertia(2, Real(0.2), 1);
    for (int i = 0; i < 3; ++i) CHECK_THAT(capsule.inertiaBody[i], WithinRel(expected[i], kRoundOff));
    const DynamicObject ball = loadedBody("DynamicObject, Shape=Capsule, Radius=0.2, Height=0, Mass=2\n");
    const Vec3 sphere = solidSphereInertia(2, Real(0.2));
    for (int i = 0; i < 3; ++i) CHECK_THAT(ball.inertiaBody[i], WithinRel(sphere[i], kRoundOff));
    const DynamicObject cylinder = loadedBody("DynamicObject, Shape=Cylinder, Radius=1, Height=2, Mass=12\n");
    CHECK_THAT(cylinder.inertiaBody.y, WithinRel(6.0, kRoundOff));
    CHECK_THAT(cylinder.inertiaBody.x, WithinRel(7.0, kRoundOff));
}
