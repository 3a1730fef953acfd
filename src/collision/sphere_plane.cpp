/// @file sphere_plane.cpp
/// @brief Sphere against an infinite plane: one dot product.
///
/// The signed distance of the centre c from the plane through p with unit
/// normal n is s = (c − p)·n. The sphere overlaps the solid half-space when
/// s < r; the depth is r − s and the sphere is pushed out along n. The
/// contact normal (from the sphere towards the plane) is therefore −n.
/// Reference: Ericson, *Real-Time Collision Detection*, §5.2.2.
#include <cmath>

#include "collision/narrowphase.hpp"

namespace stepwise {

bool collideSpherePlane(const Geometry& sphere, const Geometry& plane, ContactManifold& out) {
    const Real signedDistance = glm::dot(sphere.centre - plane.centre, plane.normal);
    if (signedDistance > sphere.radius + kTouchTolerance) return false;

    out.normal = -plane.normal;
    const Real depth = sphere.radius - signedDistance;
    // The sphere's own deepest point, not the middle of the overlap: friction
    // acting there has the lever arm r exactly, however deep the step sank it.
    out.pointCount = 0;
    out.add(sphere.centre - plane.normal * sphere.radius, depth, 0);
    return true;
}

}  // namespace stepwise
