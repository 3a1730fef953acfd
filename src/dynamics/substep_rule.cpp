/// @file substep_rule.cpp
/// @brief The islands of a step and the substeps each needs (substep_rule.hpp says why each term is there).
#include "dynamics/substep_rule.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "collision/aabb.hpp"

namespace stepwise {

namespace {

/// 60 Hz · (1/60 s) / 0.25 is 4 on paper and 4.000000000000001 in floating point: what is taken off before ⌈·⌉.
constexpr Real kStiffnessRounding = Real(1e-9);

/// The smallest power of two ≥ @p n, or @p cap if that is smaller: the counts fall into few groups.
int roundUpToGroup(int n, int cap) {
    int count = 1;
    while (count < n && count < cap) count *= 2;
    return std::min(count, cap);
}

/// ⌈x⌉ as a count, saturated at @p cap + 1, "more than the cap" (x may be huge: a 1e12 mass ratio).
int ceilingCount(Real x, int cap) { return x > Real(cap) ? cap + 1 : static_cast<int>(std::ceil(x)); }

}  // namespace

const char* substepReasonName(SubstepReason reason) {
    switch (reason) {
        case SubstepReason::Minimum: return "minimum";
        case SubstepReason::Height: return "height";
        case SubstepReason::MassRatio: return "mass ratio";
        case SubstepReason::Speed: return "speed";
        case SubstepReason::Stiffness: return "stiffness";
        case SubstepReason::FreeFlight: return "free flight";
        case SubstepReason::Cap: return "cap";
        case SubstepReason::Joint: return "joint";
    }
    return "?";
}

Real leastHalfSize(const DynamicObject& body) {
    switch (body.shape) {
        case Shape::Sphere:
        case Shape::Capsule:
        case Shape::Cylinder: return body.radius;
        case Shape::Box: {
            const Vec3 half = body.halfExtents();
            return std::min({half.x, half.y, half.z});
        }
        default: return shapeReach(body);
    }
}

int islandSubstepCount(std::uint32_t height, Real massRatio, Real speed, Real halfSize, bool hasContacts,
                       bool accelerated, const SubstepRuleInputs& inputs, SubstepReason& reason) {
    const int cap = inputs.cap;
    int wanted = kMinIslandSubsteps;
    reason = SubstepReason::Minimum;
    const auto consider = [&](int n, SubstepReason why) {
        if (n > wanted) {
            wanted = n;
            reason = why;
        }
    };
    if (!hasContacts) {
        // Free flight: Verlet is exact under a uniform field; the Eulers err by ½·a·t·h_s.
        const bool exact = inputs.integrator == IntegratorKind::Verlet || !accelerated;
        if (!exact) consider(cap, SubstepReason::FreeFlight);
    } else {
        // n_H = ⌈H/P⌉: the weight goes down one contact per pass
        consider(ceilingCount(Real(height) / Real(std::max(inputs.passes, 1)), cap), SubstepReason::Height);
        // n_M = ⌈k_M·r⌉ for unequal masses
        if (massRatio > Real(1)) consider(ceilingCount(kSubstepsPerMassRatio * massRatio, cap), SubstepReason::MassRatio);
        // n_V = ⌈v·h/(k_R·s)⌉: a substep moves a body a small part of its size
        if (halfSize > 0) consider(ceilingCount(speed * inputs.timeStep / (kReachShare * halfSize), cap), SubstepReason::Speed);
        // n_K = ⌈4·h·min(f, f_min)⌉: the contacts stay at least kMinContactHertz stiff (contactHertzInUse())
        const Real hertz = std::min(inputs.contactHertz, kMinContactHertz);
        consider(ceilingCount(hertz * inputs.timeStep / kMaxHertzPerSubstepRate - kStiffnessRounding, cap),
                 SubstepReason::Stiffness);
    }
    const int count = roundUpToGroup(wanted, cap);
    if (count == cap && wanted > cap) reason = SubstepReason::Cap;
    return count;
}

bool chooseIslandSubsteps(const BodySet& bodies, std::span<const Contact> contacts, std::span<const BodyLink> links,
                          const SubstepRuleInputs& inputs, SubstepGroups& g) {
    const auto n = static_cast<std::uint32_t>(bodies.dynamics.size());
    g.parent.resize(n);
    g.supported.assign(n, 0);
    g.adjacencyStart.assign(n + 1, 0);
    for (std::uint32_t i = 0; i < n; ++i) g.parent[i] = i;

    // 1. Islands: union–find over the contacts between dynamic bodies (each body's neighbours
    //    counted for the height) and over the joints.
    for (const Contact& c : contacts) {
        if (c.b.kind == BodyKind::Dynamic) {
            joinIslands(g.parent, c.a, c.b.index);  // the lower index stays the root
            ++g.adjacencyStart[c.a + 1];
            ++g.adjacencyStart[c.b.index + 1];
        } else {
            g.supported[c.a] = 1;  // a plane or a kinematic body carries it
        }
    }
    // A joint joins its two bodies into one island too (not into the height's layers: a hanging
    // chain is not a stack), and one to the world joins nothing.
    for (const BodyLink& link : links) {
        if (link.b != kWorldAnchor) joinIslands(g.parent, link.a, link.b);
    }
    for (std::uint32_t i = 0; i < n; ++i) g.adjacencyStart[i + 1] += g.adjacencyStart[i];
    g.adjacency.resize(g.adjacencyStart[n]);
    g.queue.assign(g.adjacencyStart.begin(), g.adjacencyStart.end() - 1);  // fill cursors
    for (const Contact& c : contacts) {
        if (c.b.kind != BodyKind::Dynamic) continue;
        g.adjacency[g.queue[c.a]++] = c.b.index;
        g.adjacency[g.queue[c.b.index]++] = c.a;
    }

    // 2. Number the islands in the order of their first (lowest) body; a root is its island's lowest body.
    g.islands.clear();
    g.islandOfBody.resize(n);
    g.halfSize.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t root = findIslandRoot(g.parent, i);
        if (root == i) {
            g.islandOfBody[i] = static_cast<std::uint32_t>(g.islands.size());
            g.islands.push_back(IslandSubsteps{.firstBody = i});
        } else {
            g.islandOfBody[i] = g.islandOfBody[root];  // root < i: already numbered
        }
        ++g.islands[g.islandOfBody[i]].bodies;
        g.halfSize[i] = leastHalfSize(bodies.dynamics[i]);
    }

