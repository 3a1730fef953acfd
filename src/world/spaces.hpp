/// @file spaces.hpp
/// @brief Spaces: several simulations side by side in one scene, one run, one CSV and one window.
///
/// A scene with `Space` records holds several simulations that never touch:
/// each space has its own bodies, broadphase and solver, and its own World
/// settings (the World record's, with the Space record's own fields over
/// them). This is the classroom's comparison tool: the same drop under
/// explicit Euler and Verlet, the tower under the Impulse solver and under
/// sequential impulses, a step of 1/30 s against one of 1/240 s, all in one
/// run.
///
/// The spaces share one clock. A space with `TimeScale=s` runs s simulated
/// seconds per second of the clock, and each keeps its own time step: after
/// the clock has advanced to T, a running space has taken every step that
/// fits in s·T, so a space of h = 1/30 s takes one step while one of 1/240 s
/// takes eight. A paused space takes none and, resumed, goes on from where
/// it stopped (its clock does not jump ahead). Objects that name no space
/// are in the default space, which runs with the World record's settings; it
/// is left out when no object is in it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "world/scene.hpp"
#include "world/world.hpp"

namespace stepwise {

/// @brief One simulation of a scene with spaces: its name, its pace, and its World.
struct Space {
    std::string name;      ///< The Space record's Name, or "default".
    Real timeScale = 1;    ///< Simulated seconds per second of the shared clock.
    bool paused = false;   ///< A paused space takes no step.
    Real runTime = 0;      ///< Seconds of the shared clock during which it ran (not paused).
    World world;           ///< Its bodies, broadphase and solver.
    std::vector<Expectation> expectations;  ///< The Expect records about its bodies (the World ignores them).
};

/// @brief The name of the default space: the objects that name no space.
inline constexpr const char* kDefaultSpaceName = "default";

/// @brief The scenes of each space of @p scene: the default space's first (if it holds an object),
/// then the Space records' in file order.
///
/// Each gets its objects in file order, its springs (their body indices
/// renumbered), joints, regions and attractors, and the Expect records about
/// its bodies; an Expect about all bodies (EnergyChange) goes to every space.
/// A scene without spaces gives one scene, itself.
std::vector<std::pair<SpaceDef, Scene>> splitIntoSpaces(Scene scene);

/// @brief Every space of a scene, stepped on one shared clock.
class Spaces {
public:
    /// @brief Builds a World for each space of @p scene (splitIntoSpaces()).
    explicit Spaces(Scene scene);

    /// @brief Advances the shared clock by @p seconds: each running space takes every step that fits.
    /// @param afterStep called with the space's index after each step any space takes (may be empty)
    /// @param beforeStep called with the space's index just before each such step (may be empty):
    ///        the viewer gives a held body its push there, as it does before World::step()
    void advance(Real seconds, const std::function<void(std::size_t)>& afterStep = {},
                 const std::function<void(std::size_t)>& beforeStep = {});

    /// @brief The clock's smallest useful tick: the shortest h/TimeScale among the spaces, s.
    Real finestTick() const;

    /// @brief Seconds on the shared clock.
    Real clock() const { return clock_; }

    /// @brief Pauses a running space, or resumes a paused one.
    void togglePause(std::size_t index);

    std::vector<Space>& all() { return spaces_; }              ///< The spaces, in order.
    const std::vector<Space>& all() const { return spaces_; }  ///< The spaces, in order.

private:
    std::vector<Space> spaces_;
    Real clock_ = 0;
};

}  // namespace stepwise
