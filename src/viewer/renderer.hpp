/// @file renderer.hpp
/// @brief Draws a World with legacy OpenGL: bodies, planes with a grid, and the debug overlays.
///
/// The renderer only reads the World (through a const Simulation): drawing
/// can never change what is simulated.
#pragma once

#include <cstddef>
#include <optional>

#include "viewer/camera.hpp"
#include "viewer/simulation.hpp"

namespace stepwise::viewer {

/// @brief Which debug drawings are switched on (the C, V, B, I keys) and what to emphasise.
struct DrawOptions {
    bool contacts = false;       ///< C: contact points and their normals.
    bool velocities = false;     ///< V: velocity (cyan) and angular velocity (magenta) vectors.
    bool boundingBoxes = false;  ///< B: bounding boxes; those in a candidate pair in yellow.
    bool islands = false;        ///< I: awake bodies coloured by island, sleeping ones in kSleepingColor.
    std::optional<BodyRef> hovered;  ///< Body under the mouse or held: drawn with a yellow outline.
    std::size_t hoveredSpace = 0;    ///< The space of `hovered` (0 without spaces).
};

/// @brief Colour of a sleeping body when islands are shown (I): a pale blue-grey, "switched off".
inline constexpr Color kSleepingColor{0.55f, 0.6f, 0.7f};

/// @brief Background colour of the 3D view (red, green, blue, 0–1); the screenshot test knows it.
inline constexpr float kBackground[3] = {0.16f, 0.18f, 0.22f};

/// @brief Draws the 3D scene into the current OpenGL context's @p width × @p height viewport.
///
/// Loads the camera's matrices, clears colour and depth, then draws the
/// planes (finite quads with a 1 m grid), every body lit in its scene colour
/// (dynamic spheres with darker meridians so rolling shows, boxes with dark
/// edges, kinematic bodies with diagonal stripes), the joints (lines from
/// each body's centre to its anchor and between the anchors; hinge and motor
/// axes in green; broken joints are gone), and the overlays
/// @p options asks for. Bodies, pairs and contacts come from
/// Simulation::view(): inside the stage walk-through (S) that is the shown
/// snapshot, so the bodies stand where that stage left them; the overlays of
/// that stage are drawn whatever the keys say (bounding boxes and pairs at
/// the broadphase; contacts from the narrowphase on, normals scaled by
/// impulse at resolve-impulses and restitution; velocity vectors after the
/// stages that change velocities), and the bodies' poses at the start of the
/// step are drawn as white ghosts.
///
/// A scene with spaces draws every space, each moved by its
/// SpaceLayout::offset(): side by side, each space's planes only across its
/// own band of x (two OpenGL clip planes), so the floors do not cover one
/// another; overlaid, every body tinted with spaceColor() of its space, and
/// a plane that an earlier space has at the same place drawn once. The names
/// above the spaces and the legend are text: drawOverlay() draws them.
void drawScene(const Simulation& simulation, const OrbitCamera& camera, int width, int height,
               const DrawOptions& options);

}  // namespace stepwise::viewer
