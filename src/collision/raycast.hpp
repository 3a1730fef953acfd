/// @file raycast.hpp
/// @brief Where a ray first meets a sphere, box, plane, capsule, cylinder, hull or triangle mesh.
///
/// A ray is the half-line x(t) = o + t·d, t ≥ 0, with d a unit vector, so t
/// is the distance from the origin in metres. Each test returns the smallest
/// t ≤ maxDistance at which the ray enters the shape, with the shape's outward
/// unit normal there. A ray that *starts inside* a shape (or behind a plane,
/// in its solid half-space) hits it at t = 0 with normal −d: it crosses no
/// surface, and the normal points back the way the ray came.
///
/// A triangle mesh is a surface, not a solid: a ray meets it from either
/// side, and its normal is the triangle's turned to face the ray (the side
/// the ray came from), so a ray under a terrain can still pick it.
#pragma once

#include <optional>

#include "collision/contact.hpp"
#include "collision/narrowphase.hpp"
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

/// Deepest mesh hierarchy a ray descends with its fixed stack of nodes. A
/// hierarchy built by halving (a leaf of a few triangles) is about log₂ n
/// deep, 20 for a million triangles; a deeper one is searched triangle by
/// triangle instead (intersectRayMesh()), which is slower but finds the same hit.
inline constexpr int kMaxMeshDepth = 64;

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

/// @brief Ray against a capsule: the points within @p radius of the segment c ± h·a (a the body's y axis).
///
/// In the capsule's frame (o', d' as for the box) the capsule is the union
/// of a finite cylinder about y, |y| ≤ h, and two balls at (0, ±h, 0). A ray
/// starting outside all three enters the union where it enters the first of
/// them, so the hit is the nearest of: the infinite cylinder x² + z² = r²,
/// \f[ (d_x^2 + d_z^2)\,t^2 + 2(o_x d_x + o_z d_z)\,t + (o_x^2 + o_z^2 - r^2) = 0, \f]
/// at its smaller root if there |y| ≤ h (normal (x, 0, z)/r), and the two
/// end balls (intersectRaySphere()). The flat ends of the finite cylinder lie
/// inside the balls, so they never come first (Ericson, RTCD §5.3.7).
/// @param direction unit vector
/// @param halfHeight h, half the segment's length, m
std::optional<RayShapeHit> intersectRayCapsule(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                               const Vec3& centre, const Quat& orientation, Real radius,
                                               Real halfHeight);

/// @brief Ray against a solid cylinder |y| ≤ h, x² + z² ≤ r² in its frame: a slab and a round slab.
///
/// As the box's slab test: the ray is inside the slab |y| ≤ h between
/// (∓h − o'_y)/d'_y, and inside the infinite cylinder between the two roots
/// of the quadratic of intersectRayCapsule(). The cylinder is where both
/// hold: from the later entry to the earlier exit. Entered last through the
/// slab, the hit is on a cap (normal ∓y against d'_y); through the round
/// side, the normal is (x, 0, z)/r at the hit (Ericson, RTCD §5.3.7).
/// @param direction unit vector
/// @param halfHeight h, half the cylinder's length, m
std::optional<RayShapeHit> intersectRayCylinder(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                                const Vec3& centre, const Quat& orientation, Real radius,
                                                Real halfHeight);

/// @brief Ray against a convex hull: the ray clipped by each face's half-space (Ericson, RTCD §5.3.8).
///
/// The hull is the intersection of the half-spaces n_f·x ≤ e_f (HullFace's
/// normal and offset). Along the ray n_f·x(t) = n_f·o' + t·(n_f·d'), so a
/// face the ray heads into (n_f·d' < 0) is crossed inwards at
/// t = (e_f − n_f·o')/(n_f·d'), raising the entry, and one it heads out of
/// lowers the exit. A face parallel to the ray with the origin outside it
/// is a miss. The face entered last gives the normal.
/// @param direction unit vector
std::optional<RayShapeHit> intersectRayHull(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                            const Vec3& centre, const Quat& orientation, const ConvexHull& hull);

/// @brief Ray against one triangle (Möller and Trumbore, 1997; Ericson, RTCD §5.3.6).
///
/// The point o + t·d = a + u·(b − a) + v·(c − a) solves a 3×3 system; by
/// Cramer's rule with e₁ = b − a, e₂ = c − a, p = d × e₂, s = o − a,
/// q = s × e₁ and det = e₁·p:
/// \f[ u = \frac{s\cdot p}{\det},\quad v = \frac{d\cdot q}{\det},\quad t = \frac{e_2\cdot q}{\det}, \f]
/// a hit when u ≥ 0, v ≥ 0, u + v ≤ 1 and 0 ≤ t ≤ maxDistance. A ray in the
/// triangle's plane (|det| tiny) misses it. Both sides count; the normal is
/// e₁ × e₂ normalised, turned against d.
/// @param direction unit vector
std::optional<RayShapeHit> intersectRayTriangle(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                                const Vec3& a, const Vec3& b, const Vec3& c);

/// @brief Ray against a triangle mesh, descending its hierarchy of boxes (TriangleMesh::nodes).
///
/// In the mesh's frame, a node whose box the ray misses, or enters beyond
/// the nearest hit so far, is skipped with everything below it (the slab
/// test of intersectRayBox()); of an inner node's two children the nearer
/// is searched first, so the far one is often skipped. A leaf's triangles
/// are tested with intersectRayTriangle(). A mesh without nodes is searched
/// triangle by triangle.
/// @param direction unit vector
std::optional<RayShapeHit> intersectRayMesh(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                            const Vec3& centre, const Quat& orientation, const TriangleMesh& mesh);

/// @brief Ray against any geometry (geometryOf(), geometryOfPart()), by its type.
///
/// A compound body has no geometry of its own (type Count, a miss here):
/// World::raycast() casts against each of its parts and keeps the nearest.
/// @param direction unit vector
std::optional<RayShapeHit> intersectRayGeometry(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                                const Geometry& shape);

/// @brief Ray against a plane through @p point with unit @p normal, solid behind.
///
/// The signed distance of x(t) is s(t) = s₀ + t·(n·d) with s₀ = n·(o − p), so
/// the ray reaches the plane at t = s₀ / (−n·d), when it is in front (s₀ > 0)
/// and heading towards it (n·d < 0). The normal is n.
/// @param direction unit vector
std::optional<RayShapeHit> intersectRayPlane(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                             const Vec3& point, const Vec3& normal);

}  // namespace stepwise
