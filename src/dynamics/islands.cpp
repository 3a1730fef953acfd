/// @file islands.cpp
/// @brief Islands by union–find over contacts and joints, and the sleep decision (see islands.hpp).
#include "dynamics/islands.hpp"

#include <algorithm>
#include <limits>

namespace stepwise {

namespace {

/// Root of i's tree, halving the path on the way (Tarjan): near-constant time.
std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

void join(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b) {
    const std::uint32_t ra = findRoot(parent, a);
    const std::uint32_t rb = findRoot(parent, b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);  // the lower index is the root: deterministic
}

bool isMovingKinematic(const BodySet& bodies, const BodyRef& ref) {
    if (ref.kind != BodyKind::Kinematic) return false;
    const KinematicsObject& k = bodies.kinematics[ref.index];
    return k.velocity != Vec3(0) || k.angularVelocity != Vec3(0);
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

std::size_t wakeIsland(std::span<DynamicObject> bodies, std::uint32_t body) {
    if (!bodies[body].asleep) return 0;
    const std::uint32_t island = bodies[body].sleepIsland;
    std::size_t woken = 0;
    for (DynamicObject& other : bodies) {
        if (other.asleep && other.sleepIsland == island) {
            other.asleep = false;
            other.stillTime = 0;
            ++woken;
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
            if (aAsleep && !bAsleep) woken += wakeIsland(bodies.dynamics, a);
            if (bAsleep && !aAsleep) woken += wakeIsland(bodies.dynamics, b.index);
        } else if (aAsleep && isMovingKinematic(bodies, b)) {
            woken += wakeIsland(bodies.dynamics, a);
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
    const std::size_t n = dynamics.size();
    const Real h = settings.timeStep;
    const Real linear2 = settings.sleepLinearSpeed * settings.sleepLinearSpeed;
    const Real angular2 = settings.sleepAngularSpeed * settings.sleepAngularSpeed;

    // 1. Islands: union–find over dynamic–dynamic contacts and joints. (First, so that the
    //    bodies are walked once for 2, not once for their still times and again for their islands:
    //    with 64k bodies each walk reads megabytes of objects for a few numbers of each.)
    workspace.parent.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) workspace.parent[i] = i;
    workspace.carried.clear();
    for (const Contact& contact : contacts) {
        if (contact.b.kind == BodyKind::Dynamic) join(workspace.parent, contact.a, contact.b.index);
        else if (isMovingKinematic(bodies, contact.b)) workspace.carried.push_back(contact.a);
    }
    for (const BodyLink& link : links) {
        if (link.b != kWorldAnchor) join(workspace.parent, link.a, link.b);
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
    workspace.islandStillTime.assign(n, std::numeric_limits<Real>::max());
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
        Real& least = workspace.islandStillTime[findRoot(workspace.parent, i)];
        least = std::min(least, body.stillTime);
    }
    for (const std::uint32_t a : workspace.carried) {  // carried by a moving platform is not still
        dynamics[a].stillTime = 0;
        if (!dynamics[a].asleep) workspace.islandStillTime[findRoot(workspace.parent, a)] = 0;
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
        const std::uint32_t root = findRoot(workspace.parent, i);
        if (workspace.islandStillTime[root] >= settings.timeToSleep) {
            body.asleep = true;
            body.sleepIsland = workspace.nextSleepIsland + root;
            body.velocity = Vec3(0);
            body.angularVelocity = Vec3(0);
            body.angularMomentum = Vec3(0);
            ++asleep;
        }
    }
    workspace.nextSleepIsland += static_cast<std::uint32_t>(n);  // fresh ids for later islands
    return asleep;
}

}  // namespace stepwise
