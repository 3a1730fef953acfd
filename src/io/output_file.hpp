/// @file output_file.hpp
/// @brief A file the program writes, whose every failure is reported with the path and the reason.
///
/// `std::fprintf` into a full disk returns an error that is easy to ignore,
/// and a buffered file may fail only when it is flushed or closed. A run
/// that ends with "Trajectory written to out.csv" must mean that every byte
/// reached the file. So a command writes through an OutputFile, asks
/// failed() between steps (a failed write sets the stream's error flag), and
/// ends with close(), which flushes and closes and says what went wrong.
#pragma once

#include <cstdio>
#include <string>

namespace stepwise {

/// @brief A file opened for writing ("w"), or standard output for the path "-".
class OutputFile {
public:
    /// @brief Opens @p path for writing; ok() says whether it could, error() why not.
    explicit OutputFile(std::string path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    bool ok() const { return file_ != nullptr && error_.empty(); }  ///< Open, and no write has failed so far.
    std::FILE* file() const { return file_; }                       ///< Where to write (nullptr when not open).
    const std::string& path() const { return path_; }               ///< As given.

    /// @brief Whether a write has failed since the file was opened; remembers the reason the first time.
    bool failed();

    /// @brief Flushes and closes the file (standard output is only flushed).
    /// @return "" when every byte reached it, else "cannot write PATH: REASON".
    std::string close();

    /// @brief Why the file could not be opened or written ("cannot write PATH: REASON"), or "".
    const std::string& error() const { return error_; }

private:
    std::string path_;
    std::FILE* file_ = nullptr;
    std::string error_;
};

}  // namespace stepwise
