/// @file precision.hpp
/// @brief `stepwise-bench precision`: every reference problem, every integrator, a sweep of time steps.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace stepwise::bench {

/// @brief Options of `stepwise-bench precision`.
struct PrecisionOptions {
    bool quick = false;                     ///< --quick: two time steps, one repetition (a smoke test for CI).
    int repeats = 5;                        ///< --repeats N: timed repetitions per point; the median is reported.
    std::string configDir;                  ///< --config DIR: where the reference_*.scene files are.
    std::optional<std::string> csvPath;     ///< --csv PATH: every measurement, one row per metric.
    std::optional<std::string> markdownPath;///< --markdown PATH: the tables for docs/benchmarks.md.
    std::vector<std::string> only;          ///< --problems a,b: run only these (default: all).
};

/// @brief The time steps swept, s: 1/30 … 1/1920, halving (or the first two with --quick).
std::vector<double> sweptTimeSteps(bool quick);

/// @brief Runs the sweep, prints one table per problem, writes the CSV and Markdown asked for.
/// @return the process exit code: 0, 1 when a problem could not be prepared, 2 for a file that cannot be written.
int runPrecision(const PrecisionOptions& options);

}  // namespace stepwise::bench
