/// @file aabb.hpp
/// @brief Axis-aligned bounding boxes: what every broadphase compares.
#pragma once

#include "collision/contact.hpp"
#include "objects/game_object.hpp"

namespace stepwise {

/// @brief Axis-aligned bounding box: the smallest box with faces along x, y, z that holds a shape.
struct Aabb {
    Vec3 min{0, 0, 0};  ///< Lowest corner, m.
    Vec3 max{0, 0, 0};  ///< Highest corner, m.

    /// @brief True when the two boxes overlap or touch on every axis (the
    /// separating-axis test restricted to x, y and z).
    bool overlaps(const Aabb& other) const {
        return min.x <= other.max.x && other.min.x <= max.x &&
               min.y <= other.max.y && other.min.y <= max.y &&
               min.z <= other.max.z && other.min.z <= max.z;
    }

    /// @brief True when @p inner lies entirely inside this box (faces may touch).
    bool contains(const Aabb& inner) const {
        return min.x <= inner.min.x && min.y <= inner.min.y && min.z <= inner.min.z &&
               inner.max.x <= max.x && inner.max.y <= max.y && inner.max.z <= max.z;
    }

    /// @brief Surface area 2(dx·dy + dy·dz + dz·dx), m²: the cost measure of the
    /// surface-area heuristic (a random ray, or a random small box, hits a
    /// convex shape with probability proportional to its surface area).
    Real surfaceArea() const {
        const Vec3 d = max - min;
        return Real(2) * (d.x * d.y + d.y * d.z + d.z * d.x);
    }

    /// @brief Length of the box's longest side, m.
    Real longestSide() const {
        const Vec3 d = max - min;
        return glm::max(d.x, glm::max(d.y, d.z));
    }

    /// @brief The box's centre, m.
    Vec3 centre() const { return Real(0.5) * (min + max); }
};

/// @brief The smallest box holding both @p a and @p b.
inline Aabb merged(const Aabb& a, const Aabb& b) { return {glm::min(a.min, b.min), glm::max(a.max, b.max)}; }

/// @brief Bounding box of a sphere of @p radius at @p centre.
Aabb sphereAabb(const Vec3& centre, Real radius);

/// @brief Bounding box of an oriented box: centre ± |R|·halfExtents (Ericson, RTCD §4.2.6).
Aabb boxAabb(const Vec3& centre, const Quat& orientation, const Vec3& halfExtents);

/// @brief The box every broadphase tests for a dynamic body: its bounding box
/// grown by kSpeculativeDistance on every side.
///
/// The narrowphase reports contacts that close (touching, or speculative for
/// boxes), so a broadphase must not rule such pairs out.
Aabb broadphaseBounds(const DynamicObject& body);
/// @copydoc broadphaseBounds(const DynamicObject&)
Aabb broadphaseBounds(const KinematicsObject& body);

/// @brief True unless @p box lies entirely in front of @p plane (the half-space
/// behind a plane is solid, so anything reaching behind it may touch it).
///
/// The box's corner deepest along −n is at depth Σ|n_i|·e_i below its centre
/// (e: half its size), so it reaches the plane when the centre's signed
/// distance is at most that.
bool aabbTouchesPlane(const Aabb& box, const CollisionPlane& plane);

}  // namespace stepwise
