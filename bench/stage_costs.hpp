/// @file stage_costs.hpp
/// @brief `stepwise-bench stage-costs`: what each stage of a step costs per body, in the settled sphere rain, at several sizes timed in turn.
///
/// The Scaling table (scaling.cpp) answers "does the cost per body stay flat?"
/// for the whole step, each size in its own run. Two things blur that answer
/// on a shared machine: a run of minutes (64k spheres) and one of seconds (1k)
/// meet the machine in different moods (the same 1k run takes 2.8 or 3.7 ms a
/// step from one minute to the next here), and the runs cover the rain's fall
/// as well as its pile. This benchmark first lets every size fall and settle
/// (untimed), then times them *in turn*, round after round, in one process, so
/// that every size meets the same moods; and it splits the cost by stage
/// (World::stageRecords()), so a growth can be traced to where it is.
///
/// Under the stages it prints where the step's data lives: the megabytes of the
/// bodies, the contacts and the contact solver's arrays at each size
/// (World::solverFootprint()), beside the processor's data caches as Linux
/// lists them. The work per body is the same at every size (contacts per
/// body, the stage table's last row); what changes is whether a walk over
/// those arrays is served by a core's own L2 cache, by the shared L3 or, once
/// what one substep walks outgrows the L3 too, by main memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace stepwise::bench {

/// @brief What `stepwise-bench stage-costs` runs.
struct StageCostOptions {
    bool quick = false;                ///< --quick: 200 and 800 spheres, 20 steps to settle, 3 rounds (CTest smoke test).
    std::vector<std::size_t> sizes;    ///< --sizes: sphere-rain counts (default 1000, 16000, 64000).
    /// --settle: untimed steps first, 300 (5 s): the rain lands in about 2 s and is a settled pile by 5.
    int settleSteps = 300;
    /// --rounds: timed rounds. In each, every size steps about as many body-steps as the largest
    /// does in one step (1k: 64 steps for 64k's one).
    int rounds = 20;
    std::uint64_t seed = 1;                   ///< --seed: seed of the rain scenes.
    std::optional<std::string> markdownPath;  ///< --markdown PATH: the table as Markdown (docs/benchmarks.md).
};

/// @brief Runs the stage-cost benchmark and prints its table; returns the exit code.
int runStageCosts(const StageCostOptions& options);

}  // namespace stepwise::bench
