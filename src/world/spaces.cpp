/// @file spaces.cpp
/// @brief Splitting a scene into its spaces, and stepping them on one clock.
#include "world/spaces.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace stepwise {

namespace {

/// The entries of @p items whose space (parallel list @p spaceOf) is @p space, in order.
template <class T>
std::vector<T> ofSpace(const std::vector<T>& items, const std::vector<std::uint32_t>& spaceOf, std::uint32_t space) {
    std::vector<T> out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (spaceOf[i] == space) out.push_back(items[i]);
    }
    return out;
}

}  // namespace

std::vector<std::pair<SpaceDef, Scene>> splitIntoSpaces(Scene scene) {
    std::vector<std::pair<SpaceDef, Scene>> out;
    if (scene.spaces.empty()) {
        SpaceDef only;
        only.name = kDefaultSpaceName;
        only.settings = scene.settings;
        out.emplace_back(std::move(only), std::move(scene));
        return out;
    }
    const std::uint32_t count = static_cast<std::uint32_t>(scene.spaces.size()) + 1;
    for (std::uint32_t space = 0; space < count; ++space) {
        SpaceDef def;
        if (space == kDefaultSpace) {
            def.name = kDefaultSpaceName;
            def.settings = scene.settings;
        } else {
            def = scene.spaces[space - 1];
        }
        Scene part;
        part.sourcePath = scene.sourcePath;
        part.settings = def.settings;
        part.settings.duration = scene.settings.duration;  // one clock: the World record's Duration
        part.dynamics = ofSpace(scene.dynamics, scene.dynamicSpace, space);
        part.kinematics = ofSpace(scene.kinematics, scene.kinematicSpace, space);
        part.planes = ofSpace(scene.planes, scene.planeSpace, space);
        part.attractors = ofSpace(scene.attractors, scene.attractorSpace, space);
        part.regions = ofSpace(scene.regions, scene.regionSpace, space);
        part.softBodies = ofSpace(scene.softBodies, scene.softBodySpace, space);
        part.materials = scene.materials;  // objects name materials by their index in the file's list
        part.materialPairs = scene.materialPairs;
        const bool anything =
            !part.dynamics.empty() || !part.kinematics.empty() || !part.planes.empty() || !part.softBodies.empty();
        if (space == kDefaultSpace && !anything) continue;  // every object named its space
        // Springs: body indices into the whole scene's dynamics → into this space's
        std::vector<std::size_t> index(scene.dynamics.size(), kFixedInWorld);
        std::size_t next = 0;
        for (std::size_t i = 0; i < scene.dynamics.size(); ++i) {
            if (scene.dynamicSpace[i] == space) index[i] = next++;
        }
        for (const Spring& spring : scene.springs) {
            if (scene.dynamicSpace[spring.bodyA] != space) continue;  // the loader checked both ends share it
            Spring s = spring;
            s.bodyA = index[spring.bodyA];
            if (spring.bodyB != kFixedInWorld) s.bodyB = index[spring.bodyB];
            part.springs.push_back(s);
        }
        const auto inSpace = [&](const std::string& name) {
            return std::any_of(part.dynamics.begin(), part.dynamics.end(),
                               [&](const DynamicObject& b) { return b.name == name; }) ||
                   std::any_of(part.softBodies.begin(), part.softBodies.end(),
                               [&](const SoftBody& b) { return b.name == name; });
        };
        for (const JointDef& joint : scene.joints) {
            if (inSpace(joint.bodyA)) part.joints.push_back(joint);
        }
        for (const Expectation& e : scene.expectations) {
            if (e.object == kAllBodies || inSpace(e.object)) part.expectations.push_back(e);
        }
        out.emplace_back(std::move(def), std::move(part));
    }
    return out;
}

Spaces::Spaces(Scene scene) {
    for (auto& [def, part] : splitIntoSpaces(std::move(scene))) {
        std::vector<Expectation> expectations = part.expectations;
        spaces_.push_back(Space{def.name, def.timeScale, def.paused, 0, World(std::move(part)), std::move(expectations)});
    }
}

Real Spaces::finestTick() const {
    Real tick = 0;
    for (const Space& space : spaces_) {
        const Real h = space.world.settings().timeStep / space.timeScale;
        tick = tick == 0 ? h : std::min(tick, h);
    }
    return tick;
}

void Spaces::advance(Real seconds, const std::function<void(std::size_t)>& afterStep,
                     const std::function<void(std::size_t)>& beforeStep) {
    clock_ += seconds;
    for (std::size_t k = 0; k < spaces_.size(); ++k) {
        Space& space = spaces_[k];
        if (space.paused) continue;
        space.runTime += seconds;
        // Every step that fits in the simulated time this space owes: TimeScale × the clock it ran.
        // Counting steps (not adding h) keeps a space of h = 1/240 s on the same step as the clock
        // after any number of ticks; the 1e-9 of a step forgives the rounding of h·n.
        const Real h = space.world.settings().timeStep;
        const auto owed = static_cast<std::uint64_t>(std::floor(space.timeScale * space.runTime / h + Real(1e-9)));
        while (space.world.stepCount() < owed) {
            if (beforeStep) beforeStep(k);
            space.world.step();
            if (afterStep) afterStep(k);
        }
    }
}

void Spaces::togglePause(std::size_t index) {
    if (index < spaces_.size()) spaces_[index].paused = !spaces_[index].paused;
}

}  // namespace stepwise
