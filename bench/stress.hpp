/// @file stress.hpp
/// @brief `stepwise-bench stress`: scenes that push the engine to its limits, each judged against a criterion from physics.
///
/// Every case runs a scene (a `config/stress_*.scene` or lesson file a
/// student can open, or one generated from a seed), measures one figure and
/// compares it with a stated criterion: how far a stack drifts, how much
/// energy a perfectly elastic gas gains, whether a fast ball passes through a
/// thin wall, … The program prints one row per case
/// (`case | criterion | measured | pass/fail | ms/step`) and exits with 1
/// when any case fails. The cases, their criteria and why are listed in
/// stress.cpp; the measured table is in docs/benchmarks.md ("Stress suite").
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace stepwise::bench {

/// @brief Options of `stepwise-bench stress`.
struct StressOptions {
    bool quick = false;                      ///< --quick: shorter runs and fewer bodies (the CTest smoke test).
    std::string configDir;                   ///< --config DIR: where the scene files are.
    std::optional<std::string> markdownPath; ///< --markdown PATH: the table as Markdown (for docs/benchmarks.md).
    std::vector<std::string> only;           ///< --cases a,b: run only these (default: every case).
};

/// @brief The names of the stress cases, in the order they run.
std::vector<std::string> stressCaseNames();

/// @brief Runs the cases, prints the table, writes the Markdown asked for.
/// @return the process exit code: 0 when every case passed, 1 when one failed
///         (or could not run), 2 for an unknown case name or a file that cannot be written.
int runStress(const StressOptions& options);

}  // namespace stepwise::bench
