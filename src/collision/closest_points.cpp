/// @file closest_points.cpp
/// @brief Closest points of two segments (two dot-product equations, then clamping), and of a box to a point.
#include "collision/closest_points.hpp"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

/// Squared lengths below this (m²) make a segment a point.
constexpr Real kDegenerateLengthSquared = Real(1e-24);

Real clamp01(Real x) { return std::clamp(x, Real(0), Real(1)); }

}  // namespace

SegmentClosestPoints closestPointsOfSegments(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
    const Vec3 d1 = q1 - p1;
    const Vec3 d2 = q2 - p2;
    const Vec3 r = p1 - p2;
    const Real a = glm::dot(d1, d1);
    const Real e = glm::dot(d2, d2);
    const Real f = glm::dot(d2, r);

    Real s = 0;
    Real t = 0;
    if (a <= kDegenerateLengthSquared && e <= kDegenerateLengthSquared) {
        // Both are points.
    } else if (a <= kDegenerateLengthSquared) {
        t = clamp01(f / e);  // first is a point: project it onto the second
    } else {
        const Real c = glm::dot(d1, r);
        if (e <= kDegenerateLengthSquared) {
            s = clamp01(-c / a);  // second is a point: project it onto the first
        } else {
            const Real b = glm::dot(d1, d2);
            const Real denominator = a * e - b * b;  // |d1 × d2|² ≥ 0
            s = denominator > Real(0) ? clamp01((b * f - c * e) / denominator) : Real(0);
            t = (b * s + f) / e;
            // t outside the second segment: clamp it, then find the s closest to that end.
            if (t < Real(0)) {
                t = 0;
                s = clamp01(-c / a);
            } else if (t > Real(1)) {
                t = 1;
                s = clamp01((b - c) / a);
            }
        }
    }
    return {p1 + d1 * s, p2 + d2 * t, s, t};
}

PointFromBox pointFromBox(const Vec3& point, const Vec3& centre, const Quat& orientation, const Vec3& halfExtents) {
    PointFromBox seen;
    seen.rotation = glm::mat3_cast(orientation);  // body → world
    seen.local = glm::transpose(seen.rotation) * (point - centre);
    seen.offset = seen.local - glm::clamp(seen.local, -halfExtents, halfExtents);
    return seen;
}

NearestFace nearestFace(const Vec3& local, const Vec3& halfExtents) {
    int axis = 0;
    Real leastInside = halfExtents.x - std::abs(local.x);
    for (int i = 1; i < 3; ++i) {
        const Real inside = halfExtents[i] - std::abs(local[i]);
        if (inside < leastInside) {
            leastInside = inside;
            axis = i;
        }
    }
    NearestFace face;
    face.normal = Vec3(0);
    face.normal[axis] = local[axis] >= Real(0) ? Real(1) : Real(-1);
    face.inside = leastInside;
    return face;
}

}  // namespace stepwise
