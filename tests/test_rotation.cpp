/// @file test_rotation.cpp
/// @brief Rigid-body rotation in each integrator, against exact solutions. Tag: [rotation].
///
/// - The Dzhanibekov (tennis-racket) flip of a 1×2×3 box spun about its
///   intermediate axis: flip times against the exact elliptic-function
///   solution of Euler's equations and an RK4 reference; |L| and energy.
/// - Explicit Euler's energy drift: it only grows, and it is first order in h.
/// - Torque-free spheres and symmetric tops: ω constant, or the figure axis
///   precessing about L at |L|/I₁.
/// - A constant torque: ω = τ·t/I for every integrator, and the angle turned
///   lagging, leading or exact exactly as the projectile's position does.
/// - The measurements (rotational energy, angular momentum about the origin)
///   and the lesson scene run through World.
/// - The turn of the packed substeps, four balls at a time (rotation_lanes.hpp):
///   the scalar turn's bits, or the lane handed back to it. Tags [rotation][lanes].
///
/// Every integrator is driven as a stage: the test supplies the force model
/// (an AccelerationFunction that writes acceleration and torque) and calls
/// the integrator function, as World::step does.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "config/scene_loader.hpp"
#include "objects/inertia.hpp"
#include "integrators/integrators.hpp"
#include "fast/rotation_lanes.hpp"
#include "test_support.hpp"
#include "world/measurements.hpp"
#include "world/world.hpp"

// The lanes test passes Lanes by value to always-inlined functions (see src/fast/lanes.hpp).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

using namespace stepwise;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// ------------------------------------------------------------------ the box of the lesson

/// 1 m × 2 m × 3 m, 1 kg: I = (2² + 3², 1² + 3², 1² + 2²)/12 = (13, 10, 5)/12 kg·m².
/// The largest moment is about body x, the intermediate about body y (along
/// the 2 m edge), the smallest about body z.
const Vec3 kBoxSize(1, 2, 3);
constexpr Real kBoxMass = 1;
const Vec3 kBoxMoments = Vec3(13, 10, 5) / Real(12);

/// Spun at 5 rad/s about the intermediate axis, with 0.01 rad/s about the
/// major axis to start the instability (a perfectly aligned spin would stay
/// put, unstably, until round-off tipped it).
const Vec3 kSpin(0.01, 5, 0);
constexpr Real kFlipDuration = 20;     ///< s, as the lesson scene
constexpr Real kLessonStep = Real(1) / 60;

/// No force and no torque: the free body.
const AccelerationFunction kNoForces = [](std::span<DynamicObject> bodies) {
    for (DynamicObject& body : bodies) {
        body.acceleration = Vec3(0);
        body.torque = Vec3(0);
    }
};

/// One step of @p kind, as stage 2 of World::step runs it (forces first).
void step(IntegratorKind kind, std::vector<DynamicObject>& bodies, Real h, const AccelerationFunction& forces) {
    forces(bodies);
    switch (kind) {
        case IntegratorKind::ExplicitEuler: integrateExplicitEuler(bodies, h); break;
        case IntegratorKind::SymplecticEuler: integrateSymplecticEuler(bodies, h); break;
        case IntegratorKind::Verlet: integrateVerlet(bodies, h, forces); break;
    }
}

DynamicObject spinningBox(const Vec3& omega, const Quat& orientation = Quat(1, 0, 0, 0)) {
    DynamicObject body;
    body.name = "box";
    body.shape = Shape::Box;
    body.scale = kBoxSize;
    body.orientation = orientation;
    body.setMass(kBoxMass);
    body.angularVelocity = omega;
    initialiseMassProperties(body);
    return body;
}

Real rotationalEnergy(const DynamicObject& body) { return Real(0.5) * glm::dot(body.angularVelocity, body.angularMomentum); }

/// Body-frame components of L, Π = Rᵀ·L. Π_y is L's component along the
/// body's y axis: (R·e_y)·L = e_y·(Rᵀ·L). Its sign says which way the
/// intermediate axis points relative to L.
Vec3 bodyMomentum(const DynamicObject& body) { return glm::conjugate(body.orientation) * body.angularMomentum; }

/// Time at which a sampled quantity crosses zero between samples (t0, s0) and (t0 + h, s1),
/// by linear interpolation.
Real crossing(Real t0, Real h, Real s0, Real s1) { return t0 + h * s0 / (s0 - s1); }

/// What one run of the spinning box shows.
struct FlipRun {
    std::vector<Real> flips;        ///< Times the body's y axis changed sides of L, s.
    Real worstMomentumError = 0;    ///< max over steps of | |L| − |L₀| | / |L₀|.
    Real worstEnergyError = 0;      ///< max over steps of |E − E₀| / E₀.
    Real energyErrorAt2s = 0;       ///< (E − E₀)/E₀ at t = 2 s, before the first flip.
    Real finalEnergyError = 0;      ///< (E − E₀)/E₀ at the end.
    Real largestEnergyDecrease = 0; ///< max over steps of (E_n − E_{n+1})/E₀ (≤ 0 when E never decreases).
    /// max over steps of |(E_{n+1} − E_n) − ½·ΔΠ·I⁻¹·ΔΠ|, J: explicit Euler's exact energy gain (see below).
    Real worstEulerGainMismatch = 0;
};

