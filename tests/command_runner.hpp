// Runs a program from a test and captures what it prints (stdout and stderr).
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
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

#ifdef STEPWISE_CLI_PATH
/// Runs `stepwise ARGS` (the program built with the tests) and captures what it prints.
inline CommandResult runStepwise(const std::string& args) {
    return shell(std::string("'") + STEPWISE_CLI_PATH + "' " + args);
}
#endif

/// A scratch file in the system's temporary folder, named after the test process so that
/// parallel test runs do not share it, and removed at scope exit.
struct TempFile {
    std::filesystem::path path;  ///< Where the file is.
    /// Names the file; writes @p contents into it unless they are empty.
    explicit TempFile(const std::string& name, const std::string& contents = "")
        : path(std::filesystem::temp_directory_path() /
               ("stepwise-test-" + std::to_string(::getpid()) + "-" + name)) {
        if (!contents.empty()) std::ofstream(path, std::ios::binary) << contents;
    }
    ~TempFile() { std::filesystem::remove(path); }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    /// The path in single quotes, for a shell command line.
    std::string quoted() const { return "'" + path.string() + "'"; }
};

}  // namespace stepwise::test
