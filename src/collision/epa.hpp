/// @file epa.hpp
/// @brief EPA (expanding polytope algorithm): penetration depth, normal and witness points of two overlapping convex shapes.
///
/// When GJK (gjk.hpp) ends with the origin inside A − B, the shapes
/// overlap, and the question becomes: what is the shortest translation
/// that separates them? It is the point p of A − B's *boundary* closest to
/// the origin: moving A by −p makes the shapes touch. Its length is the
/// penetration depth, p/|p| the contact normal (from A towards B).
///
/// EPA (van den Bergen 2001; Ericson §9.5.4 sketches it) finds p by growing
/// a polytope inside A − B, starting from GJK's final simplex:
/// 1. Of the polytope's triangles (outward unit normal n, distance
///    d = n·v₀ from the origin), take the one closest to the origin.
/// 2. Ask A − B for its support point w = s_A(n) − s_B(−n).
/// 3. If w·n − d, how far the boundary lies beyond that face, is below
///    kEpaAbsoluteTolerance + kEpaRelativeTolerance·d, the face is on the
///    boundary to within the tolerance: depth d, normal n.
/// 4. Otherwise w is a new vertex. Every face that w sees (n·(w − v₀) > 0)
///    is removed; the edges between a removed and a kept face form the
///    *horizon*, a loop; each horizon edge and w make a new face. The
///    polytope stays convex and grows towards the boundary. Go to 1.
///
/// The witness points come from the last face: the origin's projection
/// p = d·n has barycentric weights λᵢ in the face's three vertices, each
/// vertex remembers its support points aᵢ and bᵢ, and Σλᵢaᵢ, Σλᵢbᵢ are the
/// deepest points of A in B and of B in A.
///
/// **Starting tetrahedron.** GJK can stop with fewer than 4 points (the
/// origin on an edge or a triangle of A − B, or the shapes' centres
/// coincide). EPA then adds support points in directions across the
/// simplex until it holds a tetrahedron; the origin lies on it or inside.
///
/// **Storage** is fixed: kMaxEpaVertices vertices and kMaxEpaFaces faces
/// live in arrays on the stack, so a query allocates nothing.
#pragma once

#include "collision/gjk.hpp"

namespace stepwise {

/// Most points EPA adds to the starting tetrahedron. Boxes and hulls need
/// a few (A − B of two boxes has at most 8·8 vertices, and only those near
/// the origin are ever found); curved shapes are cut off here.
inline constexpr int kMaxEpaIterations = 64;
/// Vertices the polytope can hold: the tetrahedron plus one per iteration.
inline constexpr int kMaxEpaVertices = 4 + kMaxEpaIterations;
/// Faces it can hold: a closed triangle mesh of V vertices has 2V − 4 faces.
inline constexpr int kMaxEpaFaces = 2 * kMaxEpaVertices;

/// EPA stops when the support point is this close beyond the nearest face, m:
/// a tenth of a micrometre, far below what a step resolves.
inline constexpr Real kEpaAbsoluteTolerance = Real(1e-7);
/// …plus this fraction of the depth: on a curved shape (a cylinder's rim),
/// faces near the boundary get closer only quadratically with their size,
/// and 10⁻⁴ of the depth is reached in a few dozen iterations.
inline constexpr Real kEpaRelativeTolerance = Real(1e-4);

/// @brief What EPA found.
struct EpaResult {
    bool valid = false;      ///< false when A − B is flat (no volume) or the polytope broke down: nothing below is set.
    Real depth = 0;          ///< Penetration depth, m (slightly negative when the shapes just touch).
    Vec3 normal{0, 1, 0};    ///< Unit, from A towards B: A moves along −normal to separate.
    Vec3 onA{0, 0, 0};       ///< Deepest point of A inside B, m.
    Vec3 onB{0, 0, 0};       ///< Deepest point of B inside A, m (onA − onB = depth·normal).
    int iterations = 0;      ///< Support queries made after the starting tetrahedron.
};

/// @brief Penetration of two overlapping shapes (margins included), from GJK's final simplex.
/// @param start GJK's simplex (GjkResult::simplex) holding the origin; it may have 0 to 4 points
EpaResult epa(const ConvexShape& a, const ConvexShape& b, const Simplex& start);

}  // namespace stepwise
