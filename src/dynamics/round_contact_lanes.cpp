/// @file round_contact_lanes.cpp
/// @brief The round contacts solved four at a time (the why and the waves are in round_contact_lanes.hpp).
#include "dynamics/round_contact_lanes.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>

#include "dynamics/contact_solver.hpp"

// This file's helpers pass Lanes by value too, always inlined (see core/lanes.hpp).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace stepwise {

namespace {

// A solver body is two Lanes long, [v_x v_y v_z ω_x] and [ω_y ω_z m⁻¹ I⁻¹], so
// four of them are read with eight loads and regrouped by transposing (below).
static_assert(sizeof(SolverBody) == 2 * sizeof(Lanes), "SolverBody must be two Lanes: v, ω, m⁻¹, I⁻¹");
static_assert(offsetof(SolverBody, angularVelocity) == 3 * sizeof(Real) &&
                  offsetof(SolverBody, inverseMass) == 6 * sizeof(Real),
              "SolverBody's layout is read as [v_x v_y v_z ω_x][ω_y ω_z m⁻¹ I⁻¹]");

/// The four bodies of one side (A or B) of a batch, lane by lane.
struct BodyLanes {
    Vec3Lanes velocity;
    Vec3Lanes angularVelocity;
    Lanes inverseMass;
    Lanes inverseInertia;
};

STEPWISE_LANES_INLINE const Real* realsOf(const SolverBody& body) { return &body.velocity.x; }
STEPWISE_LANES_INLINE Real* realsOf(SolverBody& body) { return &body.velocity.x; }

/// Records @p index of @p bodies, lane by lane: the velocities, and the masses m⁻¹ and I⁻¹ that
/// arrive in the same loads (the second half of a record is [ω_y ω_z m⁻¹ I⁻¹]), so a batch
/// need not carry copies of them.
STEPWISE_LANES_INLINE BodyLanes gather(const std::vector<SolverBody>& bodies, const std::uint32_t (&index)[kLanes]) {
    Lanes low[kLanes];   // [v_x v_y v_z ω_x] of each body
    Lanes high[kLanes];  // [ω_y ω_z m⁻¹ I⁻¹]
    for (int i = 0; i < kLanes; ++i) {
        low[i] = load(realsOf(bodies[index[i]]));
        high[i] = load(realsOf(bodies[index[i]]) + kLanes);
    }
    transpose(low[0], low[1], low[2], low[3]);
    transpose(high[0], high[1], high[2], high[3]);
    return {{low[0], low[1], low[2]}, {low[3], high[0], high[1]}, high[2], high[3]};
}

/// Writes the velocities back to records @p index, in lane order; m⁻¹ and I⁻¹ stay as they are in memory.
///
/// A lane whose record is the static one (B of a plane contact, both sides of an empty lane)
/// writes to @p discard instead. Its velocities are zero before and after (m⁻¹ = I⁻¹ = 0), so
/// nothing is lost; but were they written back, every batch with a plane contact would
/// read the static record just after the batch before it wrote it, and wait for that store
/// (a 32-byte load of a record half written by 16-byte stores cannot be forwarded). Only
/// records that really carry a body's velocity from one contact to the next are written.
STEPWISE_LANES_INLINE void scatter(std::vector<SolverBody>& bodies, const std::uint32_t (&index)[kLanes],
                                   const BodyLanes& lanes, SolverBody& discard) {
    Lanes low[kLanes] = {lanes.velocity.x, lanes.velocity.y, lanes.velocity.z, lanes.angularVelocity.x};
    transpose(low[0], low[1], low[2], low[3]);
    // ω_y and ω_z side by side for each record, two shuffles for all four: [y₀ z₀ y₂ z₂] and
    // [y₁ z₁ y₃ z₃]; record i takes its pair from the low or the high half of one of them.
    const Lanes even = shuffleLanes<0, 4, 2, 6>(lanes.angularVelocity.y, lanes.angularVelocity.z);
    const Lanes odd = shuffleLanes<1, 5, 3, 7>(lanes.angularVelocity.y, lanes.angularVelocity.z);
    Real evenPairs[kLanes];
    Real oddPairs[kLanes];
    store(evenPairs, even);
    store(oddPairs, odd);
    const Real* pairs[kLanes] = {evenPairs, oddPairs, evenPairs + 2, oddPairs + 2};
    for (int i = 0; i < kLanes; ++i) {
        SolverBody& record = index[i] == kStaticSolverBody ? discard : bodies[index[i]];
        store(realsOf(record), low[i]);
        std::memcpy(realsOf(record) + kLanes, pairs[i], 2 * sizeof(Real));  // ω_y, ω_z
    }
}

/// The centres of records @p index, lane by lane (SolverWorkspace::centres: x, y, z and a
/// fourth Real that is never read, so each centre is one aligned load).
STEPWISE_LANES_INLINE Vec3Lanes gatherCentres(const std::vector<SolverCentre>& centres, const std::uint32_t (&index)[kLanes]) {
    Lanes rows[kLanes];
    for (int i = 0; i < kLanes; ++i) rows[i] = load(&centres[index[i]].position.x);
    transpose(rows[0], rows[1], rows[2], rows[3]);
    return {rows[0], rows[1], rows[2]};
}

// The round contact's rows (solver_body.hpp, "Rows of a round contact"), on Lanes.

/// Impulse λ along n: it moves the centres only.
STEPWISE_LANES_INLINE void applyNormal(BodyLanes& a, BodyLanes& b, const Vec3Lanes& n, Lanes lambda) {
    a.velocity -= (lambda * a.inverseMass) * n;
    b.velocity += (lambda * b.inverseMass) * n;
}

/// J·v along both tangents, with the sliding Δv = v_B − v_A and the spin s = ℓ_B·ω_B − ℓ_A·ω_A
/// (roundFrictionVelocities() in solver_body.hpp): t₁·Δv + t₂·s and t₂·Δv − t₁·s.
STEPWISE_LANES_INLINE void frictionVelocities(const BodyLanes& a, const BodyLanes& b, const RoundBatch& batch,
                                              const Vec3Lanes& tangent1, Lanes& along0, Lanes& along1) {
    const Vec3Lanes sliding = b.velocity - a.velocity;
    const Vec3Lanes spin = batch.leverB * b.angularVelocity - batch.leverA * a.angularVelocity;
    along0 = dot(sliding, batch.tangent0) + dot(tangent1, spin);
    along1 = dot(sliding, tangent1) - dot(batch.tangent0, spin);
}

/// The friction impulse P = λ₁·t₁ + λ₂·t₂ as one vector: Δv = ∓m⁻¹·P, Δω = ∓I⁻¹·ℓ·(n × P),
/// n × P = λ₁·t₂ − λ₂·t₁ (applyRoundFrictionImpulse() in solver_body.hpp).
STEPWISE_LANES_INLINE void applyFriction(BodyLanes& a, BodyLanes& b, const RoundBatch& batch,
                                         const Vec3Lanes& tangent1, Lanes lambda0, Lanes lambda1) {
    const Vec3Lanes push = lambda0 * batch.tangent0 + lambda1 * tangent1;
    const Vec3Lanes twist = lambda0 * tangent1 - lambda1 * batch.tangent0;
    a.velocity -= a.inverseMass * push;
    b.velocity += b.inverseMass * push;
    a.angularVelocity -= (a.inverseInertia * batch.leverA) * twist;
    b.angularVelocity += (b.inverseInertia * batch.leverB) * twist;
}

/// A new batch whose four lanes are empty: static record 0 on both sides, zero masses and impulses.
RoundBatch emptyBatch() {
    RoundBatch batch;
    for (int lane = 0; lane < kLanes; ++lane) {
        batch.contact[lane] = kEmptyLane;
        batch.bodyA[lane] = batch.bodyB[lane] = kStaticSolverBody;
    }
    const Lanes zero = splat(0);
    batch.normal = batch.tangent0 = Vec3Lanes{zero, zero, zero};
    batch.normalMass = batch.tangentMass = batch.friction = zero;
    batch.leverA = batch.leverB = batch.separationOffset = zero;
    batch.normalImpulse = batch.tangentImpulse0 = batch.tangentImpulse1 = batch.maxNormalImpulse = zero;
    return batch;
}

void setLane(RoundBatch& batch, int lane, std::uint32_t index, const SolverContact& c) {
    batch.contact[lane] = index;
    batch.bodyA[lane] = c.bodyA;
    batch.bodyB[lane] = c.bodyB;
    batch.normal.setLane(lane, c.normal);
    batch.tangent0.setLane(lane, c.tangent[0]);
    batch.normalMass[lane] = c.normalMass;
    batch.tangentMass[lane] = c.tangentMass[0];
    batch.friction[lane] = c.friction;
    batch.leverA[lane] = c.leverA;
    batch.leverB[lane] = c.leverB;
    batch.separationOffset[lane] = c.separationOffset;
    batch.normalImpulse[lane] = c.normalImpulse;
    batch.tangentImpulse0[lane] = c.tangentImpulse[0];
    batch.tangentImpulse1[lane] = c.tangentImpulse[1];
    batch.maxNormalImpulse[lane] = c.maxNormalImpulse;
}

}  // namespace