FlipRun spinTheBox(IntegratorKind kind, Real h, Real duration = kFlipDuration) {
    std::vector<DynamicObject> bodies{spinningBox(kSpin)};
    const Vec3 l0 = bodies[0].angularMomentum;
    const Real e0 = rotationalEnergy(bodies[0]);
    FlipRun run;
    Real previousSide = bodyMomentum(bodies[0]).y;
    Real previousEnergy = e0;
    Vec3 previousPi = bodyMomentum(bodies[0]);
    const long steps = std::lround(duration / h);
    const long stepsTo2s = std::lround(2 / h);
    for (long i = 0; i < steps; ++i) {
        step(kind, bodies, h, kNoForces);
        const DynamicObject& box = bodies[0];
        const Real side = bodyMomentum(box).y;
        if ((side < 0) != (previousSide < 0)) run.flips.push_back(crossing(Real(i) * h, h, previousSide, side));
        previousSide = side;

        const Real energy = rotationalEnergy(box);
        run.worstMomentumError =
            std::max(run.worstMomentumError, std::abs(glm::length(box.angularMomentum) - glm::length(l0)) / glm::length(l0));
        run.worstEnergyError = std::max(run.worstEnergyError, std::abs(energy - e0) / e0);
        run.largestEnergyDecrease = std::max(run.largestEnergyDecrease, (previousEnergy - energy) / e0);
        const Vec3 pi = bodyMomentum(box);
        const Vec3 deltaPi = pi - previousPi;
        const Real predictedGain = Real(0.5) * glm::dot(deltaPi, deltaPi / kBoxMoments);
        run.worstEulerGainMismatch =
            std::max(run.worstEulerGainMismatch, std::abs((energy - previousEnergy) - predictedGain));
        previousPi = pi;
        if (i + 1 == stepsTo2s) run.energyErrorAt2s = (energy - e0) / e0;
        run.finalEnergyError = (energy - e0) / e0;
        previousEnergy = energy;
    }
    return run;
}

/// Exact flip times of the box, from the elliptic-function solution of Euler's
/// equations (Landau & Lifshitz, *Mechanics*, §37, eq. 37.10). In their labels
/// I₁ < I₂ < I₃, here I₁ = I_z, I₂ = I_y, I₃ = I_x. With M² = |L|² and E the
/// energy, M² > 2E·I₂ (the perturbation is about the major axis), and
///     Ω₂ = Ω_y = √((2E·I₃ − M²)/(I₂(I₃ − I₂))) · sn(τ, k),  τ = s·t + τ₀,
///     s  = √((I₃ − I₂)(M² − 2E·I₁)/(I₁·I₂·I₃)),
///     k² = (I₂ − I₁)(2E·I₃ − M²)/((I₃ − I₂)(M² − 2E·I₁)).
/// The spin starts at its largest Ω_y, sn = 1, so τ₀ = K(k), and Ω_y (with it
/// L's component on the body y axis) changes sign whenever sn does, at
/// τ = 2K, 4K, …: t_n = (2n − 1)·K(k)/s. Near the unstable spin k is close to 1
/// and K(k) ≈ ln(4/√(1 − k²)) is large: the smaller the nudge, the longer the wait.
std::vector<Real> exactFlipTimes(Real duration) {
    const Real i1 = kBoxMoments.z, i2 = kBoxMoments.y, i3 = kBoxMoments.x;
    const Vec3 pi = kBoxMoments * kSpin;  // body-frame L at t = 0 (the box starts unrotated)
    const Real m2 = glm::dot(pi, pi);
    const Real twoE = glm::dot(kSpin, pi);
    const Real s = std::sqrt((i3 - i2) * (m2 - twoE * i1) / (i1 * i2 * i3));
    const Real k = std::sqrt((i2 - i1) * (twoE * i3 - m2) / ((i3 - i2) * (m2 - twoE * i1)));
    const Real quarterPeriod = std::comp_ellint_1(k) / s;  // K(k)/s, seconds
    std::vector<Real> times;
    for (Real t = quarterPeriod; t < duration; t += 2 * quarterPeriod) times.push_back(t);
    return times;
}

