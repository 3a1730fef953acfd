/// @file test_forces.cpp
/// @brief Stage 1 beyond uniform gravity: springs and attractors as force laws. Tag: [forces].
///
/// - A spring's force k·(l − L₀) + c·l̇ along the line of its anchors, its
///   torque r × F at an off-centre anchor, anchors in the body frame.
/// - Springs conserve linear and angular momentum (equal, opposite, collinear
///   forces); with symplectic Euler and Verlet, to round-off.
/// - An attractor's inverse-square pull, its uniform core, and its potential.
/// - A circular orbit's radius and period 2π√(r³/μ); Verlet's energy on an
///   eccentric orbit does not drift.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "config/scene_loader.hpp"
#include "objects/inertia.hpp"
#include "forces/apply_forces.hpp"
#include "test_support.hpp"
#include "world/measurements.hpp"
#include "world/world.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// Every body's acceleration and torque set to zero, as applyUniformForces leaves them without gravity.
void clearForces(std::vector<DynamicObject>& bodies) { applyUniformForces(bodies, Vec3(0)); }

/// A world with no gravity holding @p scene's bodies, springs and attractors, stepped by @p integrator.
World weightless(Scene scene, IntegratorKind integrator, Real h) {
    scene.settings.gravity = Vec3(0);
    scene.settings.integrator = integrator;
    scene.settings.timeStep = h;
    return World(std::move(scene));
}

}  // namespace

// ------------------------------------------------------------------ springs

TEST_CASE("A spring pulls both anchors together with k(l - L0) plus c times the stretch rate", "[forces]") {
    std::vector<DynamicObject> bodies{test::sphere("a", Vec3(0, 0, 0), Vec3(0), 0.1, 2),
                                      test::sphere("b", Vec3(2, 0, 0), Vec3(0), 0.1, 1)};
    Spring spring;
    spring.bodyA = 0;
    spring.bodyB = 1;
    spring.stiffness = 10;   // N/m
    spring.restLength = 1.5; // m: stretched by 0.5 m, so k·(l − L₀) = 5 N
    clearForces(bodies);
    applySprings(bodies, std::span<const Spring>(&spring, 1));
    CHECK(glm::length(bodies[0].acceleration - Vec3(2.5, 0, 0)) < 1e-12);  // +5 N on 2 kg, towards b
    CHECK(glm::length(bodies[1].acceleration - Vec3(-5, 0, 0)) < 1e-12);   // −5 N on 1 kg, towards a

    // The damper: b moving away at 1 m/s along the spring adds c·l̇ = 3 N; motion across the spring adds nothing.
    spring.damping = 3;  // N·s/m
    bodies[1].velocity = Vec3(1, 7, 0);
    clearForces(bodies);
    applySprings(bodies, std::span<const Spring>(&spring, 1));
    CHECK(glm::length(bodies[0].acceleration - Vec3(4, 0, 0)) < 1e-12);   // 8 N / 2 kg
    CHECK(glm::length(bodies[1].acceleration - Vec3(-8, 0, 0)) < 1e-12);
    CHECK(glm::length(bodies[0].torque) < 1e-12);  // anchors at the centres: no torque
}

TEST_CASE("A spring hooked off the centre turns the body: torque r x F", "[forces]") {
    // A box turned 90° about z: its body-frame anchor (0.5, 0, 0) is at world (0, 0.5, 0).
    // The world end at (3, 0.5, 0) pulls along +x with k·(l − L₀) = 4·(3 − 1) = 8 N;
    // τ = r × F = (0, 0.5, 0) × (8, 0, 0) = (0, 0, −4) N·m.
    std::vector<DynamicObject> bodies{test::dynamicBox("box", Vec3(0), Vec3(1), 2, 0.5)};
    bodies[0].orientation = glm::angleAxis(kPi / 2, Vec3(0, 0, 1));
    Spring spring;
    spring.bodyA = 0;
    spring.anchorA = Vec3(0.5, 0, 0);
    spring.anchorB = Vec3(3, 0.5, 0);
    spring.stiffness = 4;
    spring.restLength = 1;
    const SpringEnds ends = springEnds(spring, bodies);
    CHECK(glm::length(ends.a - Vec3(0, 0.5, 0)) < 1e-12);
    clearForces(bodies);
    applySprings(bodies, std::span<const Spring>(&spring, 1));
    CHECK(glm::length(bodies[0].acceleration - Vec3(4, 0, 0)) < 1e-12);  // 8 N / 2 kg
    CHECK(glm::length(bodies[0].torque - Vec3(0, 0, -4)) < 1e-12);
    CHECK_THAT(springPotentialEnergy(spring, bodies), WithinRel(Real(0.5 * 4 * 2 * 2), Real(1e-12)));
}

