/// @file test_inertia.cpp
/// @brief Inertia tensors against hand-computed integrals, the parallel-axis
/// theorem, world-frame tensors, impulses at a point, and the Hollow field.
/// Tags: [inertia], and [config] for the scene field.
///
/// Masses and sizes are chosen so that every expected value is a small
/// integer or fraction a student can check on paper. Tolerances are a few
/// ulps scaled by the size of the values (1e-12 on values of order 10–50):
/// the formulas are a handful of products, so only round-off can differ.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "config/scene_loader.hpp"
#include "objects/inertia.hpp"
#include "test_support.hpp"
#include "world/world.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// Round-off bound for the tensors below (values up to ~50 kg·m², a few operations each).
constexpr double kRoundOff = 1e-12;

/// The 1 m × 2 m × 3 m box of the lecture, with the mass that makes its moments integers:
/// I = 12·(2² + 3², 1² + 3², 1² + 2²)/12 = (13, 10, 5) kg·m².
constexpr Real kBoxMass = 12;
const Vec3 kBoxSize(1, 2, 3);
const Vec3 kBoxMoments(13, 10, 5);

Mat3 diagonal(const Vec3& d) {
    Mat3 m(0);
    m[0][0] = d.x;
    m[1][1] = d.y;
    m[2][2] = d.z;
    return m;
}

/// Element (row, column) of a GLM matrix (GLM stores columns: m[column][row]).
Real at(const Mat3& m, int row, int column) { return m[column][row]; }

void checkMatrix(const Mat3& actual, const Mat3& expected, double tolerance) {
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            INFO("element (" << r << ", " << c << ")");
            CHECK_THAT(at(actual, r, c), WithinAbs(at(expected, r, c), tolerance));
        }
    }
}

/// A matrix from its rows, as written on paper.
Mat3 rows(const Vec3& r0, const Vec3& r1, const Vec3& r2) { return glm::transpose(Mat3(r0, r1, r2)); }

DynamicObject box(Real mass, const Vec3& size, const Quat& orientation = Quat(1, 0, 0, 0)) {
    DynamicObject body;
    body.name = "box";
    body.shape = Shape::Box;
    body.scale = size;
    body.orientation = orientation;
    body.setMass(mass);
    initialiseMassProperties(body);
    return body;
}

}  // namespace

// ------------------------------------------------------------------ moments of the shapes

TEST_CASE("A solid sphere has I = 2/5 m r^2 and a hollow one 2/3 m r^2 about every axis", "[inertia]") {
    // m = 3 kg, r = 2 m: ⅖·3·4 = 4.8 and ⅔·3·4 = 8 kg·m².
    CHECK_THAT(solidSphereInertia(3, 2).x, WithinAbs(4.8, kRoundOff));
    CHECK(solidSphereInertia(3, 2).x == solidSphereInertia(3, 2).y);
    CHECK(solidSphereInertia(3, 2).y == solidSphereInertia(3, 2).z);
    CHECK_THAT(hollowSphereInertia(3, 2).x, WithinAbs(8.0, kRoundOff));
    CHECK(hollowSphereInertia(3, 2).x == hollowSphereInertia(3, 2).z);
}

TEST_CASE("A solid box has I1 = m(b^2 + c^2)/12, I2 = m(a^2 + c^2)/12, I3 = m(a^2 + b^2)/12", "[inertia]") {
    const Vec3 moments = solidBoxInertia(kBoxMass, kBoxSize);
    CHECK_THAT(moments.x, WithinAbs(13.0, kRoundOff));
    CHECK_THAT(moments.y, WithinAbs(10.0, kRoundOff));
    CHECK_THAT(moments.z, WithinAbs(5.0, kRoundOff));
    // The longest edge (c = 3 m, along z) gives the smallest moment: mass close to the axis turns easily.
    // A cube is isotropic: m·2a²/12 = m·a²/6 about every axis.
    const Vec3 cube = solidBoxInertia(6, Vec3(2, 2, 2));
    CHECK_THAT(cube.x, WithinAbs(4.0, kRoundOff));
    CHECK(cube.x == cube.y);
    CHECK(cube.y == cube.z);
}

