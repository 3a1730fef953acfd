/// @file box_contact_lanes.hpp
/// @brief The contacts with stored rows (a box's, a kinematic body's) solved four at a time in SIMD lanes.
///
/// **What.** A contact that is not round (contact_solver.hpp, SolverContact)
/// keeps its Jacobian's angular parts in stored rows (ContactRow, solver_body.hpp):
/// per direction d (the normal and two tangents) the arms r × d and the turns
/// I⁻¹(r × d) of both bodies. A pass solves it with dot products and scaled
/// additions only (solveContact(), solve_contacts.cpp):
/// \f[ J v = d\cdot(v_B - v_A) + (r_B\times d)\cdot\omega_B - (r_A\times d)\cdot\omega_A , \qquad
///     \Delta\omega_B = \lambda\, I_B^{-1}(r_B\times d) , \f]
/// which are the same lines on four contacts at once: here, on Lanes (lanes.hpp).
///
/// **Waves.** As for the round contacts (contact_waves.hpp): four contacts of
/// one wave share no dynamic body, and each body meets its contacts in the
/// plain pass's order. The plain pass solves every round contact first, then
/// the others ("The order of a pass", contact_solver.hpp), so these waves are
/// their own: they run after all round batches, and only the contacts with
/// stored rows are scheduled. The points of one manifold share both bodies, so
/// they fall in successive waves; a wave is filled by other pairs' points.
///
/// **Thin waves stay scalar.** A tower is a chain: each manifold shares a box
/// with the next, so its waves hold one contact each and a batch would carry
/// three empty lanes, which cost more than the one contact's scalar solve.
/// Where the waves hold fewer than kMinBoxContactsPerWave contacts on
/// average, the step leaves these contacts to the plain solveContact(), one
/// at a time in their order (the same numbers either way).
///
/// **The separation once a stage.** The plain pass measures each contact's
/// separation at the recorded poses, turning the box's anchors by its
/// orientation (currentSeparation()):
/// \f[ C = (c_B - c_A)\cdot n + C_\text{offset} + (R_B\,l_B - R_A\,l_A)\cdot n , \f]
/// with R the rotation of the pose's quaternion.
/// The poses do not change within a stage (the solve's passes, or the
/// relax's): only the drift and the kinematic bodies' move record new ones,
/// between the stages. So the separation is computed once per stage, four
/// contacts at a time with the same lines (BoxAnchorBatch), and the passes
/// read one number per contact instead of two poses and two anchors.
///
/// **Friction** is solved in every pass, the relax's too (contact_solver.hpp,
/// "Friction in the relax"). The plain pass skips a point that does not push
/// and holds no friction; a lane cannot skip, so it computes and then keeps
/// the bodies' and the impulses' old values in those lanes (a select), which
/// is what skipping leaves, to the bit.
///
/// Reference: Catto, Box2D v3 `contact_solver.c` (contacts in SIMD lanes), 2024;
/// Catto, "Iterative Dynamics with Temporal Coherence" (GDC 2005, stored rows).
#pragma once

#include <cstdint>

#include "fast/lanes.hpp"

