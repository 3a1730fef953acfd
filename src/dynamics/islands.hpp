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
/// References: Catto, Box2D `b2_island.c`/`solver_set.c`; Ericson §6.
#pragma once

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

/// @brief Scratch arrays for building islands, reused every step.
struct IslandWorkspace {
    /// Per dynamic body: its velocity and angular velocity at the end of the last step (zero while
    /// asleep), m/s and rad/s: what the step's velocity change, the equilibrium test, is measured from.
    std::vector<Vec3> lastVelocity;
    std::vector<Vec3> lastAngularVelocity;  ///< The angular velocity of the same, rad/s (see lastVelocity).
    /// Per dynamic body: |Δv|/h and |Δω|/h of the last step, m/s² and rad/s², as the
    /// equilibrium test measured them (for the trace: why a slow body is not yet still).
    std::vector<Real> linearAcceleration;
    std::vector<Real> angularAcceleration;  ///< |Δω|/h, rad/s² (see linearAcceleration).
    std::vector<std::uint32_t> parent;   ///< Union–find forest over dynamic bodies.
    std::vector<Real> islandStillTime;   ///< Per root: the least still time of its bodies, s.
    std::vector<std::uint32_t> carried;  ///< Bodies resting on a moving kinematic body this step (never still).
    std::uint32_t nextSleepIsland = 1;   ///< Id for the next island that falls asleep (0 = never slept).
};

/// @brief The island of awake body @p body after the last updateSleep(): the lowest body
/// index of its island (a body alone is its own island). For display (the viewer's I key).
std::uint32_t islandOf(const IslandWorkspace& workspace, std::uint32_t body);

/// @brief Drops candidate pairs that cannot change anything: a sleeping body
/// against a static object or against another sleeper (asleep together, they
/// were at rest against each other).
void dropSleepingPairs(const BodySet& bodies, std::vector<CandidatePair>& pairs);

/// @brief Wakes every sleeping island that an awake body touches or is jointed to.
/// @return the number of bodies woken.
std::size_t wakeTouchedIslands(const BodySet& bodies, std::span<const Contact> contacts, std::span<const BodyLink> links);

/// @brief Wakes @p body and every body that fell asleep in the same island.
std::size_t wakeIsland(std::span<DynamicObject> bodies, std::uint32_t body);

/// @brief After a step: updates still times, builds islands from @p contacts and
/// @p links, and puts every island that has been still for settings.timeToSleep to sleep.
/// @return the number of bodies asleep after the update.
std::size_t updateSleep(const BodySet& bodies, std::span<const Contact> contacts, std::span<const BodyLink> links,
                        const WorldSettings& settings, IslandWorkspace& workspace);

}  // namespace stepwise
