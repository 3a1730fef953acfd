/// @file box_contact_lanes.cpp
/// @brief The contacts with stored rows solved four at a time (the why is in box_contact_lanes.hpp).
#include "fast/box_contact_lanes.hpp"

#include <cstddef>
#include <vector>

#include "dynamics/contact_solver.hpp"
#include "fast/body_lanes.hpp"
#include "fast/contact_waves.hpp"
#include "fast/fast_workspace.hpp"
#include "fast/normal_row_lanes.hpp"

// This file's helpers pass Lanes by value too, always inlined (see lanes.hpp).
#if defined(__GNUC__)  // GCC, and clang, which reads GCC's pragmas
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace stepwise {

namespace {

// A stored row on Lanes (solver_body.hpp, rowVelocity() and applyRowImpulse()), the same lines.

/// J·v along the row of direction @p d: d·(v_B − v_A) + (r_B × d)·ω_B − (r_A × d)·ω_A, m/s.
STEPWISE_LANES_INLINE Lanes rowVelocity(const BodyLanes& a, const BodyLanes& b, const Vec3Lanes& d, const RowLanes& row) {
    return dot(b.velocity - a.velocity, d) + dot(row.armB, b.angularVelocity) - dot(row.armA, a.angularVelocity);
}

/// Impulse λ along the row: +λd on B, −λd on A; ω changes by ±λ·I⁻¹(r × d).
STEPWISE_LANES_INLINE void applyRow(BodyLanes& a, BodyLanes& b, const Vec3Lanes& d, const RowLanes& row, Lanes lambda) {
    a.velocity -= (lambda * a.inverseMass) * d;
    a.angularVelocity -= lambda * row.turnA;
    b.velocity += (lambda * b.inverseMass) * d;
    b.angularVelocity += lambda * row.turnB;
}

/// Lane by lane, `keep ? a : b` for vectors.
template <class Mask>
STEPWISE_LANES_INLINE Vec3Lanes selectVectors(Mask keep, const Vec3Lanes& a, const Vec3Lanes& b) {
    return {select(keep, a.x, b.x), select(keep, a.y, b.y), select(keep, a.z, b.z)};
}

void setRow(RowLanes& lanes, int lane, const ContactRow& row) {
    lanes.armA.setLane(lane, row.armA);
    lanes.armB.setLane(lane, row.armB);
    lanes.turnA.setLane(lane, row.turnA);
    lanes.turnB.setLane(lane, row.turnB);
}

/// A new batch whose four lanes are empty: static record 0 on both sides, zero rows, masses and impulses.
BoxBatch emptyBatch() {
    BoxBatch batch;
    for (int lane = 0; lane < kLanes; ++lane) {
        batch.contact[lane] = kEmptyLane;
        batch.bodyA[lane] = batch.bodyB[lane] = kStaticSolverBody;
    }
    const Lanes zero = splat(0);
    const Vec3Lanes zeros{zero, zero, zero};
    batch.normal = batch.tangent0 = zeros;
    for (RowLanes* row : {&batch.normalRow, &batch.tangentRow0, &batch.tangentRow1}) row->armA = row->armB = row->turnA = row->turnB = zeros;
    batch.normalMass = batch.tangentMass = batch.friction = zero;
    batch.normalSurfaceSpeed = batch.tangentSurfaceSpeed0 = batch.tangentSurfaceSpeed1 = batch.separation = zero;
    batch.normalImpulse = batch.tangentImpulse0 = batch.tangentImpulse1 = batch.maxNormalImpulse = zero;
    return batch;
}

/// The anchors of a batch of four empty lanes: pose 0 on both sides (any pose: nothing turns, the
/// normal is zero), so an empty lane's separation is 0.
BoxAnchorBatch emptyAnchors() {
    BoxAnchorBatch anchors;
    for (int lane = 0; lane < kLanes; ++lane) anchors.poseA[lane] = anchors.poseB[lane] = 0;
    const Lanes zero = splat(0);
    anchors.localA = anchors.localB = Vec3Lanes{zero, zero, zero};
    anchors.separationOffset = anchors.turning = zero;
    return anchors;
}

void setAnchors(BoxAnchorBatch& anchors, int lane, const SolverContact& c, const SolverWorkspace& solver) {
    anchors.poseA[lane] = c.poseA;
    anchors.poseB[lane] = c.poseB;
    anchors.separationOffset[lane] = c.separationOffset;
    if (c.turningAnchors != kNoTurningAnchors) {
        const TurningAnchors& turning = solver.turningAnchors[c.turningAnchors];
        anchors.localA.setLane(lane, turning.localA);
        anchors.localB.setLane(lane, turning.localB);
        anchors.turning[lane] = 1;
    }
}

/// The positions and orientations of poses @p index, lane by lane: q = (w; x, y, z).
///
/// A Pose is seven Reals, the centre's x, y, z and the quaternion's x, y, z, w (GLM's order),
/// so each pose is read as two overlapping runs of four, [c_x c_y c_z q_x] and [q_x q_y q_z q_w],
/// and two 4×4 transposes turn the four poses' runs into lanes (as gather() does for the
/// velocities, body_lanes.hpp). Written lane by lane into a scratch array and read back as
/// Lanes instead, each read waited for four separate stores to reach the cache: a load wider
/// than the stores before it cannot take its value from them.
STEPWISE_LANES_INLINE void gatherPoses(const std::vector<Pose>& poses, const std::uint32_t (&index)[kLanes],
                                       Vec3Lanes& position, Lanes& w, Vec3Lanes& axis) {
    static_assert(sizeof(Pose) == 7 * sizeof(Real), "a Pose is the centre's 3 Reals, then the quaternion's 4");
    static_assert(offsetof(Pose, orientation) == 3 * sizeof(Real), "the quaternion follows the centre");
    Lanes centre[kLanes];      // [c_x c_y c_z q_x] of each pose
    Lanes quaternion[kLanes];  // [q_x q_y q_z q_w]
    for (int lane = 0; lane < kLanes; ++lane) {
        const Real* reals = &poses[index[lane]].position.x;
        centre[lane] = load(reals);
        quaternion[lane] = load(reals + 3);
    }
    transpose(centre[0], centre[1], centre[2], centre[3]);
    transpose(quaternion[0], quaternion[1], quaternion[2], quaternion[3]);
    position = {centre[0], centre[1], centre[2]};
    axis = {quaternion[0], quaternion[1], quaternion[2]};
    w = quaternion[3];
}

/// v turned by the unit quaternion (w; u): v + 2·(w·(u × v) + u × (u × v)), term by term as GLM's
/// `quat * vec3` forms it (so a lane is GLM's, to the bit).
STEPWISE_LANES_INLINE Vec3Lanes rotate(Lanes w, const Vec3Lanes& u, const Vec3Lanes& v) {
    const Vec3Lanes uv = cross(u, v);
    const Vec3Lanes uuv = cross(u, uv);
    const Lanes two = splat(2);
    return v + two * (w * uv + uuv);
}

void setLane(BoxBatch& batch, int lane, std::uint32_t index, const SolverContact& c, const ContactRows& rows) {
    batch.contact[lane] = index;
    batch.bodyA[lane] = c.bodyA;
    batch.bodyB[lane] = c.bodyB;
    batch.normal.setLane(lane, c.normal);
    batch.tangent0.setLane(lane, c.tangent[0]);
    setRow(batch.normalRow, lane, rows.normal);
    setRow(batch.tangentRow0, lane, rows.tangent[0]);
    setRow(batch.tangentRow1, lane, rows.tangent[1]);
    batch.normalMass[lane] = c.normalMass;
    batch.tangentMass[lane] = c.tangentMass[0];
    batch.friction[lane] = c.friction;
    batch.normalSurfaceSpeed[lane] = rows.normalSurfaceSpeed;
    batch.tangentSurfaceSpeed0[lane] = rows.tangentSurfaceSpeed[0];
    batch.tangentSurfaceSpeed1[lane] = rows.tangentSurfaceSpeed[1];
    batch.normalImpulse[lane] = c.normalImpulse;
    batch.tangentImpulse0[lane] = c.tangentImpulse[0];
    batch.tangentImpulse1[lane] = c.tangentImpulse[1];
    batch.maxNormalImpulse[lane] = c.maxNormalImpulse;
}

}  // namespace

void batchBoxContacts(const SolverWorkspace& solver, FastWorkspace& fast) {
    fast.boxBatches.clear();
    fast.boxAnchors.clear();
    fast.boxWaveBatches.clear();
    if (solver.otherContacts.empty()) return;
    const ContactWaves waves = contactWaves(solver, solver.otherContacts, solver.colouring.otherColourEnds, fast);
    if (double(solver.otherContacts.size()) < kMinBoxContactsPerWave * double(fast.waves)) return;  // thin: one at a time
    std::uint32_t first = 0;
    for (std::uint32_t wave = 0; wave < fast.waves; ++wave) {
        fast.boxWaveBatches.push_back(static_cast<std::uint32_t>(fast.boxBatches.size()));
        const std::uint32_t end = waves.ends[wave];
        for (std::uint32_t k = first; k < end; ++k) {
            const int lane = static_cast<int>((k - first) % kLanes);
            if (lane == 0) {
                fast.boxBatches.push_back(emptyBatch());
                fast.boxBatches.back().wave = wave;
                fast.boxAnchors.push_back(emptyAnchors());
            }
            const std::uint32_t index = waves.order[k];
            const SolverContact& c = solver.contacts[index];
            setLane(fast.boxBatches.back(), lane, index, c, solver.rows[c.rows]);
            setAnchors(fast.boxAnchors.back(), lane, c, solver);
        }
        first = end;
    }
    fast.boxWaveBatches.push_back(static_cast<std::uint32_t>(fast.boxBatches.size()));
}

STEPWISE_LANES_COPIES
void recordBoxSeparations(const SolverWorkspace& solver, FastWorkspace& fast) {
    const std::size_t count = fast.boxBatches.size();
    for (std::size_t i = 0; i < count; ++i) {
        BoxBatch& batch = fast.boxBatches[i];
        const BoxAnchorBatch& anchors = fast.boxAnchors[i];
        Vec3Lanes centreA;
        Vec3Lanes centreB;
        Vec3Lanes axisA;
        Vec3Lanes axisB;
        Lanes wA;
        Lanes wB;
        gatherPoses(solver.poses, anchors.poseA, centreA, wA, axisA);
        gatherPoses(solver.poses, anchors.poseB, centreB, wB, axisB);
        // C = (c_B − c_A)·n + C_offset, plus the turning anchors' part where one turns
        const Lanes separation = dot(centreB - centreA, batch.normal) + anchors.separationOffset;
        const Vec3Lanes turned = rotate(wB, axisB, anchors.localB) - rotate(wA, axisA, anchors.localA);
        batch.separation = select(anchors.turning != splat(0), separation + dot(turned, batch.normal), separation);
    }
}

STEPWISE_LANES_COPIES
void warmStartBoxContacts(SolverWorkspace& solver, const FastWorkspace& fast) {
    SolverBody discard;  // where the static record's lanes go (scatter())
    for (const BoxBatch& batch : fast.boxBatches) {
        BodyLanes a = gather(solver.bodies, batch.bodyA);
        BodyLanes b = gather(solver.bodies, batch.bodyB);
        applyRow(a, b, batch.normal, batch.normalRow, batch.normalImpulse);
        applyRow(a, b, batch.tangent0, batch.tangentRow0, batch.tangentImpulse0);
        applyRow(a, b, cross(batch.normal, batch.tangent0), batch.tangentRow1, batch.tangentImpulse1);
        scatter(solver.bodies, batch.bodyA, a, discard);
        scatter(solver.bodies, batch.bodyB, b, discard);
    }
}

void clearBoxContactImpulses(FastWorkspace& fast) {
    for (BoxBatch& batch : fast.boxBatches) batch.normalImpulse = batch.tangentImpulse0 = batch.tangentImpulse1 = splat(0);
}

namespace {

/// solveContact()'s lines for a contact with stored rows (solve_contacts.cpp), on one batch: each
/// `if` on a contact's own numbers becomes a select between the two results, lane by lane.
template <bool PushOut>
STEPWISE_LANES_INLINE void solveBatch(BoxBatch& batch, std::vector<SolverBody>& bodies, const PassConstants& k,
                                      SolverBody& discard) {
    // Normal: λ = −K⁻¹·s_m·(v_n + bias) − s_i·λ_acc (normal_row_lanes.hpp)
    BodyLanes a = gather(bodies, batch.bodyA);
    BodyLanes b = gather(bodies, batch.bodyB);
    const Lanes vn = rowVelocity(a, b, batch.normal, batch.normalRow) + batch.normalSurfaceSpeed;
    const Lanes applied = solveNormalImpulse<PushOut>(vn, batch.separation, batch.normalMass, batch.normalImpulse,
                                                      batch.maxNormalImpulse, k);
    applyRow(a, b, batch.normal, batch.normalRow, applied);

    // Friction inside Coulomb's circle |λ_t| ≤ μ·λ_n, both tangents read before either is applied.
    // A point that does not push and holds no friction is skipped by the plain pass: its lanes
    // keep the bodies and impulses they had (`rest`).
    const Lanes limit = batch.friction * batch.normalImpulse;
    const auto rest = (limit == k.zero) & (batch.tangentImpulse0 == k.zero) & (batch.tangentImpulse1 == k.zero);
    const Vec3Lanes tangent1 = cross(batch.normal, batch.tangent0);  // t₂ = n × t₁, as prepare made it (tangentBasis())
    const Lanes along0 = rowVelocity(a, b, batch.tangent0, batch.tangentRow0) + batch.tangentSurfaceSpeed0;
    const Lanes along1 = rowVelocity(a, b, tangent1, batch.tangentRow1) + batch.tangentSurfaceSpeed1;
    Lanes total0 = batch.tangentImpulse0 - batch.tangentMass * along0;
    Lanes total1 = batch.tangentImpulse1 - batch.tangentMass * along1;
    const Lanes magnitude = sqrtLanes(total0 * total0 + total1 * total1);
    const Lanes scale = select(magnitude > limit, limit / magnitude, k.one);
    total0 *= scale;
    total1 *= scale;
    const BodyLanes aBefore = a;
    const BodyLanes bBefore = b;
    applyRow(a, b, batch.tangent0, batch.tangentRow0, total0 - batch.tangentImpulse0);
    applyRow(a, b, tangent1, batch.tangentRow1, total1 - batch.tangentImpulse1);
    a.velocity = selectVectors(rest, aBefore.velocity, a.velocity);
    a.angularVelocity = selectVectors(rest, aBefore.angularVelocity, a.angularVelocity);
    b.velocity = selectVectors(rest, bBefore.velocity, b.velocity);
    b.angularVelocity = selectVectors(rest, bBefore.angularVelocity, b.angularVelocity);
    batch.tangentImpulse0 = select(rest, batch.tangentImpulse0, total0);
    batch.tangentImpulse1 = select(rest, batch.tangentImpulse1, total1);
    scatter(bodies, batch.bodyA, a, discard);
    scatter(bodies, batch.bodyB, b, discard);
}

template <bool PushOut>
STEPWISE_LANES_INLINE void solveBatches(SolverWorkspace& solver, FastWorkspace& fast, const PassConstants& k,
                                        std::size_t first, std::size_t end) {
    SolverBody discard;  // where the static record's lanes go (scatter()); each caller has its own
    for (std::size_t i = first; i < end; ++i) solveBatch<PushOut>(fast.boxBatches[i], solver.bodies, k, discard);
}

}  // namespace

void solveBoxContacts(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings, bool useBias) {
    solveBoxContactRange(solver, fast, settings, useBias, 0, fast.boxBatches.size());
}

// Compiled three times (STEPWISE_LANES_COPIES, lanes.hpp): AVX-512, AVX2 and any x86-64, the same numbers.
STEPWISE_LANES_COPIES
void solveBoxContactRange(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings,
                          bool useBias, std::size_t first, std::size_t end) {
    const PassConstants k = makePassConstants(settings);
    if (useBias && settings.positionCorrection) solveBatches<true>(solver, fast, k, first, end);  // the soft bias pushes overlaps apart
    else solveBatches<false>(solver, fast, k, first, end);
}

void syncBoxContacts(const FastWorkspace& fast, SolverWorkspace& solver) {
    for (const BoxBatch& batch : fast.boxBatches) {
        writeImpulsesBack(batch, solver.contacts);
    }
}

}  // namespace stepwise