void batchRoundContacts(SolverWorkspace& workspace) {
    constexpr std::uint32_t kNotRound = 0xffffffffu;
    workspace.roundBatches.clear();
    workspace.otherContacts.clear();
    workspace.roundBatchesAhead = false;
    // Per record: the wave its next contact may take (one after its last contact's), 0 before any.
    workspace.nextWave.assign(workspace.bodies.size(), 0);
    workspace.waveOf.resize(workspace.contacts.size());
    std::uint32_t waves = 0;
    for (std::uint32_t i = 0; i < workspace.contacts.size(); ++i) {
        const SolverContact& c = workspace.contacts[i];
        if (c.rows != kRoundContact) {
            workspace.waveOf[i] = kNotRound;
            workspace.otherContacts.push_back(i);  // solved alone, after the batches
            continue;
        }
        const bool bothDynamic = c.bodyB != kStaticSolverBody;  // nothing moves the static record: no wait
        const std::uint32_t wave = std::max(workspace.nextWave[c.bodyA], bothDynamic ? workspace.nextWave[c.bodyB] : 0);
        workspace.waveOf[i] = wave;
        workspace.nextWave[c.bodyA] = wave + 1;
        if (bothDynamic) workspace.nextWave[c.bodyB] = wave + 1;
        waves = std::max(waves, wave + 1);
    }

    // Counting sort by wave (contact order kept within a wave): each wave's contacts, four to a batch.
    workspace.waveStart.assign(waves + 1, 0);
    for (const std::uint32_t wave : workspace.waveOf) {
        if (wave != kNotRound) ++workspace.waveStart[wave + 1];
    }
    std::size_t batches = 0;
    for (std::uint32_t wave = 0; wave < waves; ++wave) {
        batches += (workspace.waveStart[wave + 1] + kLanes - 1) / kLanes;
        workspace.waveStart[wave + 1] += workspace.waveStart[wave];
    }
    workspace.waveOrder.resize(workspace.waveStart[waves]);
    for (std::uint32_t i = 0; i < workspace.contacts.size(); ++i) {
        if (workspace.waveOf[i] != kNotRound) workspace.waveOrder[workspace.waveStart[workspace.waveOf[i]]++] = i;
    }
    // Placing moved each start to its wave's end; the batches walk the waves in turn.
    workspace.roundBatches.reserve(batches);
    std::uint32_t first = 0;
    for (std::uint32_t wave = 0; wave < waves; ++wave) {
        const std::uint32_t end = workspace.waveStart[wave];
        for (std::uint32_t k = first; k < end; ++k) {
            const int lane = static_cast<int>((k - first) % kLanes);
            if (lane == 0) {
                workspace.roundBatches.push_back(emptyBatch());
                workspace.roundBatches.back().wave = wave;
            }
            setLane(workspace.roundBatches.back(), lane, workspace.waveOrder[k], workspace.contacts[workspace.waveOrder[k]]);
        }
        first = end;
    }
}

