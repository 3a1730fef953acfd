/// @file output_file.cpp
/// @brief OutputFile (output_file.hpp): every write reported.
#include "io/output_file.hpp"

#include <cerrno>
#include <cstring>

namespace stepwise {

namespace {

std::string cannotWrite(const std::string& path, int error) {
    return "cannot write " + (path == "-" ? std::string("standard output") : "'" + path + "'") + ": " +
           std::strerror(error);
}

}  // namespace

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
    errno = 0;
    file_ = path_ == "-" ? stdout : std::fopen(path_.c_str(), "w");
    if (!file_) error_ = cannotWrite(path_, errno);
}

OutputFile::~OutputFile() {
    if (file_ && file_ != stdout) std::fclose(file_);
}

bool OutputFile::failed() {
    if (!error_.empty()) return true;
    if (file_ && std::ferror(file_)) {
        error_ = cannotWrite(path_, errno ? errno : EIO);
        return true;
    }
    return false;
}

std::string OutputFile::close() {
    if (!file_) return error_;
    failed();  // a write that failed before: its reason comes first
    errno = 0;
    const bool flushed = std::fflush(file_) == 0;
    if (!flushed && error_.empty()) error_ = cannotWrite(path_, errno ? errno : EIO);
    if (file_ != stdout) {
        errno = 0;
        if (std::fclose(file_) != 0 && error_.empty()) error_ = cannotWrite(path_, errno ? errno : EIO);
    } else if (!error_.empty()) {
        std::clearerr(stdout);  // reported here, by the caller: not again when the program ends
    }
    file_ = nullptr;
    return error_;
}

}  // namespace stepwise
