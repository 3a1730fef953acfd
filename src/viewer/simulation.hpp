/// @file simulation.hpp
/// @brief What the viewer simulates: the World of a scene file (or its Spaces), its clock, the stage walk-through and picking.
///
/// Nothing here draws (no OpenGL): this is the part of the viewer that must
/// behave exactly like `stepwise run`. A scene of one simulation gets one
/// World, and the viewer only ever calls World::step(), the same call
/// `stepwise run` makes, so the trajectory is the same whatever the frame
/// rate; drawing only reads the World. A scene with `Space` records gets its
/// Spaces (src/world/spaces.hpp), advanced a tick of the shared clock at a
/// time with Spaces::advance(), as `stepwise run` advances them, and a
/// SpaceLayout that says where each is drawn.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "viewer/event_log.hpp"
#include "viewer/fixed_step_clock.hpp"
#include "viewer/mouse_force.hpp"
#include "viewer/space_layout.hpp"
#include "viewer/stage_walkthrough.hpp"
#include "world/spaces.hpp"
#include "world/world.hpp"

namespace stepwise::viewer {

/// @brief How much work the viewer spends, at most, running a copy of a scene with spaces ahead to
/// sweep each space's box (SpaceLayout), in body-steps (ticks of the shared clock × dynamic bodies,
/// a soft body counting as one per node):
/// about a second in a Release build. Counted in work, not in wall-clock time, so the layout is the
/// same on every machine and build; a bigger scene's layout may widen later.
inline constexpr std::uint64_t kLayoutLookaheadBodySteps = 2'000'000;

/// @brief What S, Shift+S and `--stage` say in a scene with spaces: the walk-through follows one World.
inline constexpr const char* kNoWalkthroughWithSpaces =
    "the stage walk-through follows one World, and this scene has spaces: "
    "open one space's objects in a scene of their own to walk through its stages";

/// @brief A scene file's World (or Spaces) plus everything the viewer does to it between frames.
class Simulation {
public:
    /// @brief Loads @p scenePath. @throws ConfigError or std::invalid_argument when the scene is bad
    /// (at start-up there is no last good scene to keep).
    explicit Simulation(std::string scenePath);

    /// @brief Re-reads the scene file from disk (the R key).
    ///
    /// On success the new World (or Spaces) replaces the old one and the
    /// clock restarts at t = 0 (pause, time scale and the spaces' arrangement
    /// are kept). On failure the old World stays and error() holds every
    /// diagnostic, one per line.
    /// @return true when the new scene was loaded
    bool reload();

    /// @brief Advances by as many fixed steps as @p wallSeconds of a frame are worth (see FixedStepClock).
    ///
    /// With spaces, the clock's step is the shared clock's tick
    /// (Spaces::finestTick()), and each tick is one Spaces::advance().
    /// @return the number of steps (with spaces, ticks) taken
    std::uint64_t advanceFrame(double wallSeconds);

    /// @brief The N key: takes exactly one step; inside the stage walk-through, only leaves it.
    ///
    /// The walk-through's step has already run to its end (see stepStage()),
    /// so leaving it shows the World where the step left it, and the next N
    /// takes the next step: the trajectory is the one `stepwise run` computes.
    /// With spaces: ticks the shared clock until a running space has taken a step.
    /// @return false when nothing could step (every space is paused)
    bool stepOnce();

    /// @brief Steps until the world's clock reads @p seconds: `llround(seconds / h)` steps
    /// in all, exactly as many as `stepwise run --duration seconds` (with spaces,
    /// `llround(seconds / tick)` ticks of the shared clock, as `stepwise run` takes).
    void stepTo(double seconds);

    /// @brief The S key (and Shift+S with @p skipMiddleSubsteps): shows the state after the next stage.
    ///
    /// At a step boundary, runs one World::step() with a StageWalkthrough as
    /// its observer, which captures the state after every stage run (see
    /// stage_walkthrough.hpp), and shows the first. Each later press shows
    /// the next snapshot; with @p skipMiddleSubsteps, the next one outside the
    /// substep loop or in its first or last substep. After the last
    /// snapshot, the next press runs the next step. Pauses the clock.
    /// With spaces it does nothing (kNoWalkthroughWithSpaces; the viewer says so).
    void stepStage(bool skipMiddleSubsteps = false);

    /// @brief `--stage K`: shows snapshot @p k (0-based) of a step run now, as k + 1 presses of S would.
    /// @return false when the step has no snapshot @p k (the walk-through then shows its last), or the
    /// scene has spaces (nothing is run)
    bool showStageRun(std::size_t k);

    /// @brief Index of the snapshot the walk-through shows, or nothing outside it.
    std::optional<std::size_t> shownStage() const { return shownStage_; }

    /// @brief The snapshots of the step the walk-through shows (or showed last).
    const StageWalkthrough& walkthrough() const { return walkthrough_; }

