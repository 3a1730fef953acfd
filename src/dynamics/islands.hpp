/// @file islands.hpp
/// @brief Islands and sleep: bodies that touch or are jointed form an island; a still island sleeps.
///
/// A pile of boxes at rest still costs a full solve every step, and the solve
/// never quite reaches zero velocity. Sleep removes that cost: each body keeps
/// how long it has been *still*: slow (|v| below a speed and |ω| below an
/// angular speed) and in equilibrium (the step changed v by less than an
/// acceleration times h, and ω likewise: the forces and the constraint
/// impulses on it balance, so waking it would not move it). Bodies connected
/// through contacts or joints form an *island* (connected components of that
/// graph, found with union–find); when every body of an island has been still
/// for the time to sleep, the whole island sleeps: velocities are zeroed, and
/// integration, broadphase pairs among sleepers and the solver skip it. A
/// whole island, never part of it: a box whose neighbour still moves could be
/// pushed while asleep.
///
/// Slow alone is not enough. A ball on a damped spring passes through rest at
/// every turning point of its oscillation, slower and slower, and would fall
/// asleep millimetres from where the spring holds it; at a turning point its
/// acceleration is ω²·A, not zero, and the equilibrium test sees it.
///
/// Static objects (planes, kinematic bodies) never join an island: through
/// the floor every resting body in the scene would be one island, and one
/// moving ball would keep a distant sleeping stack awake. A body touching a
/// *moving* kinematic body is never still.
///
/// An island wakes when an awake body touches one of its bodies, when a
/// joint links it to an awake body, or when a tool (the viewer's picking)
/// wakes a body. Sleeping bodies remember the island they fell asleep with
/// (DynamicObject::sleepIsland) so that they wake together.
///
/// **A soft body is one unit of an island** (src/objects/soft_body.hpp). Its
/// edges are the dynamic bodies its nodes touched in the step and the soft
/// bodies it touched (SoftBody::touchedDynamics, touchedSoftBodies, noted by
/// src/soft/); planes and kinematic bodies join nothing, as for rigid bodies,
/// and a node on a moving kinematic body keeps it from being still. It is
/// still when every node is slower than `SleepLinearSpeed`, the rigid bodies'
/// threshold (a node has no spin): its fastest point is then that slow. The
/// rigid equilibrium test is not asked of each node: over a hundred nodes it
/// is far stricter than over one body, and a damped ball dropped on a floor
/// (Resolution=1, Damping=2) passes it only 8 s after it was dropped, when its
/// fastest node is below 1 mm/s; every node is below 5 cm/s after 4 s. A slow breathing
/// that turns at rest is guarded against by the time to sleep: every node
/// slower than 5 cm/s for 0.5 s is a breathing of a few millimetres at most. An asleep soft body is not stepped (its nodes
/// stay put); it wakes with its island, and when an awake body may reach it:
/// wakeSoftBodiesInReach(), before the soft step, since an unstepped body finds
/// no contact of its own. In the union–find, soft body k is element
/// dynamics.size() + k.
///
/// References: Catto, Box2D `b2_island.c`/`solver_set.c`; Ericson §6.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "collision/contact.hpp"
#include "objects/body_set.hpp"
#include "core/world_settings.hpp"

