/// @file closest_points.cpp
/// @brief Closest points of two segments (two dot-product equations, then clamping), of a box to a point, of a triangle to a point.
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

TriangleClosestPoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    // The regions in Ericson's order (§5.1.5): corner a, corner b, edge ab, corner c, edge ac,
    // edge bc, then the face. Each weight triple says where the point is.
    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    const Vec3 ap = p - a;
    const Real d1 = glm::dot(ab, ap);
    const Real d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return {a, {1, 0, 0}};

    const Vec3 bp = p - b;
    const Real d3 = glm::dot(ab, bp);
    const Real d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return {b, {0, 1, 0}};

    const Real vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const Real v = d1 / (d1 - d3);
        return {a + v * ab, {1 - v, v, 0}};
    }

    const Vec3 cp = p - c;
    const Real d5 = glm::dot(ab, cp);
    const Real d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return {c, {0, 0, 1}};

    const Real vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const Real w = d2 / (d2 - d6);
        return {a + w * ac, {1 - w, 0, w}};
    }

    const Real va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const Real w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {b + w * (c - b), {0, 1 - w, w}};
    }

    const Real denominator = 1 / (va + vb + vc);
    const Real v = vb * denominator;
    const Real w = vc * denominator;
    return {a + v * ab + w * ac, {1 - v - w, v, w}};
}

}  // namespace stepwise