/// The same flips from a numerical reference: Euler's equations in the body
/// frame, I·ω̇ = (I·ω) × ω, by classical Runge–Kutta (4th order) at dt = 1e-4 s,
/// 167 times finer than the lesson's step. ω_y changes sign when Π_y does.
std::vector<Real> referenceFlipTimes(Real duration) {
    const auto rate = [](const Vec3& w) { return glm::cross(kBoxMoments * w, w) / kBoxMoments; };
    const Real dt = Real(1e-4);
    Vec3 w = kSpin;
    std::vector<Real> times;
    const long steps = std::lround(duration / dt);
    for (long i = 0; i < steps; ++i) {
        const Vec3 k1 = rate(w);
        const Vec3 k2 = rate(w + Real(0.5) * dt * k1);
        const Vec3 k3 = rate(w + Real(0.5) * dt * k2);
        const Vec3 k4 = rate(w + dt * k3);
        const Vec3 next = w + dt / 6 * (k1 + Real(2) * k2 + Real(2) * k3 + k4);
        if ((next.y < 0) != (w.y < 0)) times.push_back(crossing(Real(i) * dt, dt, w.y, next.y));
        w = next;
    }
    return times;
}

/// Angle of a rotation about a known fixed axis, from its quaternion.
Real angleAbout(const Quat& q, const Vec3& axis) {
    return 2 * std::atan2(glm::dot(Vec3(q.x, q.y, q.z), axis), q.w);
}

}  // namespace

// ------------------------------------------------------------------ Dzhanibekov

TEST_CASE("The reference flip times agree with the exact elliptic-function solution", "[rotation]") {
    // Before trusting the reference, check it: RK4 at dt = 1e-4 has a global
    // error ~ (dt·λ)⁴ ≈ 1e-14 per unit time (λ ≈ 2.4 /s), amplified near the
    // unstable spin; 1e-6 relative on each flip time is a wide margin for it
    // and for the linear interpolation of the crossing (error ~ dt² ω̈/ω̇).
    const std::vector<Real> exact = exactFlipTimes(kFlipDuration);
    const std::vector<Real> reference = referenceFlipTimes(kFlipDuration);
    REQUIRE(exact.size() == 3);  // 3.012 s, 9.036 s, 15.060 s
    REQUIRE(reference.size() == exact.size());
    for (std::size_t i = 0; i < exact.size(); ++i) CHECK_THAT(reference[i], WithinRel(double(exact[i]), 1e-6));
}

TEST_CASE("A box spun about its intermediate axis flips periodically (Dzhanibekov)", "[rotation]") {
    const std::vector<Real> reference = referenceFlipTimes(kFlipDuration);
    for (IntegratorKind kind : {IntegratorKind::SymplecticEuler, IntegratorKind::Verlet}) {
        INFO(toString(kind) << " at h = 1/60 s");
        const FlipRun run = spinTheBox(kind, kLessonStep);

        REQUIRE(run.flips.size() >= 3);
        REQUIRE(run.flips.size() == reference.size());
        // Equal intervals within 5 %: by symmetry every flip takes the same time.
        const Real interval = run.flips[1] - run.flips[0];
        for (std::size_t i = 2; i < run.flips.size(); ++i) {
            CHECK_THAT(run.flips[i] - run.flips[i - 1], WithinRel(double(interval), 0.05));
        }
        // The splitting's phase error is O(h²): (h·ω)² ≈ (5/60)² ≈ 0.7 % per unit
        // of phase at most, so 2 % on every flip time is a safe bound (measured: 0.02 %).
        for (std::size_t i = 0; i < run.flips.size(); ++i) {
            INFO("flip " << i);
            CHECK_THAT(run.flips[i], WithinRel(double(reference[i]), 0.02));
        }
        // L is never changed without torque, so |L| is exact up to round-off
        // of ω's recomputation; 1e-6 is the brief's bound, met with room.
        CHECK(run.worstMomentumError <= 1e-6);
        // Energy error of a second-order Poisson splitting is bounded, O(h²):
        // never more than 1 % from the start (measured: 0.05 %).
        CHECK(run.worstEnergyError <= 0.01);
    }
}

TEST_CASE("The splitting's energy error is bounded and second order", "[rotation]") {
    // Halving h quarters the worst energy error over 20 s: observed order within 0.1 of 2.
    for (IntegratorKind kind : {IntegratorKind::SymplecticEuler, IntegratorKind::Verlet}) {
        INFO(toString(kind));
        const Real coarse = spinTheBox(kind, kLessonStep).worstEnergyError;
        const Real fine = spinTheBox(kind, kLessonStep / 2).worstEnergyError;
        CHECK_THAT(std::log2(coarse / fine), WithinAbs(2.0, 0.1));
    }
}

