/// @file islands.cpp
/// @brief Islands by union–find over contacts and joints, and the sleep decision (see islands.hpp).
#include "dynamics/islands.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "collision/aabb.hpp"

namespace stepwise {

namespace {

bool isMovingKinematic(const BodySet& bodies, const BodyRef& ref) {
    if (ref.kind != BodyKind::Kinematic) return false;
    const KinematicsObject& k = bodies.kinematics[ref.index];
    return k.velocity != Vec3(0) || k.angularVelocity != Vec3(0);
}

/// The box of a soft body's nodes, each a sphere of the node radius.
Aabb nodeBounds(const SoftBody& body) {
    Aabb box{body.nodePositions[0], body.nodePositions[0]};
    for (const Vec3& x : body.nodePositions) box = {glm::min(box.min, x), glm::max(box.max, x)};
    return {box.min - Vec3(body.nodeRadius), box.max + Vec3(body.nodeRadius)};
}

Aabb widened(const Aabb& box, Real by) { return {box.min - Vec3(by), box.max + Vec3(by)}; }

/// Wakes every body and soft body asleep in island @p island.
std::size_t wakeSleepIsland(std::span<DynamicObject> bodies, std::span<SoftBody> softBodies, std::uint32_t island) {
    std::size_t woken = 0;
    for (DynamicObject& other : bodies) {
        if (other.asleep && other.sleepIsland == island) {
            other.asleep = false;
            other.stillTime = 0;
            ++woken;
        }
    }
    for (SoftBody& soft : softBodies) {
        if (soft.asleep && soft.sleepIsland == island) {
            soft.asleep = false;
            soft.stillTime = 0;
            ++woken;
        }
    }
    return woken;
}

}  // namespace

std::uint32_t islandOf(const IslandWorkspace& workspace, std::uint32_t body) {
    if (body >= workspace.parent.size()) return body;  // before the first update: alone
    while (workspace.parent[body] != body) body = workspace.parent[body];
    return body;
}

void dropSleepingPairs(const BodySet& bodies, std::vector<CandidatePair>& pairs) {
    std::erase_if(pairs, [&](const CandidatePair& pair) {
        if (!bodies.dynamics[pair.a].asleep) return false;
        if (pair.b.kind == BodyKind::Dynamic) return bodies.dynamics[pair.b.index].asleep;
        return !isMovingKinematic(bodies, pair.b);  // a moving kinematic body must still find the sleeper
    });
}

std::size_t wakeIsland(std::span<DynamicObject> bodies, std::uint32_t body, std::span<SoftBody> softBodies) {
    if (!bodies[body].asleep) return 0;
    return wakeSleepIsland(bodies, softBodies, bodies[body].sleepIsland);
}

std::size_t wakeSoftIsland(std::span<DynamicObject> bodies, std::span<SoftBody> softBodies, std::uint32_t body) {
    if (!softBodies[body].asleep) return 0;
    return wakeSleepIsland(bodies, softBodies, softBodies[body].sleepIsland);
}

std::size_t wakeSoftBodiesInReach(const BodySet& bodies, Real h, const Vec3& gravity) {
    std::size_t woken = 0;
    const Real fall = Real(0.5) * glm::length(gravity) * h * h;
    for (std::uint32_t k = 0; k < bodies.softBodies.size(); ++k) {
        const SoftBody& sleeper = bodies.softBodies[k];
        if (!sleeper.asleep || sleeper.nodeCount() == 0) continue;
        const Aabb box = nodeBounds(sleeper);
        bool reached = false;
        for (const DynamicObject& body : bodies.dynamics) {
            if (!body.asleep && shapeAabb(body).overlaps(box)) reached = true;
            if (reached) break;
        }
        for (const KinematicsObject& mover : bodies.kinematics) {
            if (reached) break;
            if (mover.velocity == Vec3(0) && mover.angularVelocity == Vec3(0)) continue;
            const Real sweep = (glm::length(mover.velocity) + glm::length(mover.angularVelocity) * shapeReach(mover)) * h;
            reached = widened(shapeAabb(mover), sweep).overlaps(box);
        }
        for (std::uint32_t j = 0; j < bodies.softBodies.size() && !reached; ++j) {
            const SoftBody& other = bodies.softBodies[j];
            if (j == k || other.asleep || other.nodeCount() == 0) continue;
            Real fastest2 = 0;
            for (const Vec3& v : other.nodeVelocities) fastest2 = std::max(fastest2, glm::dot(v, v));
            reached = widened(nodeBounds(other), std::sqrt(fastest2) * h + fall).overlaps(box);
        }
        if (reached) woken += wakeSoftIsland(bodies.dynamics, bodies.softBodies, k);
    }
    return woken;
}

std::size_t wakeTouchedBySoftBodies(const BodySet& bodies) {
    std::size_t woken = 0;
    for (const SoftBody& soft : bodies.softBodies) {
        if (soft.asleep) continue;
        for (const std::uint32_t touched : soft.touchedDynamics) {
            woken += wakeIsland(bodies.dynamics, touched, bodies.softBodies);
        }
    }
    return woken;
}

std::size_t wakeTouchedIslands(const BodySet& bodies, std::span<const Contact> contacts, std::span<const BodyLink> links) {
    std::size_t woken = 0;
    auto wakePair = [&](std::uint32_t a, BodyRef b) {
        const bool aAsleep = bodies.dynamics[a].asleep;
        if (b.kind == BodyKind::Dynamic) {
            const bool bAsleep = bodies.dynamics[b.index].asleep;
            if (aAsleep && !bAsleep) woken += wakeIsland(bodies.dynamics, a, bodies.softBodies);
            if (bAsleep && !aAsleep) woken += wakeIsland(bodies.dynamics, b.index, bodies.softBodies);
        } else if (aAsleep && isMovingKinematic(bodies, b)) {
            woken += wakeIsland(bodies.dynamics, a, bodies.softBodies);
        }
    };
    for (const Contact& contact : contacts) wakePair(contact.a, contact.b);
    for (const BodyLink& link : links) {
        if (link.b != kWorldAnchor) wakePair(link.a, {BodyKind::Dynamic, link.b});
    }
    return woken;
}

std::size_t updateSleep(const BodySet& bodies, std::span<const Contact> contacts, std::span<const BodyLink> links,
                        const WorldSettings& settings, IslandWorkspace& workspace) {
    std::span<DynamicObject> dynamics = bodies.dynamics;
    std::span<SoftBody> softBodies = bodies.softBodies;
    const std::size_t n = dynamics.size();
    const std::size_t units = n + softBodies.size();  // union–find elements: the dynamic bodies, then the soft ones
    const Real h = settings.timeStep;
    const Real linear2 = settings.sleepLinearSpeed * settings.sleepLinearSpeed;
    const Real angular2 = settings.sleepAngularSpeed * settings.sleepAngularSpeed;

    // 1. Islands: union–find over dynamic–dynamic contacts and joints. (First, so that the
    //    bodies are walked once for 2, not once for their still times and again for their islands:
    //    with 64k bodies each walk reads megabytes of objects for a few numbers of each.)
    workspace.parent.resize(units);
    for (std::uint32_t i = 0; i < units; ++i) workspace.parent[i] = i;
    workspace.carried.clear();
    for (const Contact& contact : contacts) {
        if (contact.b.kind == BodyKind::Dynamic) joinIslands(workspace.parent, contact.a, contact.b.index);
        else if (isMovingKinematic(bodies, contact.b)) workspace.carried.push_back(contact.a);
    }
    for (const BodyLink& link : links) {
        if (link.b != kWorldAnchor) joinIslands(workspace.parent, link.a, link.b);
    }
    for (std::uint32_t k = 0; k < softBodies.size(); ++k) {  // what each soft body's nodes touched (src/soft/)
        const auto unit = static_cast<std::uint32_t>(n + k);
        for (const std::uint32_t body : softBodies[k].touchedDynamics) joinIslands(workspace.parent, unit, body);
        for (const std::uint32_t other : softBodies[k].touchedSoftBodies) {
            joinIslands(workspace.parent, unit, static_cast<std::uint32_t>(n + other));
        }
    }

    // 2. Still times (squared speeds: no square root per body), and each island's least. Still is
    //    slow and in equilibrium: the step changed the velocity by less than the acceleration limit
    //    times h. A body with no velocity from the last step (the first step) is not yet still.
    const bool known = workspace.lastVelocity.size() == n;
    workspace.lastVelocity.resize(n, Vec3(0));
    workspace.lastAngularVelocity.resize(n, Vec3(0));
    workspace.linearAcceleration.resize(n, Real(0));
    workspace.angularAcceleration.resize(n, Real(0));
    const Real change2 = settings.sleepLinearAcceleration * h * settings.sleepLinearAcceleration * h;
    const Real turnChange2 = settings.sleepAngularAcceleration * h * settings.sleepAngularAcceleration * h;
    workspace.islandStillTime.assign(units, std::numeric_limits<Real>::max());
    std::size_t asleep = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        DynamicObject& body = dynamics[i];
        Vec3& lastVelocity = workspace.lastVelocity[i];
        Vec3& lastAngularVelocity = workspace.lastAngularVelocity[i];
        if (body.asleep) {
            lastVelocity = lastAngularVelocity = Vec3(0);
            ++asleep;
            continue;
        }
        const Vec3 change = body.velocity - lastVelocity;
        const Vec3 turnChange = body.angularVelocity - lastAngularVelocity;
        const bool slow = glm::dot(body.velocity, body.velocity) < linear2 &&
                          glm::dot(body.angularVelocity, body.angularVelocity) < angular2;
        const bool balanced = known && glm::dot(change, change) < change2 && glm::dot(turnChange, turnChange) < turnChange2;
        workspace.linearAcceleration[i] = glm::length(change) / h;
        workspace.angularAcceleration[i] = glm::length(turnChange) / h;
        lastVelocity = body.velocity;
        lastAngularVelocity = body.angularVelocity;
        body.stillTime = slow && balanced ? body.stillTime + h : Real(0);
        Real& least = workspace.islandStillTime[findIslandRoot(workspace.parent, i)];
        least = std::min(least, body.stillTime);
    }
    for (const std::uint32_t a : workspace.carried) {  // carried by a moving platform is not still
        dynamics[a].stillTime = 0;
        if (!dynamics[a].asleep) workspace.islandStillTime[findIslandRoot(workspace.parent, a)] = 0;
    }
    // A soft body is still when every node is slower than the linear sleep speed (a node has no
    // spin); one node on a moving kinematic body makes it carried, never still.
    workspace.softNodeSpeed.resize(softBodies.size(), Real(0));
    for (std::uint32_t k = 0; k < softBodies.size(); ++k) {
        SoftBody& soft = softBodies[k];
        if (soft.asleep) continue;
        Real fastest2 = 0;
        for (const Vec3& v : soft.nodeVelocities) fastest2 = std::max(fastest2, glm::dot(v, v));
        workspace.softNodeSpeed[k] = std::sqrt(fastest2);
        const bool still = !soft.carried && fastest2 < linear2;
        soft.stillTime = still ? soft.stillTime + h : Real(0);
        Real& least = workspace.islandStillTime[findIslandRoot(workspace.parent, static_cast<std::uint32_t>(n + k))];
        least = std::min(least, soft.stillTime);
    }

