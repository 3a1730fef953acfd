/// @file position_share.cpp
/// @brief How much of a step's velocity change each integrator turns into displacement within the step.
///
/// Write each integrator's position update as x_{n+1} = x_n + h·v_n + s·h·Δv,
/// with Δv = v_{n+1} − v_n the step's velocity change:
/// - explicit Euler moves with v_n alone: s = 0;
/// - symplectic Euler moves with v_{n+1} = v_n + Δv: s = 1;
/// - velocity Verlet moves by h·v_n + ½h²·a_n, and Δv = h·a for a constant
///   force, so ½h²·a = ½h·Δv: s = ½.
/// The position-correction stage uses s to move a body supported by a
/// resting contact as the integrator would have, had the support been a force.
#include "integrators/integrators.hpp"

namespace stepwise {

Real positionShareOfVelocityChange(IntegratorKind integrator) {
    switch (integrator) {
        case IntegratorKind::ExplicitEuler: return Real(0);
        case IntegratorKind::SymplecticEuler: return Real(1);
        case IntegratorKind::Verlet: return Real(0.5);
    }
    return Real(1);
}

}  // namespace stepwise
