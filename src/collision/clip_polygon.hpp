/// @file clip_polygon.hpp
/// @brief Sutherland–Hodgman: cut a convex polygon by a plane, keeping track of which edges made each vertex.
#pragma once

#include <cstdint>

#include "core/types.hpp"

namespace stepwise {

/// Most vertices a clipped quadrilateral can have: each of the four side
/// planes of a rectangle can add at most one vertex to a convex polygon,
/// so a quad clipped by a rectangle has at most 4 + 4 = 8.
inline constexpr int kMaxClipVertices = 8;

/// @brief A polygon vertex and the two polygon edges that meet at it.
///
/// Polygon edge m runs from vertex m to vertex m + 1. Each edge carries a
/// small label (the caller decides what labels mean); a vertex records the
/// label of the edge arriving at it and of the edge leaving it. Clipping
/// keeps these labels meaningful, so a vertex is named by the two features
/// whose intersection it is, whatever its position in the array.
struct ClipVertex {
    Vec3 position{0, 0, 0};    ///< World position, m.
    std::uint8_t inEdge = 0;   ///< Label of the edge arriving at this vertex.
    std::uint8_t outEdge = 0;  ///< Label of the edge leaving this vertex.
};

/// @brief Clips a convex polygon to the half-space n·p ≤ offset (one Sutherland–Hodgman pass).
///
/// Walk the edges a → b of the polygon. With the signed distances
/// d = n·p − offset of both ends:
///
/// | a      | b       | output                                   |
/// |--------|---------|------------------------------------------|
/// | inside | inside  | b                                        |
/// | inside | outside | the crossing point (edge a→b, then plane) |
/// | outside| inside  | the crossing point (plane, then edge a→b), then b |
/// | outside| outside | nothing                                  |
///
/// The crossing point is a + (b − a)·d_a/(d_a − d_b). The new polygon edge
/// that runs along the plane gets the label @p planeLabel.
///
/// A vertex counts as inside up to @p tolerance beyond the plane: a corner
/// lying exactly on the plane (equal boxes stacked flush) then stays one
/// vertex with its own labels, instead of turning, by rounding, into two
/// nearly coincident crossing points whose labels change from step to step.
///
/// Reference: Sutherland & Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974;
/// Ericson, *Real-Time Collision Detection*, §8.3.4.
/// @param in         the polygon, convex, vertices in order (either winding)
/// @param count      number of vertices in @p in (at most kMaxClipVertices − 1)
/// @param normal     plane normal, pointing to the side that is cut away
/// @param offset     plane offset: the plane is n·p = offset
/// @param planeLabel label of the polygon edge created along the plane
/// @param tolerance  how far beyond the plane a vertex still counts as inside, m
/// @param out        the clipped polygon (room for kMaxClipVertices)
/// @return the number of vertices written to @p out (0 when all were cut away)
int clipPolygon(const ClipVertex* in, int count, const Vec3& normal, Real offset, std::uint8_t planeLabel,
                Real tolerance, ClipVertex* out);

}  // namespace stepwise
