/// @file soft_stability.cpp
/// @brief The explicit stability limit of a soft body's springs: Gershgorin's bound, then one spring's analysis.
#include "soft/soft_stability.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "forces/spring_stability.hpp"

namespace stepwise {

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
    result.undampedLimit = 2 / result.omega;
    return result;
}

}  // namespace stepwise
