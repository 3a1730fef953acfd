/// @file gjk.hpp
/// @brief GJK (Gilbert–Johnson–Keerthi): the distance and closest points of two convex shapes, or their overlap.
///
/// ### The Minkowski difference
/// Two shapes A and B overlap exactly when some a ∈ A equals some b ∈ B,
/// that is when the origin lies in the *Minkowski difference*
/// \f[ A - B = \{\, a - b : a \in A,\ b \in B \,\}, \f]
/// and their distance is the distance of A − B from the origin. A − B is
/// convex, and its support point is built from the two shapes' own:
/// \f[ s_{A-B}(d) = s_A(d) - s_B(-d) \f]
/// (support.hpp). GJK finds the point v of A − B closest to the origin
/// without ever building A − B: it keeps a *simplex* (1 to 4 points of
/// A − B) and improves it.
///
/// ### One iteration (van den Bergen 1999; Ericson §9.5)
/// 1. v is the point of the simplex closest to the origin.
/// 2. w = s_{A−B}(−v): the point of A − B farthest towards the origin.
/// 3. Stop if w brings nothing: every point of A − B has x·v ≥ w·v, so the
///    distance d satisfies w·v/|v| ≤ d ≤ |v|, and
///    \f[ |v| - d \le \frac{v\cdot v - v\cdot w}{|v|}. \f]
///    GJK stops when that bound is below kGjkRelativeTolerance·|v| (w is
///    then, to that tolerance, on the simplex already).
/// 4. Otherwise add w to the simplex and go to 1, where the simplex is
///    cut down to the smallest face (vertex, edge, triangle) that holds
///    the new closest point: the *sub-algorithm*.
/// 5. A simplex of 4 points that holds the origin, or |v| below
///    kGjkOverlapTolerance, means the shapes overlap: distance 0, and the
///    simplex is where EPA (epa.hpp) starts.
///
/// **The sub-algorithm** here is Johnson's in its geometric form: the
/// Voronoi regions of the simplex's vertices, edges and faces are tested in
/// turn (Ericson §5.1.5 for the triangle, §5.1.6 for the tetrahedron), and
/// the closest point is written with barycentric weights λᵢ on the points
/// it keeps, v = Σ λᵢ wᵢ. With each wᵢ = aᵢ − bᵢ remembered, the closest
/// points on the shapes themselves are Σ λᵢ aᵢ and Σ λᵢ bᵢ.
///
/// **Cores and radii.** GJK runs on the shapes' cores (support.hpp) and
/// subtracts the margins at the end: a sphere is one point, so sphere
/// against anything ends as soon as the other shape's closest feature is
/// found.
///
/// **Stepping through it.** gjk() takes an optional record: give it a
/// std::vector and it receives the simplex after every iteration (the
/// engine passes nullptr). In gdb, `break gjk` then `finish` and
/// `print result.simplex` show the end; the record shows the way there.
#pragma once

#include <vector>

#include "collision/support.hpp"

namespace stepwise {

/// Most iterations GJK takes. Polytopes (boxes, hulls) end in a handful,
/// since w repeats once the closest feature is on the simplex; curved
/// shapes (cylinders) converge step by step and are cut off here, with the
/// distance then within a few micrometres.
inline constexpr int kMaxGjkIterations = 64;

/// GJK stops when its distance is known to this fraction of itself: the
/// bound (v·v − v·w)/|v| of the file comment is at most this times |v|.
/// 10⁻¹⁰ of a 1 m distance is 0.1 nm, far below anything a step resolves,
/// yet well above double round-off (10⁻¹⁶) so the test does not chase noise.
inline constexpr Real kGjkRelativeTolerance = Real(1e-10);

/// Cores closer than this, m, count as overlapping: the direction between
/// two points so close is round-off, so EPA gives the normal instead.
inline constexpr Real kGjkOverlapTolerance = Real(1e-9);

/// @brief A point of the simplex: w = a − b, the two support points it came from, and its weight.
struct SimplexVertex {
    Vec3 w{0, 0, 0};    ///< Point of the Minkowski difference A − B (cores), m.
    Vec3 onA{0, 0, 0};  ///< Support point of A's core, world, m.
    Vec3 onB{0, 0, 0};  ///< Support point of B's core, world, m.
    Real weight = 0;    ///< Barycentric weight λ of this point in the closest point v.
};

/// @brief GJK's simplex: 1 to 4 points of A − B.
struct Simplex {
    SimplexVertex vertices[4];  ///< The points; the first `count` are valid.
    int count = 0;              ///< Number of points (0 before the first iteration).
    Vec3 closest{0, 0, 0};      ///< v: the simplex's point closest to the origin, m.
};

/// @brief What GJK found.
struct GjkResult {
    bool overlap = false;    ///< The cores overlap: distance and normal are not defined (run EPA).
    Real distance = 0;       ///< Gap between the shapes with their margins, m; negative when only the margins overlap.
    Vec3 normal{0, 1, 0};    ///< Unit, from A towards B (when !overlap).
    Vec3 onA{0, 0, 0};       ///< Closest point of A (its deepest point when the margins overlap), m.
    Vec3 onB{0, 0, 0};       ///< Closest point of B, m.
    int iterations = 0;      ///< Support queries made.
    Simplex simplex;         ///< The final simplex (holds the origin when overlap).
};

/// @brief Distance, closest points or overlap of two convex shapes (see the file comment).
/// @param record if not nullptr, the simplex after each iteration is appended (for lectures and debugging)
GjkResult gjk(const ConvexShape& a, const ConvexShape& b, std::vector<Simplex>* record = nullptr);

/// @brief The point of @p simplex closest to the origin (Johnson's sub-algorithm, Voronoi regions).
///
/// Cuts @p simplex down to the points that hold that closest point and sets
/// their weights; its `closest` is the point. A tetrahedron holding the
/// origin keeps all four points, with closest = 0.
/// @return true when the simplex is a tetrahedron holding the origin
bool reduceToClosest(Simplex& simplex);

}  // namespace stepwise