TEST_CASE("Explicit Euler keeps |L| but its rotational energy only grows, at first order", "[rotation][euler]") {
    // One explicit step turns Π = Rᵀ·L about the old ω_n (body frame): a turn about
    // ω_n keeps ω_n·Π, so ω_n·ΔΠ = 0, and with E = ½·Π·I⁻¹·Π, I⁻¹·Π_n = ω_n:
    //     E_{n+1} − E_n = ω_n·ΔΠ + ½·ΔΠ·I⁻¹·ΔΠ = ½·ΔΠ·I⁻¹·ΔΠ ≥ 0   exactly,
    // with ΔΠ ≈ h·Π×ω: every step adds energy, the rotational twin of the
    // oscillator's factor (1 + h²ω²).
    const FlipRun coarse = spinTheBox(IntegratorKind::ExplicitEuler, kLessonStep);
    const FlipRun fine = spinTheBox(IntegratorKind::ExplicitEuler, kLessonStep / 2);
    for (const FlipRun* run : {&coarse, &fine}) {
        CHECK(run->worstMomentumError <= 1e-6);  // L is not touched without torque
        // Never decreases: allow round-off in E (~1e-15 relative per evaluation).
        CHECK(run->largestEnergyDecrease <= 1e-13);
        // The gain of every step is the predicted ½·ΔΠ·I⁻¹·ΔΠ. E ≈ 10–21 J is
        // computed to ~1e-15 relative, so a difference of two energies is good
        // to a few 1e-14 J; 1e-12 J leaves a wide margin.
        CHECK(run->worstEulerGainMismatch <= 1e-12);
    }
    // First order while the motion is still that of the true body (t = 2 s,
    // before the first flip): halving h halves the energy error. Observed order within 0.1 of 1.
    CHECK(coarse.energyErrorAt2s > 0);
    CHECK_THAT(std::log2(coarse.energyErrorAt2s / fine.energyErrorAt2s), WithinAbs(1.0, 0.1));
    // Over 20 s the gain feeds on itself: at h = 1/60 s the energy has grown by
    // more than half (measured: +99 %, close to the +100 % of a spin about the
    // minor axis with the same |L|: E = |L|²/(2·I_z) is twice |L|²/(2·I_y)).
    // The box no longer flips; it wobbles about its long axis. Smaller h, smaller gain.
    CHECK(coarse.finalEnergyError > 0.5);
    CHECK(fine.finalEnergyError < coarse.finalEnergyError);
    CHECK(coarse.finalEnergyError <= 1.0);  // E ≤ |L|²/(2·I_min) = 2·E₀ for any orientation
}

// ------------------------------------------------------------------ torque-free spheres and tops

TEST_CASE("A torque-free sphere keeps w and turns by exactly |w|*t about it", "[rotation]") {
    // I₁ = I₂ = I₃: ω = L/I is constant whatever the orientation, and the exact
    // motion is one rotation by |ω|·t about ω. Tolerance: 120 steps of round-off.
    const Vec3 omega(0.3, -1.2, 2.0);
    const Quat q0 = glm::angleAxis(Real(1.1), glm::normalize(Vec3(1, 1, 0)));
    const Real h = kLessonStep;
    for (IntegratorKind kind : test::kAllIntegrators) {
        INFO(toString(kind));
        std::vector<DynamicObject> bodies{test::sphere("ball", Vec3(0))};
        bodies[0].orientation = q0;
        bodies[0].angularVelocity = omega;
        initialiseMassProperties(bodies[0]);
        for (int i = 0; i < 120; ++i) step(kind, bodies, h, kNoForces);
        const Real t = 120 * h;
        const Quat exact = glm::angleAxis(glm::length(omega) * t, glm::normalize(omega)) * q0;
        CHECK(glm::length(bodies[0].angularVelocity - omega) < 1e-12);
        CHECK(std::abs(std::abs(glm::dot(bodies[0].orientation, exact)) - 1) < 1e-12);  // same rotation (q ~ -q)
    }
}

TEST_CASE("A torque-free box spun about a principal axis keeps w", "[rotation]") {
    // ω along a principal axis is an equilibrium of Euler's equations (Π × ω = 0):
    // every integrator reproduces it, the splitting because the other two
    // sub-flows have zero angle. The symmetric top (1×1×3, I₁ = I₂) spun about
    // its figure axis and about a transverse axis; the 1×2×3 box about its
    // major axis. Tolerance: round-off over 600 steps.
    struct Case { Vec3 size; Vec3 bodyOmega; };
    const Quat q0 = glm::angleAxis(Real(0.8), glm::normalize(Vec3(2, -1, 3)));
    for (const Case c : {Case{Vec3(1, 1, 3), Vec3(0, 0, 7)}, Case{Vec3(1, 1, 3), Vec3(3, 0, 0)},
                         Case{kBoxSize, Vec3(4, 0, 0)}}) {
        for (IntegratorKind kind : test::kAllIntegrators) {
            INFO(toString(kind) << ", size (" << c.size.x << ", " << c.size.y << ", " << c.size.z << ")");
            DynamicObject top = spinningBox(Vec3(0), q0);
            top.scale = c.size;
            top.angularVelocity = q0 * c.bodyOmega;  // world frame
            initialiseMassProperties(top);
            std::vector<DynamicObject> bodies{top};
            for (int i = 0; i < 600; ++i) step(kind, bodies, kLessonStep, kNoForces);
            CHECK(glm::length(bodies[0].angularVelocity - top.angularVelocity) < 1e-10 * glm::length(top.angularVelocity));
        }
    }
}

