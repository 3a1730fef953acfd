/// @file sphere_box.cpp
/// @brief Sphere against oriented box: the closest point of the box to the sphere's centre.
///
/// Work in the box's own frame, where it is the axis-aligned box
/// [−e, +e]. The centre in that frame is c' = Rᵀ(c − b). Clamping each
/// coordinate of c' to [−eᵢ, +eᵢ] gives the point q of the box closest to
/// the centre (Ericson, *Real-Time Collision Detection*, §5.1.4). The sphere
/// touches the box when |c' − q| ≤ r.
///
/// If the centre is *inside* the box, clamping changes nothing and the
/// distance is zero, which gives no direction. Then the sphere leaves
/// through the nearest face: the axis i with the smallest eᵢ − |c'ᵢ|, with
/// depth r + (eᵢ − |c'ᵢ|).
#include <cmath>

#include "collision/narrowphase.hpp"

namespace stepwise {

bool collideSphereBox(const Geometry& sphere, const Geometry& box, ContactManifold& out) {
    const Mat3 rotation = glm::mat3_cast(box.orientation);      // body → world
    const Vec3 local = glm::transpose(rotation) * (sphere.centre - box.centre);
    const Vec3 closest = glm::clamp(local, -box.halfExtents, box.halfExtents);
    const Vec3 offset = local - closest;  // from the box surface to the centre, box frame
    const Real distanceSquared = glm::dot(offset, offset);
    const Real reach = sphere.radius + kTouchTolerance;
    if (distanceSquared > reach * reach) return false;

    if (distanceSquared > Real(0)) {
        // Centre outside the box: the normal runs from the sphere's centre to the closest point.
        const Real distance = std::sqrt(distanceSquared);
        out.normal = rotation * (-offset / distance);
        const Real depth = sphere.radius - distance;
        out.pointCount = 0;
        // The sphere's own deepest point (the lever arm of friction is then exactly r).
        out.add(sphere.centre + out.normal * sphere.radius, depth, 0);
        return true;
    }

    // Centre inside the box: leave through the face with the least penetration.
    int axis = 0;
    Real leastInside = box.halfExtents.x - std::abs(local.x);
    for (int i = 1; i < 3; ++i) {
        const Real inside = box.halfExtents[i] - std::abs(local[i]);
        if (inside < leastInside) {
            leastInside = inside;
            axis = i;
        }
    }
    Vec3 faceNormal(0);  // box frame, pointing out of the box through the nearest face
    faceNormal[axis] = local[axis] >= Real(0) ? Real(1) : Real(-1);
    out.normal = rotation * (-faceNormal);  // from the sphere into the box
    const Real depth = sphere.radius + leastInside;
    out.pointCount = 0;
    out.add(sphere.centre + out.normal * sphere.radius, depth, 0);
    return true;
}

}  // namespace stepwise
