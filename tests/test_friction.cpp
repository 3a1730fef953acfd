// Friction and rolling: Coulomb friction at contact points with the angular
// terms, against the classical results of rigid-body mechanics. Tag: [friction].
#include <catch2/catch.hpp>

#include <cmath>

#include "test_support.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// A plane through the origin tilted by @p degrees about z: it descends towards +x.
CollisionPlane incline(Real degrees) {
    const Real theta = degrees * kPi / 180;
    CollisionPlane plane;
    plane.name = "incline";
    plane.normal = Vec3(std::sin(theta), std::cos(theta), 0);
    return plane;
}

/// Unit vector down the slope of incline(degrees).
Vec3 downSlope(Real degrees) {
    const Real theta = degrees * kPi / 180;
    return Vec3(std::cos(theta), -std::sin(theta), 0);
}

}  // namespace

TEST_CASE("A solid sphere rolls down a 30 degree incline at 5/7 g sin(theta)", "[friction]") {
    // Rolling without slipping: m·a = m·g·sinθ − F and I·α = F·R with a = α·R.
    // With I = ⅖·m·R² that gives a = g·sinθ / (1 + I/(m·R²)) = 5/7·g·sinθ.
    // It needs μ ≥ 2/7·tanθ = 0.165; the ball has μ = 0.5.
    const Real theta = 30, R = 0.5;
    for (Real h : {Real(1) / 60, Real(1) / 240}) {
        Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, h);
        scene.planes.push_back(incline(theta));
        scene.dynamics.push_back(test::sphere("ball", R * scene.planes[0].normal, Vec3(0), R, 1, 0, 0.5));
        World world(scene);
        while (world.time() < 2 - 1e-9) world.step();
        const Real expected = Real(5) / 7 * kStandardGravity * std::sin(theta * kPi / 180);
        const DynamicObject& ball = world.dynamics()[0];
        INFO("h = " << h);
        CHECK_THAT(glm::dot(ball.velocity, downSlope(theta)) / world.time(), WithinRel(expected, 0.01));
        // And it rolls: the contact point is at rest, v = ω × R.
        const Vec3 contactVelocity = ball.velocity + glm::cross(ball.angularVelocity, -R * scene.planes[0].normal);
        CHECK(glm::length(contactVelocity) < 0.01 * glm::length(ball.velocity));
    }
}

TEST_CASE("A hollow sphere rolls slower: 3/5 g sin(theta)", "[friction]") {
    // I = ⅔·m·R² ⇒ a = g·sinθ / (1 + 2/3) = 3/5·g·sinθ.
    const Real theta = 30, R = 0.5;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 120);
    scene.planes.push_back(incline(theta));
    DynamicObject shell = test::sphere("shell", R * scene.planes[0].normal, Vec3(0), R, 1, 0, 0.8);
    shell.hollow = true;
    scene.dynamics.push_back(shell);
    World world(scene);
    while (world.time() < 2 - 1e-9) world.step();
    const Real expected = Real(3) / 5 * kStandardGravity * std::sin(theta * kPi / 180);
    CHECK_THAT(glm::dot(world.dynamics()[0].velocity, downSlope(theta)) / world.time(), WithinRel(expected, 0.01));
}

TEST_CASE("A sphere too slippery to roll slides at g(sin(theta) - mu cos(theta)) while spinning up", "[friction]") {
    // With μ < 2/7·tanθ friction cannot keep up: kinetic friction μ·m·g·cosθ acts
    // throughout, so the centre accelerates at g(sinθ − μcosθ).
    const Real theta = 30, R = 0.5, mu = 0.1;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 120);
    scene.planes.push_back(incline(theta));
    scene.dynamics.push_back(test::sphere("ball", R * scene.planes[0].normal, Vec3(0), R, 1, 0, mu));
    World world(scene);
    while (world.time() < 1 - 1e-9) world.step();
    const Real t = theta * kPi / 180;
    const Real expected = kStandardGravity * (std::sin(t) - mu * std::cos(t));
    CHECK_THAT(glm::dot(world.dynamics()[0].velocity, downSlope(theta)) / world.time(), WithinRel(expected, 0.01));
}

TEST_CASE("A sliding, non-spinning sphere ends rolling at 5/7 of its speed", "[friction]") {
    // Kinetic friction slows the centre (a = −μg) and spins the ball up
    // (α = μ·m·g·R/I) until v = ω·R. Angular momentum about the contact line
    // is conserved through it (friction acts through that line):
    // m·v0·R = m·v·R + I·v/R ⇒ v = v0 / (1 + 2/5) = 5/7·v0, whatever μ is.
    // Tolerance 0.2 %: the lever arm is short by half a step's sag (g·h²/2 = 0.09 mm).
    const Real v0 = 5;
    for (Real mu : {Real(0.1), Real(0.3), Real(0.8)}) {
        Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 240);
        scene.planes.push_back(test::ground());
        scene.dynamics.push_back(test::sphere("bowl", Vec3(0, 0.5, 0), Vec3(v0, 0, 0), 0.5, 2, 0, mu));
        World world(scene);
        while (world.time() < 6) world.step();
        const DynamicObject& ball = world.dynamics()[0];
        INFO("mu = " << mu);
        CHECK_THAT(ball.velocity.x, WithinRel(Real(5) / 7 * v0, 0.002));
        CHECK_THAT(ball.angularVelocity.z * 0.5, WithinRel(-ball.velocity.x, 0.002));  // rolling: v = −ω_z·R
    }
}