TEST_CASE("A torque-free symmetric top's figure axis precesses about L at |L|/I1", "[rotation]") {
    // For I₁ = I₂ the angular velocity is ω = L/I₁ + (1/I₃ − 1/I₁)·Π₃·e₃, so the
    // figure axis e₃ (world) moves as ė₃ = ω × e₃ = (L/I₁) × e₃: it circles the
    // fixed L at the constant rate |L|/I₁ (Goldstein, *Classical Mechanics*, §5.6).
    // The top: a 1×1×3 box, I = (10, 10, 2)/12 kg·m², started tilted off its figure axis.
    const Quat q0(1, 0, 0, 0);
    DynamicObject top = spinningBox(Vec3(1.5, 0, 6), q0);
    top.scale = Vec3(1, 1, 3);
    top.angularVelocity = Vec3(1.5, 0, 6);
    initialiseMassProperties(top);
    const Vec3 l = top.angularMomentum;
    const Real precessionRate = glm::length(l) / top.inertiaBody.x;  // rad/s
    const Real t = 2;
    const Vec3 exactAxis = glm::angleAxis(precessionRate * t, glm::normalize(l)) * Vec3(0, 0, 1);

    auto axisError = [&](IntegratorKind kind, Real h) {
        std::vector<DynamicObject> bodies{top};
        const long n = std::lround(t / h);
        for (long i = 0; i < n; ++i) step(kind, bodies, h, kNoForces);
        return glm::length(bodies[0].orientation * Vec3(0, 0, 1) - exactAxis);
    };
    // Explicit Euler turns by ω_n for h: first order, observed from h = 1/60 and 1/120 s (within 0.15:
    // at these steps the next error term is still a few per cent of the leading one).
    const Real coarse = axisError(IntegratorKind::ExplicitEuler, kLessonStep);
    const Real fine = axisError(IntegratorKind::ExplicitEuler, kLessonStep / 2);
    CHECK_THAT(std::log2(coarse / fine), WithinAbs(1, 0.15));
    // Symplectic Euler and Verlet turn a symmetric top by its closed form (free_rotation.cpp): exact
    // for any step, so after 120 steps of 1/60 s the axis is where the precession puts it up to
    // round-off (120 steps of a few ε each; the five-turn splitting was off by 3.6e-5 here).
    for (const IntegratorKind kind : {IntegratorKind::SymplecticEuler, IntegratorKind::Verlet}) {
        INFO(toString(kind));
        CHECK(axisError(kind, kLessonStep) < 1e-12);
        CHECK(axisError(kind, Real(1) / 7) < 1e-12);  // 14 steps of 1/7 s: as exact
    }
}

// ------------------------------------------------------------------ torque

TEST_CASE("A constant torque spins a sphere up as w = tau*t/I", "[rotation]") {
    // τ = 0.2 N·m about z on a ball of 1 kg, r = 0.5 m: I = ⅖·1·0.25 = 0.1 kg·m²,
    // α = τ/I = 2 rad/s². After 1 s, ω = 2 rad/s for every integrator (L = n·h·τ, sums of
    // one number). The angle turned is ½αt² = 1 rad, up to each scheme's signature,
    // the same as the projectile's position (tests/test_integrators.cpp):
    //   explicit Euler turns with ω_k = k·h·α:        θ_n = α·h²·n(n−1)/2 = ½αt² − ½αht
    //   symplectic Euler with ω_{k+1} = (k+1)·h·α:   θ_n = α·h²·n(n+1)/2 = ½αt² + ½αht
    //   Verlet with the half-step ω = (k+½)·h·α:      θ_n = α·h²·n²/2     = ½αt²  (exact)
    const Vec3 torque(0, 0, 0.2);
    const AccelerationFunction motor = [torque](std::span<DynamicObject> bodies) {
        for (DynamicObject& body : bodies) {
            body.acceleration = Vec3(0);
            body.torque = torque;
        }
    };
    const Real inertia = 0.1, alpha = 2;
    const Real h = kLessonStep;
    const int n = 60;
    const Real t = n * h;
    struct Case { IntegratorKind kind; Real angleOffset; };
    for (const Case c : {Case{IntegratorKind::ExplicitEuler, -0.5 * alpha * h * t},
                         Case{IntegratorKind::SymplecticEuler, 0.5 * alpha * h * t},
                         Case{IntegratorKind::Verlet, 0}}) {
        INFO(toString(c.kind));
        std::vector<DynamicObject> bodies{test::sphere("ball", Vec3(0), Vec3(0), 0.5, 1)};
        initialiseMassProperties(bodies[0]);
        REQUIRE_THAT(bodies[0].inertiaBody.z, WithinAbs(inertia, 1e-15));
        for (int i = 0; i < n; ++i) step(c.kind, bodies, h, motor);
        // Round-off only: 60 additions of h·τ and a division.
        CHECK(glm::length(bodies[0].angularVelocity - torque * t / inertia) < 1e-12);
        CHECK(glm::length(bodies[0].angularMomentum - torque * t) < 1e-12);
        CHECK_THAT(angleAbout(bodies[0].orientation, Vec3(0, 0, 1)), WithinAbs(0.5 * alpha * t * t + c.angleOffset, 1e-12));
    }
}

