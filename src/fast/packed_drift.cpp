/// @file packed_drift.cpp
/// @brief The drift on the packed records (packed_substeps.hpp): x + h·v, then + h·Δv, and a ball's turn once a step.
#include <cstddef>

#include "fast/packed_substeps.hpp"
#include "fast/rotation_lanes.hpp"
#include "integrators/integrators.hpp"

// This file's lane helpers pass Lanes by value too, always inlined (see lanes.hpp).
#if defined(__GNUC__)  // GCC, and clang, which reads GCC's pragmas
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace stepwise {

namespace {

/// Record @p i's drift on the packed substeps, one ball (turnFourRecords() and storeFourRecords() do four at once);
/// returns the finite probe of its velocities and of what it wrote.
template <bool LastSubstep>
Real driftOneRecord(SolverWorkspace& workspace, FastWorkspace& fast, std::size_t i, Real h) {
    // Symplectic Euler moved with the new velocity (s = 1): no (1 − s)·h²·a term, as above.
    const SolverBody& record = workspace.bodies[i];
    const BodyVelocity& kicked = workspace.substepStart[i];  // as the kick left them
    Vec3& centre = fast.centres[i].position;
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
        Quat& orientation = fast.orientations[i];
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

// The loads below read records as rows of four Reals and transpose them (lanes.hpp).
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
STEPWISE_LANES_INLINE FourRecordDrift turnFourRecords(const SolverWorkspace& workspace, const FastWorkspace& fast,
                                                      std::size_t first, Real h) {
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
        centreRows[lane] = load(&fast.centres[i].position.x);
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
        for (int lane = 0; lane < kLanes; ++lane) turnRows[lane] = load(&fast.orientations[first + static_cast<std::size_t>(lane)].x);
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
STEPWISE_LANES_INLINE void storeFourRecords(SolverWorkspace& workspace, FastWorkspace& fast, std::size_t first, Real h,
                                            FourRecordDrift& drift, Lanes& probe) {
    probe += zeroIfFinite(drift.velocity) + zeroIfFinite(drift.spin) + zeroIfFinite(drift.centre) +
             zeroIfFinite(drift.turnSum);
    Lanes centreRows[kLanes] = {drift.centre.x, drift.centre.y, drift.centre.z, drift.centrePad};
    Lanes sumRows[kLanes] = {drift.turnSum.x, drift.turnSum.y, drift.turnSum.z, drift.turnSumPad};
    transpose(centreRows[0], centreRows[1], centreRows[2], centreRows[3]);
    transpose(sumRows[0], sumRows[1], sumRows[2], sumRows[3]);
    for (int lane = 0; lane < kLanes; ++lane) {
        const std::size_t i = first + static_cast<std::size_t>(lane);
        store(&fast.centres[i].position.x, centreRows[lane]);
        store(&workspace.turnSums[i].sum.x, sumRows[lane]);
    }
    if constexpr (LastSubstep) {
        QuatLanes& q = drift.turned.orientation;
        for (int lane = 0; lane < kLanes; ++lane) {
            if (!drift.turned.needsScalar[lane]) continue;
            const std::size_t i = first + static_cast<std::size_t>(lane);
            const Vec3 turnBy(drift.turnSum.x[lane], drift.turnSum.y[lane], drift.turnSum.z[lane]);
            const Quat scalar = rotateByAngularVelocity(fast.orientations[i], turnBy, h);
            q.w[lane] = scalar.w;
            q.x[lane] = scalar.x;
            q.y[lane] = scalar.y;
            q.z[lane] = scalar.z;
        }
        probe += zeroIfFinite(q);
        Lanes turnRows[kLanes] = {q.x, q.y, q.z, q.w};
        transpose(turnRows[0], turnRows[1], turnRows[2], turnRows[3]);
        for (int lane = 0; lane < kLanes; ++lane) store(&fast.orientations[first + static_cast<std::size_t>(lane)].x, turnRows[lane]);
    }
}

/// driftPackedRecords() for one kind of substep: eight records at a time, then four, then one.
/// The turn of the last substep is a chain of some forty operations, each waiting for the last
/// (the series, the product, the Newton step): two groups of four are turned before either is
/// stored, so that their chains run side by side. The probes are summed as the numbers are
/// written, not by reading the records again.
template <bool LastSubstep>
STEPWISE_LANES_INLINE Real driftRecords(SolverWorkspace& workspace, FastWorkspace& fast, Real h, std::size_t first,
                                        std::size_t end) {
    Lanes probes = splat(0);
    std::size_t i = first;
    for (; i + 2 * kLanes <= end; i += 2 * kLanes) {
        FourRecordDrift low = turnFourRecords<LastSubstep>(workspace, fast, i, h);
        FourRecordDrift high = turnFourRecords<LastSubstep>(workspace, fast, i + kLanes, h);
        storeFourRecords<LastSubstep>(workspace, fast, i, h, low, probes);
        storeFourRecords<LastSubstep>(workspace, fast, i + kLanes, h, high, probes);
    }
    for (; i + kLanes <= end; i += kLanes) {
        FourRecordDrift drift = turnFourRecords<LastSubstep>(workspace, fast, i, h);
        storeFourRecords<LastSubstep>(workspace, fast, i, h, drift, probes);
    }
    Real probe = (probes[0] + probes[1]) + (probes[2] + probes[3]);
    for (; i < end; ++i) probe += driftOneRecord<LastSubstep>(workspace, fast, i, h);
    return probe;
}

}  // namespace

// Compiled for AVX-512, AVX2 and any x86-64 (lanes.hpp); the last substep, which turns, is its own copy.
STEPWISE_LANES_COPIES
Real driftPackedRecords(SolverWorkspace& workspace, FastWorkspace& fast, Real h, bool lastSubstep, std::size_t first,
                        std::size_t end) {
    return lastSubstep ? driftRecords<true>(workspace, fast, h, first, end)
                       : driftRecords<false>(workspace, fast, h, first, end);
}

}  // namespace stepwise
