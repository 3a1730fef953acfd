/// @file world_regions.cpp
/// @brief The World's side of the regions: who is inside each, and removing what a Kill region takes.
///
/// The force laws are in src/forces/ (region.hpp lists them); what the World
/// adds is the bookkeeping around them: finding the bodies inside a region
/// without testing every body, and taking a body out of every list that
/// names it by index.
#include <algorithm>
#include <limits>

#include "collision/aabb.hpp"
#include "fast/fast_workspace.hpp"
#include "forces/conveyor.hpp"
#include "world/world.hpp"

namespace stepwise {

RegionForces World::regionForces(Real substepTime) const {
    return {regions_, &regionMembers_, settings_.gravity, stepCount_, substepTime};
}

/// Who is inside each region this step (RegionMembers), from where the bodies are now.
///
/// With @p throughBroadphase, after the broadphase has run: the broadphase in use lists the
/// bodies whose boxes meet the region's box (Broadphase::dynamicBodiesOverlapping()), so a
/// pond in a level of 10 000 bodies tests the few near it, not all; each candidate is then
/// tested exactly (regionHolds()). Without (the Impulse pipeline, whose broadphase runs after
/// the move, or a scene where nothing can touch, whose broadphase never runs), every body is tested.
/// Then, in a scene with a Conveyor region, each body's belt velocity (conveyorVelocities()).
void World::findRegionMembers(bool throughBroadphase) {
    RegionMembers& members = regionMembers_;
    members.start.resize(regions_.size() + 1);
    members.bodies.clear();
    for (std::size_t r = 0; r < regions_.size(); ++r) {
        const Region& region = regions_[r];
        members.start[r] = static_cast<std::uint32_t>(members.bodies.size());
        if (region.effect == RegionEffect::Kill) continue;  // removeKilledBodies() tests the ends of the step
        if (throughBroadphase) {
            Aabb box;
            regionBounds(region, box.min, box.max);
            broadphase_.dynamicBodiesOverlapping(box, regionCandidates_);
            for (const std::uint32_t i : regionCandidates_) {
                if (regionHolds(region, dynamics_[i])) members.bodies.push_back(i);
            }
        } else {
            for (std::size_t i = 0; i < dynamics_.size(); ++i) {
                if (regionHolds(region, dynamics_[i])) members.bodies.push_back(static_cast<std::uint32_t>(i));
            }
        }
    }
    members.start[regions_.size()] = static_cast<std::uint32_t>(members.bodies.size());
    // The belt under each body, for the contact preparation (src/forces/conveyor.hpp)
    if (plan_.conveyors.runs) conveyorVelocities(regions_, members, dynamics_.size(), conveyorVelocities_);
}

/// The belt velocity of each dynamic body this step, for the contacts' friction (src/forces/conveyor.hpp);
/// empty in a scene without a Conveyor region, whose contacts then never ask.
std::span<const Vec3> World::beltVelocities() const {
    if (!plan_.conveyors.runs) return {};
    return conveyorVelocities_;
}

/// Takes out every body whose centre ends the step inside a Kill region.
///
/// The test runs over every dynamic body: the bodies have moved since the broadphase, so no
/// structure holds where they are now, and testing a centre against a plane or a box costs
/// about what one query would. A step that removes nobody allocates nothing. A removal is
/// rare (once per body, ever), so it may cost: the body's springs and joints go with it, the
/// indices of those that stay are shifted down, and the caches that name bodies by index
/// (contacts, warm starts, the broadphase's structures, the sleep islands) start afresh, as in
/// a new World. The bodies that stay lose one step of warm starting.
void World::removeKilledBodies() {
    constexpr std::uint32_t kGone = std::numeric_limits<std::uint32_t>::max();
    // The Kill region that holds body i's centre, or none
    auto killerOf = [&](std::size_t i) -> const Region* {
        for (const Region& region : regions_) {
            if (region.effect == RegionEffect::Kill && regionContains(region, dynamics_[i].position)) return &region;
        }
        return nullptr;
    };
    std::size_t firstKilled = 0;
    while (firstKilled < dynamics_.size() && killerOf(firstKilled) == nullptr) ++firstKilled;
    if (firstKilled == dynamics_.size()) return;  // the common step: nobody removed, nothing allocated

    // A removal: each body's new index, or kGone
    std::vector<std::uint32_t> newIndex(dynamics_.size());
    std::size_t kept = 0;
    for (std::size_t i = 0; i < dynamics_.size(); ++i) {
        const Region* killer = i < firstKilled ? nullptr : killerOf(i);
        if (killer == nullptr) {
            newIndex[i] = static_cast<std::uint32_t>(kept++);
        } else {
            newIndex[i] = kGone;
            removedBodies_.push_back({dynamics_[i].name, killer->name, time_ + settings_.timeStep, dynamics_[i].position});
        }
    }

    // The bodies, springs and joints that stay, in their order, with their indices renumbered
    std::size_t next = 0;
    for (std::size_t i = 0; i < dynamics_.size(); ++i) {
        if (newIndex[i] == kGone) continue;
        if (next != i) dynamics_[next] = std::move(dynamics_[i]);  // never onto itself, which would empty its name
        ++next;
    }
    dynamics_.resize(kept);
    std::erase_if(springs_, [&](const Spring& s) {
        return newIndex[s.bodyA] == kGone || (s.bodyB != kFixedInWorld && newIndex[s.bodyB] == kGone);
    });
    for (Spring& s : springs_) {
        s.bodyA = newIndex[s.bodyA];
        if (s.bodyB != kFixedInWorld) s.bodyB = newIndex[s.bodyB];
    }
    std::erase_if(joints_, [&](const Joint& j) {
        return newIndex[j.bodyA] == kGone || (j.bodyB != kWorldAnchor && newIndex[j.bodyB] == kGone);
    });
    for (Joint& j : joints_) {
        j.bodyA = newIndex[j.bodyA];
        if (j.bodyB != kWorldAnchor) j.bodyB = newIndex[j.bodyB];
    }
    jointLinks(joints_, links_);

    // Everything that named a body by its old index starts afresh
    pairs_.clear();
    contacts_.clear();
    impulses_.clear();
    regionMembers_.start.clear();
    regionMembers_.bodies.clear();
    broadphase_ = Broadphase();
    contactWorkspace_ = ContactWorkspace();
    solverWorkspace_ = SolverWorkspace();
    islandWorkspace_ = IslandWorkspace();
    jointWorkspace_ = JointWorkspace();
    narrowphaseWorkspace_ = NarrowphaseWorkspace();
    sweepWorkspace_ = SweepWorkspace();
    fastWorkspace_ = std::make_unique<FastWorkspace>();
    replan();
}

}  // namespace stepwise
