/// @file convex_hull.hpp
/// @brief The convex hull of a cloud of points, as faces, edges and vertices (qhull does the search).
///
/// A `Shape=Hull` body is "the smallest convex solid that holds these
/// points". Finding it is a classic algorithm of its own (Quickhull: Barber,
/// Dobkin and Huhdanpaa, 1996), and not one this course teaches, so the
/// engine asks qhull (libqhull_r, the reentrant C library: every call gets its
/// own `qhT`, nothing global, so two threads may build hulls at once).
/// What this file adds is what a physics engine needs from the answer:
///
/// - coplanar triangles merged into one polygon per flat face (a cube has 6
///   faces of 4 vertices), so contacts can clip face against face;
/// - every face's outward unit normal and its plane offset;
/// - every face's vertex loop counter-clockwise seen from outside, so
///   (v₁ − v₀) × (v₂ − v₀) points along the normal;
/// - each edge once (SAT's edge–edge axes, the viewer's wireframe);
/// - the volume (objects/mass_properties.hpp) and the bounding radius.
///
/// The hull is returned in the frame of the points; the scene loader then
/// moves it to its centre of mass and principal axes (moveToPrincipalFrame()).
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

#include "objects/shapes.hpp"

namespace stepwise {

/// @brief Most points buildConvexHull() accepts: a hull of more is not a teaching scene,
/// and each contact's support search runs over every vertex.
inline constexpr std::size_t kMaxHullPoints = 100000;

/// @brief Why a cloud of points has no usable hull.
enum class HullProblem : std::uint8_t {
    TooFewPoints,   ///< Fewer than 4 points: no solid can be spanned.
    TooManyPoints,  ///< More than kMaxHullPoints.
    NotFinite,      ///< A coordinate is NaN or infinite.
    Flat,           ///< All points coplanar, collinear or coincident: the hull has no volume.
    Failed,         ///< qhull stopped for another reason (its message is kept).
};

/// @brief Thrown by buildConvexHull(); the scene loader turns it into file:line:column.
class HullError : public std::runtime_error {
public:
    /// @brief An error of kind @p problem, with @p what saying it in words.
    HullError(HullProblem problem, const std::string& what) : std::runtime_error(what), problem_(problem) {}
    /// @brief Which way the points failed.
    HullProblem problem() const { return problem_; }

private:
    HullProblem problem_;
};

/// @brief The convex hull of @p points, in their own frame.
///
/// Points inside the hull are dropped; only the hull's corners become
/// `vertices`. qhull's messages go nowhere near stderr: a failure becomes a
/// HullError whose text says why.
/// @throws HullError for fewer than 4 points, more than kMaxHullPoints, a
///         non-finite coordinate, points without volume, or a qhull failure.
ConvexHull buildConvexHull(std::span<const Vec3> points);

}  // namespace stepwise
