/// @file overlay.hpp
/// @brief The text drawn over the 3D view: heads-up display, help, stage walk-through, errors, spaces' names.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "viewer/renderer.hpp"
#include "viewer/simulation.hpp"

namespace stepwise::viewer {

/// @brief What the overlay shows besides the simulation's own numbers.
struct OverlayState {
    bool help = false;          ///< H: the list of controls.
    bool hud = true;            ///< O: the heads-up display (off for clean pictures).
    DrawOptions draw;           ///< Which debug drawings are on (listed in the status line).
    std::string message;        ///< A short notice, e.g. "reloaded …" (empty: none).
    std::string pointed;        ///< What the mouse points at or holds, e.g. "pushing crate" (empty: nothing).
    double framesPerSecond = 0; ///< Measured drawing rate (0: not measured, e.g. in a screenshot).
};

/// @brief The controls, one per line, as the help overlay (H) shows them.
std::vector<std::string> helpLines();

/// @brief The heads-up display's lines: time and step, bodies awake and asleep,
/// contacts, energy and momentum, each stage's time in the last step, and the stages the scene skips.
///
/// With spaces: the shared clock and the layout, then one line per space
/// (spaceLine()), in place of the one World's lines.
std::vector<std::string> hudLines(const Simulation& simulation, const OverlayState& state);

/// @brief Space @p k's line of the heads-up display: its key, name, own time, step, h and
/// integrator and solver, bodies (and soft bodies, when it has any), contacts and energy, and "PAUSED" when it is.
std::string spaceLine(const Simulation& simulation, std::size_t k);

/// @brief Draws the overlay in window pixels over whatever is in the colour buffer.
///
/// With spaces (and the heads-up display on, O): side by side, each space's
/// name in its colour above the top middle of its swept box, where
/// @p camera projects it; overlaid, a legend of the names in their colours.
void drawOverlay(const Simulation& simulation, const OrbitCamera& camera, int width, int height,
                 const OverlayState& state);

}  // namespace stepwise::viewer
