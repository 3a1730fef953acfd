/// @file convex_pairs.hpp
/// @brief The pair tests of capsules, cylinders and hulls: which algorithm meets which pair, with how much reach.
///
/// Every convex pair goes through collideConvex(), which picks the routine:
///
/// | pair                               | Auto                       | GjkEpa      | Mpr         |
/// |------------------------------------|----------------------------|-------------|-------------|
/// | capsule, cylinder, hull – plane    | its plane test             | the same    | the same    |
/// | capsule – capsule, capsule – sphere| closest points of segments | GJK + EPA   | MPR         |
/// | any other convex pair              | GJK + EPA                  | GJK + EPA   | MPR         |
///
/// (Sphere–sphere, sphere–box, box–box and sphere or box against a plane
/// keep their own tests under Auto: narrowphase.cpp sends them there.)
/// The algorithm gives a normal, and convexManifold() the points.
///
/// **Reach.** GJK measures distance, so a pair whose gap is at most
/// @p maxGap gives speculative points (negative depth) as the sphere tests
/// do (contact.hpp says why). MPR answers only "do they overlap?": a pair
/// it finds apart is measured by GJK, and one that GJK finds overlapping
/// after all (touching to round-off) by EPA.
#pragma once

#include "collision/narrowphase.hpp"
#include "core/world_settings.hpp"

namespace stepwise {

/// @brief Iterations the algorithms took in the last collideConvex() call (for the benchmark's table).
struct ConvexIterations {
    int gjk = 0;  ///< GJK support queries (0: not run).
    int epa = 0;  ///< EPA support queries after its tetrahedron (0: not run).
    int mpr = 0;  ///< MPR support queries (0: not run).
};

/// @brief Contacts of two convex shapes (A not a plane) with the algorithm @p kind picks (see the file comment).
/// @param maxGap     points whose surfaces are farther apart than this are left out, m
/// @param iterations if not nullptr, receives the iteration counts
bool collideConvex(const Geometry& a, const Geometry& b, NarrowphaseKind kind, Real maxGap, ContactManifold& out,
                   ConvexIterations* iterations = nullptr);

/// @brief Capsule A against capsule or sphere B, or sphere A against capsule B (capsule_contacts.cpp).
bool capsuleContacts(const Geometry& a, const Geometry& b, Real maxGap, ContactManifold& out);
/// @brief Capsule against plane: its two end spheres (convex_plane.cpp).
bool capsulePlaneContacts(const Geometry& capsule, const Geometry& plane, Real maxGap, ContactManifold& out);
/// @brief Cylinder against plane: rim points within reach, up to 4 (convex_plane.cpp).
bool cylinderPlaneContacts(const Geometry& cylinder, const Geometry& plane, Real maxGap, ContactManifold& out);
/// @brief Hull against plane: vertices within reach, the deepest and widest 4 (convex_plane.cpp).
bool hullPlaneContacts(const Geometry& hull, const Geometry& plane, Real maxGap, ContactManifold& out);

}  // namespace stepwise
