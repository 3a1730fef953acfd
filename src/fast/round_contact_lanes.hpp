/// @file round_contact_lanes.hpp
/// @brief The round contacts (ball–ball, ball–plane, ball–resting kinematic body) solved four at a time: waves of independent contacts in SIMD lanes.
///
/// **Why.** Solving one contact is a long chain of small operations, most
/// waiting for the one before (solveContact() in dynamics/solve_contacts.cpp):
/// a few hundred instructions for a ball on a ball, and while the contacts fit
/// in the caches a pass is bound by them, not by memory. A processor can do
/// the same operation on four doubles at once (SIMD: SSE2 two, AVX2 and AVX-512 four),
/// but only on four *independent* contacts.
///
/// **Waves** (contact_waves.hpp). Gauss–Seidel solves the contacts in order, each one reading
/// the velocities the earlier ones left. But two contacts that share no
/// dynamic body do not read each other's results at all: solving them in
/// either order, or at once, gives the same numbers to the last bit. Only the
/// order of contacts on the *same* body matters. So each contact is put in
/// a *wave*: one after the latest wave of any earlier contact on either of
/// its bodies (the static record 0, B of every plane contact, does not count:
/// nothing moves it),
/// \f[ w_c = \max\big(\text{next}(A_c),\ \text{next}(B_c)\big), \qquad
///     \text{next}(A_c) = \text{next}(B_c) = w_c + 1 , \f]
/// walking the contacts in their order. Two contacts of one wave never share
/// a body, and for every body its contacts come in waves in their own order.
/// A pass then solves wave after wave, four contacts of a wave at a time (a
/// *batch*), and up to three batches of a wave side by side (solveBatches()
/// in round_contact_lanes.cpp): each body meets its contacts in exactly the
/// order the plain pass would, so the result is the plain pass's, bit for
/// bit, only faster.
/// (This is list scheduling of the contacts' dependency graph. Colouring
/// that graph, as Box2D v3 does, fills the batches with fewer, larger groups
/// but changes the order, and with it how far one pass carries a pile's
/// weight down, so the result would no longer be the plain pass's.)
///
/// The contacts whose rows are stored (a box, a moving kinematic body) have batches of
/// their own, solved after all of these (box_contact_lanes.hpp): the plain pass
/// also takes the round contacts first ("The order of a pass", contact_solver.hpp).
///
/// **The order is the contacts'.** The waves follow from the contacts
/// alone: the same on every machine, whether the lanes run in AVX-512, AVX2, SSE2 or
/// no vector registers at all (IEEE 754 rounds each lane as a scalar).
///
/// **The formulas** are the round contact's of solver_body.hpp and
/// solve_contacts.cpp, written on Lanes (lanes.hpp) instead of Reals:
/// the same lines, four contacts at a time.
///
/// Reference: Catto, Box2D v3 `contact_solver.c` (contacts in SIMD lanes) and
/// `constraint_graph.c` (the graph colouring it uses instead), 2024; Tonge,
/// "Iterative Rigid Body Solvers" (GDC 2012, independent batches).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fast/lanes.hpp"

namespace stepwise {

struct SolverWorkspace;
struct ContactSolverSettings;
struct FastWorkspace;

/// RoundBatch::contact of an empty lane (the last batch of a wave may not be full).
inline constexpr std::uint32_t kEmptyLane = 0xffffffffu;

/// @brief Four round contacts of one wave, lane by lane: the SolverContact fields a pass reads.
///
/// An empty lane names the static record 0 as both bodies, whose masses are
/// zero, so whatever it computes changes nothing.
///
/// Every pass reads every batch, so a batch holds only what cannot be had
/// otherwise: the bodies' m⁻¹ and I⁻¹ come with their velocities (the same
/// loads), and t₂ is n × t₁, formed in the pass as prepare formed it
/// (tangentBasis(), the same bits). That keeps a batch at 576 bytes: fewer
/// bytes for every pass to read. Aligned to a cache line, a batch is nine
/// whole lines, not parts of ten.
struct alignas(kCacheLine) RoundBatch {
    std::uint32_t contact[kLanes];  ///< Index in SolverWorkspace::contacts, or kEmptyLane.
    std::uint32_t bodyA[kLanes];    ///< A's solver-body record.
    std::uint32_t bodyB[kLanes];    ///< B's record (kStaticSolverBody for a plane).
    std::uint32_t wave = 0;         ///< The wave of its contacts: batches come in wave order.
    Vec3Lanes normal;               ///< n, from A to B.
    Vec3Lanes tangent0;             ///< t₁ (t₂ = n × t₁ is formed in the pass).
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

/// @brief Each record's centre at the poses last recorded (SolverWorkspace::poses) into
/// FastWorkspace::centres, where the lanes measure separations; record 0's "centre" is the origin.
void recordCentres(const SolverWorkspace& solver, FastWorkspace& fast);

/// @brief Puts the round contacts of @p solver (SolverWorkspace::roundContacts, in order) in waves
/// and packs them into @p fast's RoundBatch lanes, with their impulses as prepareContacts() left them.
void batchRoundContacts(const SolverWorkspace& solver, FastWorkspace& fast);

/// @brief The warm start of the batched contacts: their accumulated impulses applied to the bodies.
void warmStartRoundContacts(SolverWorkspace& solver, const FastWorkspace& fast);

/// @brief Starts the batched contacts' impulses from zero (a substep without accumulated impulses).
void clearRoundContactImpulses(FastWorkspace& fast);

/// @brief One Gauss–Seidel pass over the batched contacts, four at a time: solveContacts()'s first
/// half, the round contacts in their order. Separations are measured at FastWorkspace::centres.
void solveRoundContacts(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings, bool useBias);

/// @brief The same pass over the batches [@p first, @p end) only: whole waves, or part of one wave
/// (whose batches share no body, so any part of it may be solved apart from the rest, on any thread).
void solveRoundContactRange(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings,
                            bool useBias, std::size_t first, std::size_t end);

/// @brief Copies the batched contacts' impulses back into SolverWorkspace::contacts.
void syncRoundContacts(const FastWorkspace& fast, SolverWorkspace& solver);

}  // namespace stepwise
