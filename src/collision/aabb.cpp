/// @file aabb.cpp
/// @brief Bounding boxes of every shape, and the box–plane test of the broadphase.
#include "collision/aabb.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

Aabb capsuleAabb(const Vec3& centre, const Quat& orientation, Real radius, Real halfHeight) {
    const Vec3 axis = orientation * Vec3(0, 1, 0);  // a, unit: the segment's direction in the world
    const Vec3 extent = halfHeight * glm::abs(axis) + Vec3(radius);
    return {centre - extent, centre + extent};
}

Aabb cylinderAabb(const Vec3& centre, const Quat& orientation, Real radius, Real halfHeight) {
    const Vec3 axis = orientation * Vec3(0, 1, 0);
    Vec3 extent(0);
    for (int i = 0; i < 3; ++i) {
        // 1 − a_i² can come out a few ulps below 0 when a is along e_i: clamp before the root
        const Real across = std::sqrt(glm::max(Real(0), Real(1) - axis[i] * axis[i]));
        extent[i] = halfHeight * std::abs(axis[i]) + radius * across;
    }
    return {centre - extent, centre + extent};
}

namespace {

/// The box of @p points turned by @p orientation and moved to @p centre.
Aabb turnedPointsAabb(const Vec3& centre, const Quat& orientation, const std::vector<Vec3>& points) {
    if (points.empty()) return {centre, centre};
    const Mat3 rotation = glm::mat3_cast(orientation);
    Vec3 lowest(std::numeric_limits<Real>::max());
    Vec3 highest(std::numeric_limits<Real>::lowest());
    for (const Vec3& p : points) {
        const Vec3 q = rotation * p;
        lowest = glm::min(lowest, q);
        highest = glm::max(highest, q);
    }
    return {centre + lowest, centre + highest};
}

/// The box that overlaps every other: for shapes without bounds (geometryAabb()).
Aabb unbounded() {
    const Vec3 far(std::numeric_limits<Real>::infinity());
    return {-far, far};
}

}  // namespace

Aabb hullAabb(const Vec3& centre, const Quat& orientation, const ConvexHull& hull) {
    return turnedPointsAabb(centre, orientation, hull.vertices);
}

Aabb meshAabb(const Vec3& centre, const Quat& orientation, const TriangleMesh& mesh) {
    if (mesh.nodes.empty()) return turnedPointsAabb(centre, orientation, mesh.vertices);
    const MeshNode& root = mesh.nodes.front();
    const Vec3 middle = Real(0.5) * (root.lower + root.upper);  // body frame
    return boxAabb(centre + orientation * middle, orientation, Real(0.5) * (root.upper - root.lower));
}

Aabb geometryAabb(const Geometry& shape) {
    switch (shape.type) {
        case GeometryType::Sphere: return sphereAabb(shape.centre, shape.radius);
        case GeometryType::Box: return boxAabb(shape.centre, shape.orientation, shape.halfExtents);
        case GeometryType::Capsule: return capsuleAabb(shape.centre, shape.orientation, shape.radius, shape.halfHeight);
        case GeometryType::Cylinder:
            return cylinderAabb(shape.centre, shape.orientation, shape.radius, shape.halfHeight);
        case GeometryType::Hull:
            if (shape.hull != nullptr) return hullAabb(shape.centre, shape.orientation, *shape.hull);
            break;
        case GeometryType::Mesh:
            if (shape.mesh != nullptr) return meshAabb(shape.centre, shape.orientation, *shape.mesh);
            break;
        case GeometryType::Plane:
        case GeometryType::Count: break;
    }
    return unbounded();
}

