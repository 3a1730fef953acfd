/// @file display_check.hpp
/// @brief Can a window be opened? Asked before freeglut is, because freeglut exits the process when it cannot.
#pragma once

#include <optional>
#include <string>

namespace stepwise::viewer {

/// @brief Checks that an OpenGL window can be opened here, and holds the answer.
///
/// `glutInit` and `glutCreateWindow` end the whole process (a terse message,
/// exit code 1) when there is no X display or the display has no GLX
/// extension. This check asks the same questions first, with Xlib
/// (`XOpenDisplay`) and GLX (`glXQueryExtension`), so the viewer can explain
/// what is missing and how to run headless instead. Without Xlib at build
/// time it only checks that `DISPLAY` is set.
///
/// The check's own connection stays open until the object is destroyed:
/// an X server such as Xvfb *resets* when its last client disconnects, and
/// a connection attempted during the reset (freeglut's, right after a
/// closed check) fails. Destroy it once the window exists.
class DisplayCheck {
public:
    /// @brief Opens the display named by `DISPLAY` and asks for GLX.
    DisplayCheck();
    /// @brief Closes the check's connection.
    ~DisplayCheck();
    DisplayCheck(const DisplayCheck&) = delete;             ///< Owns a connection: not copyable.
    DisplayCheck& operator=(const DisplayCheck&) = delete;  ///< Owns a connection: not copyable.

    /// @brief Why no window can be opened, or nothing when one can.
    const std::optional<std::string>& problem() const { return problem_; }

private:
    std::optional<std::string> problem_;
    void* connection_ = nullptr;  // the Xlib Display*, kept opaque so Xlib's macros stay in the .cpp
};

}  // namespace stepwise::viewer
