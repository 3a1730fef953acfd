/// @file pile_metrics.hpp
/// @brief Worst overlaps of a pile of boxes (with each other, static boxes and planes), escapes and rest.
///
/// Judges the box pile and the ragdoll of `stepwise-bench bullet` from body
/// states alone, both engines by the same code. Box pairs are found by
/// sorting the centres along x and testing only boxes whose bounding spheres
/// can touch (sweep and prune on one axis, Ericson 7.5); each such pair's
/// depth is the separating-axis overlap (boxBoxOverlap()).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "overlap_depth.hpp"
#include "scenario_metrics.hpp"

namespace stepwise::bench {

/// @brief The dynamic boxes' half edge lengths, in the scene's order, m.
/// @throws std::invalid_argument naming the first dynamic body that is not a box.
std::vector<Vec3> boxHalfExtentsOf(const Scene& scene);

/// @brief Worst overlap between boxes and of boxes with the level (static boxes and planes).
class BoxPileMeter {
public:
    /// @param halfExtents each dynamic box's half edge lengths, m (boxHalfExtentsOf())
    /// @param walls       the level's static boxes (staticBoxesOf())
    /// @param planes      the level's planes
    BoxPileMeter(std::vector<Vec3> halfExtents, std::vector<OrientedBox> walls, std::vector<CollisionPlane> planes = {});

    /// @brief Measures one step's overlaps and keeps the worst.
    void observe(std::span<const BodyState> bodies);
    Real worstBoxOverlap() const { return worstBox_; }    ///< Deepest box–box overlap seen, m.
    Real worstWallOverlap() const { return worstWall_; }  ///< Deepest box–level overlap seen, m.
    Real lastBoxOverlap() const { return lastBox_; }      ///< Deepest box–box overlap of the last step observed, m.
    Real lastWallOverlap() const { return lastWall_; }    ///< Deepest box–level overlap of the last step observed, m.
    /// @brief Boxes whose centre has left the level (outsideLevel()) or is behind a plane.
    std::size_t escaped(std::span<const BodyState> bodies) const;

private:
    std::vector<Vec3> half_;
    std::vector<Real> reach_;  ///< Bounding-sphere radius of each box, |h|, m.
    std::vector<OrientedBox> walls_;
    std::vector<CollisionPlane> planes_;
    std::vector<std::uint32_t> order_;  ///< Boxes sorted by centre x (kept between steps: no allocation).
    Real largestReach_ = 0;
    Real worstBox_ = 0, worstWall_ = 0, lastBox_ = 0, lastWall_ = 0;
};

/// @brief The largest speed of any body's centre, m/s: a pile at rest has this near 0.
Real largestSpeed(std::span<const BodyState> bodies);

/// @brief The largest angular speed of any body, rad/s.
Real largestSpin(std::span<const BodyState> bodies);

}  // namespace stepwise::bench