    for (const BodyLink& link : links) ++g.islands[g.islandOfBody[link.a]].joints;

    // 3. Mass ratio and relative speed across each contact
    for (const Contact& c : contacts) {
        IslandSubsteps& island = g.islands[g.islandOfBody[c.a]];
        ++island.contacts;
        const DynamicObject& a = bodies.dynamics[c.a];
        Vec3 velocityB{0, 0, 0};
        Real sizeB = g.halfSize[c.a];
        if (c.b.kind == BodyKind::Dynamic) {
            const DynamicObject& b = bodies.dynamics[c.b.index];
            velocityB = b.velocity;
            sizeB = g.halfSize[c.b.index];
            island.massRatio = std::max(island.massRatio, std::max(a.mass / b.mass, b.mass / a.mass));
        } else if (c.b.kind == BodyKind::Kinematic) {
            velocityB = bodies.kinematics[c.b.index].velocity;
        }
        const Real speed = glm::length(velocityB - a.velocity);
        const Real size = std::min(g.halfSize[c.a], sizeB);
        // Keep the contact with the largest v/s: it sets n_V
        if (island.contacts == 1 || speed * island.halfSizeOfSpeed > island.speed * size) {
            island.speed = speed;
            island.halfSizeOfSpeed = size;
        }
    }

    // 4. Height: breadth-first layers from the supported bodies, then from the first body of an unsupported island
    g.depth.assign(n, 0);
    g.queue.clear();
    for (std::uint32_t i = 0; i < n; ++i) {
        if (g.supported[i]) {
            g.depth[i] = 1;
            g.queue.push_back(i);
        }
    }
    const auto spread = [&](std::size_t head) {
        for (; head < g.queue.size(); ++head) {
            const std::uint32_t body = g.queue[head];
            for (std::uint32_t k = g.adjacencyStart[body]; k < g.adjacencyStart[body + 1]; ++k) {
                const std::uint32_t next = g.adjacency[k];
                if (g.depth[next] != 0) continue;
                g.depth[next] = g.depth[body] + 1;
                g.queue.push_back(next);
            }
        }
    };
    spread(0);
    for (IslandSubsteps& island : g.islands) {
        if (g.depth[island.firstBody] != 0) continue;
        g.depth[island.firstBody] = 1;
        const std::size_t head = g.queue.size();
        g.queue.push_back(island.firstBody);
        spread(head);
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        IslandSubsteps& island = g.islands[g.islandOfBody[i]];
        island.height = std::max(island.height, g.depth[i]);
    }

