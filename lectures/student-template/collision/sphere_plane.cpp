/// @file sphere_plane.cpp
/// @brief YOUR sphere-plane test (lecture 3): a student template (lectures/student-template/README.md).
///
/// Copied to student/collision/sphere_plane.cpp, it replaces
/// src/collision/sphere_plane.cpp in the student preset's build. It defines
/// the pair test src/collision/narrowphase.hpp declares:
///
///     bool collideSpherePlane(const Geometry& sphere, const Geometry& plane, ContactManifold& out);
///
/// The plane passes through plane.centre with unit normal n = plane.normal
/// (out of the solid side). With c = sphere.centre and r = sphere.radius
/// (lecture 3, "1. Where the contact comes from"):
///
///     s = (c - plane.centre) . n          signed distance of the centre
///     no contact when s > r + kTouchTolerance: return false
///     out.normal = -n                     from the sphere (A) to the plane (B)
///     depth      = r - s
///     point      = c - n r                the sphere's own deepest point
///
/// Start with out.pointCount = 0, add the point with out.add(point, depth, 0)
/// and return true. Until you write it, the test stops with
/// "student stage not written yet: stepwise::collideSpherePlane".
/// Test it: ctest --preset student -L sphere-plane
#include <cmath>

#include "collision/narrowphase.hpp"
#include "core/student_todo.hpp"

namespace stepwise {

bool collideSpherePlane(const Geometry& sphere, const Geometry& plane, ContactManifold& out) {
    // ==== YOUR CODE BEGINS: lecture 3, "1. Where the contact comes from" ====
    // TODO: the signed distance s, false beyond r + kTouchTolerance, else the normal -n and one point.
    return studentTodo<bool>("stepwise::collideSpherePlane (collision/sphere_plane.cpp): "
                             "write s = (c - p).n, depth r - s, normal -n, point c - n r "
                             "(lecture 3, section 1)",
                             sphere, plane, out);
    // ==== YOUR CODE ENDS ====
}

}  // namespace stepwise