STEPWISE_LANES_COPIES
void warmStartRoundContacts(SolverWorkspace& workspace) {
    SolverBody discard;  // where the static record's lanes go (scatter())
    for (RoundBatch& batch : workspace.roundBatches) {
        BodyLanes a = gather(workspace.bodies, batch.bodyA);
        BodyLanes b = gather(workspace.bodies, batch.bodyB);
        applyNormal(a, b, batch.normal, batch.normalImpulse);
        applyFriction(a, b, batch, cross(batch.normal, batch.tangent0), batch.tangentImpulse0, batch.tangentImpulse1);
        scatter(workspace.bodies, batch.bodyA, a, discard);
        scatter(workspace.bodies, batch.bodyB, b, discard);
    }
}

void clearRoundContactImpulses(SolverWorkspace& workspace) {
    for (RoundBatch& batch : workspace.roundBatches) batch.normalImpulse = batch.tangentImpulse0 = batch.tangentImpulse1 = splat(0);
    workspace.roundBatchesAhead = true;
}

// solveContacts()'s pass (contact_solver.cpp), line for line, on four contacts at once: each `if`
// on a contact's own numbers becomes a select between the two results, lane by lane. Compiled
// three times (STEPWISE_LANES_COPIES, core/lanes.hpp): AVX-512, AVX2 and any x86-64, the same numbers.
STEPWISE_LANES_COPIES
void solveRoundContacts(SolverWorkspace& workspace, const ContactSolverSettings& settings, bool useBias) {
    const bool pushOut = useBias && settings.positionCorrection;
    const Lanes zero = splat(0);
    const Lanes one = splat(1);
    const Lanes inverseSubstep = splat(Real(1) / settings.substep);
    const Lanes biasRate = splat(settings.softness.biasRate);
    const Lanes slowestPushOut = splat(-kMaxPushOutSpeed);
    const Lanes softMassScale = splat(pushOut ? settings.softness.massScale : Real(1));
    const Lanes softImpulseScale = splat(pushOut ? settings.softness.impulseScale : Real(0));
    SolverBody discard;  // where the static record's lanes go (scatter())
    for (RoundBatch& batch : workspace.roundBatches) {
        const Vec3Lanes& n = batch.normal;
        // Normal: λ = −K⁻¹·s_m·(v_n + bias) − s_i·λ_acc (softness.hpp); a gap closes in this substep, no further.
        const Lanes separation =
            dot(gatherCentres(workspace.centres, batch.bodyB) - gatherCentres(workspace.centres, batch.bodyA), n) + batch.separationOffset;
        const auto gap = separation > zero;
        const Lanes softBias = pushOut ? maxLanes(biasRate * separation, slowestPushOut) : zero;
        const Lanes bias = select(gap, separation * inverseSubstep, softBias);
        const Lanes massScale = select(gap, one, softMassScale);
        const Lanes impulseScale = select(gap, zero, softImpulseScale);

        BodyLanes a = gather(workspace.bodies, batch.bodyA);
        BodyLanes b = gather(workspace.bodies, batch.bodyB);
        const Lanes vn = dot(b.velocity - a.velocity, n);
        const Lanes impulse = -batch.normalMass * massScale * (vn + bias) - impulseScale * batch.normalImpulse;
        Lanes applied;
        if (settings.accumulate) {
            const Lanes total = maxLanes(batch.normalImpulse + impulse, zero);
            applied = total - batch.normalImpulse;
            batch.normalImpulse = total;
        } else {  // Box2D-Lite's switch: clamp each increment
            applied = maxLanes(impulse, zero);
            batch.normalImpulse += applied;
        }
        batch.maxNormalImpulse = maxLanes(batch.maxNormalImpulse, batch.normalImpulse);
        applyNormal(a, b, n, applied);

        // Friction inside Coulomb's circle |λ_t| ≤ μ·λ_n, both tangents read before either is applied.
        // (A lane that does not push and holds no friction, which the scalar pass skips, computes a
        // scale of 0 or 1 on a zero impulse here: it changes nothing either.)
        const Lanes limit = batch.friction * batch.normalImpulse;
        Lanes along0;
        Lanes along1;
        const Vec3Lanes tangent1 = cross(n, batch.tangent0);  // t₂ = n × t₁, as prepare made it (tangentBasis())
        frictionVelocities(a, b, batch, tangent1, along0, along1);
        Lanes total0 = batch.tangentImpulse0 - batch.tangentMass * along0;
        Lanes total1 = batch.tangentImpulse1 - batch.tangentMass * along1;
        const Lanes magnitude = sqrtLanes(total0 * total0 + total1 * total1);
        const Lanes scale = select(magnitude > limit, limit / magnitude, one);
        total0 *= scale;
        total1 *= scale;
        applyFriction(a, b, batch, tangent1, total0 - batch.tangentImpulse0, total1 - batch.tangentImpulse1);
        batch.tangentImpulse0 = total0;
        batch.tangentImpulse1 = total1;

        scatter(workspace.bodies, batch.bodyA, a, discard);
        scatter(workspace.bodies, batch.bodyB, b, discard);
    }
    workspace.roundBatchesAhead = true;
}

void syncRoundContacts(SolverWorkspace& workspace) {
    if (!workspace.roundBatchesAhead) return;
    for (const RoundBatch& batch : workspace.roundBatches) {
        for (int lane = 0; lane < kLanes; ++lane) {
            if (batch.contact[lane] == kEmptyLane) continue;
            SolverContact& c = workspace.contacts[batch.contact[lane]];
            c.normalImpulse = batch.normalImpulse[lane];
            c.tangentImpulse[0] = batch.tangentImpulse0[lane];
            c.tangentImpulse[1] = batch.tangentImpulse1[lane];
            c.maxNormalImpulse = batch.maxNormalImpulse[lane];
        }
    }
    workspace.roundBatchesAhead = false;
}

}  // namespace stepwise
