/// @file raycast.hpp
/// @brief Where a ray first meets a sphere, an oriented box or a plane.
///
/// A ray is the half-line x(t) = o + t·d, t ≥ 0, with d a unit vector, so t
/// is the distance from the origin in metres. Each test returns the smallest
/// t ≤ maxDistance at which the ray enters the shape, with the shape's outward
/// unit normal there. A ray that *starts inside* a shape (or behind a plane,
/// in its solid half-space) hits it at t = 0 with normal −d: it crosses no
/// surface, and the normal points back the way the ray came.
#pragma once

#include <optional>

#include "collision/contact.hpp"
#include "core/types.hpp"

namespace stepwise {

/// @brief A ray meeting one shape.
struct RayShapeHit {
    Real distance = 0;     ///< t, m along the ray.
    Vec3 normal{0, 1, 0};  ///< Outward unit normal of the surface at the hit (−d for a ray starting inside).
};

/// @brief A ray meeting the World's first body along it (World::raycast()).
struct RayHit {
    BodyRef body;          ///< Which body: its kind and index in the World's array of that kind.
    Vec3 point{0, 0, 0};   ///< o + t·d, the hit point in world space, m.
    Vec3 normal{0, 1, 0};  ///< Outward unit normal of the body's surface there.
    Real distance = 0;     ///< t, m along the ray from its origin.
};

/// A ray component smaller than this (of a unit direction) counts as parallel
/// to a box's slab: dividing by it would only produce round-off noise.
inline constexpr Real kRayParallelTolerance = Real(1e-12);

/// @brief Ray against a sphere (Ericson, RTCD §5.3.2).
///
/// With m = o − c, the points at distance r from the centre solve
/// \f[ t^2 + 2(m\cdot d)\,t + (m\cdot m - r^2) = 0, \f]
/// and the ray enters at the smaller root t = −b − √(b² − c) with b = m·d,
/// c = m·m − r². Outside (c > 0) and pointing away (b > 0): a miss; b² − c < 0:
/// the line passes the sphere by. The normal is (x(t) − centre)/r.
/// @param direction unit vector
std::optional<RayShapeHit> intersectRaySphere(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                              const Vec3& centre, Real radius);

/// @brief Ray against an oriented box: the slab test in the box's frame (Ericson, RTCD §5.3.3).
///
/// The ray is turned into the box's frame (o' = Rᵀ(o − c), d' = Rᵀd), where the
/// box is the intersection of three slabs |x_i| ≤ h_i. The ray is inside slab
/// i for t between (−h_i − o'_i)/d'_i and (h_i − o'_i)/d'_i, and inside the
/// box where it is inside all three: from the latest entry to the earliest
/// exit. It hits if that interval is not empty; the slab entered last gives
/// the normal, ∓ its axis (against d'_i), turned back into the world.
/// @param direction unit vector
std::optional<RayShapeHit> intersectRayBox(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                           const Vec3& centre, const Quat& orientation, const Vec3& halfExtents);

/// @brief Ray against a plane through @p point with unit @p normal, solid behind.
///
/// The signed distance of x(t) is s(t) = s₀ + t·(n·d) with s₀ = n·(o − p), so
/// the ray reaches the plane at t = s₀ / (−n·d), when it is in front (s₀ > 0)
/// and heading towards it (n·d < 0). The normal is n.
/// @param direction unit vector
std::optional<RayShapeHit> intersectRayPlane(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                             const Vec3& point, const Vec3& normal);

}  // namespace stepwise
