/// @file errors.hpp
/// @brief The error a simulation raises when its state becomes impossible.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace stepwise {

/// @brief Thrown when a stage leaves an object in an impossible state
/// (a NaN or infinite position, velocity or orientation).
///
/// A physics engine that silently carries NaNs onward produces an empty
/// screen ten seconds later; failing at the first bad stage, naming the
/// object, the stage and the step, points straight at the cause.
class SimulationError : public std::runtime_error {
public:
    /// @brief Builds the error and its message
    ///        "step N (t = T s), stage 'S': object 'O': what".
    ///
    /// @p step is the step being taken, counted from 1 as `stepwise trace` counts
    /// (World::stepCount() + 1), and @p time the time at its start, (N − 1)·h.
    SimulationError(std::string objectName, std::string stageName, std::uint64_t step,
                    double time, const std::string& what);

    const std::string& objectName() const { return object_; }  ///< Object whose state is bad.
    const std::string& stageName() const { return stage_; }    ///< Stage that produced it.
    std::uint64_t step() const { return step_; }               ///< The step being taken; the first step is step 1.

private:
    std::string object_;
    std::string stage_;
    std::uint64_t step_;
};

}  // namespace stepwise