namespace stepwise {

struct SolverWorkspace;
struct ContactSolverSettings;
struct FastWorkspace;

/// @brief One row of four contacts, lane by lane: ContactRow (solver_body.hpp) on Lanes.
struct RowLanes {
    Vec3Lanes armA;   ///< r_A × d, m.
    Vec3Lanes armB;   ///< r_B × d, m.
    Vec3Lanes turnA;  ///< I_A⁻¹·(r_A × d), 1/(kg·m).
    Vec3Lanes turnB;  ///< I_B⁻¹·(r_B × d), 1/(kg·m).
};

/// @brief Four contacts with stored rows, of one wave, lane by lane: what a pass reads of them.
///
/// An empty lane names the static record 0 as both bodies and has zero rows and
/// masses, so whatever it computes changes nothing. The bodies' m⁻¹ come with
/// their velocities (body_lanes.hpp); t₂ is n × t₁, formed in the pass as
/// prepare formed it (tangentBasis(), the same bits); both tangents share one
/// mass (frictionPairMass()). 1792 bytes, 448 a contact.
struct alignas(kCacheLine) BoxBatch {
    std::uint32_t contact[kLanes];  ///< Index in SolverWorkspace::contacts, or kEmptyLane.
    std::uint32_t bodyA[kLanes];    ///< A's solver-body record.
    std::uint32_t bodyB[kLanes];    ///< B's record (kStaticSolverBody for a plane or a kinematic body).
    std::uint32_t wave = 0;         ///< The wave of its contacts: batches come in wave order.
    Vec3Lanes normal;               ///< n, from A to B.
    Vec3Lanes tangent0;             ///< t₁ (t₂ = n × t₁ is formed in the pass).
    RowLanes normalRow;             ///< The row along n.
    RowLanes tangentRow0;           ///< The row along t₁.
    RowLanes tangentRow1;           ///< The row along t₂.
    Lanes normalMass;               ///< K⁻¹ along n, kg.
    Lanes tangentMass;              ///< K⁻¹ along either tangent (one mass for both), kg.
    Lanes friction;                 ///< μ.
    Lanes normalSurfaceSpeed;       ///< A kinematic B's surface speed along n, m/s.
    Lanes tangentSurfaceSpeed0;     ///< Along t₁, m/s.
    Lanes tangentSurfaceSpeed1;     ///< Along t₂, m/s.
    Lanes separation;               ///< C at the poses of the current stage (recordBoxSeparations()), m.
    Lanes normalImpulse;            ///< Accumulated λ_n, N·s.
    Lanes tangentImpulse0;          ///< Accumulated friction along t₁, N·s.
    Lanes tangentImpulse1;          ///< Along t₂, N·s.
    Lanes maxNormalImpulse;         ///< Largest λ_n this step, N·s.
};

/// @brief What the separations of a BoxBatch's four contacts are measured from, lane by lane
/// (currentSeparation()): read once a stage, not by every pass, so kept beside the batch, not in it.
struct alignas(kCacheLine) BoxAnchorBatch {
    std::uint32_t poseA[kLanes];  ///< A's pose in SolverWorkspace::poses.
    std::uint32_t poseB[kLanes];  ///< B's pose there.
    Vec3Lanes localA;             ///< l_A, A's turning anchor in its body frame (zero if none), m.
    Vec3Lanes localB;             ///< l_B, m.
    Lanes separationOffset;       ///< C_offset, m.
    Lanes turning;                ///< 1 where an anchor turns (SolverContact::turningAnchors), else 0.
};

/// @brief The fewest contacts with stored rows a wave must hold on average for the lanes to be
/// taken. A batch of four lanes costs about what 1.3 contacts solved one at a time cost (measured
/// on the tower, docs/performance-history.md, "Speed beyond the sphere rain"); at two a wave the
/// lanes are ahead.
inline constexpr double kMinBoxContactsPerWave = 2;

/// @brief Puts the contacts with stored rows (SolverWorkspace::otherContacts, in order) in waves and,
/// if the waves are wide enough (kMinBoxContactsPerWave), packs them into @p fast's BoxBatch lanes
/// with their impulses as prepareContacts() left them; otherwise leaves FastWorkspace::boxBatches
/// empty, and the passes solve these contacts one at a time.
void batchBoxContacts(const SolverWorkspace& solver, FastWorkspace& fast);

/// @brief Each batched contact's separation at the poses recorded now (currentSeparation()'s lines,
/// four at a time: the same bits), for the passes of the stage that follows.
void recordBoxSeparations(const SolverWorkspace& solver, FastWorkspace& fast);

/// @brief The warm start of the batched contacts: their accumulated impulses applied to the bodies
/// (warmStartContact(): the normal row, then each tangent's).
void warmStartBoxContacts(SolverWorkspace& solver, const FastWorkspace& fast);

/// @brief Starts the batched contacts' impulses from zero (a substep without accumulated impulses).
void clearBoxContactImpulses(FastWorkspace& fast);

/// @brief One Gauss–Seidel pass over the batched contacts, four at a time: solveContacts()'s second
/// half, the contacts with stored rows in their order, at the separations recordBoxSeparations() left.
void solveBoxContacts(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings, bool useBias);

/// @brief The same pass over the batches [@p first, @p end) only: whole waves, or part of one wave
/// (whose batches share no body, so any part of it may be solved apart from the rest, on any thread).
void solveBoxContactRange(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings,
                          bool useBias, std::size_t first, std::size_t end);

/// @brief Copies the batched contacts' impulses back into SolverWorkspace::contacts.
void syncBoxContacts(const FastWorkspace& fast, SolverWorkspace& solver);

}  // namespace stepwise
