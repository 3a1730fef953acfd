/// @file spring_stability.cpp
/// @brief The amplification matrix of each integrator on a damped spring, and its spectral radius.
///
/// Rather than copy three formulas for M, each integrator's step is written
/// out once on the scalar oscillator u¨ = a(u, u̇) = −ω²u − 2ζω·u̇, in the same
/// order as its file in src/integrators/ (including where Verlet's damper
/// reads the half-kicked velocity). The step is linear, so its matrix M has
/// as columns the images of the states (1, 0) and (0, 1). For a 2×2 matrix
/// with trace T and determinant D the eigenvalues are
/// \f[ \lambda = \tfrac{T}{2} \pm \sqrt{\tfrac{T^2}{4} - D}, \f]
/// a complex pair of modulus √D when T²/4 < D, otherwise two reals.
#include "forces/spring_stability.hpp"

#include <cmath>

namespace stepwise {

namespace {

/// A state of the scalar oscillator: displacement u (m) and its rate w = u̇ (m/s).
struct OscillatorState {
    Real u = 0;
    Real w = 0;
};

/// ρ within this of 1 counts as neutral: the symplectic methods have ρ = 1
/// exactly, computed as √D with D = 1 up to rounding.
constexpr Real kNeutralTolerance = Real(1e-12);
/// Bisection steps for the largest stable step: halving the interval 60 times
/// takes it below double precision.
constexpr int kBisectionSteps = 60;
/// Doublings allowed while looking for an unstable step to start the bisection from.
constexpr int kMaxDoublings = 60;
/// The first step tried as unstable, in units of 1/ω: the undamped limit h·ω = 2.
constexpr Real kUndampedLimit = 2;

OscillatorState step(IntegratorKind integrator, const OscillatorState& s, Real h, Real omega, Real zeta) {
    const auto accel = [&](Real u, Real w) { return -omega * omega * u - 2 * zeta * omega * w; };
    OscillatorState next;
    switch (integrator) {
        case IntegratorKind::ExplicitEuler:  // explicit_euler.cpp: both from the old state
            next.u = s.u + h * s.w;
            next.w = s.w + h * accel(s.u, s.w);
            break;
        case IntegratorKind::SymplecticEuler:  // symplectic_euler.cpp: velocity first, then move with it
            next.w = s.w + h * accel(s.u, s.w);
            next.u = s.u + h * next.w;
            break;
        case IntegratorKind::Verlet: {  // verlet.cpp: half kick, drift, forces again, half kick
            const Real a0 = accel(s.u, s.w);
            next.u = s.u + h * s.w + Real(0.5) * h * h * a0;
            const Real halfKicked = s.w + Real(0.5) * h * a0;
            next.w = halfKicked + Real(0.5) * h * accel(next.u, halfKicked);
            break;
        }
    }
    return next;
}

bool isStable(IntegratorKind integrator, Real h, Real omega, Real zeta) {
    return amplificationPerStep(integrator, h, omega, zeta) <= 1 + kNeutralTolerance;
}

/// Largest h with ρ(h) ≤ 1, by bisection; assumes the stable steps form one interval from 0.
Real largestStableStep(IntegratorKind integrator, Real omega, Real zeta) {
    // Undamped explicit Euler has ρ = √(1 + h²ω²) > 1 for every h > 0: never stable.
    if (integrator == IntegratorKind::ExplicitEuler && zeta == 0) return 0;
    Real stable = 0;
    Real unstable = kUndampedLimit / omega;
    for (int i = 0; i < kMaxDoublings && isStable(integrator, unstable, omega, zeta); ++i) {
        stable = unstable;
        unstable *= 2;
    }
    for (int i = 0; i < kBisectionSteps; ++i) {
        const Real middle = Real(0.5) * (stable + unstable);
        (isStable(integrator, middle, omega, zeta) ? stable : unstable) = middle;
    }
    return stable;
}

}  // namespace

Real amplificationPerStep(IntegratorKind integrator, Real h, Real omega, Real dampingRatio) {
    const OscillatorState column1 = step(integrator, {1, 0}, h, omega, dampingRatio);  // M·(1, 0)
    const OscillatorState column2 = step(integrator, {0, 1}, h, omega, dampingRatio);  // M·(0, 1)
    const Real trace = column1.u + column2.w;
    const Real determinant = column1.u * column2.w - column2.u * column1.w;
    const Real discriminant = Real(0.25) * trace * trace - determinant;
    if (discriminant < 0) return std::sqrt(determinant);  // complex pair: |λ|² = λ·λ̄ = D
    return Real(0.5) * std::abs(trace) + std::sqrt(discriminant);
}

SpringStability analyseSpring(const Spring& spring, std::span<const DynamicObject> bodies,
                              IntegratorKind integrator, Real h) {
    SpringStability result;
    result.effectiveMass = springEffectiveMass(spring, bodies);
    if (spring.stiffness <= 0) {
        // A pure damper has no oscillation to grow; its own limit (h·c/m < 2) is not checked here.
        result.largestStableStep = std::numeric_limits<Real>::infinity();
        return result;
    }
    result.omega = std::sqrt(spring.stiffness / result.effectiveMass);
    result.dampingRatio = spring.damping / (2 * std::sqrt(spring.stiffness * result.effectiveMass));
    result.growthPerStep = amplificationPerStep(integrator, h, result.omega, result.dampingRatio);
    result.largestStableStep = largestStableStep(integrator, result.omega, result.dampingRatio);
    return result;
}

}  // namespace stepwise
