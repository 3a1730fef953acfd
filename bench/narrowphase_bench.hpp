/// @file narrowphase_bench.hpp
/// @brief `stepwise-bench narrowphase`: SAT, GJK+EPA and MPR on the same pairs, time per pair and iterations.
#pragma once

#include <string>
#include <vector>

namespace stepwise::bench {

/// @brief Usage of `stepwise-bench narrowphase`, for `stepwise-bench --help`.
extern const char* const kNarrowphaseUsage;

/// @brief Parses the arguments after `narrowphase` and prints the table; the exit code (0, or 2 for a bad argument).
int narrowphaseCommand(const std::vector<std::string>& args);

}  // namespace stepwise::bench
