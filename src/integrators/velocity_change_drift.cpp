/// @file velocity_change_drift.cpp
/// @brief Sequential impulse, within a substep: the bodies move by what the constraints did to their velocities.
///
/// The integrator has already carried each body through the substep with its
/// free-flight velocity; the constraint solve then changed that velocity by
/// Δv (and the angular velocity by Δω). Had those impulses been there from
/// the substep's start, the body would also have moved by h_s·Δv and turned
/// by h_s·Δω, so that is added here:
/// \f[ x \leftarrow x + h_s\,\Delta v, \qquad
///     q \leftarrow \frac{q + \tfrac12 h_s\,(0, \Delta\omega)\otimes q}{\lVert\cdot\rVert}. \f]
/// The turn is the first-order update Box2D makes for every rotation
/// (turnBySmallAngle()): h_s·Δω is the solver's correction of one substep, a
/// milliradian or less, and the update misses the exact turn exp(½h_s Δω)·q
/// by (h_s|Δω|)³/12, far below what splitting the substep into a free-flight
/// turn and this one already costs, O(h_s²·|ω|·|Δω|). The exact turn, with
/// its series for cos and sin, took 5 % of a sphere rain's step here, this
/// one 2 % (perf, 4 096 spheres).
///
/// **A ball under symplectic Euler turns with its new ω.** For a body
/// with three equal moments of inertia the free rotation is exact:
/// q(t + h) = exp(½h·ω̂)·q(t) with ω constant (rotateByAngularVelocity()).
/// So a ball the constraints turned need not add a correction to the
/// integrator's turn: its substep's turn is h_s·ω_{n+1}, by the solved ω,
/// the rotational twin of x_n + h_s·v_{n+1}. A box's free rotation depends
/// on how its axes lie (rotateTorqueFree()), so it keeps the correction above.
///
/// **A ball turns once a step.** Nothing inside a step reads a ball's
/// orientation: its contacts are measured from its centre (a sphere's
/// surface point is the centre plus R·n however it is turned) and its
/// inertia is the same about every axis. Only a joint's or a spring's
/// anchor turns with its ball, so in a scene without joints and springs
/// (SolverWorkspace::ballsTurnOnce) the drift keeps each ball at the step's
/// orientation q_n, adds each
/// substep's ω to a sum, and in the last substep turns it once:
/// \f[ q_{n+1} = \exp\!\Big(\tfrac12 h_s \sum_{k=1}^{S} \hat\omega_k\Big)\, q_n
///     \quad\text{instead of}\quad
///     \prod_{k=1}^{S} \exp\!\big(\tfrac12 h_s\, \hat\omega_k\big)\, q_n . \f]
/// While the spin keeps its axis, the two are the same rotation. When
/// contacts tip the axis within the step, the product and the exponential
/// of the sum differ by the commutators of the substeps' turns (the
/// Baker–Campbell–Hausdorff series), ½Σ_{j<k} h_s²·ω_j × ω_k: of order
/// h²·|ω|·|Δω|, the order of the error symplectic Euler makes with one
/// substep, and a turn of a ball that nothing in the physics can see. It
/// saves S − 1 of the S turns, each a chain of some forty operations: the
/// 1k sphere rain's step −3.6 % (bench/solver_performance.md, fifteenth
/// round). With one substep nothing changes. An observer watching the
/// substeps sees a ball's orientation held until the last one.
///
/// For symplectic Euler the result is exactly x_n + h_s·v_{n+1}, the
/// position update every sequential-impulse engine makes after its solve
/// (Box2D's "integrate positions"). Without this drift a resting body would
/// sink by g·h_s² each substep and be pushed back out by the soft bias: jitter.
///
/// The other integrators moved the position with a different velocity u
/// than the v they ended with: u = v − (1 − s)·h_s·a, with s the share from
/// positionShareOfVelocityChange() (explicit Euler moved with the old
/// velocity, s = 0; Verlet with the mean, s = ½). A constraint force acts
/// *implicitly*, on the end-of-substep velocity, whatever the integrator, so
/// a constrained body ends at x_n + h_s·v_{n+1}:
/// \f[ x \leftarrow x + h_s\,\Delta v + (1 - s)\,h_s^2\,a. \f]
/// A body the constraints did not touch (Δv = 0, Δω = 0) keeps its
/// integrator's free flight exactly. Check: a resting ball (v_n = 0) ends
/// where it started with every integrator, because Δv = −h_s·a.
#include <cstddef>

