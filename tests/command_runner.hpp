// Runs a program from a test and captures what it prints (stdout and stderr).
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <stdexcept>
#include <string>

namespace stepwise::test {

/// What a command printed and how it ended.
struct CommandResult {
    int exitCode = -1;    ///< The exit status, or −1 if it did not exit normally.
    std::string output;   ///< stdout and stderr together.
};

/// Runs @p command through the shell and captures its output.
inline CommandResult shell(const std::string& command) {
    CommandResult result;
    std::FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) throw std::runtime_error("cannot run: " + command);
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) result.output.append(buffer, n);
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

}  // namespace stepwise::test
