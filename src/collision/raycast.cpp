/// @file raycast.cpp
/// @brief Ray against sphere, oriented box and plane: the first point where the ray enters each.
#include "collision/raycast.hpp"

#include <cmath>
#include <limits>

namespace stepwise {

namespace {

/// The answer for a ray that starts inside the shape (see raycast.hpp).
RayShapeHit startsInside(const Vec3& direction) { return {0, -direction}; }

}  // namespace

std::optional<RayShapeHit> intersectRaySphere(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                              const Vec3& centre, Real radius) {
    const Vec3 m = origin - centre;
    const Real b = glm::dot(m, direction);
    const Real c = glm::dot(m, m) - radius * radius;
    if (c <= 0) return startsInside(direction);
    if (b > 0) return std::nullopt;  // outside and heading away
    const Real discriminant = b * b - c;
    if (discriminant < 0) return std::nullopt;  // the line passes the sphere by
    const Real t = -b - std::sqrt(discriminant);
    if (t > maxDistance) return std::nullopt;
    return RayShapeHit{t, (origin + t * direction - centre) / radius};
}

std::optional<RayShapeHit> intersectRayBox(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                           const Vec3& centre, const Quat& orientation, const Vec3& halfExtents) {
    const Quat toBody = glm::conjugate(orientation);
    const Vec3 o = toBody * (origin - centre);
    const Vec3 d = toBody * direction;
    Real enter = 0;  // entries behind the origin do not count: t ≥ 0
    Real exit = maxDistance;
    int enterAxis = -1;  // stays −1 when the origin is inside every slab
    Real enterSign = 0;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d[i]) < kRayParallelTolerance) {
            if (std::abs(o[i]) > halfExtents[i]) return std::nullopt;  // parallel to the slab and outside it
            continue;
        }
        const Real near = (-std::copysign(halfExtents[i], d[i]) - o[i]) / d[i];  // the face the ray meets first
        const Real far = (std::copysign(halfExtents[i], d[i]) - o[i]) / d[i];
        if (near > enter) {
            enter = near;
            enterAxis = i;
            enterSign = d[i] > 0 ? Real(-1) : Real(1);  // that face's outward normal is against the ray
        }
        if (far < exit) exit = far;
        if (enter > exit) return std::nullopt;
    }
    if (enterAxis < 0) return startsInside(direction);
    Vec3 normal(0);
    normal[enterAxis] = enterSign;
    return RayShapeHit{enter, orientation * normal};
}

std::optional<RayShapeHit> intersectRayPlane(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                             const Vec3& point, const Vec3& normal) {
    const Real height = glm::dot(origin - point, normal);
    if (height <= 0) return startsInside(direction);  // in the solid half-space
    const Real approach = -glm::dot(direction, normal);
    if (approach <= 0) return std::nullopt;  // parallel, or heading away
    const Real t = height / approach;
    if (t > maxDistance) return std::nullopt;
    return RayShapeHit{t, normal};
}

}  // namespace stepwise