TEST_CASE("The World's force stage is gravity plus springs plus attractors", "[forces]") {
    std::vector<DynamicObject> bodies{test::sphere("p", Vec3(2, 0, 0), Vec3(0), 0.1, 4)};
    Spring spring;  // to the world origin, rest length 0: F = −k·x = (−6, 0, 0) N
    spring.stiffness = 3;
    Attractor sun;  // at (0, 0, 0), μ = 8: a = −μ/r² x̂ = (−2, 0, 0) m/s²
    sun.mu = 8;
    const SceneForces forces{Vec3(0, -9.81, 0), std::span<const Spring>(&spring, 1),
                             std::span<const Attractor>(&sun, 1), RegionForces{}};  // no regions
    bodies[0].torque = Vec3(1, 2, 3);  // stale: the stage must reset it
    forces(bodies);
    CHECK(glm::length(bodies[0].acceleration - Vec3(-1.5 - 2, -9.81, 0)) < 1e-12);
    CHECK(glm::length(bodies[0].torque) == 0);
}

TEST_CASE("Springs keep total linear and angular momentum with the symplectic integrators", "[forces]") {
    // Equal and opposite forces on one line: Σ F = 0 and Σ (x + r) × F = 0.
    // Symplectic Euler and Verlet are compositions of kicks (which change
    // each L by h·(x + r) × F, summing to 0) and drifts (x + h·v keeps x × m·v),
    // so both totals are conserved to round-off, tumbling boxes and all.
    Scene scene;
    // Far enough apart never to touch: a contact would move them by position correction.
    scene.dynamics = {test::dynamicBox("a", Vec3(-3, 0, 0), Vec3(1, 0.5, 2), 2, 0.5),
                      test::dynamicBox("b", Vec3(3, 0.3, 0), Vec3(0.4, 1, 1), 1, 0.5)};
    scene.dynamics[0].velocity = Vec3(0.3, -0.2, 0.1);
    scene.dynamics[0].angularVelocity = Vec3(1, 2, -0.5);
    scene.dynamics[1].angularVelocity = Vec3(-3, 0.5, 1);
    Spring spring;
    spring.bodyA = 0;
    spring.bodyB = 1;
    spring.anchorA = Vec3(0.5, 0.25, -1);
    spring.anchorB = Vec3(-0.2, 0.5, 0.5);
    spring.stiffness = 40;
    spring.damping = 0.5;
    spring.restLength = 5;
    scene.springs = {spring};
    for (IntegratorKind integrator : {IntegratorKind::SymplecticEuler, IntegratorKind::Verlet}) {
        INFO(toString(integrator));
        World world = weightless(scene, integrator, Real(1) / 120);
        const Vec3 p0 = linearMomentumOf(world);
        const Vec3 l0 = angularMomentumOf(world);
        // A body's own spin L changes only under torque (a free box's ω wobbles, its L does not).
        const Vec3 spin0 = world.dynamics()[0].angularMomentum;
        Real turned = 0;
        for (int i = 0; i < 2000; ++i) {
            world.step();
            turned = std::max(turned, glm::length(world.dynamics()[0].angularMomentum - spin0) / glm::length(spin0));
        }
        CHECK(glm::length(linearMomentumOf(world) - p0) < 1e-12);
        CHECK(glm::length(angularMomentumOf(world) - l0) < 1e-11 * glm::length(l0));
        CHECK(turned > 0.1);  // the spring's torque did change the spins: the test saw torques
        CHECK(world.contacts().empty());
    }
}

TEST_CASE("A damped spring loses energy and never gains it", "[forces]") {
    // dE/dt = −c·l̇² ≤ 0 for the exact motion; Verlet at a small step follows it.
    Scene scene = parseScene("World, Gravity=(0, 0, 0), Integrator=Verlet, TimeStep=0.001\n"
                             "DynamicObject, Name=bob, Position=(1.5, 0, 0)\n"
                             "Spring, BodyA=bob, Stiffness=20, Damping=0.5, RestLength=1\n",
                             "damped.scene");
    World world(std::move(scene));
    const Real e0 = energyOf(world).total();
    for (int i = 0; i < 5000; ++i) world.step();  // 5 s: the amplitude decays as e^(−c t/2m) = e^(−1.25)
    const Real e1 = energyOf(world).total();
    CHECK(e1 < e0 * std::exp(-2 * 0.25 * 5) * 1.05);
    CHECK(e1 > e0 * std::exp(-2 * 0.25 * 5) * 0.8);
}

// ------------------------------------------------------------------ attractors

TEST_CASE("An Attractor pulls with mu/r^2 towards its position, and like a uniform ball inside its core", "[forces]") {
    Attractor sun;
    sun.position = Vec3(1, 1, 1);
    sun.mu = 8;
    CHECK(glm::length(attractorAcceleration(sun, Vec3(3, 1, 1)) - Vec3(-2, 0, 0)) < 1e-12);  // 8/2² towards it
    CHECK(glm::length(attractorAcceleration(sun, Vec3(1, -3, 1)) - Vec3(0, 0.5, 0)) < 1e-12); // 8/4²
    // Inside the core a = −μ·r/r_c³: linear in r, zero at the centre, continuous at r_c.
    const Vec3 inside(kAttractorCoreRadius / 2, 0, 0);
    const Real rc3 = kAttractorCoreRadius * kAttractorCoreRadius * kAttractorCoreRadius;
    CHECK_THAT(attractorAcceleration(sun, sun.position + inside).x, WithinRel(-sun.mu * inside.x / rc3, Real(1e-12)));
    CHECK(glm::length(attractorAcceleration(sun, sun.position)) == 0);
    const Vec3 edge(kAttractorCoreRadius, 0, 0);
    CHECK_THAT(attractorAcceleration(sun, sun.position + edge).x,
               WithinRel(-sun.mu / (kAttractorCoreRadius * kAttractorCoreRadius), Real(1e-12)));
}

