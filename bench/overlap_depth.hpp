/// @file overlap_depth.hpp
/// @brief How deep two solids overlap: oriented boxes and spheres, for the benchmark's meters.
///
/// The meters of the side-by-side benchmark (scenario_metrics.hpp,
/// pile_metrics.hpp) judge both engines from body states alone, so they
/// compute overlaps themselves, from the geometry, without either engine's
/// collision code:
///
/// - a sphere (centre c, radius r) and a box: r − d(c), where d is the signed
///   distance of c from the box (negative inside: minus the distance to the
///   nearest face), Ericson, "Real-Time Collision Detection", 5.1.3;
/// - two boxes: the separating-axis test (Ericson 4.4.1) over the 15 axes
///   (3 face normals of each box and the 9 cross products of their edges).
///   Along a unit axis L the boxes' shadows overlap by
///   \f[ o(L) = r_A(L) + r_B(L) - |(c_B - c_A)\cdot L|, \qquad r(L) = \sum_i h_i\,|u_i \cdot L| \f]
///   and the depth is the least o(L). For two convex polyhedra the shortest
///   push that parts them lies along one of these axes, so that least
///   overlap is the penetration depth; negative means apart by at least that much.
#pragma once

#include <span>
#include <vector>

#include "core/types.hpp"
#include "world/scene.hpp"

namespace stepwise::bench {

/// @brief A box in world space: centre, rotation (body to world) and half edge lengths, m.
struct OrientedBox {
    Vec3 centre{0, 0, 0};         ///< m.
    Quat orientation{1, 0, 0, 0}; ///< Body to world.
    Vec3 halfExtents{0.5, 0.5, 0.5};  ///< m.
};

/// @brief Signed distance of @p point from @p box, m: positive outside, negative inside.
Real signedDistance(const Vec3& point, const OrientedBox& box);

/// @brief How deep a sphere of centre @p centre and radius @p radius overlaps @p box, m (negative: apart).
Real sphereBoxOverlap(const Vec3& centre, Real radius, const OrientedBox& box);

/// @brief Penetration depth of two boxes by the separating-axis test, m (negative: apart).
Real boxBoxOverlap(const OrientedBox& a, const OrientedBox& b);

/// @brief The scene's KinematicsObjects as boxes; they must be boxes that do not move.
/// @throws std::invalid_argument naming the first one that is not a box or has a velocity.
std::vector<OrientedBox> staticBoxesOf(const Scene& scene);

/// @brief Whether @p point has left a level built of @p walls: it is inside one
/// of them, or outside the box that bounds them all (it went over or through).
/// A level that is a floor alone is bounded by the floor's own box: this
/// question is for containers, whose walls reach above what they hold.
bool outsideLevel(const Vec3& point, std::span<const OrientedBox> walls);

}  // namespace stepwise::bench
