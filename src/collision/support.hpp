/// @file support.hpp
/// @brief Support functions: the farthest point of a convex shape in a given direction.
///
/// GJK, EPA and MPR never look at a shape's faces or formulas: all they ask
/// of it is its *support point* in a direction d,
/// \f[ s_S(d) = \arg\max_{x \in S} d\cdot x , \f]
/// the point a plane with normal d touches first when it is pushed against
/// the shape. A shape whose support point can be computed can be collided
/// with every other such shape by the same code (van den Bergen, *Collision
/// Detection in Interactive 3D Environments*, §4.3; Ericson §9.5.1).
///
/// **Core and radius.** A sphere is a point grown by a radius and a capsule
/// is a segment grown by one: S = C ⊕ ball(r). Support points add, so
/// \f[ s_S(d) = s_C(d) + r\,\frac{d}{|d|}. \f]
/// GJK runs on the *core* C alone (a point or a segment has exact, finite
/// support points, so GJK ends in one or two iterations) and subtracts the
/// radii from the distance it finds; only when the cores themselves
/// overlap does EPA need the grown shape. ConvexShape keeps the core and
/// the radius (its `margin`) apart for that reason.
#pragma once

#include "collision/narrowphase.hpp"

namespace stepwise {

/// @brief The convex cores a support function knows.
enum class ConvexCore : std::uint8_t {
    Point,     ///< A single point: a sphere's centre.
    Segment,   ///< A segment of half length `halfHeight` along the local y axis: a capsule's.
    Box,       ///< A box of half edges `halfExtents`.
    Cylinder,  ///< A solid cylinder of radius `discRadius` and half length `halfHeight` along local y.
    Hull,      ///< The vertices of `hull`.
    Triangle,  ///< The three world points `corners` (one triangle of a mesh).
};

/// @brief A convex shape in world space as GJK, EPA and MPR see it: a core grown by a margin.
///
/// Made from a Geometry (convexShapeOf()) or from one triangle of a mesh
/// (convexShapeOfTriangle()); the rotation is turned into a matrix once, so
/// each support query costs a few dot products.
struct ConvexShape {
    ConvexCore core = ConvexCore::Point;  ///< Which fields below are meaningful.
    Vec3 centre{0, 0, 0};       ///< A point inside the core (its centre), world, m.
    Mat3 rotation{1};           ///< Shape frame → world (columns: the shape's axes).
    Vec3 halfExtents{0, 0, 0};  ///< Box half edge lengths, m.
    Real halfHeight = 0;        ///< Segment or cylinder half length along local y, m.
    Real discRadius = 0;        ///< Cylinder radius, m.
    Real margin = 0;            ///< Radius added all round the core (sphere, capsule), m.
    const ConvexHull* hull = nullptr;  ///< Hull vertices, shape frame.
    Vec3 corners[3]{};          ///< Triangle corners, world, m.
};

/// @brief The ConvexShape of a Sphere, Box, Capsule, Cylinder or Hull geometry.
ConvexShape convexShapeOf(const Geometry& geometry);

/// @brief The ConvexShape of the triangle @p p0, @p p1, @p p2 (world points), with no margin.
ConvexShape convexShapeOfTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2);

/// @brief Support point of the core alone (no margin), world, m.
///
/// Per core, with d′ = Rᵀd the direction in the shape's frame:
/// - point: the point;
/// - segment: the end with the larger d·y, c ± h·y;
/// - box: the corner (sign(d′ₓ)eₓ, sign(d′_y)e_y, sign(d′_z)e_z);
/// - cylinder: the cap with the larger d·y, and on its rim the point along
///   the part of d′ across the axis: (r d′ₓ/ρ, ±h, r d′_z/ρ), ρ = √(d′ₓ² + d′_z²)
///   (the cap's centre when ρ = 0);
/// - hull, triangle: the vertex with the largest d·v (a linear scan).
///
/// On a tie (d perpendicular to an edge or face) the first candidate wins,
/// so the same direction always gives the same point.
Vec3 coreSupport(const ConvexShape& shape, const Vec3& direction);

/// @brief Support point of the whole shape: coreSupport() + margin·d/|d|, world, m.
Vec3 support(const ConvexShape& shape, const Vec3& direction);

}  // namespace stepwise
