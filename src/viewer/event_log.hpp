/// @file event_log.hpp
/// @brief `stepwise view --log-events FILE`: one line of text per thing the mouse did to the scene.
///
/// The log lets a script (the viewer's end-to-end test, or a student's own)
/// check what the mouse did without reading pixels. The lines, with lengths
/// in m, velocities in m/s, forces in N, angular velocities in rad/s:
///
///     highlight NAME                        the body under the cursor (or held) changed; "none" when nothing is
///     pick NAME pixel PX PY hit X Y Z KIND   a button went down on a body; KIND is dynamic, kinematic or plane
///     pick none pixel PX PY                  a button went down on empty space
///     push NAME step N at X Y Z force FX FY FZ   step N begins with the push's impulse at that point ("pull" for the right button)
///     release NAME v VX VY VZ w WX WY WZ     the button came up; the held body's velocity and angular velocity
///
/// PX, PY are the cursor's pixel, from the window's top-left corner; the ray
/// is cast through the pixel's centre (PX + ½, PY + ½). Every line is flushed
/// as it is written, so a log is complete even if the viewer is killed.
#pragma once

#include <cstdarg>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/types.hpp"

namespace stepwise::viewer {

/// @brief The event log file; writes nothing unless opened.
class EventLog {
public:
    /// @brief A log that writes nothing until open() is called.
    EventLog() = default;
    EventLog(const EventLog&) = delete;             ///< One owner of the file.
    EventLog& operator=(const EventLog&) = delete;  ///< One owner of the file.
    /// @brief Closes the file.
    ~EventLog() {
        if (file_) std::fclose(file_);
    }

    /// @brief Opens (and truncates) @p path; lines go there from now on.
    /// @throws std::runtime_error when it cannot be written.
    void open(const std::string& path) {
        if (file_) std::fclose(file_);
        file_ = std::fopen(path.c_str(), "w");
        if (!file_) throw std::runtime_error("cannot write the event log '" + path + "'");
    }

    /// @brief True when lines are written somewhere.
    bool enabled() const { return file_ != nullptr; }

    /// @brief Writes one line (printf-style @p format, without the newline) and flushes it.
    [[gnu::format(printf, 2, 3)]] void line(const char* format, ...) {
        if (!file_) return;
        va_list args;
        va_start(args, format);
        std::vfprintf(file_, format, args);
        va_end(args);
        std::fputc('\n', file_);
        std::fflush(file_);
    }

    /// @brief A vector as three numbers separated by spaces, with ten significant digits.
    static std::string vec(const Vec3& v) {
        char text[96];
        std::snprintf(text, sizeof text, "%.10g %.10g %.10g", double(v.x), double(v.y), double(v.z));
        return text;
    }

private:
    std::FILE* file_ = nullptr;
};

}  // namespace stepwise::viewer
