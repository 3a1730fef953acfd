/// @file box_sphere.cpp
/// @brief Oriented box against sphere: the sphere–box test with the roles swapped.
///
/// The dispatch table calls a test with the dynamic body first, so a
/// dynamic box meeting a sphere arrives as (box, sphere). The geometry is
/// the same as sphere against box (sphere_box.cpp): only the convention
/// "normal from A towards B" changes, so the normal is flipped. The contact
/// point (the sphere's deepest point) and the depth do not depend on which
/// body is called A.
#include "collision/narrowphase.hpp"

namespace stepwise {

bool collideBoxSphere(const Geometry& box, const Geometry& sphere, ContactManifold& out) {
    if (!collideSphereBox(sphere, box, out)) return false;
    out.normal = -out.normal;  // sphere → box became box → sphere
    return true;
}

}  // namespace stepwise