namespace stepwise {

/// @brief Marks a body index of a link as "the world" (a joint anchored to a fixed point).
inline constexpr std::uint32_t kWorldAnchor = 0xffffffffu;

/// @brief Two dynamic bodies that a joint holds together (b may be kWorldAnchor).
struct BodyLink {
    std::uint32_t a = 0;  ///< Index of a dynamic body.
    std::uint32_t b = 0;  ///< Index of a dynamic body, or kWorldAnchor.
};

/// @brief The root of @p i's tree in the union–find forest @p parent, halving the path on the way
/// (Tarjan): near-constant time. Shared by the sleep's islands and the substep rule's.
inline std::uint32_t findIslandRoot(std::vector<std::uint32_t>& parent, std::uint32_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

/// @brief Joins the trees of @p a and @p b in @p parent; the lower index is the root, so an island's
/// root is its lowest body whatever the order of the joins.
inline void joinIslands(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b) {
    const std::uint32_t ra = findIslandRoot(parent, a);
    const std::uint32_t rb = findIslandRoot(parent, b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
}

/// @brief Scratch arrays for building islands, reused every step.
struct IslandWorkspace {
    /// Per dynamic body: its velocity and angular velocity at the end of the last step (zero while
    /// asleep), m/s and rad/s: what the step's velocity change, the equilibrium test, is measured from.
    std::vector<Vec3> lastVelocity;
    std::vector<Vec3> lastAngularVelocity;  ///< As lastVelocity, for the angular velocity, rad/s.
    /// Per dynamic body: |Δv|/h and |Δω|/h of the last step, m/s² and rad/s², as the
    /// equilibrium test measured them (for the trace: why a slow body is not yet still).
    std::vector<Real> linearAcceleration;
    std::vector<Real> angularAcceleration;  ///< As linearAcceleration, for |Δω|/h, rad/s².
    std::vector<std::uint32_t> parent;   ///< Union–find forest over dynamic bodies.
    std::vector<Real> islandStillTime;   ///< Per root: the least still time of its bodies, s.
    std::vector<std::uint32_t> carried;  ///< Bodies resting on a moving kinematic body this step (never still).
    /// Per soft body: its fastest node's speed at the end of the last step, m/s (for the trace).
    std::vector<Real> softNodeSpeed;
    std::uint32_t nextSleepIsland = 1;   ///< Id for the next island that falls asleep (0 = never slept).
};

/// @brief The island of awake body @p body after the last updateSleep(): the lowest body
/// index of its island (a body alone is its own island). For display (the viewer's I key).
/// Soft body k is element dynamics.size() + k, so an island with a dynamic body in it is named by one.
std::uint32_t islandOf(const IslandWorkspace& workspace, std::uint32_t body);

/// @brief Drops candidate pairs that cannot change anything: a sleeping body
/// against a static object or against another sleeper (asleep together, they
/// were at rest against each other).
void dropSleepingPairs(const BodySet& bodies, std::vector<CandidatePair>& pairs);

/// @brief Wakes every sleeping island that an awake body touches or is jointed to.
/// @return the number of bodies woken.
std::size_t wakeTouchedIslands(const BodySet& bodies, std::span<const Contact> contacts, std::span<const BodyLink> links);

/// @brief Wakes @p body and every body and soft body that fell asleep in the same island.
/// @return the number of bodies and soft bodies woken.
std::size_t wakeIsland(std::span<DynamicObject> bodies, std::uint32_t body, std::span<SoftBody> softBodies = {});

/// @brief Wakes soft body @p body and every body and soft body that fell asleep in its island.
std::size_t wakeSoftIsland(std::span<DynamicObject> bodies, std::span<SoftBody> softBodies, std::uint32_t body);

/// @brief Before the soft step: wakes the island of every asleep soft body that an awake object
/// may reach in this step, since the soft step does not move, and so does not collide, an asleep one.
///
/// The test is on boxes, as a broadphase's: the sleeper's nodes' box, widened by its node radius,
/// against an awake dynamic body's box where the step's solve left it, a moving kinematic body's
/// box widened by what it moves in the step, and an awake soft body's box widened by its node
/// radius and what its fastest node can move in the step, |v|·h + ½|g|·h². A box that overlaps
/// may not touch: the sleeper then wakes a little early, and falls asleep again once still.
/// @return the number of bodies and soft bodies woken.
std::size_t wakeSoftBodiesInReach(const BodySet& bodies, Real h, const Vec3& gravity);

/// @brief After the soft step: wakes the island of every asleep dynamic body that an awake soft
/// body's nodes touched (its touchedDynamics): the body took the nodes' impulses and must move.
/// @return the number of bodies and soft bodies woken.
std::size_t wakeTouchedBySoftBodies(const BodySet& bodies);

/// @brief After a step: updates still times, builds islands from @p contacts, @p links and the
/// soft bodies' touches, and puts every island that has been still for settings.timeToSleep to
/// sleep (a soft body that falls asleep has its node velocities zeroed, as a rigid body's).
/// @return the number of dynamic bodies asleep after the update.
std::size_t updateSleep(const BodySet& bodies, std::span<const Contact> contacts, std::span<const BodyLink> links,
                        const WorldSettings& settings, IslandWorkspace& workspace);

}  // namespace stepwise
