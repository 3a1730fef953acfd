/// @file round_contact_lanes.cpp
/// @brief The round contacts solved four at a time (the why and the waves are in round_contact_lanes.hpp).
#include "fast/round_contact_lanes.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>

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

/// How many contacts ahead the batching asks for a contact's record. The batches are built in
/// wave order, which jumps about the contacts: with 64k balls they are 32 MB, and each record
/// read where it is first needed waits for memory.
constexpr std::uint32_t kBatchingLookAhead = 8;

/// The same for syncRoundContacts(), in batches of four contacts.
constexpr std::size_t kSyncLookAhead = 2;

}  // namespace

void recordCentres(const SolverWorkspace& solver, FastWorkspace& fast) {
    fast.centres.resize(solver.bodies.size());
    fast.centres[0] = SolverCentre{};
    for (std::size_t i = 1; i < solver.bodies.size(); ++i) fast.centres[i].position = solver.poses[solver.recordBody[i]].position;
}

void batchRoundContacts(const SolverWorkspace& solver, FastWorkspace& fast) {
    // Each round contact's wave (contact_waves.hpp), then each wave's contacts, four to a batch.
    const ContactWaves waves = contactWaves(solver, solver.roundContacts, solver.colouring.roundColourEnds, fast);
    std::size_t batches = 0;
    for (std::size_t wave = 0; wave < waves.ends.size(); ++wave) {
        const std::uint32_t first = wave == 0 ? 0 : waves.ends[wave - 1];
        batches += (waves.ends[wave] - first + kLanes - 1) / kLanes;
    }
    // The batches walk the waves in turn.
    fast.roundBatches.clear();
    fast.roundBatches.reserve(batches);
    fast.waveBatches.clear();
    std::uint32_t first = 0;
    for (std::uint32_t wave = 0; wave < waves.ends.size(); ++wave) {
        fast.waveBatches.push_back(static_cast<std::uint32_t>(fast.roundBatches.size()));
        const std::uint32_t end = waves.ends[wave];
        for (std::uint32_t k = first; k < end; ++k) {
            if (k + kBatchingLookAhead < waves.order.size()) {
                const SolverContact& ahead = solver.contacts[waves.order[k + kBatchingLookAhead]];
                for (std::size_t byte = 0; byte < sizeof(SolverContact); byte += kCacheLine) {
                    __builtin_prefetch(reinterpret_cast<const char*>(&ahead) + byte);
                }
            }
            const int lane = static_cast<int>((k - first) % kLanes);
            if (lane == 0) {
                fast.roundBatches.push_back(emptyBatch());
                fast.roundBatches.back().wave = wave;
            }
            setLane(fast.roundBatches.back(), lane, waves.order[k], solver.contacts[waves.order[k]]);
        }
        first = end;
    }
    fast.waveBatches.push_back(static_cast<std::uint32_t>(fast.roundBatches.size()));
}

STEPWISE_LANES_COPIES
void warmStartRoundContacts(SolverWorkspace& solver, const FastWorkspace& fast) {
    SolverBody discard;  // where the static record's lanes go (scatter())
    for (const RoundBatch& batch : fast.roundBatches) {
        BodyLanes a = gather(solver.bodies, batch.bodyA);
        BodyLanes b = gather(solver.bodies, batch.bodyB);
        applyNormal(a, b, batch.normal, batch.normalImpulse);
        applyFriction(a, b, batch, cross(batch.normal, batch.tangent0), batch.tangentImpulse0, batch.tangentImpulse1);
        scatter(solver.bodies, batch.bodyA, a, discard);
        scatter(solver.bodies, batch.bodyB, b, discard);
    }
}

void clearRoundContactImpulses(FastWorkspace& fast) {
    for (RoundBatch& batch : fast.roundBatches) batch.normalImpulse = batch.tangentImpulse0 = batch.tangentImpulse1 = splat(0);
}

