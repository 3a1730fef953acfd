/// @file substep_rule.hpp
/// @brief How many substeps each island needs this step (`World, SubstepsPerIsland=true`).
///
/// The soft step (contact_solver.hpp) holds the contacts through `Substeps`
/// short substeps. Sixteen are there for the hard cases: a tall tower, a
/// 100:1 stack. A settled pile of a few equal boxes, or balls lying on the
/// floor, reach the same answer with far fewer, and a scene pays for its
/// worst island in every island. With `SubstepsPerIsland=true` the World
/// finds the islands of this step (bodies joined by this step's contacts and
/// by the joints; planes and kinematic bodies join nothing) before the substeps, gives each
/// island its own count n ≤ `Substeps`, and runs the substeps of each group
/// of islands with one count on that group's bodies and contacts alone. An
/// island's substeps read and write only its own bodies, so the groups do
/// not depend on each other; an island given the full count computes the
/// very numbers of the fixed count.
///
/// **The rule.** With N = `Substeps` (the cap) and P = `Iterations` (solve
/// passes per substep), an island's count is the largest of four terms,
/// rounded up to a power of two (at most log₂N + 1 groups), at least
/// kMinIslandSubsteps and at most N:
///
/// - **Height.** Projected Gauss–Seidel carries a stack's weight down one
///   contact per pass: a pass solves the top contact first or last, and
///   the bottom one learns of the load above only when each contact in
///   between has passed it on. A stack H bodies high needs H passes a step
///   to carry its weight to the floor, so n_H = ⌈H / P⌉. H is the number of
///   bodies on the longest path of contacts from a body that touches a plane
///   or kinematic body (breadth-first from those; an island that touches
///   neither counts from its first body).
/// - **Mass ratio.** A light body under a heavy one converges slowly: one
///   pass gives the light body's contact the share m_light/(m_light + m_heavy)
///   of what it must carry, so the error after k passes shrinks like
///   (r/(1+r))^k with r the mass ratio of the pair. n_M = ⌈kSubstepsPerMassRatio·r⌉
///   for r > 1 (equal masses: no term), so a 100:1 pair gets the full count.
/// - **Speed.** Contacts are found once a step and held with the normal and
///   lever arms of the step's start; a speculative contact closes its gap at
///   C/h_s. Both are right while a body moves a small part of its size in a
///   substep: the relative speed v of a contact's two bodies times h_s stays
///   below kReachShare times the smaller body's least half-size s, so
///   n_V = ⌈v·h / (kReachShare·s)⌉.
/// - **Stiffness.** A soft contact's frequency is capped at a quarter of
///   its substep rate, n/(4h) (contactHertzInUse(); stiffer, the implicit
///   spring is faster than a substep resolves, and a tower sways). A resting
///   body sinks g/ω² into its support, so fewer substeps mean deeper sag
///   and a slower build-up of the normal force that friction is limited by.
///   The island keeps at least kMinContactHertz (or ContactHertz, if lower):
///   n_K = ⌈4·h·min(ContactHertz, kMinContactHertz)⌉, 4 at 1/60 s, 16 at 1/15 s.
/// - **Free flight.** An island without contacts needs no solver; its
///   integrator alone sets the count. Velocity Verlet is exact under a
///   uniform field for any h_s, so n = 1 (kMinIslandSubsteps); symplectic and
///   explicit Euler err by ½·a·t·h_s, which the scene's count sets, so an
///   accelerated free body keeps the full count.
///
/// **Joints: the island at the fixed count.** A joint is solved in every
/// pass of every substep, and how well it holds depends on h_s: a chain's
/// links stretch farther, and its soft rows are stiffer, at fewer substeps
/// (JointHertz is capped by the substep rate like ContactHertz). The rule has
/// no term for that, so an island a joint holds (any body of it jointed to
/// another or to the world) runs N, reason `joint`, and computes the very
/// numbers of the fixed count; the islands beside it still get their own.
///
/// **Whole scene at the fixed count.** Springs, attractors and moving
/// kinematic bodies act inside every substep on whatever they hold (the
/// forces worked out again each substep, a kinematic body moved h_s at a
/// time); a scene with any of them runs every island at N (the plan says so).
///
/// References: Catto, "Solver2D" and "Soft Step" (box2d.org, 2024) on
/// substeps against stacks and mass ratios; Tonge, "Iterative Rigid Body
/// Solvers" (GDC 2012) on Gauss–Seidel carrying a load one contact per pass.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "collision/contact.hpp"
#include "dynamics/contact_solver.hpp"
#include "dynamics/islands.hpp"
#include "core/world_settings.hpp"
#include "objects/body_set.hpp"

