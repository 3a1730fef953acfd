/// @file round_contact_lanes.hpp
/// @brief The round contacts (ball–ball, ball–plane) solved four at a time: graph colouring and SIMD lanes.
///
/// **Why.** A contact pass is a long chain of small dependent operations on
/// one contact (contact_solver.cpp): about 260 instructions for a ball on a
/// ball, one after the other. A processor can do the same operation on four
/// doubles at once (SIMD: SSE2 two, AVX four), but only on four *independent*
/// contacts: two contacts that push the same body must be solved one after
/// the other, since Gauss–Seidel's second one reads what the first did.
///
/// **Colours.** So the contacts are first *coloured*, as one colours a graph
/// whose vertices are the contacts and whose edges join contacts sharing a
/// dynamic body: each contact gets the lowest colour none of its two bodies
/// has yet (greedy colouring; every body remembers its colours as bits). Two
/// contacts of one colour never share a dynamic body (the static record 0,
/// B of every plane contact, does not count: nothing can move it). A pass
/// then walks the colours in order, and within a colour takes the contacts
/// four at a time, in the contacts' own order: a *batch*. Solving a batch in
/// four lanes is exactly solving its four contacts one after the other,
/// because none of them reads what another writes. A ball touches at most
/// twelve equal balls and a few walls, so kContactColours colours are plenty;
/// a contact that finds none free is solved alone after the batches, as is
/// every contact whose rows are stored (boxes, kinematic bodies).
///
/// **The order changes, the physics does not.** Gauss–Seidel's result
/// depends on the order in which it meets the contacts (to within what the
/// passes have not yet converged): colour by colour is another order than
/// the broadphase's, so the trajectory is another one, as it would be with
/// another broadphase order. It is still one order, fixed by the contacts
/// alone: the same on every machine, whether the lanes run in AVX, SSE2 or
/// no vector registers at all (IEEE 754 rounds each lane as a scalar).
///
/// **The formulas** are the round contact's of solver_body.hpp and
/// contact_solver.cpp, written on Lanes (core/lanes.hpp) instead of Reals:
/// the same lines, four contacts at a time.
///
/// Reference: Catto, Box2D v3 `constraint_graph.c` (graph colouring of
/// constraints) and `contact_solver.c` (contacts in SIMD lanes), 2024;
/// Tonge, "Iterative Rigid Body Solvers" (GDC 2012, parallel batches).
#pragma once

#include <cstdint>
#include <vector>

#include "core/lanes.hpp"

namespace stepwise {

struct SolverWorkspace;
struct ContactSolverSettings;

/// Colours a round contact may take (bits of a 32-bit mask per body). A ball
/// among equal balls touches at most twelve and a few walls; a contact that
/// finds every colour taken is solved alone, after the batches.
inline constexpr int kContactColours = 24;

/// RoundBatch::contact of an empty lane (the last batch of a colour may not be full).
inline constexpr std::uint32_t kEmptyLane = 0xffffffffu;

/// @brief Four round contacts of one colour, lane by lane: the SolverContact fields a pass reads.
///
/// An empty lane names the static record 0 as both bodies and has zero
/// masses, so whatever it computes changes nothing.
struct RoundBatch {
    std::uint32_t contact[kLanes];  ///< Index in SolverWorkspace::contacts, or kEmptyLane.
    std::uint32_t bodyA[kLanes];    ///< A's solver-body record.
    std::uint32_t bodyB[kLanes];    ///< B's record (kStaticSolverBody for a plane).
    std::uint32_t poseA[kLanes];    ///< A's pose in SolverWorkspace::poses.
    std::uint32_t poseB[kLanes];    ///< B's pose.
    std::uint32_t colour = 0;       ///< The colour of its contacts: batches come in colour order.
    Vec3Lanes normal;               ///< n, from A to B.
    Vec3Lanes tangent0;             ///< t₁; t₂ = n × t₁.
    Vec3Lanes tangent1;             ///< t₂.
    Lanes normalMass;               ///< K⁻¹ along n, kg.
    Lanes tangentMass;              ///< K⁻¹ along either tangent (the same for a round contact), kg.
    Lanes friction;                 ///< μ.
    Lanes leverA;                   ///< ℓ_A = r_A·n, m.
    Lanes leverB;                   ///< ℓ_B = r_B·n, m.
    Lanes separationOffset;         ///< C_offset, m.
    Lanes normalImpulse;            ///< Accumulated λ_n, N·s.
    Lanes tangentImpulse0;          ///< Accumulated friction along t₁, N·s.
    Lanes tangentImpulse1;          ///< Along t₂, N·s.
    Lanes maxNormalImpulse;         ///< Largest λ_n this step, N·s.
};

/// @brief Colours the round contacts of @p workspace and packs them into RoundBatch lanes;
/// lists every other contact in SolverWorkspace::otherContacts. Once a step, after prepare.
void batchRoundContacts(SolverWorkspace& workspace);

/// @brief The warm start of the batched contacts: their accumulated impulses applied to the bodies.
void warmStartRoundContacts(SolverWorkspace& workspace);

/// @brief Starts the batched contacts' impulses from zero (a substep without accumulated impulses).
void clearRoundContactImpulses(SolverWorkspace& workspace);

/// @brief One Gauss–Seidel pass over the batched contacts, four at a time (solveContacts()'s round half).
void solveRoundContacts(SolverWorkspace& workspace, const ContactSolverSettings& settings, bool useBias);

/// @brief Copies the batched contacts' impulses back into SolverWorkspace::contacts, if the passes changed them since.
void syncRoundContacts(SolverWorkspace& workspace);

}  // namespace stepwise