namespace {

/// Batches of one wave solved side by side (solveBatches()): the most the
/// processor's registers and reorder window profit from (below).
constexpr std::size_t kBatchesSideBySide = 3;

/// The friction part of solveBatches(): on the bodies @p a, @p b of @p N batches of one wave,
/// after their normal impulses.
template <std::size_t N>
STEPWISE_LANES_INLINE void solveFrictionOfBatches(RoundBatch* batches, BodyLanes (&a)[N], BodyLanes (&b)[N],
                                                  const PassConstants& k) {
    // Friction inside Coulomb's circle |λ_t| ≤ μ·λ_n, both tangents read before either is applied.
    // (A lane that does not push and holds no friction, which the scalar pass skips, computes a
    // scale of 0 or 1 on a zero impulse here: it changes nothing either.)
    Vec3Lanes tangent1[N];
    Lanes total0[N];
    Lanes total1[N];
    for (std::size_t j = 0; j < N; ++j) {
        const RoundBatch& batch = batches[j];
        tangent1[j] = cross(batch.normal, batch.tangent0);  // t₂ = n × t₁, as prepare made it (tangentBasis())
        Lanes along0;
        Lanes along1;
        frictionVelocities(a[j], b[j], batch, tangent1[j], along0, along1);
        total0[j] = batch.tangentImpulse0 - batch.tangentMass * along0;
        total1[j] = batch.tangentImpulse1 - batch.tangentMass * along1;
    }
    for (std::size_t j = 0; j < N; ++j) {
        const Lanes limit = batches[j].friction * batches[j].normalImpulse;
        const Lanes magnitude = sqrtLanes(total0[j] * total0[j] + total1[j] * total1[j]);
        const Lanes scale = select(magnitude > limit, limit / magnitude, k.one);
        total0[j] *= scale;
        total1[j] *= scale;
    }
    for (std::size_t j = 0; j < N; ++j) {
        RoundBatch& batch = batches[j];
        applyFriction(a[j], b[j], batch, tangent1[j], total0[j] - batch.tangentImpulse0, total1[j] - batch.tangentImpulse1);
        batch.tangentImpulse0 = total0[j];
        batch.tangentImpulse1 = total1[j];
    }
}

/// solveContacts()'s pass (solve_contacts.cpp), line for line, on the @p N batches from @p batches on, all of one wave:
/// each `if` on a contact's own numbers becomes a select between the two results, lane by lane.
///
/// **Why N batches at once.** One batch is a chain of about 130 cycles, each step
/// waiting for the last: gather, v_n, λ, the velocities it leaves, friction's square root
/// and division, scatter. The processor overlaps the next batch only as far as its
/// reorder window reaches ahead, about one batch's instructions. Batches of one wave share
/// no body, so their chains are independent: written phase by phase, every phase once
/// for each batch, the N chains run side by side. Three fit the registers; with four,
/// values spill to the stack. The
/// numbers are each batch's own, so the bits are the same whatever N.
///
/// With @p Friction false (a relax pass, unless ContactSolverSettings::relaxBallFriction) the
/// batches' normal rows are solved and their friction is left as the solve pass left it
/// (contact_solver.hpp, "Friction in the relax").
template <std::size_t N, bool PushOut, bool Friction>
STEPWISE_LANES_INLINE void solveBatches(RoundBatch* batches, std::vector<SolverBody>& bodies,
                                        const std::vector<SolverCentre>& centres, const PassConstants& k,
                                        SolverBody& discard) {
    BodyLanes a[N];
    BodyLanes b[N];
    Lanes applied[N];
    // Normal: λ = −K⁻¹·s_m·(v_n + bias) − s_i·λ_acc (normal_row_lanes.hpp)
    for (std::size_t j = 0; j < N; ++j) {
        RoundBatch& batch = batches[j];
        const Vec3Lanes& n = batch.normal;
        const Lanes separation =
            dot(gatherCentres(centres, batch.bodyB) - gatherCentres(centres, batch.bodyA), n) +
            batch.separationOffset;
        a[j] = gather(bodies, batch.bodyA);
        b[j] = gather(bodies, batch.bodyB);
        const Lanes vn = dot(b[j].velocity - a[j].velocity, n);
        applied[j] = solveNormalImpulse<PushOut>(vn, separation, batch.normalMass, batch.normalImpulse,
                                                 batch.maxNormalImpulse, k);
    }
    for (std::size_t j = 0; j < N; ++j) applyNormal(a[j], b[j], batches[j].normal, applied[j]);
    if constexpr (Friction) solveFrictionOfBatches<N>(batches, a, b, k);
    for (std::size_t j = 0; j < N; ++j) {
        scatter(bodies, batches[j].bodyA, a[j], discard);
        scatter(bodies, batches[j].bodyB, b[j], discard);
    }
}

/// One pass over the batches [@p from, @p count): wave by wave, up to kBatchesSideBySide batches of
/// a wave at a time. With @p PushOut a template argument, the relax pass (no push) is compiled
/// without the soft bias's selects and scales, which are 1 and 0 there (the same bits).
template <bool PushOut, bool Friction>
STEPWISE_LANES_INLINE void solveWaves(SolverWorkspace& solver, FastWorkspace& fast, const PassConstants& k,
                                      std::size_t from, std::size_t count) {
    SolverBody discard;  // where the static record's lanes go (scatter()); each caller has its own
    RoundBatch* const batches = fast.roundBatches.data();
    for (std::size_t first = from; first < count;) {
        std::size_t run = 1;  // batches from `first` on in its wave, at most kBatchesSideBySide
        while (run < kBatchesSideBySide && first + run < count && batches[first + run].wave == batches[first].wave) ++run;
        static_assert(kBatchesSideBySide == 3, "one solveBatches<N> below for each N up to kBatchesSideBySide");
        if (run == 3) solveBatches<3, PushOut, Friction>(batches + first, solver.bodies, fast.centres, k, discard);
        else if (run == 2) solveBatches<2, PushOut, Friction>(batches + first, solver.bodies, fast.centres, k, discard);
        else solveBatches<1, PushOut, Friction>(batches + first, solver.bodies, fast.centres, k, discard);
        first += run;
    }
}

}  // namespace

