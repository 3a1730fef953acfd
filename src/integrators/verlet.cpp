/// @file verlet.cpp
/// @brief Velocity Verlet: second order, symplectic, exact under constant acceleration.
///
/// \f[ x_{n+1} = x_n + h\,v_n + \tfrac12 h^2 a_n, \qquad
///     a_{n+1} = a(x_{n+1}), \qquad
///     v_{n+1} = v_n + \tfrac12 h\,(a_n + a_{n+1}). \f]
/// The position update is the Taylor series to the h² term; the velocity
/// uses the trapezoidal rule, the average of the accelerations at both ends
/// of the step. The global error is O(h²): halve the step, quarter the
/// error. Like symplectic Euler it preserves phase-space area, so energy
/// errors stay bounded. For constant acceleration (a projectile under
/// gravity) both updates are the exact kinematic formulas, so it reproduces
/// x(t) = x₀ + v₀t + ½gt² to round-off at any step size.
///
/// It needs the acceleration at the new position, so it calls the force
/// model a second time per step. (A production engine would reuse that
/// a_{n+1} as the next step's a_n; Stepwise recomputes forces in their own
/// stage every step, because contacts may have moved the bodies in between.)
///
/// ## Rotation: half kick, free drift, half kick
/// Velocity Verlet is "kick h/2, drift h, kick h/2", and that is how it
/// treats rotation (the scheme of Dullweber, Leimkuhler & McLachlan 1997):
/// \f[ L_{n+\frac12} = L_n + \tfrac12 h\,\tau_n, \quad
///     q_{n+1} = \Phi_h^\text{free}(q_n;\, L_{n+\frac12}), \quad
///     L_{n+1} = L_{n+\frac12} + \tfrac12 h\,\tau(q_{n+1}). \f]
/// Φ^free is the symmetric free-body splitting (rotateTorqueFree(),
/// free_rotation.cpp). A symmetric composition of exact sub-flows is second
/// order and symplectic, with or without torque; without torque |L| is
/// exact and the energy error bounded, O(h²).
///
/// Reference: Swope, Andersen, Berens & Wilson, J. Chem. Phys. 76 (1982) 637;
/// Hairer, Lubich & Wanner, *Geometric Numerical Integration*, §I.1.4 and §VII.5;
/// Dullweber, Leimkuhler & McLachlan, J. Chem. Phys. 107 (1997) 5840.
#include "objects/inertia.hpp"
#include "integrators/integrators.hpp"

namespace stepwise {

void integrateVerlet(std::span<DynamicObject> bodies, Real h, const AccelerationFunction& accelerations) {
    const Real halfHSquared = Real(0.5) * h * h;
    for (DynamicObject& body : bodies) {
        if (body.asleep) continue;  // a sleeping body keeps its state until its island wakes
        body.position += h * body.velocity + halfHSquared * body.acceleration;
        // Half the velocity update now, with a_n; the other half needs a_{n+1}.
        body.velocity += Real(0.5) * h * body.acceleration;
        if (skipsRotation(body)) continue;  // a still sphere: the update below would change nothing

        body.angularMomentum += Real(0.5) * h * body.torque;  // half kick with τ_n
        body.orientation = rotateTorqueFree(body.orientation, body.angularMomentum, body.inverseInertiaBody, h);
        updateAngularVelocity(body);  // the force model may read ω at the new orientation
    }
    accelerations(bodies);  // a_{n+1} = a(x_{n+1}) and τ_{n+1} = τ(q_{n+1}), written into each body
    for (DynamicObject& body : bodies) {
        if (body.asleep) continue;  // a sleeping body keeps its state until its island wakes
        body.velocity += Real(0.5) * h * body.acceleration;
        if (skipsRotation(body)) continue;  // τ_{n+1} = 0 and L = 0: nothing to kick
        body.angularMomentum += Real(0.5) * h * body.torque;  // the other half kick, with τ_{n+1}
        updateAngularVelocity(body);
    }
}

}  // namespace stepwise
