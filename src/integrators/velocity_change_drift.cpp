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
/// **A ball under symplectic Euler turns once, with its new ω.** For a body
/// with three equal moments of inertia the free rotation is exact:
/// q(t + h) = exp(½h·ω̂)·q(t) with ω constant (rotateByAngularVelocity()).
/// So a ball the constraints turned need not add a correction to the
/// integrator's turn: it is turned again from where the substep started
/// (its recorded pose), by h_s·ω_{n+1}, the solved ω,
/// \f[ q \leftarrow \exp\!\big(\tfrac12 h_s\,\hat\omega_{n+1}\big)\, q_n , \f]
/// the rotational twin of x_n + h_s·v_{n+1}: no splitting error at all, and
/// on the packed substeps (World::substepOnRecords()) one turn a substep
/// instead of two (the 1k sphere rain −7 %, bench/solver_performance.md,
/// tenth round); there the turn is also done four balls at a time, in SIMD
/// lanes (rotation_lanes.hpp, the same bits: −3 %, twelfth round). A box's free rotation depends on how its axes lie
/// (rotateTorqueFree()), so it keeps the correction above.
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

void driftByVelocityChange(SolverWorkspace& workspace, Real h, IntegratorKind integrator) {
    const Real lag = Real(1) - positionShareOfVelocityChange(integrator);
    // Only a body with a solver record can have been pushed: one in a contact or a joint (prepareContacts()).
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) {
        const std::uint32_t index = workspace.recordBody[i];
        DynamicObject& body = copyVelocitiesOut(workspace, i);  // the solved v and ω, in the same pass
        const BodyVelocity& before = workspace.substepStart[i];  // as free flight left it (recordSubstepStart())
        const Vec3 change = body.velocity - before.velocity;
        const Vec3 turn = body.angularVelocity - before.angularVelocity;
        if (!body.asleep && (change != Vec3(0) || turn != Vec3(0))) {  // else free flight's own step stands
            Vec3 move = h * change;
            if (lag != Real(0)) move += lag * h * h * body.acceleration;  // explicit Euler, Verlet: an older velocity
            body.position += move;
            if (turn != Vec3(0)) {
                body.orientation = turnsWithNewVelocity(workspace, i, integrator)
                                       ? rotateByAngularVelocity(workspace.poses[index].orientation, body.angularVelocity, h)
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
/// returns the finite probe of its velocities and new pose.
Real driftOneRecord(SolverWorkspace& workspace, std::size_t i, Real h) {
    // Symplectic Euler moved with the new velocity (s = 1): no (1 − s)·h²·a term, as above.
    const SolverBody& record = workspace.bodies[i];
    const BodyVelocity& kicked = workspace.substepStart[i];  // as the kick left them
    Vec3& centre = workspace.centres[i].position;
    Quat& orientation = workspace.orientations[i];
    // Free flight, as integrateSymplecticEuler() moves an object (x + h·v), then what the constraints changed
    Vec3 position = centre + h * kicked.velocity;
    const Vec3 change = record.velocity - kicked.velocity;
    const Vec3 turn = record.angularVelocity - kicked.angularVelocity;
    if (change != Vec3(0) || turn != Vec3(0)) position += h * change;
    // One exact turn from the substep's start, by the new ω, or by free flight's if the constraints left it
    orientation = rotateByAngularVelocity(orientation, turn != Vec3(0) ? record.angularVelocity : kicked.angularVelocity, h);
    centre = position;  // where the relax passes measure the separations
    return zeroIfFinite(record.velocity) + zeroIfFinite(record.angularVelocity) + zeroIfFinite(centre) +
           zeroIfFinite(orientation);
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
    Vec3Lanes turnBy;        ///< The ω each ball turns by, rad/s.
    Vec3Lanes centre;        ///< Where each ball moves to, m.
    Lanes centrePad;         ///< The centres' fourth Real, stored back as it was.
    TurnLanes turned;        ///< The turn, and the lanes that need the scalar one.
};

/// driftOneRecord() on records @p first … @p first + 3, in lanes, up to the turn: the same
/// lines, the same bits (the turn is rotation_lanes.hpp's).
STEPWISE_LANES_INLINE FourRecordDrift turnFourRecords(const SolverWorkspace& workspace, std::size_t first, Real h) {
    Lanes record[2][kLanes];   // [v_x v_y v_z ω_x], [ω_y ω_z m⁻¹ I⁻¹]
    Lanes kicked[2][kLanes];   // [v_x v_y v_z ω_x], [v_z ω_x ω_y ω_z]
    Lanes centreRows[kLanes];  // [x y z pad]
    Lanes turnRows[kLanes];    // [x y z w]
    for (int lane = 0; lane < kLanes; ++lane) {
        const std::size_t i = first + static_cast<std::size_t>(lane);
        record[0][lane] = load(&workspace.bodies[i].velocity.x);
        record[1][lane] = load(&workspace.bodies[i].velocity.x + kLanes);
        kicked[0][lane] = load(&workspace.substepStart[i].velocity.x);
        kicked[1][lane] = load(&workspace.substepStart[i].velocity.x + 2);
        centreRows[lane] = load(&workspace.centres[i].position.x);
        turnRows[lane] = load(&workspace.orientations[i].x);
    }
    for (auto* rows : {record[0], record[1], kicked[0], kicked[1], centreRows, turnRows}) {
        transpose(rows[0], rows[1], rows[2], rows[3]);
    }
    FourRecordDrift drift;
    drift.velocity = {record[0][0], record[0][1], record[0][2]};
    drift.spin = {record[0][3], record[1][0], record[1][1]};
    const Vec3Lanes kickedVelocity{kicked[0][0], kicked[0][1], kicked[0][2]};
    const Vec3Lanes kickedSpin{kicked[1][1], kicked[1][2], kicked[1][3]};
    const Vec3Lanes centre{centreRows[0], centreRows[1], centreRows[2]};
    const QuatLanes orientation{turnRows[3], turnRows[0], turnRows[1], turnRows[2]};

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
    drift.turnBy = {select(turned, drift.spin.x, kickedSpin.x), select(turned, drift.spin.y, kickedSpin.y),
                    select(turned, drift.spin.z, kickedSpin.z)};
    drift.turned = rotateByAngularVelocity(orientation, drift.turnBy, h);
    return drift;
}

/// The rest of driftOneRecord() on records @p first … @p first + 3: a lane the series does
/// not cover takes the scalar turn; then the new centres and orientations are stored, and the
/// four records' finite probes added to @p probe.
STEPWISE_LANES_INLINE void storeFourRecords(SolverWorkspace& workspace, std::size_t first, Real h, FourRecordDrift& drift,
                                            Lanes& probe) {
    QuatLanes& q = drift.turned.orientation;
    for (int lane = 0; lane < kLanes; ++lane) {
        if (!drift.turned.needsScalar[lane]) continue;
        const std::size_t i = first + static_cast<std::size_t>(lane);
        const Vec3 turnBy(drift.turnBy.x[lane], drift.turnBy.y[lane], drift.turnBy.z[lane]);
        const Quat scalar = rotateByAngularVelocity(workspace.orientations[i], turnBy, h);
        q.w[lane] = scalar.w;
        q.x[lane] = scalar.x;
        q.y[lane] = scalar.y;
        q.z[lane] = scalar.z;
    }
    probe += zeroIfFinite(drift.velocity) + zeroIfFinite(drift.spin) + zeroIfFinite(drift.centre) +
             zeroIfFinite(q);
    Lanes centreRows[kLanes] = {drift.centre.x, drift.centre.y, drift.centre.z, drift.centrePad};
    Lanes turnRows[kLanes] = {q.x, q.y, q.z, q.w};
    transpose(centreRows[0], centreRows[1], centreRows[2], centreRows[3]);
    transpose(turnRows[0], turnRows[1], turnRows[2], turnRows[3]);
    for (int lane = 0; lane < kLanes; ++lane) {
        const std::size_t i = first + static_cast<std::size_t>(lane);
        store(&workspace.centres[i].position.x, centreRows[lane]);
        store(&workspace.orientations[i].x, turnRows[lane]);
    }
}

}  // namespace

// Eight records at a time, then four, then one; compiled for AVX-512, AVX2 and any x86-64
// (core/lanes.hpp). The turn is a chain of some forty operations, each waiting for the last
// (the series, the product, the Newton step): two groups of four are turned before either is
// stored, so that their chains run side by side (the 1k rain's solve stage, which holds the
// drift, −5 %; bench/solver_performance.md, thirteenth round). The probes are summed as the
// numbers are written: reading the records again for them cost 4 % of the 1k rain's step.
STEPWISE_LANES_COPIES
Real driftRecordsByVelocityChange(SolverWorkspace& workspace, Real h) {
    const std::size_t end = workspace.bodies.size();
    Lanes probes = splat(0);
    std::size_t i = 1;  // record 0 is the static one
    for (; i + 2 * kLanes <= end; i += 2 * kLanes) {
        FourRecordDrift low = turnFourRecords(workspace, i, h);
        FourRecordDrift high = turnFourRecords(workspace, i + kLanes, h);
        storeFourRecords(workspace, i, h, low, probes);
        storeFourRecords(workspace, i + kLanes, h, high, probes);
    }
    for (; i + kLanes <= end; i += kLanes) {
        FourRecordDrift drift = turnFourRecords(workspace, i, h);
        storeFourRecords(workspace, i, h, drift, probes);
    }
    Real probe = (probes[0] + probes[1]) + (probes[2] + probes[3]);
    for (; i < end; ++i) probe += driftOneRecord(workspace, i, h);
    return probe;
}

}  // namespace stepwise
