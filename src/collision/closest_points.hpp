/// @file closest_points.hpp
/// @brief Closest points: of two line segments (the edge–edge contact of box_box.cpp), of a box to a point (sphere_box.cpp,
/// continuous.cpp), and of a triangle to a point (mesh_contacts.cpp).
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

/// @brief A point seen from an oriented box: where it is in the box's frame, and how far outside.
struct PointFromBox {
    Mat3 rotation{1};         ///< The box's rotation, box frame → world.
    Vec3 local{0, 0, 0};      ///< The point in the box frame, Rᵀ(p − b), m.
    Vec3 offset{0, 0, 0};     ///< From the box's closest point to the point, box frame, m (zero inside).
};

/// @brief The point @p point in the frame of the box (centre @p centre, rotation
/// @p orientation, half edges @p halfExtents), and its offset from the box's closest point.
///
/// In its own frame the box is [−e, +e]; clamping each coordinate of the
/// point c′ = Rᵀ(p − b) to [−eᵢ, +eᵢ] gives the closest point q of the box
/// (Ericson, *Real-Time Collision Detection*, §5.1.4), and c′ − q is zero
/// exactly when the point is inside. The narrowphase (sphere_box.cpp) and the
/// continuous stage's separation (continuous.cpp) both start from it.
PointFromBox pointFromBox(const Vec3& point, const Vec3& centre, const Quat& orientation, const Vec3& halfExtents);

/// @brief The way out of a box for a point inside it: the nearest face.
struct NearestFace {
    Vec3 normal{0, 1, 0};  ///< Unit, box frame, pointing out of the box through that face.
    Real inside = 0;       ///< eᵢ − |c′ᵢ|: how far inside that face the point is, m.
};

/// @brief The face of the box (half edges @p halfExtents) nearest to @p local, a point
/// inside it in the box's frame: the axis i with the least eᵢ − |c′ᵢ| (the first on a tie).
///
/// A point inside gives no closest-point direction (the offset is zero), so
/// a sphere whose centre is inside a box leaves through this face.
NearestFace nearestFace(const Vec3& local, const Vec3& halfExtents);

/// @brief The point of a triangle closest to a point, with its barycentric weights.
///
/// The weights say which feature holds it: all three above 0, the face; one
/// of them 0, the edge opposite that corner; two of them 0, the remaining corner.
struct TriangleClosestPoint {
    Vec3 point{0, 0, 0};         ///< The closest point of the triangle, m.
    Real weights[3] = {1, 0, 0}; ///< point = w₀·a + w₁·b + w₂·c, each in [0, 1], summing to 1.
};

/// @brief The point of the triangle @p a, @p b, @p c closest to @p p (Ericson, *Real-Time Collision
/// Detection*, §5.1.5).
///
/// The plane of the triangle is cut by the lines through its edges and the
/// perpendiculars at its corners into seven *Voronoi regions*: three of the
/// corners, three of the edges, one of the face. The tests go from the
/// corners to the edges to the face, each by dot products of ab = b − a,
/// ac = c − a and the vectors to p: with d₁ = ab·ap and d₂ = ac·ap, p lies in
/// a's region when d₁ ≤ 0 and d₂ ≤ 0; in ab's when the signed area
/// vc = d₁d₄ − d₃d₂ (d₃ = ab·bp, d₄ = ac·bp) is ≤ 0 with 0 ≤ d₁ and d₃ ≤ 0, and
/// its point is then a + (d₁/(d₁ − d₃))·ab; and so on. In the face region the
/// point is p's projection, a + v·ab + w·ac with v = vb/(va + vb + vc),
/// w = vc/(va + vb + vc). A triangle of zero area is not handled (a mesh has none).
TriangleClosestPoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace stepwise
