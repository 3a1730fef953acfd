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
#include <cstring>

#include "core/lanes.hpp"
#include "dynamics/contact_solver.hpp"
#include "objects/inertia.hpp"
#include "integrators/integrators.hpp"

// This file's lane helpers pass Lanes by value too, always inlined (see core/lanes.hpp).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

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

namespace {

/// Record @p i's kick on the packed substeps, line by line (the reference for kickRecordRows()); returns
/// the finite probe of the velocities it leaves in the record.
STEPWISE_LANES_INLINE Real kickOneRecord(SolverWorkspace& workspace, std::size_t i, Real h, bool canTurn, bool firstSubstep) {
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
    return zeroIfFinite(warmVelocity) + zeroIfFinite(warmAngularVelocity);  // while still in registers
}

/// Two Reals from memory in lanes 0 and 1, zeros in lanes 2 and 3. (Filled through memory instead,
/// half a Lanes would make the next whole load of it wait for a store it cannot forward.)
STEPWISE_LANES_INLINE Lanes loadTwo(const Real* from) {
    using Two = Real __attribute__((vector_size(2 * sizeof(Real))));
    Two two;
    std::memcpy(&two, from, sizeof two);
    return __builtin_shufflevector(two, Two{0, 0}, 0, 1, 2, 3);
}

/// kickOneRecord() for a ball that can turn, on whole rows. A record is two rows, [v_x v_y v_z ω_x]
/// and [ω_y ω_z m⁻¹ I⁻¹], and a substep start [v ω] and a FreeFlight [a τ] lie the same way. On a
/// v lane the kick is v + h·a, on an ω lane I⁻¹·(I·ω + h·τ): both are s·(L + h·f), with s = 1 and
/// L = v on the v lanes and s = I⁻¹, L = I·ω on the ω lanes, and 1·x is x exactly, so each row is
/// one line for all its lanes, with the scalar lines' bits. m⁻¹ and I⁻¹ ride along: 1·(m⁻¹ + h·0).
/// Twelve scalar lines of three components become a few operations on two rows (the settled 1k
/// rain's integrate stage 106–110 → 86–91 ns a sphere; bench/solver_performance.md, fifteenth round).
template <bool FirstSubstep>
STEPWISE_LANES_INLINE Lanes kickRecordRows(SolverWorkspace& workspace, std::size_t i, Lanes h) {
    const Lanes zero = splat(0);
    const Lanes one = splat(1);
    const auto angular0 = Lanes{0, 1, 2, 3} == splat(3);  // [v_x v_y v_z ω_x]: lane 3 is ω
    const auto angular1 = Lanes{0, 1, 2, 3} < splat(2);   // [ω_y ω_z m⁻¹ I⁻¹]: lanes 0 and 1 are ω
    Real* record = &workspace.bodies[i].velocity.x;
    Real* start = &workspace.substepStart[i].velocity.x;
    const Real* flight = &workspace.freeFlight[i].acceleration.x;
    const Lanes row0 = load(record);
    const Lanes row1 = load(record + kLanes);
    const Lanes change0 = row0 - load(start);  // what the contacts did in the last substep, as above
    const Lanes change1 = select(angular1, row1 - loadTwo(start + kLanes), zero);
    Lanes momentum0;
    Lanes momentum1;
    if constexpr (FirstSubstep) {  // the step's L
        const Vec3& L = workspace.startMomentum[i];
        momentum0 = select(angular0, splat(L.x), row0);
        momentum1 = select(angular1, Lanes{L.y, L.z, 0, 0}, row1);
    } else {  // I·ω
        const Lanes inertia = splat(workspace.ballInertia[i]);
        momentum0 = select(angular0, inertia * row0, row0);
        momentum1 = select(angular1, inertia * row1, row1);
    }
    const Lanes inverseInertia = splat(workspace.bodies[i].inverseInertia);
    const Lanes kicked0 = select(angular0, inverseInertia, one) * (momentum0 + h * load(flight));
    const Lanes kicked1 = select(angular1, inverseInertia, one) * (momentum1 + h * loadTwo(flight + kLanes));
    std::memcpy(start, &kicked0, sizeof kicked0);
    std::memcpy(start + kLanes, &kicked1, 2 * sizeof(Real));  // ω_y, ω_z
    const Lanes warm0 = FirstSubstep ? kicked0 : kicked0 + change0;
    const Lanes warm1 = FirstSubstep ? kicked1 : kicked1 + change1;
    store(record, warm0);
    store(record + kLanes, warm1);
    return warm0 * zero + warm1 * zero;  // the finite probe (m⁻¹ and I⁻¹ are finite)
}

template <bool FirstSubstep>
STEPWISE_LANES_INLINE Real kickTurningRecords(SolverWorkspace& workspace, Real h) {
    const Lanes hs = splat(h);
    Lanes probes = splat(0);
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) probes += kickRecordRows<FirstSubstep>(workspace, i, hs);
    return (probes[0] + probes[1]) + (probes[2] + probes[3]);
}

}  // namespace

// Compiled three times like the lanes (core/lanes.hpp): for the rows above, and for the AVX
// encoding's three-operand instructions, which spare the scalar loop its sixteen register
// copies (the settled 1k rain's integrate stage −6 %, bench/solver_performance.md, thirteenth round).
STEPWISE_LANES_COPIES
Real integrateSymplecticEulerOnRecords(SolverWorkspace& workspace, Real h, bool canTurn, bool firstSubstep) {
    if (canTurn) return firstSubstep ? kickTurningRecords<true>(workspace, h) : kickTurningRecords<false>(workspace, h);
    // Frictionless balls without spin: ω is left exactly as it is (skipsTurn), line by line
    Real probe = 0;
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) probe += kickOneRecord(workspace, i, h, canTurn, firstSubstep);
    return probe;
}

}  // namespace stepwise
