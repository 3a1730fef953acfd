/// @file aabb.hpp
/// @brief Axis-aligned bounding boxes: what every broadphase compares.
///
/// Every shape's box is exact (the smallest box with faces along x, y and z
/// that holds it), except a triangle mesh's, which is its hierarchy's root
/// box turned into the world (meshAabb() says why).
#pragma once

#include "collision/contact.hpp"
#include "collision/narrowphase.hpp"
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

/// @brief Bounding box of a capsule: its segment's box grown by the radius on every side.
///
/// The capsule is every point within r of the segment c ± h·a (a: the body's
/// y axis in the world), so along world axis i it reaches h·|a_i| + r either
/// side of its centre.
/// @param halfHeight half the segment's length, m
Aabb capsuleAabb(const Vec3& centre, const Quat& orientation, Real radius, Real halfHeight);

/// @brief Bounding box of a solid cylinder of @p radius and length 2·@p halfHeight along the body's y axis.
///
/// The cylinder is the segment c ± h·a swept by a disc of radius r at right
/// angles to a. Along world axis e_i the segment reaches h·|a_i| and the disc
/// r·|e_i × a| = r·√(1 − a_i²) (the disc's widest extent along e_i is r times
/// the part of e_i that lies in the disc's plane), so the half-width is
/// \f[ h\,|a_i| + r\sqrt{1 - a_i^2}. \f]
Aabb cylinderAabb(const Vec3& centre, const Quat& orientation, Real radius, Real halfHeight);

/// @brief Bounding box of a convex hull: the lowest and highest of its vertices turned into the world.
///
/// A convex polyhedron's extreme point along any direction is one of its
/// vertices, so the box of the turned vertices is exact. It costs one
/// rotation per vertex, a few dozen for the hulls students build.
Aabb hullAabb(const Vec3& centre, const Quat& orientation, const ConvexHull& hull);

/// @brief Bounding box of a triangle mesh: its hierarchy's root box, turned as boxAabb() turns a box.
///
/// Exact while the mesh is not rotated (level geometry usually is not) and
/// at most √3 times as wide when it is, for a cost that does not grow with
/// the number of triangles: a terrain of 100 000 vertices is bounded in
/// the time of one box. Without a hierarchy (no nodes) the vertices are
/// turned one by one, as hullAabb() does.
Aabb meshAabb(const Vec3& centre, const Quat& orientation, const TriangleMesh& mesh);

/// @brief Bounding box of one geometry (geometryOf(), geometryOfPart()).
///
/// A plane has no bounds: its box is infinite on every side. A compound
/// body's geometry carries no parts (type Count), so it too gets the
/// infinite box, which overlaps everything and lets the exact test decide;
/// shapeAabb() of the body is the compound's real box.
Aabb geometryAabb(const Geometry& shape);

/// @brief The exact bounding box of a dynamic body's shape where it is now (no sweep, no margin).
///
/// A compound's box is the union of its parts' boxes (geometryOfPart()).
Aabb shapeAabb(const DynamicObject& body);
/// @copydoc shapeAabb(const DynamicObject&)
Aabb shapeAabb(const KinematicsObject& body);
/// @brief The box shapeAabb() would give were @p body's centre at @p position (its orientation kept).
Aabb shapeAabb(const DynamicObject& body, const Vec3& position);

/// @brief Distance from a body's position to the farthest point of its shape, m.
///
/// What a turn at angular speed ω can move a surface point by, at most
/// ω·reach (v_P = v + ω × r). Sphere r; box |half extents|; capsule h + r;
/// cylinder √(h² + r²) (h: half its length); hull and compound their
/// `boundingRadius`. A mesh's is its root box's farthest corner: an upper
/// bound, found in constant time.
Real shapeReach(const DynamicObject& body);
/// @copydoc shapeReach(const DynamicObject&)
Real shapeReach(const KinematicsObject& body);

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
