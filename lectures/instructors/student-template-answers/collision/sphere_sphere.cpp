/// @file sphere_sphere.cpp
/// @brief YOUR sphere-sphere test (lecture 3): a student template (lectures/student-template/README.md).
///
/// Copied to student/collision/sphere_sphere.cpp, it replaces
/// src/collision/sphere_sphere.cpp in the student preset's build. It defines
/// the pair test src/collision/narrowphase.hpp declares:
///
///     bool collideSphereSphere(const Geometry& a, const Geometry& b, ContactManifold& out);
///
/// With u = b.centre - a.centre (lecture 3, "1. Where the contact comes from"):
///
///     no contact when |u| > r_A + r_B + kTouchTolerance: return false
///     out.normal = u / |u|                from A to B (world up, (0, 1, 0),
///                                         when |u| < kCoincidentCentres: no direction)
///     depth      = r_A + r_B - |u|
///     point      = c_A + n (r_A - depth/2)   the middle of the overlap
///
/// Start with out.pointCount = 0, add the point with out.add(point, depth, 0)
/// and return true. Until you write it, the test stops with
/// "student stage not written yet: stepwise::collideSphereSphere".
/// Test it: ctest --preset student -L sphere-sphere
#include <cmath>

#include "collision/narrowphase.hpp"
#include "core/student_todo.hpp"

namespace stepwise {

/// Centres closer than this (m) have no usable direction between them.
constexpr Real kCoincidentCentres = Real(1e-12);

bool collideSphereSphere(const Geometry& a, const Geometry& b, ContactManifold& out) {
    // ==== YOUR CODE BEGINS: lecture 3, "1. Where the contact comes from" ====
    const Vec3 between = b.centre - a.centre;
    const Real radii = a.radius + b.radius;
    // Compare squared lengths first: no square root for the many pairs that miss.
    const Real reach = radii + kTouchTolerance;
    const Real distanceSquared = glm::dot(between, between);
    if (distanceSquared > reach * reach) return false;

    const Real distance = std::sqrt(distanceSquared);
    // Concentric spheres: any direction separates them; pick world up so the
    // result is repeatable.
    out.normal = distance > kCoincidentCentres ? between / distance : Vec3(0, 1, 0);
    const Real depth = radii - distance;
    out.pointCount = 0;
    out.add(a.centre + out.normal * (a.radius - Real(0.5) * depth), depth, 0);
    return true;
    // ==== YOUR CODE ENDS ====
}

}  // namespace stepwise
