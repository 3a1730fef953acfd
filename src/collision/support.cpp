/// @file support.cpp
/// @brief Support points of points, segments, boxes, cylinders, hulls and triangles (support.hpp gives the formulas).
#include "collision/support.hpp"

#include <cmath>

namespace stepwise {

namespace {

/// Directions shorter than this (in any unit: only its sign and direction matter) have no
/// direction; a cylinder then answers with its cap's centre, support() adds no margin.
constexpr Real kTinyDirectionSquared = Real(1e-30);

/// +1 for x ≥ 0, −1 otherwise: a tie (x = 0) picks the + side, so ties are repeatable.
Real signOf(Real x) { return x >= Real(0) ? Real(1) : Real(-1); }

/// Index of the point among @p count with the largest d·p (the first on a tie).
template <class Point>
std::size_t farthestAlong(const Point* points, std::size_t count, const Vec3& direction) {
    std::size_t best = 0;
    Real bestDot = glm::dot(Vec3(points[0]), direction);
    for (std::size_t i = 1; i < count; ++i) {
        const Real value = glm::dot(Vec3(points[i]), direction);
        if (value > bestDot) {
            bestDot = value;
            best = i;
        }
    }
    return best;
}

}  // namespace

ConvexShape convexShapeOf(const Geometry& geometry) {
    ConvexShape shape;
    shape.centre = geometry.centre;
    shape.rotation = glm::mat3_cast(geometry.orientation);
    switch (geometry.type) {
        case GeometryType::Sphere:
            shape.core = ConvexCore::Point;
            shape.rotation = Mat3(1);  // a sphere has no orientation of its own
            shape.margin = geometry.radius;
            break;
        case GeometryType::Capsule:
            shape.core = ConvexCore::Segment;
            shape.halfHeight = geometry.halfHeight;
            shape.margin = geometry.radius;
            break;
        case GeometryType::Box:
            shape.core = ConvexCore::Box;
            shape.halfExtents = geometry.halfExtents;
            break;
        case GeometryType::Cylinder:
            shape.core = ConvexCore::Cylinder;
            shape.halfHeight = geometry.halfHeight;
            shape.discRadius = geometry.radius;
            break;
        case GeometryType::Hull:
            shape.core = geometry.hull != nullptr ? ConvexCore::Hull : ConvexCore::Point;
            shape.hull = geometry.hull;
            break;
        case GeometryType::Plane:
        case GeometryType::Mesh:
        case GeometryType::Count: break;  // not convex shapes: a point, which the pair tests never ask for
    }
    return shape;
}

ConvexShape convexShapeOfTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    ConvexShape shape;
    shape.core = ConvexCore::Triangle;
    shape.corners[0] = p0;
    shape.corners[1] = p1;
    shape.corners[2] = p2;
    shape.centre = (p0 + p1 + p2) / Real(3);
    return shape;
}

Vec3 coreSupport(const ConvexShape& shape, const Vec3& direction) {
    switch (shape.core) {
        case ConvexCore::Point: return shape.centre;
        case ConvexCore::Segment: {
            const Vec3 axis = shape.rotation[1];
            return shape.centre + axis * (signOf(glm::dot(axis, direction)) * shape.halfHeight);
        }
        case ConvexCore::Box: {
            Vec3 p = shape.centre;
            for (int i = 0; i < 3; ++i) {
                p += shape.rotation[i] * (signOf(glm::dot(shape.rotation[i], direction)) * shape.halfExtents[i]);
            }
            return p;
        }
        case ConvexCore::Cylinder: {
            const Vec3 local = glm::transpose(shape.rotation) * direction;
            const Real across = local.x * local.x + local.z * local.z;  // ρ²
            Vec3 point(0, signOf(local.y) * shape.halfHeight, 0);
            if (across > kTinyDirectionSquared) {
                const Real scale = shape.discRadius / std::sqrt(across);
                point.x = local.x * scale;
                point.z = local.z * scale;
            }
            return shape.centre + shape.rotation * point;
        }
        case ConvexCore::Hull: {
            const Vec3 local = glm::transpose(shape.rotation) * direction;
            const std::vector<Vec3>& vertices = shape.hull->vertices;
            return shape.centre + shape.rotation * vertices[farthestAlong(vertices.data(), vertices.size(), local)];
        }
        case ConvexCore::Triangle: return shape.corners[farthestAlong(shape.corners, 3, direction)];
    }
    return shape.centre;
}

Vec3 support(const ConvexShape& shape, const Vec3& direction) {
    const Vec3 core = coreSupport(shape, direction);
    if (shape.margin == Real(0)) return core;
    const Real lengthSquared = glm::dot(direction, direction);
    if (lengthSquared <= kTinyDirectionSquared) return core;
    return core + direction * (shape.margin / std::sqrt(lengthSquared));
}

}  // namespace stepwise