TEST_CASE("initialiseMassProperties picks the shape's moments, their inverses and L = I_world w", "[inertia]") {
    DynamicObject ball = test::sphere("ball", Vec3(0), Vec3(0), 2, 3);  // r = 2 m, m = 3 kg
    ball.angularVelocity = Vec3(1, -2, 0.5);
    initialiseMassProperties(ball);
    CHECK_THAT(ball.inertiaBody.x, WithinAbs(4.8, kRoundOff));
    CHECK_THAT(ball.inverseInertiaBody.y, WithinAbs(1 / 4.8, kRoundOff));
    CHECK(glm::length(ball.angularMomentum - Real(4.8) * ball.angularVelocity) < kRoundOff);

    ball.hollow = true;
    initialiseMassProperties(ball);
    CHECK_THAT(ball.inertiaBody.z, WithinAbs(8.0, kRoundOff));

    // A box turned 90° about z has its 2 m edge along world x: spinning about
    // world x is spinning about its body y axis, I = 10 kg·m², so L = 10·ω.
    DynamicObject turned = box(kBoxMass, kBoxSize, glm::angleAxis(kPi / 2, Vec3(0, 0, 1)));
    turned.angularVelocity = Vec3(2, 0, 0);
    initialiseMassProperties(turned);
    CHECK(glm::length(turned.angularMomentum - Vec3(20, 0, 0)) < kRoundOff);
}

// ------------------------------------------------------------------ parallel-axis theorem

TEST_CASE("Parallel axis: the box about a face centre matches the hand integral", "[inertia]") {
    // Pivot at the centre of the face x = +a/2: offset d = (0.5, 0, 0).
    // By hand, with the box spanning x ∈ [0, a] from the pivot:
    //   I_xx = m(b² + c²)/12 = 13 (the axis through the pivot along x passes through the centre),
    //   I_yy = m(a²/3 + c²/12) = 12·(1/3 + 9/12) = 13,
    //   I_zz = m(a²/3 + b²/12) = 12·(1/3 + 4/12) = 8,
    // and no products of inertia (the pivot lies on two symmetry planes).
    // This is the rod-about-its-end result m·L²/3 = m·L²/12 + m·(L/2)², per axis.
    const Mat3 about = parallelAxis(diagonal(kBoxMoments), kBoxMass, Vec3(0.5, 0, 0));
    checkMatrix(about, diagonal(Vec3(13, 13, 8)), kRoundOff);
}

TEST_CASE("Parallel axis: the box about a corner, products of inertia included", "[inertia]") {
    // Pivot at the corner (a/2, b/2, c/2) = (0.5, 1, 1.5). Integrating over the box
    // [0, a]×[0, b]×[0, c] measured from the corner, by hand:
    //   I_xx = m(b² + c²)/3 = 12·13/3 = 52,  I_yy = m(a² + c²)/3 = 40,  I_zz = m(a² + b²)/3 = 20,
    //   I_xy = −∫x·y dm = −m·ab/4 = −6,  I_xz = −m·ac/4 = −9,  I_yz = −m·bc/4 = −18.
    const Mat3 expected = rows(Vec3(52, -6, -9), Vec3(-6, 40, -18), Vec3(-9, -18, 20));
    checkMatrix(parallelAxis(diagonal(kBoxMoments), kBoxMass, Vec3(0.5, 1, 1.5)), expected, kRoundOff);
    // The tensor depends on d only through d·dᵀ: the opposite corner gives the same products.
    checkMatrix(parallelAxis(diagonal(kBoxMoments), kBoxMass, Vec3(-0.5, -1, -1.5)), expected, kRoundOff);
    // Products flip sign with one coordinate: the corner (−a/2, b/2, c/2).
    const Mat3 mirrored = rows(Vec3(52, 6, 9), Vec3(6, 40, -18), Vec3(9, -18, 20));
    checkMatrix(parallelAxis(diagonal(kBoxMoments), kBoxMass, Vec3(-0.5, 1, 1.5)), mirrored, kRoundOff);
}

