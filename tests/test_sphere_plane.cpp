// Sphere against plane: detection and impulse response, against analytic physics.
// Tags: [sphere-plane].
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "collision/narrowphase.hpp"
#include "test_support.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// Drops a ball of restitution e from bottom height H and returns the apex
/// heights (of its lowest point) after each of the first @p bounces bounces.
std::vector<Real> apexHeights(IntegratorKind integrator, Real h, Real e, Real H, int bounces,
                              SolverKind solver = SolverKind::SequentialImpulse) {
    const Real radius = 0.1;
    Scene scene = test::emptyScene(integrator, h);
    scene.settings.solver = solver;
    scene.dynamics.push_back(test::sphere("ball", Vec3(0, radius + H, 0), Vec3(0), radius, 1, e));
    scene.planes.push_back(test::ground());
    World world(scene);

    std::vector<Real> apexes;
    Real highest = 0;
    bool rising = false;
    while (static_cast<int>(apexes.size()) < bounces && world.time() < 60) {
        world.step();
        const DynamicObject& ball = world.dynamics()[0];
        if (ball.velocity.y > 0) {
            rising = true;
            highest = std::max(highest, ball.position.y - radius);
        } else if (rising) {  // just passed the top: record the highest sample
            highest = std::max(highest, ball.position.y - radius);
            apexes.push_back(highest);
            rising = false;
            highest = 0;
        }
    }
    return apexes;
}

}  // namespace

TEST_CASE("Sphere-plane test finds depth and normal on a tilted plane", "[sphere-plane]") {
    Geometry plane;
    plane.type = GeometryType::Plane;
    plane.centre = Vec3(0, 1, 0);
    plane.normal = glm::normalize(Vec3(1, 1, 0));
    Geometry ball;
    ball.radius = 0.5;
    // Centre 0.3 m in front of the plane along its normal: overlap 0.2 m.
    ball.centre = plane.centre + Real(0.3) * plane.normal + Vec3(0, 0, 2);
    ContactManifold c;
    REQUIRE(collideSpherePlane(ball, plane, c));
    CHECK_THAT(c.points[0].depth, WithinAbs(0.2, 1e-12));
    CHECK(glm::length(c.normal + plane.normal) < 1e-12);  // from the sphere into the plane

    ball.centre = plane.centre + Real(0.6) * plane.normal;  // 0.1 m clear
    CHECK_FALSE(collideSpherePlane(ball, plane, c));
}

TEST_CASE("Bounce apexes follow e^(2n) h with Verlet at any time step", "[sphere-plane][verlet]") {
    // Energy argument: a bounce with restitution e keeps e² of the kinetic
    // energy at impact, so the n-th apex is e^(2n)·H. Verlet flies the exact
    // parabola; the impulse uses the reconstructed impact speed, so the only
    // error is sampling the apex between steps: at most g·h²/8. The
    // sequential-impulse solver's soft contact may also leave the ball up to
    // its resting sag g/ω² (restingSag) into the floor when it bounces.
    const Real e = 0.8, H = 1;
    for (SolverKind solver : {SolverKind::Impulse, SolverKind::SequentialImpulse}) {
        for (Real h : {Real(1) / 30, Real(1) / 60, Real(1) / 240}) {
            const std::vector<Real> apexes = apexHeights(IntegratorKind::Verlet, h, e, H, 5, solver);
            REQUIRE(apexes.size() == 5);
            WorldSettings settings;
            settings.timeStep = h;
            const Real sag = solver == SolverKind::Impulse ? Real(0) : restingSag(settings);
            const Real tolerance = kStandardGravity * h * h / 8 + sag + 1e-9;
            for (int n = 1; n <= 5; ++n) {
                INFO(toString(solver) << ", h = " << h << ", bounce " << n);
                CHECK_THAT(apexes[n - 1], WithinAbs(std::pow(e, 2 * n) * H, tolerance));
            }
        }
    }
}

TEST_CASE("Bounce apexes follow e^(2n) h with the Euler integrators to O(h)", "[sphere-plane][euler][symplectic-euler]") {
    // The Euler schemes displace the flight path by ½·g·h·t, so the apex is
    // off by about v·h: tolerance 2·sqrt(2gH)·h (9 mm at h = 1 ms).
    const Real e = 0.8, H = 1, h = 0.001;
    const Real tolerance = 2 * std::sqrt(2 * kStandardGravity * H) * h;
    for (IntegratorKind kind : {IntegratorKind::ExplicitEuler, IntegratorKind::SymplecticEuler}) {
        const std::vector<Real> apexes = apexHeights(kind, h, e, H, 4);
        REQUIRE(apexes.size() == 4);
        for (int n = 1; n <= 4; ++n) {
            INFO(toString(kind) << ", bounce " << n);
            CHECK_THAT(apexes[n - 1], WithinAbs(std::pow(e, 2 * n) * H, tolerance));
        }
    }
}

TEST_CASE("A sphere at rest on a plane stays within 1 mm for 10 s", "[sphere-plane][euler][symplectic-euler][verlet]") {
    for (IntegratorKind kind : test::kAllIntegrators) {
        for (Real e : {Real(0), Real(0.5), Real(1)}) {
            Scene scene = test::emptyScene(kind, Real(1) / 60);
            scene.dynamics.push_back(test::sphere("ball", Vec3(0, 0.5, 0), Vec3(0), 0.5, 1, e));
            scene.planes.push_back(test::ground());
            World world(scene);
            Real worst = 0;
            while (world.time() < 10) {
                world.step();
                worst = std::max(worst, std::abs(world.dynamics()[0].position.y - Real(0.5)));
            }
            INFO(toString(kind) << ", e = " << e);
            CHECK(worst < 1e-3);
            CHECK(glm::length(world.dynamics()[0].velocity) < 1e-9);  // at rest at the end of each step
        }
    }
}

TEST_CASE("A sphere with e = 0 stops at the first impact", "[sphere-plane]") {
    // The impulse scheme puts the ball exactly on the floor; the soft contacts
    // of sequential impulses hold it within its resting sag g/ω² (17 µm), at
    // rest (sleep is off: the velocity is the solver's, not zeroed by sleep).
    for (SolverKind solver : {SolverKind::Impulse, SolverKind::SequentialImpulse}) {
        Scene scene = test::emptyScene(IntegratorKind::Verlet, Real(1) / 60);
        scene.settings.solver = solver;
        scene.settings.sleeping = false;
        scene.dynamics.push_back(test::sphere("ball", Vec3(0, 2, 0), Vec3(0), 0.5, 1, 0));
        scene.planes.push_back(test::ground());
        World world(scene);
        while (world.time() < 3) world.step();
        INFO(toString(solver));
        const Real sag = solver == SolverKind::Impulse ? Real(0) : restingSag(scene.settings);
        CHECK_THAT(world.dynamics()[0].position.y, WithinAbs(0.5 - sag, 1e-9 + 0.1 * sag));
        CHECK(std::abs(world.dynamics()[0].velocity.y) < 1e-9 + kStandardGravity * scene.settings.timeStep * 1e-6);
    }
}
