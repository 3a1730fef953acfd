/// @file soft_stability.cpp
/// @brief The explicit stability limit of a soft body's springs: Gershgorin's bound, then one spring's analysis.
#include "soft/soft_stability.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "forces/spring_stability.hpp"

namespace stepwise {

namespace {

/// ρ within this of 1 counts as neutral: the symplectic methods have ρ = 1 to rounding.
constexpr Real kNeutralTolerance = Real(1e-12);
/// Halvings of the interval: 60 take it below double precision.
constexpr int kBisectionSteps = 60;

/// The largest h with ρ(h) ≤ 1, by bisection from the undamped limit 2/ω (doubled until unstable).
Real largestStableStep(IntegratorKind integrator, Real omega, Real zeta) {
    const auto stable = [&](Real h) { return amplificationPerStep(integrator, h, omega, zeta) <= 1 + kNeutralTolerance; };
    if (integrator == IntegratorKind::ExplicitEuler && zeta == 0) return 0;  // ρ = √(1 + h²ω²) > 1 for every h
    Real low = 0, high = 2 / omega;
    for (int i = 0; i < kBisectionSteps && stable(high); ++i) {
        low = high;
        high *= 2;
    }
    for (int i = 0; i < kBisectionSteps; ++i) {
        const Real middle = Real(0.5) * (low + high);
        (stable(middle) ? low : high) = middle;
    }
    return low;
}

}  // namespace

SoftStability analyseSoftBody(const SoftBody& body, IntegratorKind integrator, Real h) {
    SoftStability result;
    if (body.nodeCount() == 0) return result;
    // Σ k and Σ c of the springs at each node
    std::vector<Real> stiffness(body.nodeCount(), 0), damping(body.nodeCount(), 0);
    for (const SoftSpring& s : body.springs) {
        stiffness[s.a] += s.stiffness;
        stiffness[s.b] += s.stiffness;
        damping[s.a] += s.damping;
        damping[s.b] += s.damping;
    }
    const std::size_t busiest = static_cast<std::size_t>(std::max_element(stiffness.begin(), stiffness.end()) - stiffness.begin());
    result.nodeMass = Real(1) / body.nodeInverseMasses[busiest];
    result.effectiveStiffness = 2 * stiffness[busiest];
    if (result.effectiveStiffness <= 0) return result;
    result.omega = std::sqrt(result.effectiveStiffness / result.nodeMass);
    result.dampingRatio = 2 * damping[busiest] / (2 * std::sqrt(result.effectiveStiffness * result.nodeMass));
    result.growthPerStep = amplificationPerStep(integrator, h, result.omega, result.dampingRatio);
    result.largestStableStep = largestStableStep(integrator, result.omega, result.dampingRatio);
    return result;
}

}  // namespace stepwise
