/// @file interrupt.hpp
/// @brief Ctrl-C and `kill` during a long command: stop between two steps, not in the middle of a row.
///
/// A signal may arrive while the program is writing a CSV row. Ending the
/// process there leaves half a row and no summary. So while an
/// InterruptGuard lives, SIGINT and SIGTERM only set a flag; the command
/// checks it between steps, finishes what it is writing, flushes its files,
/// prints what it has, and exits with the shell's code for that signal,
/// 128 + its number: 130 for SIGINT, 143 for SIGTERM.
#pragma once

namespace stepwise::cli {

/// @brief Catches SIGINT and SIGTERM for its lifetime (SA_RESTART: an interrupted write carries on).
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// @brief The signal that arrived since the guard was made, or 0.
    static int signalReceived();
};

/// @brief The exit code for having stopped on @p signal: 128 + the signal's number.
int exitCodeForSignal(int signal);

}  // namespace stepwise::cli
