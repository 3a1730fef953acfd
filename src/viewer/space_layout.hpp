/// @file space_layout.hpp
/// @brief Where the viewer draws each space of a scene with `Space` records: side by side, or overlaid.
///
/// The spaces of a scene (src/world/spaces.hpp) are simulations that never
/// touch, and most comparison scenes put their bodies at the same place (the
/// same ball thrown three times from the origin). The physics keeps each
/// space in its own coordinates; only the drawing moves them.
///
/// **Side by side**, space k is drawn shifted along x by an offset d_k, so
/// that the x extents of the spaces follow one another with a gap between:
///
///     d_0 = 0,   d_k = (max_x,k−1 + d_k−1) + gap − min_x,k
///
/// where [min_x,k, max_x,k] is the x extent of space k's *swept box*: the box
/// around every dynamic and kinematic body's bounding box, and every soft
/// body's nodes, at every step seen so far. The viewer first runs a copy of the scene for its Duration to
/// sweep the boxes (Simulation), so the layout of a run stays put: a ball
/// thrown 10 m along x has its 10 m of room from the start, and the other
/// spaces do not slide away as it flies. Past the Duration the boxes keep
/// growing with what the live spaces do, so two spaces never overlap; the
/// layout then widens. Planes are infinite and are left out of the boxes;
/// the renderer draws each space's planes only across its own band of x.
///
/// **Overlaid**, every offset is zero: all spaces at the same place, each
/// drawn in its own colour (spaceColor()).
///
/// Plain arithmetic (no OpenGL): the viewer's test checks it without a window.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "collision/aabb.hpp"
#include "objects/game_object.hpp"
#include "viewer/camera.hpp"
#include "world/world.hpp"

namespace stepwise::viewer {

/// @brief The two ways the viewer draws the spaces of a scene (the L key toggles them).
enum class SpaceArrangement {
    SideBySide,  ///< Each space shifted along x into a band of its own, its name above it.
    Overlaid,    ///< All spaces at the same place, each tinted with its own colour.
};

/// @brief The smallest gap between two spaces' bands side by side, m.
inline constexpr Real kMinSpaceGap = Real(1);
/// @brief The gap between two bands as a share of the widest band: wide scenes get a wider gap.
inline constexpr Real kSpaceGapShare = Real(0.2);
/// @brief Edge of the box drawn for a space that holds no body (only planes), m, about its origin.
inline constexpr Real kEmptySpaceSize = Real(1);
/// @brief The camera's yaw for a scene with spaces, rad: nearly head-on (OrbitCamera's 0.6 rad
/// would foreshorten a row of spaces along x), turned enough to show depth.
inline constexpr Real kSpacesYaw = Real(0.2);
/// @brief Room kept above the spaces for their names and the heads-up display over them, as a
/// share of their height (at least 0.5 m).
inline constexpr Real kNameRoomShare = Real(0.4);
/// @brief How much wider than the spaces the view is: a margin around them.
inline constexpr Real kSpacesFrameMargin = Real(1.15);

/// @brief Space @p k's colour: its tint when overlaid, its name's colour above it and in the legend.
Color spaceColor(std::size_t k);

/// @brief The space that key @p key pauses and resumes: '1' → 0, …, '9' → 8; nothing for any other key.
std::optional<std::size_t> spaceForKey(unsigned char key);

/// @brief Each space's swept box, and the offset it is drawn at.
class SpaceLayout {
public:
    /// @brief Forgets every box: @p spaces spaces, none seen yet.
    void reset(std::size_t spaces);

    /// @brief Grows space @p space's swept box by the box of every dynamic and kinematic body of @p world,
    /// and of every soft body's nodes (each a sphere of its node radius).
    void grow(std::size_t space, const World& world);

    /// @brief Draws the spaces side by side or overlaid.
    void arrange(SpaceArrangement arrangement) { arrangement_ = arrangement; }
    /// @brief How the spaces are drawn.
    SpaceArrangement arrangement() const { return arrangement_; }

    /// @brief Number of spaces.
    std::size_t size() const { return boxes_.size(); }

    /// @brief Where space @p space's origin is drawn, m: (d_k, 0, 0) side by side, zero overlaid.
    Vec3 offset(std::size_t space) const;

    /// @brief Space @p space's swept box in its own coordinates (a kEmptySpaceSize cube about
    /// the origin while no body was seen).
    Aabb bounds(std::size_t space) const;

    /// @brief The x range space @p space owns side by side, in its own coordinates: its swept box's
    /// widened by half the gap on each side (every x overlaid). Its planes are drawn, and picked, there.
    /// @return the range as {min x, max x}, m
    std::pair<Real, Real> band(std::size_t space) const;

    /// @brief The box around every space as drawn (each swept box moved by its offset): what the camera frames.
    Aabb drawnBox() const;

    /// @brief The gap between two neighbouring bands, m: kSpaceGapShare of the widest, at least kMinSpaceGap.
    Real gap() const { return gap_; }

private:
    void place();  // recomputes gap_ and offsets_ from the boxes

    std::vector<Aabb> boxes_;
    std::vector<char> seen_;  // 1 once space k has had a body in its box
    std::vector<Real> offsets_;
    Real gap_ = kMinSpaceGap;
    SpaceArrangement arrangement_ = SpaceArrangement::SideBySide;
};

/// @brief The camera that frames every space as drawn (SpaceLayout::drawnBox(), with room above
/// for the names) in a view of aspect ratio @p aspect = width / height, looking nearly head-on (kSpacesYaw).
///
/// A row of spaces is wide and low, so the box's width is fitted into the
/// horizontal field of view and its height into the vertical one (whichever
/// needs the greater distance), not its bounding sphere as cameraForScene() does:
/// d = margin · max(w / (2·tan(φ/2)·aspect), h / (2·tan(φ/2))) + depth / 2.
inline OrbitCamera cameraForSpaces(const SpaceLayout& layout, Real aspect) {
    Aabb box = layout.drawnBox();
    box.max.y += std::max(Real(0.5), kNameRoomShare * (box.max.y - box.min.y));
    OrbitCamera camera;
    camera.yaw = kSpacesYaw;
    camera.target = (box.min + box.max) / Real(2);
    const Real tanHalf = std::tan(camera.fovY / 2);
    const Vec3 size = box.max - box.min;
    const Real fit = std::max(size.x / (2 * tanHalf * std::max(aspect, Real(0.1))), size.y / (2 * tanHalf));
    camera.distance = std::max(Real(1), kSpacesFrameMargin * fit + size.z / 2);
    return camera;
}

}  // namespace stepwise::viewer
