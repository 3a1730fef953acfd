/// @file step_observer.hpp
/// @brief One interface through which the stages of a step report what they did.
///
/// Stages do not print. The World calls an observer before and after every
/// stage it runs; the observer reads what it wants through the World's const
/// accessors (bodies, candidatePairs(), contacts(), impulses(),
/// solverContacts(), joints(), islands(), stageRecords()). Three users share
/// it: `stepwise trace` (src/app/trace.cpp), the viewer's stage-by-stage
/// walk-through (the S key) and the tests that check what a stage produced.
///
/// Cost when no observer is set: one pointer test per stage run (not per
/// body or pair). Observers must not change the World: they get it by const
/// reference, so a run with an observer gives the same trajectory as one
/// without.
#pragma once

#include <cstdint>

#include "core/types.hpp"
#include "core/stages.hpp"

namespace stepwise {

class World;

/// @brief Where in the step a stage runs: which step, which substep, and when.
struct StageEvent {
    Stage stage = Stage::ApplyForces;  ///< The stage that is about to run or has just run.
    std::uint64_t step = 0;            ///< Number of the step being taken, counting from 1.
    int substep = -1;                  ///< Substep 0 … substeps−1 inside the substep loop; −1 outside it.
    int substeps = 1;                  ///< Substeps in this step (1 for `Solver=Impulse`).
    Real stepStartTime = 0;            ///< Simulated time at the start of the step, s.
    Real timeStep = 0;                 ///< Length of the step, s (a substep lasts timeStep / substeps).
};

/// @brief Receives a call before and after every stage the World runs.
///
/// Override what you need; both default to doing nothing. Calls arrive in
/// pipeline order, the same order for the same scene every run.
class StepObserver {
public:
    virtual ~StepObserver() = default;
    /// @brief @p world as the stage of @p event found it.
    virtual void beforeStage(const StageEvent& event, const World& world);
    /// @brief @p world as the stage of @p event left it (after its finite-state check).
    virtual void afterStage(const StageEvent& event, const World& world);
    /// @brief The step has finished: time and step count have advanced.
    virtual void afterStep(const World& world);
};

}  // namespace stepwise
