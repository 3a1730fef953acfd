/// @file interrupt.hpp
/// @brief Ctrl-C, `kill` and a time budget during a long command: stop between two steps, not in
/// the middle of a row.
///
/// A signal may arrive while the program is writing a CSV row. Ending the
/// process there leaves half a row and no summary. So while an
/// InterruptGuard lives, SIGINT and SIGTERM only set a flag; the command
/// checks it between steps, finishes what it is writing, flushes its files,
/// prints what it has, and exits with the shell's code for that signal,
/// 128 + its number: 130 for SIGINT, 143 for SIGTERM.
/// A budget of wall-clock time (`--max-seconds`) stops a command the same
/// way: a hostile scene that would run for hours ends with the steps it did
/// and exit code 1 instead.
#pragma once

#include <chrono>
#include <optional>

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

/// @brief A wall-clock budget, started when it is made; checked between steps.
class Deadline {
public:
    /// @param seconds the budget; none: it never passes.
    explicit Deadline(std::optional<double> seconds)
        : seconds_(seconds), start_(std::chrono::steady_clock::now()) {}

    /// @brief True once the budget has been spent.
    bool passed() const {
        return seconds_ && std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() > *seconds_;
    }
    /// @brief The budget, s (0 when there is none).
    double seconds() const { return seconds_.value_or(0); }

private:
    std::optional<double> seconds_;
    std::chrono::steady_clock::time_point start_;
};

/// @brief The exit code for having stopped on @p signal: 128 + the signal's number.
int exitCodeForSignal(int signal);

}  // namespace stepwise::cli