#include "dynamics/contact_solver.hpp"
#include "integrators/integrators.hpp"
#include "integrators/rotation_lanes.hpp"

// This file's lane helpers pass Lanes by value too, always inlined (see core/lanes.hpp).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace stepwise {

namespace {

/// Record @p i is a ball moved by symplectic Euler: it turns again from the substep's start, by h·ω_{n+1}.
bool turnsWithNewVelocity(const SolverWorkspace& workspace, std::size_t i, IntegratorKind integrator) {
    return integrator == IntegratorKind::SymplecticEuler && workspace.ballInertia[i] != Real(0);
}

}  // namespace

void driftByVelocityChange(SolverWorkspace& workspace, Real h, IntegratorKind integrator, bool lastSubstep) {
    const Real lag = Real(1) - positionShareOfVelocityChange(integrator);
    // Only a body with a solver record can have been pushed: one in a contact or a joint (prepareContacts()).
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) {
        const std::uint32_t index = workspace.recordBody[i];
        DynamicObject& body = copyVelocitiesOut(workspace, i);  // the solved v and ω, in the same pass
        const BodyVelocity& before = workspace.substepStart[i];  // as free flight left it (recordSubstepStart())
        const Vec3 change = body.velocity - before.velocity;
        const Vec3 turn = body.angularVelocity - before.angularVelocity;
        const bool ball = turnsWithNewVelocity(workspace, i, integrator);
        if (!body.asleep && ball && workspace.ballsTurnOnce) {
            // Once a step: back to the step's start (the last drift's pose), the substep's ω added to the sum
            if (change != Vec3(0) || turn != Vec3(0)) body.position += h * change;
            Vec3& sum = workspace.turnSums[i].sum;
            sum += turn != Vec3(0) ? body.angularVelocity : before.angularVelocity;
            body.orientation = lastSubstep ? rotateByAngularVelocity(workspace.poses[index].orientation, sum, h)
                                           : workspace.poses[index].orientation;
        } else if (!body.asleep && (change != Vec3(0) || turn != Vec3(0))) {  // else free flight's own step stands
            Vec3 move = h * change;
            if (lag != Real(0)) move += lag * h * h * body.acceleration;  // explicit Euler, Verlet: an older velocity
            body.position += move;
            if (turn != Vec3(0)) {
                body.orientation = ball ? rotateByAngularVelocity(workspace.poses[index].orientation, body.angularVelocity, h)
                                        : turnBySmallAngle(body.orientation, turn, h);
            }
        }
        // The relax passes measure separations here; no other body's pose is read by a constraint.
        workspace.poses[index] = {body.position, body.orientation};
        workspace.centres[i].position = body.position;
    }
}