namespace stepwise {

/// @brief The least count the rule gives an island: velocity Verlet's free flight needs no more.
inline constexpr int kMinIslandSubsteps = 1;
/// @brief n_M = ⌈kSubstepsPerMassRatio·r⌉ for a contact whose bodies' masses differ by r > 1
/// (2: a 2:1 pair gets 4 substeps, 8:1 gets 16).
inline constexpr Real kSubstepsPerMassRatio = Real(2);
/// @brief The least contact frequency an island keeps, Hz: a resting body sinks g/ω² = 69 µm at 60 Hz
/// (the sag the `Substeps=16` default allows at TimeStep=1/15 s, where the stress suite's large step holds).
inline constexpr Real kMinContactHertz = Real(60);
/// @brief The part of its least half-size a body may move against its contact partner in one substep.
inline constexpr Real kReachShare = Real(0.1);

/// @brief Which term set an island's count (the largest; for `--explain` and the trace).
enum class SubstepReason : std::uint8_t {
    Minimum,    ///< No term asked for more than kMinIslandSubsteps.
    Height,     ///< n_H: the stack's height in bodies over the solve passes.
    MassRatio,  ///< n_M: the largest mass ratio across one of its contacts.
    Speed,      ///< n_V: the largest relative speed across one of its contacts.
    Stiffness,  ///< n_K: the substeps that keep its contacts at kMinContactHertz.
    FreeFlight, ///< No contacts, integrated by an integrator whose error depends on h_s.
    Cap,        ///< A term asked for more than `Substeps`: the full count.
    Joint,      ///< A joint holds one of its bodies: the full count (the file's header says why).
};

/// @brief A one-word name of @p reason ("height", "mass ratio", …).
const char* substepReasonName(SubstepReason reason);

/// @brief One island of this step and the count the rule gave it.
struct IslandSubsteps {
    std::uint32_t firstBody = 0;  ///< Its lowest body index (names the island).
    std::uint32_t bodies = 0;     ///< How many dynamic bodies it holds.
    std::uint32_t contacts = 0;   ///< How many contact points it holds.
    std::uint32_t joints = 0;     ///< How many acting joints hold its bodies (then it runs the full count).
    std::uint32_t height = 0;     ///< H: bodies on the longest path of contacts from a support.
    Real massRatio = 1;           ///< r: the largest mass ratio across one of its contacts.
    Real speed = 0;               ///< v: the relative speed across the contact with the largest v/s, m/s.
    Real halfSizeOfSpeed = 0;     ///< s: the smaller least half-size of that contact's two bodies, m.
    int count = 1;                ///< The substeps it runs this step.
    SubstepReason reason = SubstepReason::Minimum; ///< The term that set the count.
};

/// @brief What chooseIslandSubsteps() needs of the World's settings.
struct SubstepRuleInputs {
    int cap = kDefaultSubsteps;   ///< N, `Substeps`: the most any island gets.
    int passes = 1;               ///< P, `Iterations`: solve passes per substep.
    Real timeStep = kDefaultTimeStep; ///< h, s.
    IntegratorKind integrator = IntegratorKind::SymplecticEuler; ///< Free flight's integrator.
    Real contactHertz = kDefaultContactHertz; ///< `ContactHertz`, Hz (the stiffness term).
};

/// @brief The islands of one step, their counts, and the groups of islands that share a count,
/// as index lists into the World's arrays; reused every step, so a settled scene allocates nothing.
struct SubstepGroups {
    std::vector<IslandSubsteps> islands;       ///< One per island, in the order of their first body.
    std::vector<std::uint32_t> islandOfBody;   ///< Per dynamic body: its island in `islands`.
    std::vector<int> counts;                   ///< The distinct counts, largest first: one group each.
    std::vector<std::uint32_t> groupBodies;    ///< Per group, its bodies in index order (slices: bodyStart).
    std::vector<std::uint32_t> bodyStart;      ///< Group g's bodies are groupBodies[bodyStart[g], bodyStart[g+1]).
    std::vector<std::uint32_t> groupRecords;   ///< Per group, the solver records of its bodies, in order (slices: recordStart).
    std::vector<std::uint32_t> recordStart;    ///< Group g's records are groupRecords[recordStart[g], recordStart[g+1]).
    std::vector<std::uint32_t> groupRound;     ///< Per group, its round contacts in the order of a pass (slices: roundStart).
    std::vector<std::uint32_t> roundStart;     ///< Group g's round contacts start here in groupRound.
    std::vector<std::uint32_t> groupOther;     ///< Per group, its other contacts in the order of a pass (slices: otherStart).
    std::vector<std::uint32_t> otherStart;     ///< Group g's other contacts start here in groupOther.
    std::vector<std::uint32_t> allRound;       ///< The whole step's round contacts, set aside while the groups run.
    std::vector<std::uint32_t> allOther;       ///< The whole step's other contacts, set aside while the groups run.
    // Scratch of the island search.
    std::vector<std::uint32_t> parent;         ///< Union–find forest over the dynamic bodies.
    std::vector<std::uint32_t> adjacencyStart; ///< Per body: where its neighbours start in `adjacency`.
    std::vector<std::uint32_t> adjacency;      ///< The bodies each body touches (both directions of each contact).
    std::vector<std::uint32_t> depth;          ///< Per body: its breadth-first layer, 0 unvisited.
    std::vector<std::uint32_t> queue;          ///< The breadth-first queue.
    std::vector<std::uint8_t> supported;       ///< Per body: 1 if it touches a plane or a kinematic body.
    std::vector<Real> halfSize;                ///< Per body: its least half-size s, m.
};

/// @brief The least half-size s of @p body, m: a ball's, capsule's or cylinder's radius, a box's
/// smallest half edge, for any other shape its reach (the farthest point from its centre).
Real leastHalfSize(const DynamicObject& body);

/// @brief Finds this step's islands from @p contacts and the joints' @p links, applies the rule to
/// each, and lists each count's bodies (groups.counts, groups.groupBodies). Allocates nothing once
/// the arrays have grown.
/// @param links one per acting joint (jointLinks()); b is kWorldAnchor for a joint to the world
/// @return true if some island got fewer than inputs.cap substeps (else the fixed count runs as is).
bool chooseIslandSubsteps(const BodySet& bodies, std::span<const Contact> contacts, std::span<const BodyLink> links,
                          const SubstepRuleInputs& inputs, SubstepGroups& groups);

/// @brief Lists each group's solver records and contacts (groups.groupRecords, groupRound,
/// groupOther) from the prepared @p workspace, each in the order of the whole step's lists: so a
/// pass over one group's contacts solves its islands' contacts in the order the fixed count does.
void splitSolverWork(const SolverWorkspace& workspace, SubstepGroups& groups);

/// @brief The slice @p group of a list split by @p starts (SubstepGroups::groupBodies and the others).
inline std::span<const std::uint32_t> groupSlice(const std::vector<std::uint32_t>& list,
                                                 const std::vector<std::uint32_t>& starts, std::size_t group) {
    return std::span(list).subspan(starts[group], starts[group + 1] - starts[group]);
}

/// @brief The count the rule gives an island with these inputs (a pure function, for the tests and the docs).
/// @param height     H, bodies
/// @param massRatio  r ≥ 1
/// @param speed      v, m/s
/// @param halfSize   s, m
/// @param hasContacts false: the island is in free flight
/// @param accelerated true if a free body accelerates (its integrator's error then depends on h_s)
/// @param inputs     N, P, h and the integrator
/// @param reason     set to the term that decided
int islandSubstepCount(std::uint32_t height, Real massRatio, Real speed, Real halfSize, bool hasContacts,
                       bool accelerated, const SubstepRuleInputs& inputs, SubstepReason& reason);

}  // namespace stepwise
