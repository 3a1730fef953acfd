/// @file viewer.hpp
/// @brief `stepwise view`: the freeglut window onto a scene, and its headless screenshot mode.
#pragma once

#include "viewer/view_options.hpp"

namespace stepwise::viewer {

/// @brief Runs `stepwise view` with the parsed @p options. Returns the exit code.
///
/// Interactive: opens a window, simulates at the scene's fixed time step
/// (FixedStepClock) and draws after every frame until Esc or the window is
/// closed. With `--screenshot PATH`: simulates to `--at T` exactly as
/// `stepwise run --duration T` does, draws one frame, reads it back with
/// `glReadPixels` from the back buffer, writes it as a PNG and returns.
///
/// Exit codes: 0 success; 1 the simulation failed (non-finite state) before T;
/// 2 bad scene file, or no window can be opened (the message says why and how
/// to run under `xvfb-run`), or the screenshot could not be written.
int runViewer(const ViewOptions& options);

}  // namespace stepwise::viewer
