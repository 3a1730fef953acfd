/// @file overlap_depth.cpp
/// @brief Sphere–box and box–box overlap depths (overlap_depth.hpp says which maths).
#include "overlap_depth.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace stepwise::bench {

namespace {

/// A cross product of two edges shorter than this is two parallel edges: no new axis,
/// (the face normals already cover that direction).
constexpr Real kParallelEdges = Real(1e-9);

/// The box's axes in world space (the columns of its rotation).
std::array<Vec3, 3> axesOf(const OrientedBox& box) {
    const Mat3 r = glm::mat3_cast(box.orientation);
    return {r[0], r[1], r[2]};
}

/// r(L) = Σ h_i |u_i · L|: half the box's shadow on the unit axis L.
Real halfShadow(const std::array<Vec3, 3>& axes, const Vec3& half, const Vec3& l) {
    return half.x * std::abs(glm::dot(axes[0], l)) + half.y * std::abs(glm::dot(axes[1], l)) +
           half.z * std::abs(glm::dot(axes[2], l));
}

}  // namespace

Real signedDistance(const Vec3& point, const OrientedBox& box) {
    const Vec3 local = glm::conjugate(box.orientation) * (point - box.centre);
    const Vec3 beyond = glm::abs(local) - box.halfExtents;  // > 0 along an axis where the point is outside the slab
    const Vec3 outside = glm::max(beyond, Vec3(0, 0, 0));
    const Real inside = std::min(std::max({beyond.x, beyond.y, beyond.z}), Real(0));  // −(distance to nearest face)
    return glm::length(outside) + inside;
}

Real sphereBoxOverlap(const Vec3& centre, Real radius, const OrientedBox& box) {
    return radius - signedDistance(centre, box);
}

Real boxBoxOverlap(const OrientedBox& a, const OrientedBox& b) {
    const std::array<Vec3, 3> ua = axesOf(a), ub = axesOf(b);
    const Vec3 between = b.centre - a.centre;
    Real least = std::numeric_limits<Real>::infinity();
    const auto test = [&](const Vec3& axis) {
        const Real length = glm::length(axis);
        if (length < kParallelEdges) return;
        const Vec3 l = axis / length;
        const Real overlap = halfShadow(ua, a.halfExtents, l) + halfShadow(ub, b.halfExtents, l) - std::abs(glm::dot(between, l));
        least = std::min(least, overlap);
    };
    for (const Vec3& u : ua) test(u);
    for (const Vec3& u : ub) test(u);
    for (const Vec3& u : ua) {
        for (const Vec3& v : ub) test(glm::cross(u, v));
    }
    return least;
}

std::vector<OrientedBox> staticBoxesOf(const Scene& scene) {
    std::vector<OrientedBox> boxes;
    for (const KinematicsObject& k : scene.kinematics) {
        if (k.shape != Shape::Box || k.velocity != Vec3(0, 0, 0) || k.angularVelocity != Vec3(0, 0, 0)) {
            throw std::invalid_argument(k.name + ": the benchmark's meters take only static boxes "
                                                 "(a KinematicsObject with Shape=Box and no velocity)");
        }
        boxes.push_back({k.position, k.orientation, k.halfExtents()});
    }
    return boxes;
}

bool outsideLevel(const Vec3& point, std::span<const OrientedBox> walls) {
    if (walls.empty()) return false;
    Vec3 lo(std::numeric_limits<Real>::infinity()), hi(-std::numeric_limits<Real>::infinity());
    for (const OrientedBox& w : walls) {
        // The box's world bounds: its centre ± Σ h_i |u_i| (Ericson 4.2.6).
        const Mat3 r = glm::mat3_cast(w.orientation);
        const Vec3 reach = glm::abs(r[0]) * w.halfExtents.x + glm::abs(r[1]) * w.halfExtents.y +
                           glm::abs(r[2]) * w.halfExtents.z;
        lo = glm::min(lo, w.centre - reach);
        hi = glm::max(hi, w.centre + reach);
    }
    if (glm::any(glm::lessThan(point, lo)) || glm::any(glm::greaterThan(point, hi))) return true;
    return std::any_of(walls.begin(), walls.end(), [&](const OrientedBox& w) { return signedDistance(point, w) < 0; });
}

}  // namespace stepwise::bench
