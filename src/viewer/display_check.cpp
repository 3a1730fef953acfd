/// @file display_check.cpp
/// @brief The X display probe. Kept in its own file: Xlib's macros (None, Bool, Status, …) must not leak into other code.
#include "viewer/display_check.hpp"

#include <cstdlib>

#ifdef STEPWISE_VIEWER_X11
#include <GL/glx.h>
#include <X11/Xlib.h>
#endif

namespace stepwise::viewer {

DisplayCheck::DisplayCheck() {
    const char* name = std::getenv("DISPLAY");
    if (name == nullptr || *name == '\0') {
        problem_ = "DISPLAY is not set: there is no X server to open a window on";
        return;
    }
#ifdef STEPWISE_VIEWER_X11
    Display* display = XOpenDisplay(nullptr);
    if (display == nullptr) {
        problem_ = "cannot open the X display '" + std::string(name) + "' (is the X server running, and may you use it?)";
        return;
    }
    connection_ = display;
    int errorBase = 0, eventBase = 0;
    if (!glXQueryExtension(display, &errorBase, &eventBase)) {
        problem_ = "the X display '" + std::string(name) + "' has no GLX extension: it cannot show OpenGL";
    }
#endif
}

DisplayCheck::~DisplayCheck() {
#ifdef STEPWISE_VIEWER_X11
    if (connection_ != nullptr) XCloseDisplay(static_cast<Display*>(connection_));
#endif
}

}  // namespace stepwise::viewer
