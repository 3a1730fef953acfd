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
/// depth r + (eᵢ − |c'ᵢ|). Both halves, pointFromBox() and nearestFace()
/// (closest_points.hpp), are shared with the continuous stage's separation
/// (continuous.cpp), so the two measure a sphere against a box the same way.
#include <cmath>

#include "collision/closest_points.hpp"
#include "collision/narrowphase.hpp"

namespace stepwise {

bool collideSphereBox(const Geometry& sphere, const Geometry& box, ContactManifold& out) {
    const PointFromBox seen = pointFromBox(sphere.centre, box.centre, box.orientation, box.halfExtents);
    const Vec3 offset = seen.offset;  // from the box surface to the centre, box frame
    const Real distanceSquared = glm::dot(offset, offset);
    const Real reach = sphere.radius + kTouchTolerance;
    if (distanceSquared > reach * reach) return false;

    if (distanceSquared > Real(0)) {
        // Centre outside the box: the normal runs from the sphere's centre to the closest point.
        const Real distance = std::sqrt(distanceSquared);
        out.normal = seen.rotation * (-offset / distance);
        const Real depth = sphere.radius - distance;
        out.pointCount = 0;
        // The sphere's own deepest point (the lever arm of friction is then exactly r).
        out.add(sphere.centre + out.normal * sphere.radius, depth, 0);
        return true;
    }

    // Centre inside the box: leave through the face with the least penetration.
    const NearestFace face = nearestFace(seen.local, box.halfExtents);
    out.normal = seen.rotation * (-face.normal);  // from the sphere into the box
    const Real depth = sphere.radius + face.inside;
    out.pointCount = 0;
    out.add(sphere.centre + out.normal * sphere.radius, depth, 0);
    return true;
}

}  // namespace stepwise
