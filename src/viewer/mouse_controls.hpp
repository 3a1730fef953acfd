/// @file mouse_controls.hpp
/// @brief What a mouse button or drag does to the camera: the mapping from pixels to orbit, pan and zoom.
///
/// The GLUT callbacks in viewer.cpp only translate GLUT's button codes into
/// MouseButton and call these functions, so the mapping itself is plain
/// maths (no OpenGL) that the viewer test checks without a window:
///
/// | drag               | camera change                                                   |
/// |--------------------|-----------------------------------------------------------------|
/// | orbit, (dx, dy) px | yaw −= kOrbitPerPixel·dx, pitch += kOrbitPerPixel·dy             |
/// | pan, (dx, dy) px   | target moves so the point at the target's depth follows the cursor |
/// | zoom, dy px        | distance ×= exp(kZoomPerPixel·dy) (down: away, up: closer)        |
/// | wheel click        | distance ×= kZoomPerWheelClick (up: closer) or its inverse (down) |
#pragma once

#include <cmath>

#include "viewer/camera.hpp"

namespace stepwise::viewer {

/// @brief Camera turn per pixel of mouse drag, rad: a drag across a 785-pixel window turns it by 2π.
inline constexpr Real kOrbitPerPixel = Real(0.008);
/// @brief Zoom exponent per pixel of vertical drag: 100 px multiply the distance by e.
inline constexpr Real kZoomPerPixel = Real(0.01);
/// @brief Distance factor of one wheel click towards the target (10 % closer).
inline constexpr Real kZoomPerWheelClick = Real(0.9);

/// @brief A mouse button, independent of GLUT's codes. X11 reports the wheel as buttons 4 and 5.
enum class MouseButton { Left, Middle, Right, WheelUp, WheelDown };

/// @brief What a mouse drag does, decided when the button goes down.
enum class Drag {
    None,   ///< Nothing: no button held, or a wheel click.
    Orbit,  ///< Turn the camera about its target.
    Pan,    ///< Slide the target (and the eye with it).
    Zoom,   ///< Move the eye towards or away from the target.
    Grab,   ///< Push or pull the body under the cursor.
};

/// @brief Modifier keys held when a button went down.
struct Modifiers {
    bool shift = false;  ///< Shift: the left button pans.
    bool ctrl = false;   ///< Ctrl: the left button zooms.
};

/// @brief The drag a button press starts.
///
/// Middle (or Shift + left) pans and Ctrl + left zooms wherever the cursor
/// is; otherwise the left or right button on a dynamic body grabs it (left
/// pushes, right pulls), and on anything else the left button orbits and the
/// right button zooms. Wheel clicks start no drag (see wheelZoom()).
/// @param onDynamicBody the ray through the cursor hits a dynamic body first
inline Drag dragForPress(MouseButton button, Modifiers modifiers, bool onDynamicBody) {
    switch (button) {
        case MouseButton::Middle: return Drag::Pan;
        case MouseButton::Left:
            if (modifiers.shift) return Drag::Pan;
            if (modifiers.ctrl) return Drag::Zoom;
            return onDynamicBody ? Drag::Grab : Drag::Orbit;
        case MouseButton::Right: return onDynamicBody ? Drag::Grab : Drag::Zoom;
        case MouseButton::WheelUp:
        case MouseButton::WheelDown: return Drag::None;
    }
    return Drag::None;
}

/// @brief Moves @p camera for a drag of (@p dx, @p dy) pixels (y down, as the
/// mouse reports it) in a viewport @p viewportHeight pixels high.
///
/// Orbit: dragging right turns the camera left about the target (the scene
/// seems to turn with the mouse), dragging down raises the eye. Pan: the
/// target moves by −dx and +dy pixels' worth of the visible height at the
/// target, 2·d·tan(fovY/2) for @p viewportHeight pixels, so the scene at the
/// target's depth follows the cursor exactly. Zoom: dragging down moves the
/// eye away. A Grab or None drag leaves the camera alone.
inline void dragCamera(OrbitCamera& camera, Drag drag, Real dx, Real dy, int viewportHeight) {
    switch (drag) {
        case Drag::Orbit: camera.orbit(-dx * kOrbitPerPixel, dy * kOrbitPerPixel); break;
        case Drag::Pan: camera.pan(-dx / Real(viewportHeight), dy / Real(viewportHeight)); break;
        case Drag::Zoom: camera.zoom(std::exp(dy * kZoomPerPixel)); break;
        case Drag::Grab:
        case Drag::None: break;
    }
}

/// @brief One wheel click: up multiplies the distance by kZoomPerWheelClick (closer), down divides by it.
inline void wheelZoom(OrbitCamera& camera, MouseButton wheel) {
    if (wheel == MouseButton::WheelUp) camera.zoom(kZoomPerWheelClick);
    if (wheel == MouseButton::WheelDown) camera.zoom(1 / kZoomPerWheelClick);
}

}  // namespace stepwise::viewer
