/// @file closest_points.hpp
/// @brief Closest points of two line segments (the edge–edge contact of box_box.cpp).
#pragma once

#include "core/types.hpp"

namespace stepwise {

/// @brief The closest pair of points of two segments, and where they lie on them.
struct SegmentClosestPoints {
    Vec3 onFirst{0, 0, 0};   ///< Point of the first segment, p1 + s·(q1 − p1).
    Vec3 onSecond{0, 0, 0};  ///< Point of the second segment, p2 + t·(q2 − p2).
    Real s = 0;              ///< Parameter on the first segment, 0–1.
    Real t = 0;              ///< Parameter on the second segment, 0–1.
};

/// @brief Closest points of the segments p1q1 and p2q2 (Ericson, *Real-Time Collision Detection*, §5.1.9).
///
/// With d₁ = q1 − p1, d₂ = q2 − p2 and r = p1 − p2, the points
/// L₁(s) = p1 + s·d₁ and L₂(t) = p2 + t·d₂ are closest when the segment
/// between them is perpendicular to both directions:
/// \f[ (L_1(s) - L_2(t))\cdot d_1 = 0, \qquad (L_1(s) - L_2(t))\cdot d_2 = 0. \f]
/// With a = d₁·d₁, b = d₁·d₂, c = d₁·r, e = d₂·d₂, f = d₂·r that is
/// \f[ s = \frac{bf - ce}{ae - b^2}, \qquad t = \frac{bs + f}{e}. \f]
/// For segments, s is clamped to [0, 1] first; if the t it gives falls
/// outside [0, 1], t is clamped and s recomputed for that t (and clamped
/// again). Parallel segments (ae − b² = 0) have many closest pairs: s = 0
/// is taken. A segment of zero length is treated as a point.
SegmentClosestPoints closestPointsOfSegments(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2);

}  // namespace stepwise