void solveRoundContacts(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings, bool useBias) {
    solveRoundContactRange(solver, fast, settings, useBias, 0, fast.roundBatches.size());
}

// Compiled three times (STEPWISE_LANES_COPIES, lanes.hpp): AVX-512, AVX2 and any x86-64, the same numbers.
STEPWISE_LANES_COPIES
void solveRoundContactRange(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings,
                            bool useBias, std::size_t first, std::size_t end) {
    const PassConstants k = makePassConstants(settings);
    if (useBias && settings.positionCorrection) solveWaves<true, true>(solver, fast, k, first, end);  // the soft bias pushes overlaps apart
    else if (passSolvesRoundFriction(settings, useBias)) solveWaves<false, true>(solver, fast, k, first, end);
    else solveWaves<false, false>(solver, fast, k, first, end);  // a relax pass: the normal rows only
}

void syncRoundContacts(const FastWorkspace& fast, SolverWorkspace& solver) {
    const std::size_t count = fast.roundBatches.size();
    for (std::size_t b = 0; b < count; ++b) {
        const RoundBatch& batch = fast.roundBatches[b];
        // The contacts again in wave order: their records asked for (to be written) a few batches ahead
        if (b + kSyncLookAhead < count) {
            for (const std::uint32_t index : fast.roundBatches[b + kSyncLookAhead].contact) {
                if (index == kEmptyLane) continue;
                __builtin_prefetch(&solver.contacts[index].normalImpulse, 1);
                __builtin_prefetch(&solver.contacts[index].maxNormalImpulse, 1);
            }
        }
        writeImpulsesBack(batch, solver.contacts);
    }
}

}  // namespace stepwise
