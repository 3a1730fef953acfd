/// @file fixed_step_clock.hpp
/// @brief How many fixed physics steps a frame of wall-clock time is worth: the accumulator.
///
/// The physics always advances by the scene's own time step h, never by the
/// frame's length, so what the viewer shows is a trajectory `stepwise run`
/// would compute too (Glenn Fiedler, "Fix your timestep!", 2004). Each frame
/// adds its wall-clock duration, times the time scale, to an accumulator and
/// takes as many whole steps as fit; the remainder waits for the next frame:
///
///     accumulator += scale · frame
///     while accumulator ≥ h:  step();  accumulator −= h
///
/// Plain arithmetic, no OpenGL, so the viewer test checks it directly.
#pragma once

#include <algorithm>
#include <cstdint>

namespace stepwise::viewer {

/// @brief The accumulator that turns frame times into a whole number of fixed steps.
class FixedStepClock {
public:
    /// Longest frame counted, s: after a stall (a breakpoint, a dragged
    /// window) the simulation resumes instead of racing to catch up.
    static constexpr double kMaxFrameSeconds = 0.25;

    /// @brief A clock for steps of @p timeStep seconds.
    explicit FixedStepClock(double timeStep) : timeStep_(timeStep) {}

    /// @brief Adds a frame of @p wallSeconds and returns how many steps to take now.
    ///
    /// Paused, it counts nothing (and forgets any remainder).
    std::uint64_t advance(double wallSeconds) {
        if (paused_) {
            accumulator_ = 0;
            return 0;
        }
        accumulator_ += scale_ * std::clamp(wallSeconds, 0.0, kMaxFrameSeconds);
        // Compare with a tolerance of a millionth of a step, so that frames
        // that add up to exactly k·h give k steps despite round-off.
        const double tolerance = 1e-6 * timeStep_;
        std::uint64_t steps = 0;
        while (accumulator_ + tolerance >= timeStep_) {
            accumulator_ -= timeStep_;
            ++steps;
        }
        if (accumulator_ < 0) accumulator_ = 0;
        return steps;
    }

    double timeStep() const { return timeStep_; }          ///< h, s.
    double accumulator() const { return accumulator_; }    ///< Simulated time owed but not yet stepped, s.
    double scale() const { return scale_; }               ///< Simulated seconds per wall-clock second.
    bool paused() const { return paused_; }                ///< True while paused.

    /// @brief Sets the time scale, kept between 1/64 and 8.
    void setScale(double scale) { scale_ = std::clamp(scale, 1.0 / 64, 8.0); }
    /// @brief Pauses or resumes.
    void setPaused(bool paused) { paused_ = paused; }

private:
    double timeStep_;
    double accumulator_ = 0;
    double scale_ = 1;
    bool paused_ = false;
};

}  // namespace stepwise::viewer