    /// @brief What to draw: the shown snapshot inside the walk-through, else the live World (the first space's).
    SceneView view() const { return shownStage_ ? walkthrough_.view() : liveView(worldAt(0)); }
    /// @brief What to draw of space @p k (of the World when @p k is 0 and the scene has no spaces).
    SceneView viewOf(std::size_t k) const { return spaces_ ? liveView(worldAt(k)) : view(); }

    /// @brief Starts holding dynamic body @p body of space @p space at point @p point, in the
    /// space's own coordinates (see mouse_force.hpp). Space 0 is the World of a scene without spaces.
    void grab(std::uint32_t body, const Vec3& point, const Vec3& rayDirection, bool pull, std::size_t space = 0);
    /// @brief Follows the mouse: the force now points along (or against) @p rayDirection.
    void aimGrab(const Vec3& rayDirection);
    /// @brief Lets go; logs the held body's velocity and angular velocity (a `release` line).
    void release();
    /// @brief The body being held, if any.
    const std::optional<Grab>& grabbed() const { return grab_; }
    /// @brief The space of the body being held (0 without spaces).
    std::size_t grabbedSpace() const { return grabSpace_; }
    /// @brief Position of the held point now, in its space's own coordinates, m.
    Vec3 grabPoint() const;
    /// @brief Force applied to the held body, N: mass × grabAcceleration(g), along the grab's direction.
    Vec3 grabForce() const;

    /// @brief Sends a `push`/`pull` line for every step a held body is pushed, and a
    /// `release` line, to @p log (`--log-events`); nullptr: none. The log must outlive the Simulation.
    void setEventLog(EventLog* log) { log_ = log; }

    /// @brief Writes the current state as `stepwise run --csv` writes a sample (header plus one row per
    /// object; with spaces, the `space` column and every space's rows).
    /// @throws std::runtime_error when the file cannot be written.
    void dumpState(const std::string& path) const;

    /// @brief Pauses or resumes space @p k (keys 1–9; Spaces::togglePause).
    /// @return false when the scene has no space @p k (nothing changes)
    bool toggleSpacePause(std::size_t k);

    bool hasSpaces() const { return spaces_ != nullptr; }  ///< True for a scene with `Space` records.
    /// @brief The spaces of a scene with `Space` records; nullptr for a scene of one World.
    const Spaces* spaces() const { return spaces_.get(); }
    /// @brief Number of Worlds drawn: the spaces, or 1.
    std::size_t worldCount() const { return spaces_ ? spaces_->all().size() : 1; }
    /// @brief Space @p k's World, or (k = 0) the only World of a scene without spaces.
    const World& worldAt(std::size_t k) const { return spaces_ ? spaces_->all()[k].world : *world_; }
    /// @brief Where each space is drawn (unused without spaces: one World, drawn where it is).
    SpaceLayout& layout() { return layout_; }
    /// @brief Where each space is drawn.
    const SpaceLayout& layout() const { return layout_; }

    const World& world() const { return worldAt(0); }       ///< The simulated world (with spaces: the first space's).
    const std::string& scenePath() const { return path_; }  ///< The scene file.
    FixedStepClock& clock() { return clock_; }              ///< Pause and time scale.
    const FixedStepClock& clock() const { return clock_; }  ///< Pause and time scale.
    /// @brief The last problem to show on screen (a reload's diagnostics, a simulation error), or "".
    const std::string& error() const { return error_; }
    /// @brief Clears error().
    void clearError() { error_.clear(); }
    /// @brief How many times the scene has been (re)loaded successfully, counting the first load.
    int loads() const { return loads_; }

private:
    /// A scene just read: a World or Spaces, and the spaces' layout swept ahead.
    struct Loaded {
        std::unique_ptr<World> world;
        std::unique_ptr<Spaces> spaces;
        SpaceLayout layout;
    };

    static Loaded load(const std::string& path);  // throws ConfigError or std::invalid_argument
    void adopt(Loaded loaded);  // it becomes the simulation; the clock restarts with its step
    void pushHeld(World& world);  // the held body's impulse for the next step of @p world
    void takeStep();  // one World::step() with the grab's impulse before it; catches SimulationError
    std::uint64_t takeTick();  // one tick of the spaces' clock; returns the steps the spaces took
    bool recordStep();  // takeStep() with the walk-through watching; false when the step failed

    std::string path_;
    std::unique_ptr<World> world_;    // a scene without spaces
    std::unique_ptr<Spaces> spaces_;  // a scene with spaces (world_ is then empty)
    SpaceLayout layout_;
    FixedStepClock clock_;
    std::optional<Grab> grab_;
    std::size_t grabSpace_ = 0;
    std::optional<std::size_t> shownStage_;
    StageWalkthrough walkthrough_;
    std::string error_;
    int loads_ = 0;
    EventLog* log_ = nullptr;
};

/// @brief The name of the object @p ref points to in @p world.
std::string bodyName(const World& world, const BodyRef& ref);

}  // namespace stepwise::viewer
