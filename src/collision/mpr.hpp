/// @file mpr.hpp
/// @brief MPR (Minkowski portal refinement, Snethen): overlap, normal, depth and contact point of two convex shapes.
///
/// Snethen's XenoCollide (*Game Programming Gems 7*, §2.5) asks a simpler
/// question than GJK: does the ray from a point v₀ deep inside A − B to
/// the origin leave A − B before it reaches the origin? If it does not,
/// the origin is inside and the shapes overlap.
///
/// 1. **Interior point.** v₀ = c_A − c_B, the difference of the shapes'
///    centres, lies inside A − B.
/// 2. **Find a portal.** A *portal* is a triangle (v₁, v₂, v₃) of support
///    points that the ray v₀ → origin passes through. Start with
///    v₁ = s(−v₀) (the support towards the origin), v₂ = s(v₁ × v₀), then
///    v₃ = s(n) with n the normal of (v₀, v₁, v₂) on the origin's side;
///    while the origin lies outside one of the side planes (v₀, vᵢ, vⱼ),
///    replace the vertex opposite that plane by a new support point. Any
///    support point with s·n < 0 proves a separating plane: no overlap.
/// 3. **Refine the portal.** With n the portal's outward normal: if
///    n·v₁ ≥ 0 the origin is inside the tetrahedron (v₀, v₁, v₂, v₃) and
///    the shapes overlap. Take v₄ = s(n); if A − B reaches no farther than
///    the portal along n (within kMprTolerance), the portal is on the
///    boundary: stop. Otherwise v₄ replaces one portal vertex, chosen so
///    the ray still passes through the new, smaller portal (the three
///    triangle tests in mpr.cpp).
///
/// The result's normal is the last portal's normal and its depth the
/// distance from the origin to that portal's plane. This is the boundary
/// where the *ray from v₀* crosses it, not necessarily the nearest one: for
/// boxes far off-centre the ray can leave through a side face while the
/// shortest way out is through the top. That is MPR's known trade: fewer,
/// cheaper iterations than EPA, a depth and normal that are exact only when
/// the centres line up with the contact (the side-by-side test and
/// `stepwise-bench narrowphase` measure how far off it is).
///
/// The contact point comes from the last portal: the origin's projection
/// on its plane has barycentric weights in (v₁, v₂, v₃), which, applied to
/// each vertex's support points on A and on B, give a point on each shape.
#pragma once

#include "collision/support.hpp"

namespace stepwise {

/// Most portal refinements MPR makes before it stops with the portal it has.
inline constexpr int kMaxMprIterations = 64;

/// MPR stops refining when A − B reaches less than this beyond the portal, m.
inline constexpr Real kMprTolerance = Real(1e-7);

/// @brief What MPR found.
struct MprResult {
    bool overlap = false;    ///< The shapes (with their margins) overlap; nothing below but `iterations` is set otherwise.
    Real depth = 0;          ///< Distance from the origin to the last portal's plane, m.
    Vec3 normal{0, 1, 0};    ///< The portal's unit normal, from A towards B.
    Vec3 onA{0, 0, 0};       ///< Point of A's surface under the portal, m.
    Vec3 onB{0, 0, 0};       ///< Point of B's surface under the portal, m.
    int iterations = 0;      ///< Support queries made.
};

/// @brief Overlap, normal, depth and points of two convex shapes, margins included (see the file comment).
MprResult mpr(const ConvexShape& a, const ConvexShape& b);

}  // namespace stepwise
