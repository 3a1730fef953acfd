/// @file aabb.cpp
/// @brief Bounding boxes of spheres and oriented boxes, and the box–plane test of the broadphase.
#include "collision/aabb.hpp"

namespace stepwise {

Aabb sphereAabb(const Vec3& centre, Real radius) {
    const Vec3 r(radius);
    return {centre - r, centre + r};
}

Aabb boxAabb(const Vec3& centre, const Quat& orientation, const Vec3& halfExtents) {
    // The box's extent along world axis i is Σ_j |R_ij|·e_j: each body axis
    // contributes its half-length projected onto the world axis.
    const Mat3 rotation = glm::mat3_cast(orientation);
    Vec3 extent(0);
    for (int j = 0; j < 3; ++j) {
        extent += glm::abs(rotation[j]) * halfExtents[j];  // rotation[j] is body axis j in world space
    }
    return {centre - extent, centre + extent};
}

namespace {

template <class Body>
Aabb grownBounds(const Body& body) {
    Aabb box = body.shape == Shape::Sphere ? sphereAabb(body.position, body.radius)
                                           : boxAabb(body.position, body.orientation, body.halfExtents());
    // Plus the body's sweep (GameObject::sweep): how far it can move this
    // step, so a contact ahead of it is found before the surfaces meet.
    box.min -= Vec3(kSpeculativeDistance + body.sweep);
    box.max += Vec3(kSpeculativeDistance + body.sweep);
    return box;
}

}  // namespace

Aabb broadphaseBounds(const DynamicObject& body) { return grownBounds(body); }

Aabb broadphaseBounds(const KinematicsObject& body) { return grownBounds(body); }

bool aabbTouchesPlane(const Aabb& box, const CollisionPlane& plane) {
    const Vec3 centre = Real(0.5) * (box.min + box.max);
    const Vec3 halfSize = Real(0.5) * (box.max - box.min);
    const Real reach = glm::dot(glm::abs(plane.normal), halfSize);
    return plane.signedDistance(centre) <= reach + plane.sweep;  // plus how far a knock may carry the body (GameObject::sweep)
}

}  // namespace stepwise