    // 5. The rule, island by island
    bool reduced = false;
    for (IslandSubsteps& island : g.islands) {
        const DynamicObject& first = bodies.dynamics[island.firstBody];
        // A free body's integration error depends on h_s if it accelerates or a non-ball turns
        const bool accelerated = first.acceleration != Vec3(0) ||
                                 (first.shape != Shape::Sphere && first.angularVelocity != Vec3(0));
        if (island.joints > 0) {
            island.count = inputs.cap;  // the joint passes run at the scene's h_s (the file's header says why)
            island.reason = SubstepReason::Joint;
        } else if (first.asleep && island.bodies == 1) {
            island.count = kMinIslandSubsteps;  // not integrated, not solved: nothing depends on h_s
            island.reason = SubstepReason::Minimum;
        } else {
            island.count = islandSubstepCount(island.height, island.massRatio, island.speed, island.halfSizeOfSpeed,
                                              island.contacts > 0, accelerated, inputs, island.reason);
        }
        reduced = reduced || island.count < inputs.cap;
    }

    // 6. The groups: one per distinct count, largest first; each lists its bodies in index order
    g.counts.clear();
    for (const IslandSubsteps& island : g.islands) {
        if (std::find(g.counts.begin(), g.counts.end(), island.count) == g.counts.end()) g.counts.push_back(island.count);
    }
    std::sort(g.counts.begin(), g.counts.end(), std::greater<>());
    g.bodyStart.assign(g.counts.size() + 1, 0);
    const auto groupOf = [&](std::uint32_t body) {
        const int count = g.islands[g.islandOfBody[body]].count;
        return static_cast<std::size_t>(std::find(g.counts.begin(), g.counts.end(), count) - g.counts.begin());
    };
    for (std::uint32_t i = 0; i < n; ++i) ++g.bodyStart[groupOf(i) + 1];
    for (std::size_t k = 0; k < g.counts.size(); ++k) g.bodyStart[k + 1] += g.bodyStart[k];
    g.groupBodies.resize(n);
    g.queue.assign(g.bodyStart.begin(), g.bodyStart.end() - 1);  // fill cursors
    for (std::uint32_t i = 0; i < n; ++i) g.groupBodies[g.queue[groupOf(i)]++] = i;
    return reduced;
}

namespace {

/// Splits @p list (indices of @p keyOf's items) into @p groupCount slices by group, keeping its order.
template <class GroupOf>
void splitByGroup(std::span<const std::uint32_t> list, std::size_t groupCount, GroupOf groupOf,
                  std::vector<std::uint32_t>& out, std::vector<std::uint32_t>& starts, std::vector<std::uint32_t>& cursor) {
    starts.assign(groupCount + 1, 0);
    for (const std::uint32_t item : list) ++starts[groupOf(item) + 1];
    for (std::size_t k = 0; k < groupCount; ++k) starts[k + 1] += starts[k];
    out.resize(list.size());
    cursor.assign(starts.begin(), starts.end() - 1);
    for (const std::uint32_t item : list) out[cursor[groupOf(item)]++] = item;
}

}  // namespace

void splitSolverWork(const SolverWorkspace& w, SubstepGroups& g) {
    const std::size_t groups = g.counts.size();
    // The group of a body: its island's count's place in `counts` (at most a dozen counts)
    const auto groupOfBody = [&](std::uint32_t body) {
        const int count = g.islands[g.islandOfBody[body]].count;
        return static_cast<std::size_t>(std::find(g.counts.begin(), g.counts.end(), count) - g.counts.begin());
    };
    const auto groupOfRecord = [&](std::uint32_t record) { return groupOfBody(w.recordBody[record]); };
    const auto groupOfContact = [&](std::uint32_t contact) { return groupOfRecord(w.contacts[contact].bodyA); };
    // Records 1, 2, … (record 0 is the static body, which no loop over records visits)
    g.depth.resize(w.bodies.size() > 0 ? w.bodies.size() - 1 : 0);
    for (std::size_t r = 0; r < g.depth.size(); ++r) g.depth[r] = static_cast<std::uint32_t>(r + 1);
    splitByGroup(g.depth, groups, groupOfRecord, g.groupRecords, g.recordStart, g.queue);
    splitByGroup(w.roundContacts, groups, groupOfContact, g.groupRound, g.roundStart, g.queue);
    splitByGroup(w.otherContacts, groups, groupOfContact, g.groupOther, g.otherStart, g.queue);
}

}  // namespace stepwise
