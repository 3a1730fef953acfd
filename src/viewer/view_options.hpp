/// @file view_options.hpp
/// @brief What `stepwise view` is asked to do: the viewer's options, parsed by the command line (src/app/options.cpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace stepwise::viewer {

/// @brief Options of `stepwise view` (the viewer in src/viewer/, built when STEPWISE_VIEWER is ON).
struct ViewOptions {
    std::string scenePath;                     ///< Scene file; the default scene when not given.
    std::optional<std::string> screenshotPath; ///< --screenshot PATH: draw one frame into this PNG and exit.
    double at = 0;                             ///< --at T: simulated time of the screenshot, s (≥ 0).
    int width = 960;                           ///< --size WxH: window width, pixels.
    int height = 600;                          ///< --size WxH: window height, pixels.
    std::optional<std::string> dumpStatePath;  ///< --dump-state PATH: the state drawn, as `run --csv` writes it.
    std::string keys;                          ///< --keys KEYS: keys pressed before the screenshot (e.g. "CV").
    std::optional<std::string> logEventsPath;  ///< --log-events PATH: one line per pick, push and release (window only).
    std::optional<std::size_t> stage;          ///< --stage K: show the state after the K-th stage run of the next step (S).
    bool help = false;                         ///< --help: print the usage and the controls, open nothing.
};

/// @brief The window's controls, one per line: the help overlay (H) shows them, and so does
/// `stepwise view --help` (src/app/options.cpp), so the two cannot disagree.
inline constexpr const char* kViewerControls[] = {
        "Controls (H hides this)",
        "  mouse, left drag      orbit the camera around its target",
        "  mouse, middle drag    pan (or Shift + left drag)",
        "  wheel / right drag    zoom (or Ctrl + left drag)",
        "  left button on body   push it at that point (a force along the mouse ray)",
        "  right button on body  pull it at that point (towards the camera)",
        "  Space   pause / resume",
        "  N       one step (pauses); during S, the end of the step",
        "  S       one stage: the state after the next stage of the step, and what it produced",
        "  Shift+S the same, skipping the substeps between the first and the last",
        "  + / -   time scale x2 / x0.5 (wall-clock speed; the time step stays the scene's)",
        "  R       reload the scene file (a broken file shows its errors, the last good scene stays)",
        "  C       contact points and normals",
        "  V       velocity (cyan) and angular velocity (magenta) vectors",
        "  B       bounding boxes; the broadphase's candidate pairs in yellow",
        "  I       islands: awake bodies coloured by island, sleeping bodies in pale blue-grey",
        "  F       frame the scene again (reset the camera)",
        "  O       hide / show the on-screen text",
        "  P       save a picture of the window (stepwise-SCENE-stepN.png, current directory)",
        "  L       a scene with spaces: side by side / overlaid, each space in its own colour",
        "  1 - 9   a scene with spaces: pause / resume space 1 to 9 (the others run on)",
        "  Esc, Q  quit",
        "Kinematic bodies wear diagonal stripes; joints are drawn as lines to their anchors.",
};

}  // namespace stepwise::viewer