    // 3. An island sleeps when its least still body has been still long enough. Most steps no
    //    island has (a pile with one body still rolling is one island, awake): then the bodies
    //    are not walked again.
    const Real none = std::numeric_limits<Real>::max();  // the entry of a body that is no root, or roots only sleepers
    const bool anyFallsAsleep = std::any_of(workspace.islandStillTime.begin(), workspace.islandStillTime.end(),
                                            [&](Real least) { return least != none && least >= settings.timeToSleep; });
    if (!anyFallsAsleep) return asleep;
    for (std::uint32_t i = 0; i < n; ++i) {
        DynamicObject& body = dynamics[i];
        if (body.asleep) continue;
        const std::uint32_t root = findIslandRoot(workspace.parent, i);
        if (workspace.islandStillTime[root] >= settings.timeToSleep) {
            body.asleep = true;
            body.sleepIsland = workspace.nextSleepIsland + root;
            body.velocity = Vec3(0);
            body.angularVelocity = Vec3(0);
            body.angularMomentum = Vec3(0);
            ++asleep;
        }
    }
    for (std::uint32_t k = 0; k < softBodies.size(); ++k) {
        SoftBody& soft = softBodies[k];
        if (soft.asleep) continue;
        const std::uint32_t root = findIslandRoot(workspace.parent, static_cast<std::uint32_t>(n + k));
        if (workspace.islandStillTime[root] >= settings.timeToSleep) {
            soft.asleep = true;
            soft.sleepIsland = workspace.nextSleepIsland + root;
            std::fill(soft.nodeVelocities.begin(), soft.nodeVelocities.end(), Vec3(0));
            soft.velocity = Vec3(0);
        }
    }
    workspace.nextSleepIsland += static_cast<std::uint32_t>(units);  // fresh ids for later islands
    return asleep;
}

}  // namespace stepwise