TEST_CASE("A constant torque along a rotated box's principal axis gives w = tau*t/I_i", "[rotation]") {
    // The box 1×2×3 turned arbitrarily; the torque points along its body y axis
    // (I_y = 10/12 kg·m²) in the world. L = τ·t stays along that axis, which
    // is principal, so ω = τ·t/I_y along it, for every integrator, to round-off.
    const Quat q0 = glm::angleAxis(Real(0.9), glm::normalize(Vec3(-1, 2, 2)));
    const Vec3 torque = q0 * Vec3(0, 0.5, 0);  // 0.5 N·m along body y
    const AccelerationFunction motor = [torque](std::span<DynamicObject> bodies) {
        for (DynamicObject& body : bodies) {
            body.acceleration = Vec3(0);
            body.torque = torque;
        }
    };
    const Real t = 1;
    for (IntegratorKind kind : test::kAllIntegrators) {
        INFO(toString(kind));
        std::vector<DynamicObject> bodies{spinningBox(Vec3(0), q0)};
        for (int i = 0; i < 60; ++i) step(kind, bodies, kLessonStep, motor);
        CHECK(glm::length(bodies[0].angularVelocity - torque * t / kBoxMoments.y) < 1e-10);
    }
}

TEST_CASE("The apply-forces stage clears last step's torque", "[rotation]") {
    // A uniform field exerts no torque about the centre of mass; nothing else does yet.
    std::vector<DynamicObject> bodies{test::sphere("ball", Vec3(0))};
    bodies[0].torque = Vec3(1, 2, 3);
    uniformForces(Vec3(0, -kStandardGravity, 0))(bodies);
    CHECK(bodies[0].torque == Vec3(0));
}

// ------------------------------------------------------------------ measurements and the lesson scene

TEST_CASE("Energy splits into translational and rotational, and L about the origin adds x cross m v", "[rotation]") {
    // One box moving and spinning: m = 1 kg at x = (1, 0, 0) with v = (0, 2, 0), ω = (0, 0, 3) about
    // its body z axis (I_z = 5/12): translational ½·1·4 = 2 J, rotational ½·(5/12)·9 = 15/8 J,
    // L_O = x × m·v + I_z·ω = (0, 0, 2) + (0, 0, 5/4) kg·m²/s.
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, kLessonStep, Vec3(0));
    DynamicObject box = spinningBox(Vec3(0, 0, 3));
    box.position = Vec3(1, 0, 0);
    box.velocity = Vec3(0, 2, 0);
    scene.dynamics.push_back(box);
    const World world(scene);
    const Energy energy = energyOf(world);
    CHECK_THAT(energy.translational, WithinAbs(2.0, 1e-14));
    CHECK_THAT(energy.rotational, WithinAbs(15.0 / 8, 1e-14));
    CHECK_THAT(energy.kinetic, WithinAbs(2.0 + 15.0 / 8, 1e-14));
    CHECK_THAT(energy.total(), WithinAbs(2.0 + 15.0 / 8, 1e-14));  // no gravity, no potential
    CHECK(glm::length(angularMomentumOf(world) - Vec3(0, 0, 2 + 1.25)) < 1e-14);
}

TEST_CASE("The lesson 4 scene flips the box on time through World::step", "[rotation]") {
    // config/lesson04_dzhanibekov.scene is the box of the tests above, run by
    // the whole pipeline: the same bounds as the stage-level test.
    World world(loadSceneFile(STEPWISE_SOURCE_DIR "/config/lesson04_dzhanibekov.scene"));
    REQUIRE(world.dynamics().size() == 1);
    const Vec3 l0 = angularMomentumOf(world);
    const Energy e0 = energyOf(world);
    REQUIRE(glm::length(l0) > 0);
    CHECK(e0.translational == 0);

    const std::vector<Real> reference = referenceFlipTimes(world.settings().duration);
    std::vector<Real> flips;
    Real previousSide = bodyMomentum(world.dynamics()[0]).y;
    Real worstMomentumError = 0, worstEnergyError = 0;
    const long steps = std::lround(world.settings().duration / world.settings().timeStep);
    for (long i = 0; i < steps; ++i) {
        const Real t0 = world.time();
        world.step();
        const Real side = bodyMomentum(world.dynamics()[0]).y;
        if ((side < 0) != (previousSide < 0)) flips.push_back(crossing(t0, world.settings().timeStep, previousSide, side));
        previousSide = side;
        worstMomentumError = std::max(worstMomentumError, glm::length(angularMomentumOf(world) - l0) / glm::length(l0));
        worstEnergyError = std::max(worstEnergyError, std::abs(energyOf(world).rotational - e0.rotational) / e0.rotational);
    }
    REQUIRE(flips.size() == reference.size());
    for (std::size_t i = 0; i < flips.size(); ++i) CHECK_THAT(flips[i], WithinRel(double(reference[i]), 0.02));
    CHECK(worstMomentumError <= 1e-6);
    CHECK(worstEnergyError <= 0.01);
}