namespace {

/// Record @p i's drift on the packed substeps, one ball (turnFourRecords() and storeFourRecords() do four at once);
/// returns the finite probe of its velocities and of what it wrote.
template <bool LastSubstep>
Real driftOneRecord(SolverWorkspace& workspace, std::size_t i, Real h) {
    // Symplectic Euler moved with the new velocity (s = 1): no (1 − s)·h²·a term, as above.
    const SolverBody& record = workspace.bodies[i];
    const BodyVelocity& kicked = workspace.substepStart[i];  // as the kick left them
    Vec3& centre = workspace.centres[i].position;
    Vec3& sum = workspace.turnSums[i].sum;
    // Free flight, as integrateSymplecticEuler() moves an object (x + h·v), then what the constraints changed
    Vec3 position = centre + h * kicked.velocity;
    const Vec3 change = record.velocity - kicked.velocity;
    const Vec3 turn = record.angularVelocity - kicked.angularVelocity;
    if (change != Vec3(0) || turn != Vec3(0)) position += h * change;
    // This substep's turn: by the new ω, or by free flight's if the constraints left it; made once, at the step's end
    sum += turn != Vec3(0) ? record.angularVelocity : kicked.angularVelocity;
    centre = position;  // where the relax passes measure the separations
    Real probe = zeroIfFinite(record.velocity) + zeroIfFinite(record.angularVelocity) + zeroIfFinite(centre) + zeroIfFinite(sum);
    if constexpr (LastSubstep) {
        Quat& orientation = workspace.orientations[i];
        orientation = rotateByAngularVelocity(orientation, sum, h);
        probe += zeroIfFinite(orientation);
    }
    return probe;
}

/// A Vec3Lanes lane by lane: all bits set where any component differs from zero (a NaN does).
STEPWISE_LANES_INLINE auto nonZero(const Vec3Lanes& v) {
    const Lanes zero = splat(0);
    return (v.x != zero) | (v.y != zero) | (v.z != zero);
}

// The loads below read records as rows of four Reals and transpose them (core/lanes.hpp).
static_assert(sizeof(SolverBody) == 2 * sizeof(Lanes), "a record is [v_x v_y v_z ω_x][ω_y ω_z m⁻¹ I⁻¹]");
static_assert(sizeof(BodyVelocity) == 6 * sizeof(Real), "a substep start is [v_x v_y v_z ω_x ω_y ω_z]");
static_assert(sizeof(SolverCentre) == sizeof(Lanes), "a centre is [x y z, a Real never read]");
static_assert(sizeof(Quat) == sizeof(Lanes) && offsetof(Quat, x) == 0 && offsetof(Quat, w) == 3 * sizeof(Real),
              "a quaternion is stored [x y z w] (glm's default)");

/// The finite probe of four vectors, lane by lane (zeroIfFinite(), core/types.hpp).
STEPWISE_LANES_INLINE Lanes zeroIfFinite(const Vec3Lanes& v) {
    const Lanes zero = splat(0);
    return v.x * zero + v.y * zero + v.z * zero;
}

/// The same for four quaternions.
STEPWISE_LANES_INLINE Lanes zeroIfFinite(const QuatLanes& q) {
    const Lanes zero = splat(0);
    return q.w * zero + q.x * zero + q.y * zero + q.z * zero;
}

/// Four records' drift in lanes, between turnFourRecords() and storeFourRecords().
struct FourRecordDrift {
    Vec3Lanes velocity;      ///< The solved v, m/s.
    Vec3Lanes spin;          ///< The solved ω, rad/s.
    Vec3Lanes turnSum;       ///< The sum of the ω each ball has turned by, this substep's included, rad/s.
    Lanes turnSumPad;        ///< The sums' fourth Real, stored back as it was.
    Vec3Lanes centre;        ///< Where each ball moves to, m.
    Lanes centrePad;         ///< The centres' fourth Real, stored back as it was.
    TurnLanes turned;        ///< The last substep: the turn, and the lanes that need the scalar one.
};

/// driftOneRecord() on records @p first … @p first + 3, in lanes, up to the turn: the same
/// lines, the same bits (the turn is rotation_lanes.hpp's).
template <bool LastSubstep>
STEPWISE_LANES_INLINE FourRecordDrift turnFourRecords(const SolverWorkspace& workspace, std::size_t first, Real h) {
    Lanes record[2][kLanes];   // [v_x v_y v_z ω_x], [ω_y ω_z m⁻¹ I⁻¹]
    Lanes kicked[2][kLanes];   // [v_x v_y v_z ω_x], [v_z ω_x ω_y ω_z]
    Lanes centreRows[kLanes];  // [x y z pad]
    Lanes sumRows[kLanes];     // [Σω_x Σω_y Σω_z pad]
    for (int lane = 0; lane < kLanes; ++lane) {
        const std::size_t i = first + static_cast<std::size_t>(lane);
        record[0][lane] = load(&workspace.bodies[i].velocity.x);
        record[1][lane] = load(&workspace.bodies[i].velocity.x + kLanes);
        kicked[0][lane] = load(&workspace.substepStart[i].velocity.x);
        kicked[1][lane] = load(&workspace.substepStart[i].velocity.x + 2);
        centreRows[lane] = load(&workspace.centres[i].position.x);
        sumRows[lane] = load(&workspace.turnSums[i].sum.x);
    }
    for (auto* rows : {record[0], record[1], kicked[0], kicked[1], centreRows, sumRows}) {
        transpose(rows[0], rows[1], rows[2], rows[3]);
    }
    FourRecordDrift drift;
    drift.velocity = {record[0][0], record[0][1], record[0][2]};
    drift.spin = {record[0][3], record[1][0], record[1][1]};
    const Vec3Lanes kickedVelocity{kicked[0][0], kicked[0][1], kicked[0][2]};
    const Vec3Lanes kickedSpin{kicked[1][1], kicked[1][2], kicked[1][3]};
    const Vec3Lanes centre{centreRows[0], centreRows[1], centreRows[2]};

    const Lanes hs = splat(h);
    const Vec3Lanes freeFlight = centre + hs * kickedVelocity;
    const Vec3Lanes change = drift.velocity - kickedVelocity;
    const Vec3Lanes turn = drift.spin - kickedSpin;
    const auto pushed = nonZero(change) | nonZero(turn);
    const Vec3Lanes pushedTo = freeFlight + hs * change;
    drift.centre = {select(pushed, pushedTo.x, freeFlight.x), select(pushed, pushedTo.y, freeFlight.y),
                    select(pushed, pushedTo.z, freeFlight.z)};
    drift.centrePad = centreRows[3];
    const auto turned = nonZero(turn);
    const Vec3Lanes turnBy{select(turned, drift.spin.x, kickedSpin.x), select(turned, drift.spin.y, kickedSpin.y),
                           select(turned, drift.spin.z, kickedSpin.z)};
    drift.turnSum = Vec3Lanes{sumRows[0], sumRows[1], sumRows[2]} + turnBy;
    drift.turnSumPad = sumRows[3];
    if constexpr (LastSubstep) {
        Lanes turnRows[kLanes];  // [x y z w]
        for (int lane = 0; lane < kLanes; ++lane) turnRows[lane] = load(&workspace.orientations[first + static_cast<std::size_t>(lane)].x);
        transpose(turnRows[0], turnRows[1], turnRows[2], turnRows[3]);
        const QuatLanes orientation{turnRows[3], turnRows[0], turnRows[1], turnRows[2]};
        drift.turned = rotateByAngularVelocity(orientation, drift.turnSum, h);
    }
    return drift;
}

/// The rest of driftOneRecord() on records @p first … @p first + 3: the new centres and sums
/// are stored; in the last substep, a lane the series does not cover takes the scalar turn and
/// the orientations are stored; the four records' finite probes are added to @p probe.
template <bool LastSubstep>
STEPWISE_LANES_INLINE void storeFourRecords(SolverWorkspace& workspace, std::size_t first, Real h, FourRecordDrift& drift,
                                            Lanes& probe) {
    probe += zeroIfFinite(drift.velocity) + zeroIfFinite(drift.spin) + zeroIfFinite(drift.centre) +
             zeroIfFinite(drift.turnSum);
    Lanes centreRows[kLanes] = {drift.centre.x, drift.centre.y, drift.centre.z, drift.centrePad};
    Lanes sumRows[kLanes] = {drift.turnSum.x, drift.turnSum.y, drift.turnSum.z, drift.turnSumPad};
    transpose(centreRows[0], centreRows[1], centreRows[2], centreRows[3]);
    transpose(sumRows[0], sumRows[1], sumRows[2], sumRows[3]);
    for (int lane = 0; lane < kLanes; ++lane) {
        const std::size_t i = first + static_cast<std::size_t>(lane);
        store(&workspace.centres[i].position.x, centreRows[lane]);
        store(&workspace.turnSums[i].sum.x, sumRows[lane]);
    }
    if constexpr (LastSubstep) {
        QuatLanes& q = drift.turned.orientation;
        for (int lane = 0; lane < kLanes; ++lane) {
            if (!drift.turned.needsScalar[lane]) continue;
            const std::size_t i = first + static_cast<std::size_t>(lane);
            const Vec3 turnBy(drift.turnSum.x[lane], drift.turnSum.y[lane], drift.turnSum.z[lane]);
            const Quat scalar = rotateByAngularVelocity(workspace.orientations[i], turnBy, h);
            q.w[lane] = scalar.w;
            q.x[lane] = scalar.x;
            q.y[lane] = scalar.y;
            q.z[lane] = scalar.z;
        }
        probe += zeroIfFinite(q);
        Lanes turnRows[kLanes] = {q.x, q.y, q.z, q.w};
        transpose(turnRows[0], turnRows[1], turnRows[2], turnRows[3]);
        for (int lane = 0; lane < kLanes; ++lane) store(&workspace.orientations[first + static_cast<std::size_t>(lane)].x, turnRows[lane]);
    }
}

/// driftRecordsByVelocityChange() for one kind of substep: eight records at a time, then four,
/// then one. The turn of the last substep is a chain of some forty operations, each waiting
/// for the last (the series, the product, the Newton step): two groups of four are turned
/// before either is stored, so that their chains run side by side (the 1k rain's solve stage,
/// which holds the drift, −5 % when every substep turned; bench/solver_performance.md,
/// thirteenth round). The probes are summed as the numbers are written: reading the records
/// again for them cost 4 % of the 1k rain's step.
template <bool LastSubstep>
STEPWISE_LANES_INLINE Real driftRecords(SolverWorkspace& workspace, Real h) {
    const std::size_t end = workspace.bodies.size();
    Lanes probes = splat(0);
    std::size_t i = 1;  // record 0 is the static one
    for (; i + 2 * kLanes <= end; i += 2 * kLanes) {
        FourRecordDrift low = turnFourRecords<LastSubstep>(workspace, i, h);
        FourRecordDrift high = turnFourRecords<LastSubstep>(workspace, i + kLanes, h);
        storeFourRecords<LastSubstep>(workspace, i, h, low, probes);
        storeFourRecords<LastSubstep>(workspace, i + kLanes, h, high, probes);
    }
    for (; i + kLanes <= end; i += kLanes) {
        FourRecordDrift drift = turnFourRecords<LastSubstep>(workspace, i, h);
        storeFourRecords<LastSubstep>(workspace, i, h, drift, probes);
    }
    Real probe = (probes[0] + probes[1]) + (probes[2] + probes[3]);
    for (; i < end; ++i) probe += driftOneRecord<LastSubstep>(workspace, i, h);
    return probe;
}

}  // namespace

// Compiled for AVX-512, AVX2 and any x86-64 (core/lanes.hpp); the last substep, which turns, is its own copy.
STEPWISE_LANES_COPIES
Real driftRecordsByVelocityChange(SolverWorkspace& workspace, Real h, bool lastSubstep) {
    return lastSubstep ? driftRecords<true>(workspace, h) : driftRecords<false>(workspace, h);
}

}  // namespace stepwise
