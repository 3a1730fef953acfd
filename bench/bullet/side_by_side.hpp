/// @file side_by_side.hpp
/// @brief `stepwise-bench bullet`: the same scene files in Stepwise and in Bullet 3, one table per scenario.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace stepwise::bench {

/// @brief What `stepwise-bench bullet` runs.
struct SideBySideOptions {
    bool quick = false;                      ///< --quick: small rain, few steps (a smoke test).
    std::vector<std::size_t> rainSizes;      ///< --sizes: sphere counts of the rain and the wall rain (default 1000, 4000, 16000).
    std::string configDir;                   ///< --config DIR: where the scene files are.
    std::optional<std::string> markdownPath; ///< --markdown PATH: the tables as Markdown.
    std::optional<std::string> sweepCsvPath; ///< --sweep-csv PATH: the rain sweep's runs as CSV (for the plot).
    std::optional<std::string> ratiosCsvPath; ///< --ratios-csv PATH: each scene's times, speed ratio and accuracy as CSV.
    int rainSteps = 600;                     ///< --steps N: steps of each sphere rain (issue #7: 600).
    /// --scenarios: which of rain, rain-sweep, stacks, pyramid-sweep, free-box, bounce, incline, reference,
    /// wall-rain, box-pile, chain, ragdoll to run (default all).
    std::vector<std::string> scenarios;
};

/// @brief Runs every scenario in both engines and prints the tables; returns the exit code.
int runSideBySide(const SideBySideOptions& options);

}  // namespace stepwise::bench
