/// @file symplectic_euler.cpp
/// @brief Symplectic (semi-implicit) Euler: one line swapped, energy tamed.
///
/// Update the velocity first, then move with the *new* velocity:
/// \f[ v_{n+1} = v_n + h\,a_n, \qquad x_{n+1} = x_n + h\,v_{n+1}. \f]
/// Still first order (global error O(h)), but the map preserves phase-space
/// area (it is symplectic), so on an oscillator the energy oscillates about
/// the true value with an amplitude O(h) instead of growing without bound.
/// This is the integrator most game engines use (Box2D, Bullet): it is as
/// cheap as explicit Euler and stable for stiff springs up to h·ω < 2.
///
/// With constant gravity the position leads by ½·g·h·t (the mirror image of
/// explicit Euler's lag).
///
/// ## Rotation: kick, then the free-body splitting
/// The same order for the rotational pair (L, q): the torque changes the
/// momentum first, then the body turns with the *new* momentum:
/// \f[ L_{n+1} = L_n + h\,\tau_n, \qquad q_{n+1} = \Phi_h^\text{free}(q_n;\, L_{n+1}), \f]
/// where Φ^free is the torque-free motion over h, computed by the symmetric
/// splitting of the free-body energy into three exact spins about the body
/// axes (rotateTorqueFree(), free_rotation.cpp). "Move with the new
/// momentum" is the same idea as x + h·v_{n+1}; here the move itself is
/// solved so well (second order, Poisson) that without torque the rotation
/// is better than first order: |L| is exact and the rotational energy
/// stays within an O(h²) band for ever, which is what keeps a spinning box
/// flipping at the right rate for thousands of turns. With torque the
/// method is first order, like the linear part.
///
/// ## On the solver's records (the packed substeps)
/// A ball in a contact can live in the contact solver's packed record for a
/// whole step (World::substepOnRecords()). There the two lines are split
/// around the solve: the kick v + h·a (and L + h·τ, ω = L/I) before it,
/// integrateSymplecticEulerOnRecords() below; the move x + h·v after it,
/// with the kicked velocities and then the solver's change, and the turn
/// once a step, driftRecordsByVelocityChange(). The operations are those of the object
/// road (this integrator, then driftByVelocityChange()), in the same order,
/// so the ball ends where the object road leaves it, to the bit.
///
/// Reference: Hairer, Lubich & Wanner, *Geometric Numerical Integration*, §I.1.2
/// and §VII.5; Millington, *Game Physics Engine Development*, §3.3;
/// Dullweber, Leimkuhler & McLachlan, J. Chem. Phys. 107 (1997) 5840.
#include "core/lanes.hpp"
#include "dynamics/contact_solver.hpp"
#include "dynamics/inertia.hpp"
#include "integrators/integrators.hpp"

namespace stepwise {

void integrateSymplecticEuler(std::span<DynamicObject> bodies, Real h) {
    for (DynamicObject& body : bodies) {
        if (body.asleep) continue;  // a sleeping body keeps its state until its island wakes
        body.velocity += h * body.acceleration;
        body.position += h * body.velocity;  // the new velocity: that is the whole difference
        if (skipsRotation(body)) continue;   // a still sphere: the update below would change nothing

        body.angularMomentum += h * body.torque;  // kick: L_{n+1} = L_n + h·τ_n
        // Drift: the torque-free motion with the new L (normalised inside).
        body.orientation = rotateTorqueFree(body.orientation, body.angularMomentum, body.inverseInertiaBody, h);
        updateAngularVelocity(body);  // ω_{n+1} = I_world(q_{n+1})⁻¹·L_{n+1}
    }
}

// Compiled three times like the lanes (core/lanes.hpp): not for SIMD, but for the AVX
// encoding's three-operand instructions, which spare this short loop its sixteen register
// copies (the settled 1k rain's integrate stage −6 %, bench/solver_performance.md, thirteenth round).
STEPWISE_LANES_COPIES
Real integrateSymplecticEulerOnRecords(SolverWorkspace& workspace, Real h, bool canTurn, bool firstSubstep) {
    Real probe = 0;
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) {
        SolverBody& record = workspace.bodies[i];
        BodyVelocity& start = workspace.substepStart[i];
        const FreeFlight& flight = workspace.freeFlight[i];
        // What the contacts did to the ball in the last substep: Σ_c λ_c·M⁻¹J_cᵀ (warmStartFromLastSubstep())
        const Vec3 change = record.velocity - start.velocity;
        const Vec3 turn = record.angularVelocity - start.angularVelocity;
        const Vec3 velocity = record.velocity + h * flight.acceleration;  // kick: v_{n+1} = v_n + h·a_n
        // L: the object's at the step's start; after a substep, I·ω, as copyVelocitiesOut() writes it
        const Vec3 momentum = firstSubstep ? workspace.startMomentum[i] : workspace.ballInertia[i] * record.angularVelocity;
        Vec3 angularVelocity = record.angularVelocity;
        const bool skipsTurn = !canTurn && momentum == Vec3(0) && angularVelocity == Vec3(0) && flight.torque == Vec3(0);
        if (!skipsTurn) angularVelocity = record.inverseInertia * (momentum + h * flight.torque);  // ω = (L + h·τ)/I
        start = {velocity, angularVelocity};  // free flight's velocities: what the drift measures Δv from
        const Vec3 warmVelocity = firstSubstep ? velocity : velocity + change;
        const Vec3 warmAngularVelocity = firstSubstep ? angularVelocity : angularVelocity + turn;
        record.velocity = warmVelocity;
        record.angularVelocity = warmAngularVelocity;
        probe += zeroIfFinite(warmVelocity) + zeroIfFinite(warmAngularVelocity);  // while still in registers
    }
    return probe;
}

}  // namespace stepwise