namespace {

/// The union of a compound's parts' boxes; a compound without parts (the loader refuses one) is a point.
Aabb compoundAabb(const Geometry& body, const CompoundShape& compound) {
    Aabb box{body.centre, body.centre};
    for (std::uint32_t i = 0; i < compound.parts.size(); ++i) {
        const Aabb part = geometryAabb(geometryOfPart(body, compound.parts[i], i));
        box = i == 0 ? part : merged(box, part);
    }
    return box;
}

template <class Body>
Aabb exactBounds(const Body& body, const Vec3& position) {
    // Spheres and boxes, nearly every body of a large scene, straight from the body's fields
    switch (body.shape) {
        case Shape::Sphere: return sphereAabb(position, body.radius);
        case Shape::Box: return boxAabb(position, body.orientation, body.halfExtents());
        case Shape::Capsule:
        case Shape::Cylinder:
        case Shape::Hull:
        case Shape::Compound:
        case Shape::Mesh: break;
    }
    Geometry shape = geometryOf(body);
    shape.centre = position;
    if (body.shape == Shape::Compound) return body.compound ? compoundAabb(shape, *body.compound) : Aabb{position, position};
    // A hull or mesh object whose data is missing bounds only its centre, not all of space
    if ((shape.type == GeometryType::Hull && shape.hull == nullptr) ||
        (shape.type == GeometryType::Mesh && shape.mesh == nullptr)) {
        return {position, position};
    }
    return geometryAabb(shape);
}

/// The length of the longest of the eight corner vectors of the box [lower, upper].
Real farthestCorner(const Vec3& lower, const Vec3& upper) {
    const Vec3 far = glm::max(glm::abs(lower), glm::abs(upper));  // each coordinate's larger magnitude
    return glm::length(far);
}

template <class Body>
Real reachOf(const Body& body) {
    const Real h = Real(0.5) * body.height;
    switch (body.shape) {
        case Shape::Sphere: return body.radius;
        case Shape::Box: return glm::length(body.halfExtents());
        case Shape::Capsule: return h + body.radius;
        case Shape::Cylinder: return std::sqrt(h * h + body.radius * body.radius);
        case Shape::Hull: return body.hull ? body.hull->boundingRadius : Real(0);
        case Shape::Compound: return body.compound ? body.compound->boundingRadius : Real(0);
        case Shape::Mesh: break;
    }
    return Real(0);
}

template <class Body>
Aabb grownBounds(const Body& body) {
    Aabb box = exactBounds(body, body.position);
    // Plus the body's sweep (GameObject::sweep): how far it can move this
    // step, so a contact ahead of it is found before the surfaces meet.
    box.min -= Vec3(kSpeculativeDistance + body.sweep);
    box.max += Vec3(kSpeculativeDistance + body.sweep);
    return box;
}

}  // namespace

Aabb shapeAabb(const DynamicObject& body) { return exactBounds(body, body.position); }

Aabb shapeAabb(const KinematicsObject& body) { return exactBounds(body, body.position); }

Aabb shapeAabb(const DynamicObject& body, const Vec3& position) { return exactBounds(body, position); }

Real shapeReach(const DynamicObject& body) { return reachOf(body); }

Real shapeReach(const KinematicsObject& body) {
    if (body.shape != Shape::Mesh) return reachOf(body);
    if (!body.mesh) return Real(0);
    const TriangleMesh& mesh = *body.mesh;
    if (!mesh.nodes.empty()) return farthestCorner(mesh.nodes.front().lower, mesh.nodes.front().upper);
    Real farthest = 0;
    for (const Vec3& v : mesh.vertices) farthest = std::max(farthest, glm::length(v));
    return farthest;
}

Aabb broadphaseBounds(const DynamicObject& body) { return grownBounds(body); }

Aabb broadphaseBounds(const KinematicsObject& body) { return grownBounds(body); }

bool aabbTouchesPlane(const Aabb& box, const CollisionPlane& plane) {
    const Vec3 centre = Real(0.5) * (box.min + box.max);
    const Vec3 halfSize = Real(0.5) * (box.max - box.min);
    const Real reach = glm::dot(glm::abs(plane.normal), halfSize);
    return plane.signedDistance(centre) <= reach + plane.sweep;  // plus how far a knock may carry the body (GameObject::sweep)
}

}  // namespace stepwise
