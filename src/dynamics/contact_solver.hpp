/// @file contact_solver.hpp
/// @brief The sequential-impulse solver's contact constraints: soft, warm-started, sub-stepped.
///
/// This is the contact half of `Solver=SequentialImpulse` (the joints are in
/// src/dynamics/joints/). The foundation's pairwise scheme
/// (impulse_resolver.hpp, `Solver=Impulse`) integrates first and repairs the
/// overlap afterwards; this solver follows Catto's *soft step* (Box2D v3):
/// contacts are found at the start of the step and then held through every
/// substep, so the position error is seen while it is being made.
///
/// **The constraint.** For a contact point with normal n (from A to B) and
/// lever arms r_A, r_B, the separation C = (p_B − p_A)·n must stay ≥ 0. Its
/// time derivative is the relative normal velocity
/// \f[ \dot C = J v = \big((v_B + \omega_B\times r_B) - (v_A + \omega_A\times r_A)\big)\cdot n, \f]
/// so J = [−nᵀ, −(r_A×n)ᵀ, nᵀ, (r_B×n)ᵀ] and the effective mass is
/// \f[ K = J M^{-1} J^T = m_A^{-1} + m_B^{-1} + (r_A\times n)\cdot I_A^{-1}(r_A\times n) + (r_B\times n)\cdot I_B^{-1}(r_B\times n). \f]
/// One iteration applies λ = −K⁻¹(J v + bias), clamped so the *accumulated*
/// λ stays ≥ 0 (contacts push, never pull): projected Gauss–Seidel.
///
/// **Position error without energy.** While the surfaces overlap (C < 0) the
/// bias is soft (softness.hpp): b·C, at most kMaxPushOutSpeed, with a softened
/// mass. While they are still apart (C > 0, a *speculative* point) the bias
/// is C/h_s: the bodies may close the gap within this substep, not more. The
/// push-out speed would be kinetic energy if it stayed, so after moving the
/// positions each substep *relaxes*: it solves again without the soft bias,
/// removing the push-out velocity but keeping the position it gained.
///
/// **Friction.** Two tangent directions t₁, t₂ with the same J structure;
/// the accumulated friction impulse is kept inside Coulomb's circle
/// |λ_t| ≤ μ·λ_n, with λ_n the current accumulated normal impulse.
///
/// **Friction in the relax.** The relax pass is there for the normal rows: it
/// takes back the push-out speed they were given. Friction rows have no bias.
/// Whether the relax must solve them again depends on how a contact's normal
/// impulse moves its own point across the surface, the off-diagonal entry
/// K_nt = J_n·M⁻¹·J_tᵀ. At a box's corner it is not zero (r × n and r × t
/// are not at right angles in general): the relax's normal impulse turns the
/// box and sets the corner sliding, and without friction in the relax a 100:1
/// stack creeps sideways ("A 100 kg box stands on a 1 kg box", tests/test_solver.cpp). At a ball's contact the
/// normal row has no angular part (the impulse passes through the centres)
/// and n ⊥ t, so K_nt = 0: the relax's normal impulse leaves that contact's
/// sliding exactly as it was, and its friction rows are solved once a
/// substep, in the solve pass. So a relax pass solves a contact with stored
/// rows (a box's, a kinematic body's) whole, and a round contact's normal row
/// only, unless ContactSolverSettings::relaxBallFriction (`RelaxBallFriction=true`)
/// asks for both. Other contacts' relax impulses still change a ball's sliding
/// (it is a Gauss–Seidel pass), and the next solve pass takes that up. What
/// that costs is small and measured: three balls stacked as a triangle, which
/// stand exactly from μ = 2 − √3 = 0.2679 between them, stand in the engine
/// within about 1 % of Coulomb's line with or without the relax's friction
/// (tests/test_friction.cpp: they fall at μ = 0.25 and stand at 0.29).
/// Engines commonly solve friction in fewer passes than the normal rows:
/// PhysX's PGS solver, by default, skips it in all but the last three of its
/// biased (position) iterations (`PxSceneFlag::eENABLE_FRICTION_EVERY_ITERATION`
/// turns it on in all).
///
/// **Restitution** is applied once, after all substeps, by Poisson's law:
/// each contact gets e times its compression impulse again (applyRestitution()).
///
/// **Warm starting.** Each point found again (same ContactKey) starts from
/// last step's impulses; they are applied at the start of every substep.
///
/// References: Catto, "Solver2D" and "Soft Step" (box2d.org blog, 2024);
/// Catto, "Iterative Dynamics with Temporal Coherence" (GDC 2005);
/// Tonge, "Iterative Rigid Body Solvers" (GDC 2012).
#pragma once