// ------------------------------------------------------------------ world frame

TEST_CASE("The world inertia of a rotated box is symmetric with the same invariants", "[inertia]") {
    // R·I·Rᵀ is a similarity transform: symmetric, and the coefficients of the
    // characteristic polynomial are unchanged, i.e. the eigenvalues (13, 10, 5):
    //   trace = 13 + 10 + 5 = 28,
    //   sum of principal 2×2 minors = 13·10 + 13·5 + 10·5 = 245,
    //   determinant = 13·10·5 = 650.
    const Quat q = glm::normalize(glm::angleAxis(Real(0.7), glm::normalize(Vec3(1, -2, 0.5))) *
                                  glm::angleAxis(Real(2.1), Vec3(0, 0, 1)));
    const Mat3 world = worldInertia(q, kBoxMoments);
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) CHECK_THAT(at(world, r, c), WithinAbs(at(world, c, r), kRoundOff));
    }
    CHECK(std::abs(at(world, 0, 1)) > 0.1);  // really rotated: off-diagonal terms appear
    const Real trace = at(world, 0, 0) + at(world, 1, 1) + at(world, 2, 2);
    const Real minors = at(world, 0, 0) * at(world, 1, 1) - at(world, 0, 1) * at(world, 1, 0) +
                        at(world, 0, 0) * at(world, 2, 2) - at(world, 0, 2) * at(world, 2, 0) +
                        at(world, 1, 1) * at(world, 2, 2) - at(world, 1, 2) * at(world, 2, 1);
    CHECK_THAT(trace, WithinAbs(28.0, kRoundOff));
    CHECK_THAT(minors, WithinAbs(245.0, 1e-10));        // products of values ~13: 1e-10 on 245
    CHECK_THAT(glm::determinant(world), WithinAbs(650.0, 1e-10));
    // The inverse tensor really is the inverse.
    checkMatrix(worldInverseInertia(q, Real(1) / kBoxMoments) * world, Mat3(1), kRoundOff);
}

TEST_CASE("A 90-degree turn about z swaps the x and y moments", "[inertia]") {
    // Body x now points along world y and body y along world −x.
    const Mat3 world = worldInertia(glm::angleAxis(kPi / 2, Vec3(0, 0, 1)), kBoxMoments);
    checkMatrix(world, diagonal(Vec3(10, 13, 5)), kRoundOff);
}

// ------------------------------------------------------------------ impulses

TEST_CASE("An impulse through the centre changes only the velocity", "[inertia]") {
    DynamicObject body = box(kBoxMass, kBoxSize);
    body.position = Vec3(1, 2, 3);
    body.angularVelocity = Vec3(0.1, 0.2, 0.3);
    initialiseMassProperties(body);
    const Vec3 spinBefore = body.angularMomentum;
    const Vec3 impulse(6, -12, 24);  // N·s
    applyImpulseAt(body, impulse, body.position);
    CHECK(glm::length(body.velocity - impulse / kBoxMass) < kRoundOff);  // Δv = J/m = (0.5, −1, 2)
    CHECK(glm::length(body.angularMomentum - spinBefore) < kRoundOff);
    CHECK(glm::length(body.angularVelocity - Vec3(0.1, 0.2, 0.3)) < kRoundOff);
}