TEST_CASE("An Attractor's potential energy is the potential of its force", "[forces]") {
    // F = −∇U, checked by central differences outside and inside the core.
    Attractor sun;
    sun.mu = 3;
    const Real mass = 2;
    for (Real r : {Real(2), Real(0.3), kAttractorCoreRadius * Real(0.6)}) {
        const Vec3 x(r * Real(0.6), r * Real(0.8), 0);
        const Real dx = r * Real(1e-5);
        Vec3 gradient;
        for (int k = 0; k < 3; ++k) {
            Vec3 step(0);
            step[k] = dx;
            gradient[k] = (attractorPotentialEnergy(sun, mass, x + step) - attractorPotentialEnergy(sun, mass, x - step)) /
                          (2 * dx);
        }
        INFO("r = " << r);
        const Vec3 force = mass * attractorAcceleration(sun, x);
        CHECK(glm::length(force + gradient) < 1e-6 * glm::length(force));
    }
}

TEST_CASE("A circular orbit about an Attractor keeps its radius and the period 2 pi sqrt(r^3/mu)", "[forces][verlet]") {
    // r = 2 m, μ = 5 m³/s²: v = √(μ/r) = 1.5811 m/s, T = 2π√(r³/μ) = 7.9477 s.
    // Verlet at h = T/1000 (h·ω = 0.0063): the radius wobbles by O((hω)²) ≈ 4·10⁻⁵
    // relative and the period is off by O((hω)²) too; 10⁻⁴ holds both.
    const Real r = 2, mu = 5;
    const Real period = 2 * kPi * std::sqrt(r * r * r / mu);
    Scene scene;
    scene.dynamics = {test::sphere("planet", Vec3(r, 0, 0), Vec3(0, std::sqrt(mu / r), 0), 0.05)};
    Attractor sun;
    sun.mu = mu;
    scene.attractors = {sun};
    const Real h = period / 1000;
    World world = weightless(scene, IntegratorKind::Verlet, h);
    std::vector<Real> crossings;  // upward crossings of the +x axis: one per orbit
    Real worstRadius = 0;
    Real previousY = 0;
    for (int i = 0; i < 10000; ++i) {
        world.step();
        const Vec3 x = world.dynamics()[0].position;
        worstRadius = std::max(worstRadius, std::abs(glm::length(x) - r) / r);
        if (previousY < 0 && x.y >= 0 && x.x > 0) crossings.push_back(world.time() - h + h * previousY / (previousY - x.y));
        previousY = x.y;
    }
    CHECK(worstRadius < 1e-4);
    REQUIRE(crossings.size() >= 9);
    const Real measured = (crossings.back() - crossings.front()) / Real(crossings.size() - 1);
    CHECK_THAT(measured, WithinRel(period, Real(1e-4)));
}

TEST_CASE("Verlet's energy on an eccentric orbit oscillates but does not drift", "[forces][verlet]") {
    // A symplectic method conserves a modified energy, so its energy error
    // repeats orbit after orbit: the largest error over orbits 91–100 is the
    // largest over orbits 1–10 (up to the slow turning of the orbit, which
    // moves where on the ellipse the steps fall; 20 % covers it). Explicit
    // Euler's grows without bound instead.
    const Real mu = 4 * kPi * kPi;  // the period of an orbit with a = 2/3 m is (2/3)^1.5 s
    Scene scene;
    scene.dynamics = {test::sphere("comet", Vec3(1, 0, 0), Vec3(0, std::sqrt(mu * 0.5), 0), 0.03)};  // e = 0.5
    Attractor sun;
    sun.mu = mu;
    scene.attractors = {sun};
    const Real period = std::pow(Real(2) / 3, Real(1.5));
    const Real h = Real(1) / 480;
    const long perOrbit = std::lround(period / h);
    const auto energyErrors = [&](IntegratorKind integrator) {
        World world = weightless(scene, integrator, h);
        const Real e0 = energyOf(world).total();
        Real first = 0, last = 0;
        for (long i = 0; i < 100 * perOrbit; ++i) {
            world.step();
            const Real error = std::abs(energyOf(world).total() - e0) / std::abs(e0);
            if (i < 10 * perOrbit) first = std::max(first, error);
            if (i >= 90 * perOrbit) last = std::max(last, error);
        }
        return std::pair{first, last};
    };
    const auto [verletFirst, verletLast] = energyErrors(IntegratorKind::Verlet);
    CHECK(verletLast < Real(1.2) * verletFirst);
    CHECK(verletLast < Real(0.01));
    const auto [eulerFirst, eulerLast] = energyErrors(IntegratorKind::ExplicitEuler);
    CHECK(eulerLast > eulerFirst);  // still growing, towards escape
    CHECK(eulerFirst > 10 * verletLast);
}
