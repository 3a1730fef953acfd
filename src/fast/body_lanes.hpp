/// @file body_lanes.hpp
/// @brief Four solver bodies read into lanes and written back: what every contact pass in lanes starts and ends with.
///
/// A contact pass in lanes (round_contact_lanes.hpp, box_contact_lanes.hpp)
/// solves four contacts of one wave at once. Each reads its two bodies' records
/// (SolverBody, solver_body.hpp), which lie anywhere in the array; the four
/// records of one side are loaded one by one and regrouped into lanes by a
/// transpose, and after the contact they are regrouped back and stored.
/// Only the file that solves the contacts includes this one; its functions
/// are inlined into that file's `target_clones` copies (lanes.hpp).
#pragma once

// The helpers below pass Lanes by value too, always inlined (see lanes.hpp).
#if defined(__GNUC__)  // GCC, and clang, which reads GCC's pragmas
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "dynamics/contact_solver.hpp"
#include "dynamics/solver_body.hpp"
#include "fast/lanes.hpp"
#include "fast/round_contact_lanes.hpp"

namespace stepwise {

// A solver body is two Lanes long, [v_x v_y v_z ω_x] and [ω_y ω_z m⁻¹ I⁻¹], so
// four of them are read with eight loads and regrouped by transposing (below).
static_assert(sizeof(SolverBody) == 2 * sizeof(Lanes), "SolverBody must be two Lanes: v, ω, m⁻¹, I⁻¹");
static_assert(offsetof(SolverBody, angularVelocity) == 3 * sizeof(Real) &&
                  offsetof(SolverBody, inverseMass) == 6 * sizeof(Real),
              "SolverBody's layout is read as [v_x v_y v_z ω_x][ω_y ω_z m⁻¹ I⁻¹]");

/// @brief The four bodies of one side (A or B) of a batch of contacts, lane by lane.
struct BodyLanes {
    Vec3Lanes velocity;         ///< v, m/s.
    Vec3Lanes angularVelocity;  ///< ω, rad/s.
    Lanes inverseMass;          ///< m⁻¹, 1/kg.
    Lanes inverseInertia;       ///< A ball's I⁻¹ (zero for a box), 1/(kg·m²).
};

/// @brief The Reals of a record, from v_x on.
STEPWISE_LANES_INLINE const Real* realsOf(const SolverBody& body) { return &body.velocity.x; }
/// @brief The Reals of a record, from v_x on.
STEPWISE_LANES_INLINE Real* realsOf(SolverBody& body) { return &body.velocity.x; }

/// @brief Records @p index of @p bodies, lane by lane: the velocities, and the masses m⁻¹ and I⁻¹ that
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

/// @brief Writes the velocities back to records @p index, in lane order; m⁻¹ and I⁻¹ stay as they are in memory.
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

/// @brief Copies the accumulated impulses of @p batch's contacts (a RoundBatch or a BoxBatch) back to
/// @p contacts, lane by lane, skipping the empty lanes: the end of the substeps, for the bounce and
/// the next step's warm start.
template <class Batch>
inline void writeImpulsesBack(const Batch& batch, std::vector<SolverContact>& contacts) {
    for (int lane = 0; lane < kLanes; ++lane) {
        if (batch.contact[lane] == kEmptyLane) continue;
        SolverContact& c = contacts[batch.contact[lane]];
        c.normalImpulse = batch.normalImpulse[lane];
        c.tangentImpulse[0] = batch.tangentImpulse0[lane];
        c.tangentImpulse[1] = batch.tangentImpulse1[lane];
        c.maxNormalImpulse = batch.maxNormalImpulse[lane];
    }
}

}  // namespace stepwise

#if defined(__GNUC__)  // GCC, and clang, which reads GCC's pragmas
#pragma GCC diagnostic pop
#endif
