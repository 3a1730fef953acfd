/// @file soft_stability.hpp
/// @brief Will a soft body's springs blow up at this time step? The explicit limit h·ω < 2.
///
/// A node of mass m held by springs of stiffness k_j swings; the fastest
/// swing of the whole network sets the limit, exactly as for one spring
/// (src/forces/spring_stability.hpp): symplectic Euler and Verlet stay
/// bounded while h·ω ≤ 2, explicit Euler never does without damping.
/// The fastest angular frequency is ω_max = √(λ_max/m) with λ_max the
/// largest eigenvalue of the springs' stiffness matrix. Gershgorin's circle
/// theorem bounds it by the largest row sum: node i's own block has norm at
/// most Σ_j k_ij and each neighbour's block at most k_ij, so
/// \f[ \lambda_{max} \le k_{eff} = 2\,\max_i \sum_{j} k_{ij} . \f]
/// The bound is reached by a chain whose neighbours swing against each
/// other (ω² = 4k/m for two springs a node); on a curved mesh the springs
/// point different ways and the true ω is somewhat lower, so the check
/// warns a little early, never late. The gas stiffens the surface too
/// (its force grows as the ball is squeezed), by much less than the springs
/// for the pressures a ball is inflated with; it is left out.
#pragma once

#include "core/types.hpp"
#include "core/world_settings.hpp"
#include "objects/soft_body.hpp"

namespace stepwise {

/// @brief What a soft body's stability comes down to.
struct SoftStability {
    Real nodeMass = 0;          ///< m of one node, kg.
    Real effectiveStiffness = 0;///< k_eff = 2·max over nodes of Σ k of its springs, N/m.
    Real omega = 0;             ///< ω = √(k_eff/m), rad/s.
    Real dampingRatio = 0;      ///< ζ = c_eff/(2√(k_eff·m)), c_eff from the dampers the same way.
    Real growthPerStep = 1;     ///< ρ = amplificationPerStep(): the swing's factor per step.
    Real largestStableStep = 0; ///< The largest h with ρ ≤ 1, s (dampers included); 0 when none is (undamped explicit Euler).
};

/// @brief Stability of @p body's springs stepped by @p integrator at the step @p h (a substep under the sequential impulse).
SoftStability analyseSoftBody(const SoftBody& body, IntegratorKind integrator, Real h);

}  // namespace stepwise