#include <span>
#include <vector>

#include "collision/contact.hpp"
#include "dynamics/impulse_resolver.hpp"
#include "dynamics/islands.hpp"
#include "dynamics/softness.hpp"
#include "dynamics/solver_body.hpp"
#include "objects/body_set.hpp"
#include "core/thread_pool.hpp"
#include "core/world_settings.hpp"

namespace stepwise {

/// Largest speed at which a soft contact pushes overlapping bodies apart, m/s.
/// A deep overlap (a body dropped inside another) is removed over several
/// steps at this speed instead of exploding out of it.
inline constexpr Real kMaxPushOutSpeed = Real(3);

/// @brief Where a body is: the part of its state the separation of a contact depends on.
struct Pose {
    Vec3 position{0, 0, 0};        ///< Centre, m.
    Quat orientation{1, 0, 0, 0};  ///< Body-to-world rotation.
};

/// @brief Index of SolverContact::turningAnchors for a contact whose anchors both stay at fixed offsets (spheres, planes).
inline constexpr std::uint32_t kNoTurningAnchors = 0xffffffffu;

/// @brief SolverContact::rows of a *round* contact, whose rows are computed from its normal (solver_body.hpp).
inline constexpr std::uint32_t kRoundContact = 0xffffffffu;

/// @brief One contact point held by the sequential-impulse solver through a step: what every pass reads.
///
/// A pass reads this array once per solve or relax pass, 32 times a step at the
/// default 16 substeps, so it holds only what a pass reads; where the contact came
/// from (its bodies, lever arms, point and start gap) and its bounce are in
/// the parallel ContactStart array. The bodies are named by their
/// solver-body records (solver_body.hpp), not by pointers into the World's
/// objects.
///
/// **Rows stored or computed.** The Jacobian's angular parts, ContactRow per
/// direction, are 288 bytes. A contact between two balls, or a ball and a
/// body that neither moves nor turns this step (a plane, or a kinematic body
/// at rest: KinematicsObject::atRest()), does not need them: its lever arms lie
/// along the normal and a ball's inertia is a number, so the rows follow from
/// the levers ℓ_A = r_A·n and ℓ_B = r_B·n (solver_body.hpp, "Rows of a round
/// contact"; ℓ_B = 0 for a static B, whose m⁻¹ and I⁻¹ are zero). Such a *round*
/// contact has `rows == kRoundContact` and a pass computes its rows; any other
/// (a box, a moving kinematic body, whose surface speed v + ω × r enters J·v,
/// or a surface under a conveyor belt, whose belt speed does: src/forces/conveyor.hpp)
/// keeps them in the side array SolverWorkspace::rows, which a pass reads at
/// index `rows`. A kinematic body at rest is measured as a plane is, from the
/// fixed pose at the origin: its anchor is a fixed point for the whole step.
///
/// **The order of a pass.** A Gauss–Seidel pass solves the contacts one
/// after the other, each reading the velocities the earlier ones left, so
/// the order is part of the result. A pass here takes the round contacts
/// first, then the others (SolverWorkspace::roundContacts,
/// SolverWorkspace::otherContacts), each group colour by colour: no two
/// contacts of a colour share a dynamic body (contact_colours.hpp,
/// `ContactOrder=Colours`), or, with `ContactOrder=Found`, in the order the
/// narrowphase found them. Any fixed order is a valid sweep; the colour order
/// is one in which the fast path (src/fast/) can solve a whole colour four
/// contacts at a time and on several threads, so the roads compute the same
/// numbers.
///
/// **The separation without the contact point.** An anchor either turns with
/// its body (a box's material point: p = c + R·l, with l fixed in the body)
/// or stays at a fixed offset from the centre (a sphere's support, which
/// stays under the centre while the ball rolls; a plane's point, whose
/// "centre" is the origin and never moves). The separation of the two anchors
/// along the fixed normal,
/// \f[ C = C_0 + (p_B - p_A)\cdot n - (p_{B,0} - p_{A,0})\cdot n = (c_B - c_A)\cdot n + C_\text{offset}
///        + (R_B l_B - R_A l_A)\cdot n, \f]
/// folds everything fixed through the step into one number, C_offset (the
/// start gap and the fixed offsets), and keeps the turning anchors l_A, l_B
/// in a side array that only box contacts read. A sphere's contact then costs
/// one dot product of two centres.
struct SolverContact {
    std::uint32_t bodyA = 0;         ///< A's record in SolverWorkspace::bodies.
    std::uint32_t bodyB = kStaticSolverBody; ///< B's record, or kStaticSolverBody for a plane or kinematic body.
    Vec3 normal{0, 1, 0};            ///< From A towards B, fixed for the step.
    Vec3 tangent[2];                 ///< Friction directions across the normal, with n × t₁ = t₂ (tangentBasis()).
    Real normalMass = 0;             ///< K⁻¹ along n, kg.
    Real tangentMass[2] = {0, 0};    ///< K⁻¹ along the tangents: one mass for both, frictionPairMass(), kg.
    Real friction = 0;               ///< μ of the pair.
    Real normalImpulse = 0;          ///< Accumulated λ_n of the current substep, N·s.
    Real tangentImpulse[2] = {0, 0}; ///< Accumulated friction impulses, N·s.
    Real maxNormalImpulse = 0;       ///< Largest λ_n seen this step (0: never pushed), N·s.
    Real leverA = 0;                 ///< Round contact: ℓ_A = r_A·n, the lever arm along the normal, m.
    Real leverB = 0;                 ///< Round contact: ℓ_B = r_B·n (zero against a plane), m.
    // The separation at the recorded poses (currentSeparation() in solve_contacts.cpp).
    Real separationOffset = 0;       ///< C_offset: C₀ and the fixed anchor offsets along n, m.
    std::uint32_t poseA = 0;         ///< A's pose in SolverWorkspace::poses.
    std::uint32_t poseB = 0;         ///< B's pose there (a plane or a kinematic body at rest: the fixed pose at the origin).
    std::uint32_t rows = kRoundContact; ///< Index in SolverWorkspace::rows, or kRoundContact: computed from n, ℓ_A, ℓ_B.
    std::uint32_t turningAnchors = kNoTurningAnchors; ///< Index in SolverWorkspace::turningAnchors, if an anchor turns.
};

/// @brief The stored Jacobian rows of a contact that is not round (a box, a moving kinematic body, a belt), read by every pass.
struct ContactRows {
    ContactRow normal;                    ///< J's angular parts along n (solver_body.hpp), fixed for the step.
    ContactRow tangent[2];                ///< The same along each tangent.
    Real normalSurfaceSpeed = 0;          ///< A kinematic B's surface velocity along n, m/s (zero for a plane or a dynamic B).
    Real tangentSurfaceSpeed[2] = {0, 0}; ///< The same along each tangent, plus a conveyor belt's (conveyor.hpp), m/s.
};

/// @brief The anchors of a contact that turn with their body, in body frames (zero for a side that does not turn), m.
struct TurningAnchors {
    Vec3 localA{0, 0, 0};  ///< l_A: the point in A's body frame (a box's material point; a capsule's axis point under the contact).
    Vec3 localB{0, 0, 0};  ///< l_B: the same in B's body frame.
};

/// @brief Where a contact came from and what it was at the start of the step:
/// read once a step (prepare, the bounce) and by the trace, never by a pass.
struct ContactStart {
    std::uint32_t indexA = 0;        ///< A's index in the dynamic array.
    BodyRef refB;                    ///< B: its kind and index.
    Vec3 rA{0, 0, 0};                ///< Lever arm from A's centre to the point (world frame, start of step), m.
    Vec3 rB{0, 0, 0};                ///< The same from B's centre (zero for a plane), m.
    Vec3 startPoint{0, 0, 0};        ///< The contact point at the start of the step, where both anchors were, m.
    Real startSeparation = 0;        ///< C₀, the gap at the start of the step: −Contact::depth, m (> 0: a gap).
    Real restitution = 0;            ///< e of the pair (0 when the contact is resting): an impact's, for reports.
    Real elasticity = 0;             ///< e of the pair, resting or not: what the compression impulse is multiplied by.
    Real approachAtTouch = 0;        ///< v_c: approach speed when the surfaces meet, m/s (≥ 0).
    /// The normal velocity the compression starts from, m/s: −v_c for an impact, 0 for a resting
    /// contact (its approach is gravity's, not an impact's), v_n for a separating one.
    Real touchVelocity = 0;
    /// Pressed shut by an acceleration (gravity along n) and approaching no faster than it makes
    /// them: a load, not an impact. Left out of the compression, so it never bounces.
    bool carriesLoad = false;
    Real compression = 0;            ///< P: the compression impulse applyRestitution() found, N·s (0 until then).
    Real bounceVelocity = 0;         ///< e·(J·Δu): the normal velocity Poisson's law parts the contact at, m/s.
    Real bounceImpulse = 0;          ///< What applyRestitution() applied to bring the contact there, N·s.
    Vec3 staticVelocity{0, 0, 0};    ///< Velocity of a kinematic B's surface at the point, m/s (zero for a plane or a dynamic B).
};

/// @brief A body's linear and angular velocity, m/s and rad/s.
struct BodyVelocity {
    Vec3 velocity{0, 0, 0};         ///< v, m/s.
    Vec3 angularVelocity{0, 0, 0};  ///< ω, world frame, rad/s.
};

/// @brief A sum of angular velocities, padded to four Reals so that it is one aligned load (SolverWorkspace::turnSums).
struct alignas(4 * sizeof(Real)) SpinSum {
    Vec3 sum{0, 0, 0};  ///< Σ ω, rad/s.
    Real unused = 0;    ///< Padding to four Reals.
};

/// @brief What the contact solver needs of the World's settings for one substep (makeContactSolverSettings()).
struct ContactSolverSettings {
    Real substep = 0;                ///< h_s = h / substeps, s.
    Real inverseSubstep = 0;         ///< 1/h_s, 1/s: a speculative gap C may close at C/h_s.
    Softness softness;               ///< From ContactHertz and ContactDampingRatio at h_s.
    bool accumulate = true;          ///< Clamp the accumulated impulse (true) or each increment (false).
    bool positionCorrection = true;  ///< Use the soft bias on overlaps (false: overlaps are never pushed out).
    bool relaxBallFriction = false;  ///< The relax passes solve a round contact's friction too ("Friction in the relax", above).
};

/// @brief The contact solver's settings for substeps of @p substep seconds, from the World record @p settings.
ContactSolverSettings makeContactSolverSettings(const WorldSettings& settings, Real substep);

/// @brief Whether a pass solves the friction rows of the round contacts: every solve pass does,
/// a relax pass (@p useBias false) only with ContactSolverSettings::relaxBallFriction
/// ("Friction in the relax", above).
inline bool passSolvesRoundFriction(const ContactSolverSettings& settings, bool useBias) {
    return useBias || settings.relaxBallFriction;
}

/// @brief Whether a pass solves the friction rows of contact @p c: a contact with stored rows in
/// every pass, a round one as passSolvesRoundFriction() says.
inline bool passSolvesFriction(const SolverContact& c, const ContactSolverSettings& settings, bool useBias) {
    return c.rows != kRoundContact || passSolvesRoundFriction(settings, useBias);
}

/// @brief The stored rows and turning anchors that one range of contacts prepared (prepareContacts(),
/// on several threads), joined in range order afterwards.
struct PreparedSideArrays {
    std::vector<ContactRows> rows;               ///< Like SolverWorkspace::rows, indexed from 0 within the range.
    std::vector<TurningAnchors> turningAnchors;  ///< Like SolverWorkspace::turningAnchors, the same.
};

/// Contacts from which prepareContacts() splits its work between threads: a contact costs some
/// 200 ns to prepare, so 1024 are some 200 µs against a hand-over of a few.
inline constexpr std::size_t kParallelPrepareContacts = 1024;

/// @brief A list of contacts put in waves by scheduleWaves() (contact_colours.hpp), and its scratch.
struct ContactWaveSchedule {
    std::vector<std::uint32_t> nextWave;  ///< Per record: the first wave its next contact may take (scratch).
    std::vector<std::uint32_t> waveOf;    ///< Per contact of the list, in the list's order: its wave.
    std::vector<std::uint32_t> ends;      ///< Per wave: where its contacts end in `order`; then the list's size.
    std::vector<std::uint32_t> order;     ///< The list wave by wave, each wave in the list's order.
    std::uint32_t waves = 0;              ///< How many waves.
};

/// Contacts of the compression from which applyRestitution() splits its passes between threads:
/// fewer cannot fill a wave of kParallelRestitutionWave twice over.
inline constexpr std::size_t kParallelRestitution = 2048;

/// A wave of the compression's contacts is split between threads from this many contacts on; smaller
/// ones run on the calling thread. A contact costs some 10–30 ns a pass, so 1024 are some 10–30 µs,
/// against a hand-over and a barrier of a few µs (more on a busy machine), every pass, every wave.
inline constexpr std::size_t kParallelRestitutionWave = 1024;

/// @brief Scratch arrays of orderByColour() (contact_colours.hpp), kept so that a settled scene allocates nothing.
struct ContactColouring {
    std::vector<std::uint64_t> usedColours;  ///< Per record: bit k set when one of its contacts has colour k.
    std::vector<std::uint32_t> colourOf;     ///< Per contact of the list: its colour.
    /// Per colour of SolverWorkspace::roundContacts: where its contacts end there (orderByColour()),
    /// then the list's size. Empty unless the list is in colour order.
    std::vector<std::uint32_t> roundColourEnds;
    std::vector<std::uint32_t> otherColourEnds;  ///< The same for SolverWorkspace::otherContacts.
    std::vector<std::uint32_t> ordered;      ///< The list in colour order, swapped in.
};

/// @brief The contact solver's arrays, rebuilt by prepareContacts() every step and reused, so a
/// step allocates nothing once the scene has settled.
struct SolverWorkspace {
    std::vector<SolverContact> contacts;         ///< One per contact point, this step: what the passes read.
    std::vector<ContactStart> starts;            ///< The same contacts' origin and bounce (read by prepare, the bounce, the trace).
    std::vector<ContactRows> rows;               ///< Rows of the contacts that are not round (boxes, moving kinematic bodies).
    std::vector<TurningAnchors> turningAnchors;  ///< Anchors of the contacts with a turning anchor (boxes).
    std::vector<std::uint32_t> roundContacts;    ///< The round contacts, in pass order: a pass solves these first.
    std::vector<std::uint32_t> otherContacts;    ///< The contacts with stored rows, in pass order: a pass solves these next.
    /// Pass order (`ContactOrder`): each list colour by colour (true, contact_colours.hpp) or as found. Set by the World.
    bool colourOrder = true;
    ContactColouring colouring;                  ///< orderByColour()'s scratch.
    std::vector<PreparedSideArrays> preparedRanges; ///< prepareContacts()'s per-range side arrays (scratch).
    /// The impacts of the step (ContactStart::touchVelocity < 0), in order: without one that
    /// pushed, applyRestitution() has nothing to do (in a pile at rest there is none).
    std::vector<std::uint32_t> bouncing;
    std::vector<std::uint32_t> pressed;          ///< applyRestitution(): the contacts that pushed this step.
    ContactWaveSchedule pressedWaves;            ///< applyRestitution() on threads: `pressed` in waves.
    std::vector<SolverBody> impactBodies;        ///< applyRestitution(): each record's velocity change in the compression.
    std::vector<SolverBody> bodies;              ///< Record 0 static, then one per dynamic body in a contact or a joint (solver_body.hpp).
    std::vector<SolverBodyInertia> inertias;     ///< The same records' inertia (read by prepare and a box's write-back).
    std::vector<std::uint32_t> recordBody;       ///< Per record: its body's index in the World's dynamic array (the copies in and out).
    std::vector<Real> ballInertia;               ///< Per record: a ball's I, kg·m², for L = I·ω at the write-back (zero: a box).
    std::vector<std::uint32_t> bodyRecord;       ///< Per dynamic body: its record in `bodies`, or kStaticSolverBody if none.
    std::span<DynamicObject> dynamics;           ///< The World's dynamic bodies, as prepareContacts() saw them (copyVelocitiesIn(), copyVelocitiesOut()).
    std::vector<CachedImpulse> previousImpulses; ///< Last step's impulses, sorted by key.
    std::vector<CachedImpulse> currentImpulses;  ///< This step's, swapped in at the end.
    /// The poses separations are measured at: the dynamic bodies (by index, as the joints read them), then the
    /// kinematic bodies, then one fixed pose at the origin that every plane contact's B uses.
    std::vector<Pose> poses;
    /// Per record: v and ω as free flight left them, before this substep's warm start (of joints or
    /// contacts): what the drift measures Δv from, and what warmStartFromLastSubstep() subtracts.
    std::vector<BodyVelocity> substepStart;
    /// Per record: the ω its ball has turned by in each substep so far, summed, rad/s; the last
    /// substep's drift turns the ball once by h_s times the sum (velocity_change_drift.hpp, "A ball
    /// turns once a step"). Zeroed by prepareContacts().
    std::vector<SpinSum> turnSums;
    /// No joint holds a body and no spring pulls one: then nothing reads a ball's orientation inside
    /// the step, and a ball under symplectic Euler turns once, at its end (`turnSums`). A joint's or a
    /// spring's anchor turns with its ball, so with either every ball turns in every substep. Set by
    /// the World before the substeps.
    bool ballsTurnOnce = true;
};

/// @brief How many bytes the solver's arrays hold this step (sizes, not capacities).
///
/// Why a benchmark asks: a step costs the same per body at every size only while the arrays
/// its passes read stay in the processor's caches (`stepwise-bench stage-costs`).
/// solverFootprint() names every array of SolverWorkspace: a new one belongs there too.
struct SolverFootprint {
    std::size_t passBytes = 0;  ///< What every contact pass reads.
    /// What one substep walks, each array counted once: the passes' arrays and the per-record arrays
    /// of the moves between them (the warm start's substep-start velocities, the drift's summed turns;
    /// on the packed substeps, the kick's free flight and I). Every substep walks them all again, so
    /// they stay in a cache from one substep to the next only while they fit in it. (The dynamic
    /// objects the plain substeps also walk are not the workspace's: they are not counted.)
    std::size_t substepBytes = 0;
    std::size_t allBytes = 0;   ///< Every array of the workspace, those included.
};

/// @brief The footprint of @p workspace as the last prepareContacts() (and the substeps) left it,
/// for the plain passes: the body records, the contacts, their stored rows and turning anchors, the poses.
SolverFootprint solverFootprint(const SolverWorkspace& workspace);

/// @brief Builds one SolverContact per contact: anchors, effective masses,
/// bounce, and (with @p warmStart) last step's impulses; and a SolverBody
/// record for each dynamic body in a contact or held by a joint (@p links),
/// with its world I⁻¹ for the step. Every body a constraint can move has a
/// record, so the passes over the records (the copies, the drift) reach
/// all of them and no other. Lists the round and the other contacts in the
/// order a pass takes them: colour by colour (orderByColour(),
/// SolverWorkspace::colourOrder) or as found.
///
/// The bounce: the relative normal velocity v_n (< 0 approaching) is taken
/// before any impulse, at the start of the step, when the surfaces are a gap
/// C apart (negative: an overlap). Under the approach acceleration a (the
/// bodies' accelerations along −n) the approach speed when they meet is
/// \f[ v_c = \sqrt{\max(0,\; v_n^2 + 2\,a\,C)}, \f]
/// which is the speed the restitution law e·v_c refers to: bouncing with v_n
/// instead would make a ball's apex depend on where in the step it touched.
/// Below kRestingContactSteps·h·(acceleration along n) the contact is
/// resting and does not bounce (a box on a floor is pulled in by g·h every
/// step; that is not an impact).
///
/// Each contact is prepared from its own contact and bodies alone, so with
/// a @p pool of several threads and at least kParallelPrepareContacts
/// contacts the work is cut into ranges of contacts; each range keeps the
/// rows and anchors it makes in arrays of its own, which are then joined in
/// range order, so every number and index is what one thread gives.
///
/// A conveyor belt (src/forces/conveyor.hpp): a contact of a body on a belt
/// with a static or kinematic surface gets stored rows, whose tangent surface
/// speeds carry the belt's velocity in the contact's plane, v_s·t_k, as a moving
/// kinematic body's carry its own: the passes, plain and fast, read those numbers
/// and nothing else of the belt.
/// @param h full step, s (for the resting rule)
/// @param pool threads to share the work (nullptr: the calling thread alone)
/// @param beltVelocities each dynamic body's belt velocity u, m/s (conveyorVelocities()); empty: no belt in the scene
void prepareContacts(const BodySet& bodies, std::span<const Contact> contacts, std::span<const BodyLink> links, Real h,
                     bool warmStart, SolverWorkspace& workspace, ThreadPool* pool = nullptr,
                     std::span<const Vec3> beltVelocities = {});

/// @brief Records every body's pose: the separations of the next solveContacts() are measured there.
///
/// The solve measures C where the bodies were at the start of the substep,
/// before free flight moved them: its bias then means what Box2D's does,
/// "C + h_s·v_n ≥ 0 after the substep" (the drift moves the bodies with the
/// solved velocity). The relax pass measures C where they are after the drift,
/// which records the poses of the bodies it moves (driftByVelocityChange())
/// and leaves the kinematic ones to recordKinematicPoses().
void recordPoses(const BodySet& bodies, SolverWorkspace& workspace);

/// @brief recordPoses() for the dynamic bodies @p dynamicBodies (one group of islands, substep_rule.hpp)
/// and every kinematic body and plane.
void recordPoses(const BodySet& bodies, SolverWorkspace& workspace, std::span<const std::uint32_t> dynamicBodies);

/// @brief Records the kinematic bodies' poses only: where move-kinematics left them, for the relax passes.
void recordKinematicPoses(const BodySet& bodies, SolverWorkspace& workspace);

/// @brief C of contact @p c at the poses recordPoses() last recorded, m (> 0: a gap).
///
/// The centres' separation along n plus what is fixed through the step, plus
/// the turning anchors' part for a box (SolverContact above). Box2D v3 tracks
/// separation the same way between collision passes: no new collision test is needed.
Real currentSeparation(const SolverContact& c, const SolverWorkspace& workspace);

/// @brief Copies the velocities of the bodies in contacts from the World's objects into their solver bodies.
///
/// The contact passes (warmStartContacts(), solveContacts(),
/// applyRestitution()) read and write only the solver bodies
/// (solver_body.hpp); the integrators, the drift and the joints work on the
/// objects. So the step copies the velocities in before a run of contact
/// passes and out after it, not around every pass: once per stage when the
/// scene has no joints.
void copyVelocitiesIn(SolverWorkspace& workspace);

/// @brief copyVelocitiesIn() for the solver records @p records alone (one group of islands, substep_rule.hpp).
void copyVelocitiesIn(SolverWorkspace& workspace, std::span<const std::uint32_t> records);

/// @brief Writes the solver bodies' velocities back to the World's objects; the angular
/// momentum follows: L = I·ω for a ball, L + I_world·Δω for a box.
void copyVelocitiesOut(SolverWorkspace& workspace);

/// @brief copyVelocitiesOut() for the solver records @p records alone (one group of islands, substep_rule.hpp).
void copyVelocitiesOut(SolverWorkspace& workspace, std::span<const std::uint32_t> records);

/// @brief copyVelocitiesOut() for record @p record alone; returns its object.
/// (The drift writes back each body it is about to move, in the same pass: driftByVelocityChange().)
inline DynamicObject& copyVelocitiesOut(SolverWorkspace& workspace, std::size_t record) {
    const SolverBody& s = workspace.bodies[record];
    DynamicObject& body = workspace.dynamics[workspace.recordBody[record]];
    body.velocity = s.velocity;
    // The passes changed ω by I⁻¹·ΔL with the step's world I⁻¹, so L changed by ΔL = I·Δω.
    // A ball's I is one number, the same in every orientation, so its L is simply I·ω: written
    // from ω alone, it is the same whether the record is written back once or many times.
    const Real ballInertia = workspace.ballInertia[record];
    if (ballInertia != Real(0)) {
        body.angularMomentum = ballInertia * s.angularVelocity;
    } else {
        body.angularMomentum += workspace.inertias[record].inertia * (s.angularVelocity - body.angularVelocity);
    }
    body.angularVelocity = s.angularVelocity;
    return body;
}

/// @brief Notes each record's v and ω as free flight left them (SolverWorkspace::substepStart), before
/// anything acts on them this substep: the drift moves a body by what the constraints changed since.
void recordSubstepStart(SolverWorkspace& workspace);

/// @brief recordSubstepStart() for the solver records @p records alone (one group of islands, substep_rule.hpp).
void recordSubstepStart(SolverWorkspace& workspace, std::span<const std::uint32_t> records);

/// @brief Applies every contact's accumulated impulses (the warm start), at the start of a substep,
/// in the order of a pass (the round contacts, then the others). With @p accumulate off, instead
/// starts each contact's impulses from zero.
void warmStartContacts(SolverWorkspace& workspace, bool accumulate);

/// @brief The warm start of contact @p index alone: its accumulated impulses applied to its two solver bodies.
void warmStartContact(SolverWorkspace& workspace, std::uint32_t index);

/// @brief The same warm start in a later substep of the step, per body instead of per contact;
/// copies the velocities in from the objects as copyVelocitiesIn() does, and notes them as
/// recordSubstepStart() does.
///
/// The warm start gives each body Σ_c λ_c·M⁻¹J_cᵀ over its contacts, with the
/// accumulated impulses λ_c as the last substep left them. Within a step the
/// rows of J are fixed (solver_body.hpp), and between the end of one substep
/// and the warm start of the next no λ_c changes, so that sum is exactly the
/// velocity change the contact passes made to the body in the last substep:
/// Δv = v_end − v_start, Δω = ω_end − ω_start. Adding it per body gives the
/// same velocities, to rounding, without reading the contacts: a pass over the
/// bodies instead of over the (several times more, and larger) contacts.
/// It holds only when nothing but the contact passes changed the
/// records during the last substep: not in the first substep (the λ_c come
/// from the last step, with other rows), not with joints (a joint pass changes
/// the velocities too), and not without accumulated impulses.
void warmStartFromLastSubstep(SolverWorkspace& workspace);

/// @brief warmStartFromLastSubstep() for the solver records @p records alone (one group of islands, substep_rule.hpp).
void warmStartFromLastSubstep(SolverWorkspace& workspace, std::span<const std::uint32_t> records);

/// @brief One Gauss–Seidel pass over all contacts: the round ones in their order, then the
/// others in theirs ("The order of a pass", SolverContact).
/// @param useBias true for the solve (soft push-out), false for the relax pass (which solves a
///        round contact's friction only with ContactSolverSettings::relaxBallFriction: passSolvesFriction()).
void solveContacts(SolverWorkspace& workspace, const ContactSolverSettings& settings, bool useBias);

/// @brief Contact @p index solved once: its normal row, then its friction rows if this pass solves them.
void solveContact(SolverWorkspace& workspace, std::uint32_t index, const ContactSolverSettings& settings, bool useBias);

/// @brief Most passes of the compression's projected Gauss–Seidel (applyRestitution()). A row of
/// touching balls passes the impulse on one ball per pass, so it is as long a row as converges
/// exactly; a pile hit by a ball is left where the passes got to.
inline constexpr int kMaxCompressionPasses = 32;

/// @brief The compression has converged when no pass changes a contact's normal velocity by
/// more than this fraction of the fastest impact's approach speed.
inline constexpr Real kCompressionTolerance = Real(1e-6);

/// @brief After the substeps: the bounce, by Poisson's law of restitution.
///
/// An impact has two phases. In the *compression* the bodies stop approaching: the normal
/// impulses P_i ≥ 0 are those of a perfectly inelastic impact, the complementarity problem
/// \f[ w_i + (J M^{-1} J^T P)_i \ge 0, \quad P_i \ge 0, \quad P_i \,(w_i + (J M^{-1} J^T P)_i) = 0, \f]
/// over every contact that pushed during the step and does not carry a load (ContactStart::carriesLoad:
/// a stack's weight), where w_i is ContactStart::touchVelocity (−v_c for an impact, 0 for bodies
/// that merely touch). It is solved here by projected Gauss–Seidel
/// passes on the velocity *changes* Δu = M⁻¹JᵀP, from zero, until they stop changing
/// (kMaxCompressionPasses, kCompressionTolerance). In the *restitution* each contact pushes back
/// e_i·P_i, all at once, so the contacts that pushed part at v_n = e_i·(J Δu)_i
/// (ContactStart::bounceVelocity); the stage drives them there with the same kind of passes.
///
/// For one contact this is Newton's law: the bounce leaves at v_n = e·v_c. For several at once,
/// a ball into a row of touching balls, a crowded gas, Poisson's impulses keep the energy when
/// e = 1: the energy before the impact is ½(u_c − Δu)ᵀM(u_c − Δu) and after it
/// ½(u_c + Δu)ᵀM(u_c + Δu), where u_c is the velocity at the end of the compression; they differ
/// by 2·(J u_c)ᵀP = 0, since every contact that pushes ends the compression at (J u_c)_i = 0
/// (Stronge, "Impact Mechanics", 2000, ch. 4; Mirtich, PhD thesis, 1996, ch. 3). Driving each
/// contact to v_n = e·v_c one after the other does not: the last one driven undoes the others,
/// and a gas of 1000 balls loses most of its energy in seconds.
/// @return true if any contact bounced (only then did a solver body's velocity change).
///
/// **On threads.** Each contact's update reads and writes only its own two bodies' records and its
/// own numbers. So with a @p pool of several threads and at least kParallelRestitution contacts in
/// the compression, the passes take the contacts wave by wave (scheduleWaves(), contact_colours.hpp:
/// no wave holds a body twice, and every body meets its contacts in the order of the one-thread
/// pass), and cut each wide wave into ranges on the threads: every number is the one-thread pass's,
/// to the bit, and so is each pass's largest change, a maximum, which no order changes.
/// @param pool threads to share the passes (nullptr: the calling thread alone)
bool applyRestitution(SolverWorkspace& workspace, ThreadPool* pool = nullptr);

/// @brief Keeps this step's impulses for the next step's warm start, and fills @p reports (may be empty).
void storeContactImpulses(std::span<const Contact> contacts, SolverWorkspace& workspace,
                          std::span<ImpulseReport> reports);

}  // namespace stepwise