TEST_CASE("An off-centre impulse J at r changes L by r x J and v by J/m", "[inertia]") {
    DynamicObject body = box(kBoxMass, kBoxSize);
    body.position = Vec3(1, 2, 3);
    // Hit the corner (0.5, 1, 1.5) from the centre with J = (0, 0, −6) N·s:
    // ΔL = r × J = (1·(−6) − 1.5·0, 1.5·0 − 0.5·(−6), 0) = (−6, 3, 0) kg·m²/s,
    // Δω = I⁻¹·ΔL = (−6/13, 3/10, 0) rad/s (the box is unrotated: I is diagonal).
    const Vec3 r(0.5, 1, 1.5);
    const Vec3 impulse(0, 0, -6);
    applyImpulseAt(body, impulse, body.position + r);
    CHECK(glm::length(body.velocity - Vec3(0, 0, -0.5)) < kRoundOff);
    CHECK(glm::length(body.angularMomentum - Vec3(-6, 3, 0)) < kRoundOff);
    CHECK(glm::length(body.angularVelocity - Vec3(-6.0 / 13, 0.3, 0)) < kRoundOff);
    // The hit point's velocity, v + ω × r: what the impulse resolver works with.
    const Vec3 pointVelocity = velocityAt(body, body.position + r);
    CHECK(glm::length(pointVelocity - (Vec3(0, 0, -0.5) + glm::cross(body.angularVelocity, r))) < kRoundOff);
}

// ------------------------------------------------------------------ the Hollow field

TEST_CASE("Hollow takes true/false, yes/no, 1/0 in any case and defaults to false", "[config][inertia]") {
    const Scene scene = parseScene(
        "DynamicObject, Name=a\n"
        "DynamicObject, Name=b, Hollow=true\n"
        "DynamicObject, Name=c, Hollow=YES\n"
        "DynamicObject, Name=d, Hollow=1\n"
        "DynamicObject, Name=e, Hollow=False\n"
        "DynamicObject, Name=f, hollow=no\n"
        "DynamicObject, Name=g, Hollow=0\n"
        "DynamicObject, Name=h, Shape=Box, Hollow=false\n",
        "test.scene");
    const bool expected[] = {false, true, true, true, false, false, false, false};
    REQUIRE(scene.dynamics.size() == 8);
    for (std::size_t i = 0; i < 8; ++i) {
        INFO(scene.dynamics[i].name);
        CHECK(scene.dynamics[i].hollow == expected[i]);
    }
}

TEST_CASE("A hollow ball in a World turns with I = 2/3 m r^2", "[config][inertia]") {
    const Scene scene = parseScene("DynamicObject, Radius=2, Mass=3, Hollow=yes, AngularVelocity=(0, 1, 0)\n"
                                   "DynamicObject, Name=solid, Radius=2, Mass=3, AngularVelocity=(0, 1, 0)\n",
                                   "test.scene");
    const World world(scene);
    CHECK_THAT(world.dynamics()[0].angularMomentum.y, WithinRel(8.0, 1e-14));  // ⅔·3·2²·1
    CHECK_THAT(world.dynamics()[1].angularMomentum.y, WithinRel(4.8, 1e-14));  // ⅖·3·2²·1
}

TEST_CASE("Hollow on a Box, or a word that is not yes or no, is an error", "[config][inertia]") {
    auto problems = [](std::string_view text) -> std::vector<ConfigDiagnostic> {
        try {
            (void)parseScene(text, "test.scene");
        } catch (const ConfigError& error) {
            return error.diagnostics();
        }
        return {};
    };
    const auto onBox = problems("DynamicObject, Shape=Box, Hollow=Yes\n");
    //                            1234567890123456789012345678901234
    REQUIRE(onBox.size() == 1);
    CHECK(onBox[0].column == 34);
    CHECK(onBox[0].message() == "test.scene:1:34: error: Hollow: expected false for a Box, found 'Yes'; only a "
                                "sphere can be hollow (a thin shell, I = 2/3 m r^2); boxes are solid");

    const auto maybe = problems("DynamicObject, Hollow=maybe\n");
    REQUIRE(maybe.size() == 1);
    CHECK(maybe[0].message() ==
          "test.scene:1:23: error: Hollow: expected one of true, false, yes, no, 1, 0, found 'maybe'");
    const auto typo = problems("DynamicObject, Hollow=fals\n");
    REQUIRE(typo.size() == 1);
    CHECK_THAT(typo[0].message(), Catch::Contains("did you mean 'false'?"));
}
