/// @file simulation.hpp
/// @brief What the viewer simulates: the World of a scene file, its clock, the stage walk-through and picking.
///
/// Nothing here draws (no OpenGL): this is the part of the viewer that must
/// behave exactly like `stepwise run`. It owns one World and only ever calls
/// World::step(), the same call `stepwise run` makes, so the trajectory is
/// the same whatever the frame rate; drawing only reads the World.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "viewer/event_log.hpp"
#include "viewer/fixed_step_clock.hpp"
#include "viewer/mouse_force.hpp"
#include "viewer/stage_walkthrough.hpp"
#include "world/world.hpp"

namespace stepwise::viewer {

/// @brief A scene file's World plus everything the viewer does to it between frames.
class Simulation {
public:
    /// @brief Loads @p scenePath. @throws ConfigError or std::invalid_argument when the scene is bad
    /// (at start-up there is no last good scene to keep).
    explicit Simulation(std::string scenePath);

    /// @brief Re-reads the scene file from disk (the R key).
    ///
    /// On success the new World replaces the old one and the clock restarts
    /// at t = 0 (pause and time scale are kept). On failure the old World
    /// stays and error() holds every diagnostic, one per line.
    /// @return true when the new scene was loaded
    bool reload();

    /// @brief Advances by as many fixed steps as @p wallSeconds of a frame are worth (see FixedStepClock).
    /// @return the number of steps taken
    std::uint64_t advanceFrame(double wallSeconds);

    /// @brief The N key: takes exactly one step; inside the stage walk-through, only leaves it.
    ///
    /// The walk-through's step has already run to its end (see stepStage()),
    /// so leaving it shows the World where the step left it, and the next N
    /// takes the next step: the trajectory is the one `stepwise run` computes.
    void stepOnce();

    /// @brief Steps until the world's clock reads @p seconds: `llround(seconds / h)` steps
    /// in all, exactly as many as `stepwise run --duration seconds`.
    void stepTo(double seconds);

    /// @brief The S key (and Shift+S with @p skipMiddleSubsteps): shows the state after the next stage.
    ///
    /// At a step boundary, runs one World::step() with a StageWalkthrough as
    /// its observer, which captures the state after every stage run (see
    /// stage_walkthrough.hpp), and shows the first. Each later press shows
    /// the next snapshot; with @p skipMiddleSubsteps, the next one outside the
    /// substep loop or in its first or last substep. After the last
    /// snapshot, the next press runs the next step. Pauses the clock.
    void stepStage(bool skipMiddleSubsteps = false);

    /// @brief `--stage K`: shows snapshot @p k (0-based) of a step run now, as k + 1 presses of S would.
    /// @return false when the step has no snapshot @p k (the walk-through then shows its last)
    bool showStageRun(std::size_t k);

    /// @brief Index of the snapshot the walk-through shows, or nothing outside it.
    std::optional<std::size_t> shownStage() const { return shownStage_; }

    /// @brief The snapshots of the step the walk-through shows (or showed last).
    const StageWalkthrough& walkthrough() const { return walkthrough_; }

    /// @brief What to draw: the shown snapshot inside the walk-through, else the live World.
    SceneView view() const { return shownStage_ ? walkthrough_.view() : liveView(*world_); }

    /// @brief Starts holding dynamic body @p body at world point @p point (see mouse_force.hpp).
    void grab(std::uint32_t body, const Vec3& point, const Vec3& rayDirection, bool pull);
    /// @brief Follows the mouse: the force now points along (or against) @p rayDirection.
    void aimGrab(const Vec3& rayDirection);
    /// @brief Lets go; logs the held body's velocity and angular velocity (a `release` line).
    void release();
    /// @brief The body being held, if any.
    const std::optional<Grab>& grabbed() const { return grab_; }
    /// @brief World-space position of the held point now, m.
    Vec3 grabPoint() const;
    /// @brief Force applied to the held body, N: mass × grabAcceleration(g), along the grab's direction.
    Vec3 grabForce() const;

    /// @brief Sends a `push`/`pull` line for every step a held body is pushed, and a
    /// `release` line, to @p log (`--log-events`); nullptr: none. The log must outlive the Simulation.
    void setEventLog(EventLog* log) { log_ = log; }

    /// @brief Writes the current state as `stepwise run --csv` writes a sample (header plus one row per object).
    /// @throws std::runtime_error when the file cannot be written.
    void dumpState(const std::string& path) const;

    const World& world() const { return *world_; }          ///< The simulated world.
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
    void takeStep();  // one World::step() with the grab's impulse before it; catches SimulationError
    bool recordStep();  // takeStep() with the walk-through watching; false when the step failed

    std::string path_;
    std::unique_ptr<World> world_;
    FixedStepClock clock_;
    std::optional<Grab> grab_;
    std::optional<std::size_t> shownStage_;
    StageWalkthrough walkthrough_;
    std::string error_;
    int loads_ = 0;
    EventLog* log_ = nullptr;
};

/// @brief The name of the object @p ref points to in @p world.
std::string bodyName(const World& world, const BodyRef& ref);

}  // namespace stepwise::viewer