TEST_CASE("rotateByAngularVelocity turns by |w|*h about w, on the series path and the library path", "[rotation]") {
    // The exact turn: angle |ω|·h about ω/|ω| (glm::angleAxis: cos and sin from the library).
    // Half-angles from 1e-6 rad (series) through 0.1 (the switch) to 1.2 (sin and cos),
    // about an oblique axis, from an oblique start.
    const Quat start = glm::normalize(Quat(0.8, -0.3, 0.4, 0.33));
    const Vec3 axis = glm::normalize(Vec3(1, -2, 0.5));
    const Real h = Real(1) / Real(960);
    for (const Real halfAngle : {Real(1e-6), Real(1e-3), Real(0.05), Real(0.0999), Real(0.1001), Real(0.7), Real(1.2)}) {
        const Real speed = 2 * halfAngle / h;  // rad/s
        const Quat exact = glm::angleAxis(2 * halfAngle, axis) * start;
        const Quat got = rotateByAngularVelocity(start, speed * axis, h);
        INFO("half-angle " << halfAngle << " rad");
        // Both are unit quaternions; a few ulps of 1 apart (the series is exact to rounding).
        CHECK(std::abs(glm::length(got) - 1) < 4 * std::numeric_limits<Real>::epsilon());
        for (int k = 0; k < 4; ++k) CHECK(std::abs(got[k] - exact[k]) < 8 * std::numeric_limits<Real>::epsilon());
    }
    // The series' last terms matter only near the switch: from the identity the turn is
    // (cos φ, sin φ·axis) itself, which must match the library to 2 ulps of 1 at φ = 0.0999
    // (a coefficient of sin φ/φ off in its third digit, 1/5000 for 1/7!, fails here; the
    // cosine's own small errors are taken out by the renormalisation, as |q| = 1 fixes cos φ
    // from sin φ).
    const Real halfAngle = Real(0.0999);
    const Quat turn = rotateByAngularVelocity(Quat(1, 0, 0, 0), (2 * halfAngle / h) * axis, h);
    CHECK(std::abs(turn.w - std::cos(halfAngle)) < 2 * std::numeric_limits<Real>::epsilon());
    for (int k = 0; k < 3; ++k) {
        CHECK(std::abs(turn[k] - std::sin(halfAngle) * axis[k]) < 2 * std::numeric_limits<Real>::epsilon());
    }
}

TEST_CASE("rotateByAngularVelocity returns a unit quaternion from one far off unit length", "[rotation]") {
    // The Newton renormalisation is only for |q|² within 1e-6 of 1; farther, the full one.
    const Quat stretched = Real(1.5) * glm::normalize(Quat(0.8, -0.3, 0.4, 0.33));
    const Quat got = rotateByAngularVelocity(stretched, Vec3(0, 3, 0), Real(1) / Real(60));
    CHECK(std::abs(glm::length(got) - 1) < 4 * std::numeric_limits<Real>::epsilon());
    const Quat exact = glm::angleAxis(Real(3) / Real(60), Vec3(0, 1, 0)) * glm::normalize(stretched);
    for (int k = 0; k < 4; ++k) CHECK(std::abs(got[k] - exact[k]) < 8 * std::numeric_limits<Real>::epsilon());
}

