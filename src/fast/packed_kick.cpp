/// @file packed_kick.cpp
/// @brief Symplectic Euler's kick on the packed records (packed_substeps.hpp): v + h·a, L + h·τ, ω = L/I.
#include <cstring>

#include "fast/lanes.hpp"
#include "fast/packed_substeps.hpp"

// This file's lane helpers pass Lanes by value too, always inlined (see lanes.hpp).
#if defined(__GNUC__)  // GCC, and clang, which reads GCC's pragmas
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace stepwise {

namespace {

/// Record @p i's kick on the packed substeps, line by line (the reference for kickRecordRows()); returns
/// the finite probe of the velocities it leaves in the record.
STEPWISE_LANES_INLINE Real kickOneRecord(SolverWorkspace& workspace, const FastWorkspace& fast, std::size_t i, Real h,
                                          bool canTurn, bool firstSubstep) {
    SolverBody& record = workspace.bodies[i];
    BodyVelocity& start = workspace.substepStart[i];
    const FreeFlight& flight = fast.freeFlight[fast.sharedFlight ? 1 : i];
    // What the contacts did to the ball in the last substep: Σ_c λ_c·M⁻¹J_cᵀ (warmStartFromLastSubstep(), contact_solver.hpp)
    const Vec3 change = record.velocity - start.velocity;
    const Vec3 turn = record.angularVelocity - start.angularVelocity;
    const Vec3 velocity = record.velocity + h * flight.acceleration;  // kick: v_{n+1} = v_n + h·a_n
    // L: the object's at the step's start; after a substep, I·ω, as copyVelocitiesOut() writes it
    const Vec3 momentum = firstSubstep ? fast.startMomentum[i] : workspace.ballInertia[i] * record.angularVelocity;
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
/// Twelve scalar lines of three components become a few operations on two rows.
template <bool FirstSubstep>
STEPWISE_LANES_INLINE Lanes kickRecordRows(SolverWorkspace& workspace, const FastWorkspace& fast, std::size_t i, Lanes h) {
    const Lanes zero = splat(0);
    const Lanes one = splat(1);
    const auto angular0 = Lanes{0, 1, 2, 3} == splat(3);  // [v_x v_y v_z ω_x]: lane 3 is ω
    const auto angular1 = Lanes{0, 1, 2, 3} < splat(2);   // [ω_y ω_z m⁻¹ I⁻¹]: lanes 0 and 1 are ω
    Real* record = &workspace.bodies[i].velocity.x;
    Real* start = &workspace.substepStart[i].velocity.x;
    const Real* flight = &fast.freeFlight[fast.sharedFlight ? 1 : i].acceleration.x;  // FastWorkspace::sharedFlight
    const Lanes row0 = load(record);
    const Lanes row1 = load(record + kLanes);
    const Lanes change0 = row0 - load(start);  // what the contacts did in the last substep, as above
    const Lanes change1 = select(angular1, row1 - loadTwo(start + kLanes), zero);
    Lanes momentum0;
    Lanes momentum1;
    if constexpr (FirstSubstep) {  // the step's L
        const Vec3& L = fast.startMomentum[i];
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
STEPWISE_LANES_INLINE Real kickTurningRecords(SolverWorkspace& workspace, const FastWorkspace& fast, Real h,
                                              std::size_t first, std::size_t end) {
    const Lanes hs = splat(h);
    Lanes probes = splat(0);
    for (std::size_t i = first; i < end; ++i) probes += kickRecordRows<FirstSubstep>(workspace, fast, i, hs);
    return (probes[0] + probes[1]) + (probes[2] + probes[3]);
}

}  // namespace

// Compiled three times like the lanes (lanes.hpp): for the rows above, and for the AVX
// encoding's three-operand instructions, which spare the scalar loop its register copies.
STEPWISE_LANES_COPIES
Real kickPackedRecords(SolverWorkspace& workspace, const FastWorkspace& fast, Real h, bool canTurn, bool firstSubstep,
                       std::size_t first, std::size_t end) {
    if (canTurn) {
        return firstSubstep ? kickTurningRecords<true>(workspace, fast, h, first, end)
                            : kickTurningRecords<false>(workspace, fast, h, first, end);
    }
    // Frictionless balls without spin: ω is left exactly as it is (skipsTurn), line by line
    Real probe = 0;
    for (std::size_t i = first; i < end; ++i) probe += kickOneRecord(workspace, fast, i, h, canTurn, firstSubstep);
    return probe;
}

}  // namespace stepwise
