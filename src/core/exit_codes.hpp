/// @file exit_codes.hpp
/// @brief The exit codes of the `stepwise` program, shared by its commands and the viewer.
#pragma once

namespace stepwise {

/// Exit codes, as documented in the README.
inline constexpr int kExitOk = 0;              ///< Success.
inline constexpr int kExitSimulationError = 1; ///< The simulation reached an impossible state.
inline constexpr int kExitUsageError = 2;      ///< Bad command line or bad scene file.
inline constexpr int kExitExpectationFailed = 3; ///< An Expect record failed (run), or a graded scene did (grade).

}  // namespace stepwise