TEST_CASE("The turn in lanes is rotateByAngularVelocity, to the bit, or hands the lane back", "[rotation][lanes]") {
    // The packed substeps turn four balls at once (rotation_lanes.hpp). Each lane must be
    // the scalar turn's bits, or say that it needs the scalar turn: a half-angle past the
    // series (φ > 0.1), a start too far from unit length for the Newton step, a NaN.
    // Groups of four mixing the cases, so a lane's case cannot leak into its neighbours.
    const Real h = Real(1) / Real(960);
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    const Quat unit = glm::normalize(Quat(0.8, -0.3, 0.4, 0.33));
    const Quat nearlyUnit = Real(1 + 1e-9) * unit;  // rounding's drift: the Newton step's
    const Quat stretched = Real(1.5) * unit;        // the full normalisation's
    const Vec3 axis = glm::normalize(Vec3(1, -2, 0.5));
    struct Case {
        Quat start;
        Vec3 omega;
        bool lanesCover;  // the lanes give the answer themselves
    };
    const std::vector<Case> cases = {
        {unit, Vec3(0), true},                                    // no turn: q itself
        {unit, Vec3(1e-14, 0, 0), true},                          // negligible: q itself
        {unit, (2 * Real(1e-6) / h) * axis, true},                // series
        {nearlyUnit, (2 * Real(0.05) / h) * axis, true},          // series, Newton step
        {unit, (2 * Real(0.0999) / h) * axis, true},              // just inside the series
        {unit, (2 * Real(0.1001) / h) * axis, false},             // just past it: sin and cos
        {stretched, Vec3(0, 3, 0), false},                        // far from unit length
        {unit, Vec3(nan, 0, 0), false},                           // not finite
        {unit, Vec3(0.3, -40, 7), true},                          // a rolling ball's
        {Quat(1, 0, 0, 0), Vec3(-2, 0.5, 150), true},             // fast (φ = 0.078), still in the series
        {unit, (2 * Real(1.2) / h) * axis, false},                // far past the series
        {nearlyUnit, Vec3(0), true},                              // no turn, off unit: q itself
    };
    int covered = 0;
    for (std::size_t first = 0; first + kLanes <= cases.size(); ++first) {  // every window of four
        QuatLanes q;
        Vec3Lanes omega;
        for (int lane = 0; lane < kLanes; ++lane) {
            const Case& c = cases[first + static_cast<std::size_t>(lane)];
            q.w[lane] = c.start.w;
            q.x[lane] = c.start.x;
            q.y[lane] = c.start.y;
            q.z[lane] = c.start.z;
            omega.setLane(lane, c.omega);
        }
        const TurnLanes turned = rotateByAngularVelocity(q, omega, h);
        for (int lane = 0; lane < kLanes; ++lane) {
            const Case& c = cases[first + static_cast<std::size_t>(lane)];
            INFO("case " << first + static_cast<std::size_t>(lane) << ", lane " << lane);
            REQUIRE((turned.needsScalar[lane] == 0) == c.lanesCover);
            if (!c.lanesCover) continue;
            ++covered;
            const Quat expected = rotateByAngularVelocity(c.start, c.omega, h);
            const Real got[4] = {turned.orientation.w[lane], turned.orientation.x[lane], turned.orientation.y[lane],
                                 turned.orientation.z[lane]};
            const Real want[4] = {expected.w, expected.x, expected.y, expected.z};
            for (int k = 0; k < 4; ++k) CHECK(std::memcmp(&got[k], &want[k], sizeof(Real)) == 0);
        }
    }
    CHECK(covered > 0);

    // And many ordinary turns: random unit starts, half-angles up to 0.12 (some past the series).
    std::mt19937 random(11);
    std::uniform_real_distribution<double> component(-1, 1);
    int mismatches = 0, handedBack = 0;
    for (int group = 0; group < 500; ++group) {
        QuatLanes q;
        Vec3Lanes omega;
        Quat starts[kLanes];
        Vec3 omegas[kLanes];
        for (int lane = 0; lane < kLanes; ++lane) {
            starts[lane] = glm::normalize(Quat(component(random), component(random), component(random), component(random)));
            omegas[lane] = Vec3(component(random), component(random), component(random)) * Real(130);  // |ω|·h/2 ≤ 0.12
            q.w[lane] = starts[lane].w;
            q.x[lane] = starts[lane].x;
            q.y[lane] = starts[lane].y;
            q.z[lane] = starts[lane].z;
            omega.setLane(lane, omegas[lane]);
        }
        const TurnLanes turned = rotateByAngularVelocity(q, omega, h);
        for (int lane = 0; lane < kLanes; ++lane) {
            if (turned.needsScalar[lane]) {
                ++handedBack;
                continue;
            }
            const Quat expected = rotateByAngularVelocity(starts[lane], omegas[lane], h);
            const Real got[4] = {turned.orientation.w[lane], turned.orientation.x[lane], turned.orientation.y[lane],
                                 turned.orientation.z[lane]};
            const Real want[4] = {expected.w, expected.x, expected.y, expected.z};
            mismatches += std::memcmp(got, want, sizeof got) != 0 ? 1 : 0;
        }
    }
    CHECK(mismatches == 0);
    CHECK(handedBack > 0);          // some were past the series,
    CHECK(handedBack < 500 * kLanes / 10);  // and most were not
}

TEST_CASE("World inertia of an isotropic body is I*E in every orientation, as the rotated tensor", "[rotation][inertia]") {
    // rotateDiagonal's shortcut for three equal moments against R·diag·Rᵀ computed by hand.
    const Quat q = glm::normalize(Quat(0.2, 0.9, -0.3, 0.25));
    const Mat3 r = glm::mat3_cast(q);
    const Real moment = Real(0.4) * Real(523.6) * Real(0.25);  // ⅖·m·r², kg·m²
    const Mat3 byHand = r * Mat3(moment) * glm::transpose(r);
    const Mat3 got = worldInertia(q, Vec3(moment));
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) CHECK(std::abs(got[i][j] - byHand[i][j]) < 1e-12 * moment);
    }
}
