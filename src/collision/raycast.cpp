/// @file raycast.cpp
/// @brief Ray against every shape: the first point where the ray enters each.
#include "collision/raycast.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace stepwise {

namespace {

/// The answer for a ray that starts inside the shape (see raycast.hpp).
RayShapeHit startsInside(const Vec3& direction) { return {0, -direction}; }

/// A ray turned into a shape's frame: o' = Rᵀ(o − c), d' = Rᵀd (d' stays a unit vector).
struct LocalRay {
    Vec3 origin;
    Vec3 direction;
};

LocalRay toShapeFrame(const Vec3& origin, const Vec3& direction, const Vec3& centre, const Quat& orientation) {
    const Quat toBody = glm::conjugate(orientation);
    return {toBody * (origin - centre), toBody * direction};
}

/// The roots t₀ ≤ t₁ of the ray's crossings of the infinite cylinder x² + z² = r² about y
/// (intersectRayCapsule() in raycast.hpp), or nothing when the line misses it or runs along y.
struct Crossings {
    Real enter;
    Real exit;
};

std::optional<Crossings> roundSideCrossings(const LocalRay& ray, Real radius) {
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    const Real a = d.x * d.x + d.z * d.z;
    if (a < kRayParallelTolerance) return std::nullopt;  // along the axis: never crosses the side
    const Real b = o.x * d.x + o.z * d.z;
    const Real c = o.x * o.x + o.z * o.z - radius * radius;
    const Real discriminant = b * b - a * c;
    if (discriminant < 0) return std::nullopt;  // the line passes the cylinder by
    const Real root = std::sqrt(discriminant);
    return Crossings{(-b - root) / a, (-b + root) / a};
}

/// The outward normal of the round side at the local point @p p: (x, 0, z)/r.
Vec3 roundSideNormal(const Vec3& p, Real radius) { return Vec3(p.x, 0, p.z) / radius; }

/// Where the ray enters the box [lower, upper] (its frame's axes), t ≥ 0, if before @p maxDistance.
std::optional<Real> rayEntersBox(const LocalRay& ray, const Vec3& lower, const Vec3& upper, Real maxDistance) {
    Real enter = 0;
    Real exit = maxDistance;
    for (int i = 0; i < 3; ++i) {
        const Real o = ray.origin[i];
        const Real d = ray.direction[i];
        if (std::abs(d) < kRayParallelTolerance) {
            if (o < lower[i] || o > upper[i]) return std::nullopt;
            continue;
        }
        Real near = (lower[i] - o) / d;
        Real far = (upper[i] - o) / d;
        if (near > far) std::swap(near, far);
        enter = std::max(enter, near);
        exit = std::min(exit, far);
        if (enter > exit) return std::nullopt;
    }
    return enter;
}

/// The nearest of @p hit and @p candidate.
void keepNearer(std::optional<RayShapeHit>& hit, const std::optional<RayShapeHit>& candidate) {
    if (candidate && (!hit || candidate->distance < hit->distance)) hit = candidate;
}

/// Every triangle of @p mesh, one by one: for a mesh without a hierarchy, or one too deep for the stack.
std::optional<RayShapeHit> everyTriangle(const LocalRay& ray, Real maxDistance, const TriangleMesh& mesh) {
    std::optional<RayShapeHit> nearest;
    const std::size_t vertexCount = mesh.vertices.size();
    for (const std::array<std::uint32_t, 3>& t : mesh.triangles) {
        if (t[0] >= vertexCount || t[1] >= vertexCount || t[2] >= vertexCount) continue;  // the loader refuses these
        const Real reach = nearest ? nearest->distance : maxDistance;
        keepNearer(nearest, intersectRayTriangle(ray.origin, ray.direction, reach, mesh.vertices[t[0]],
                                                 mesh.vertices[t[1]], mesh.vertices[t[2]]));
    }
    return nearest;
}

/// The hierarchy's descent (intersectRayMesh()); nothing in `overflow` when the stack sufficed.
std::optional<RayShapeHit> descend(const LocalRay& ray, Real maxDistance, const TriangleMesh& mesh, bool& overflow) {
    std::optional<RayShapeHit> nearest;
    std::array<std::uint32_t, kMaxMeshDepth> stack{};  // nodes still to visit; the nearer child on top
    int top = 0;
    stack[top++] = 0;
    const std::size_t nodeCount = mesh.nodes.size();
    const std::size_t vertexCount = mesh.vertices.size();
    while (top > 0) {
        const MeshNode& node = mesh.nodes[stack[--top]];
        const Real reach = nearest ? nearest->distance : maxDistance;
        if (!rayEntersBox(ray, node.lower, node.upper, reach)) continue;
        if (node.count > 0) {  // a leaf
            for (std::uint32_t k = node.first; k < node.first + node.count && k < mesh.order.size(); ++k) {
                const std::uint32_t index = mesh.order[k];
                if (index >= mesh.triangles.size()) continue;
                const std::array<std::uint32_t, 3>& t = mesh.triangles[index];
                if (t[0] >= vertexCount || t[1] >= vertexCount || t[2] >= vertexCount) continue;
                keepNearer(nearest, intersectRayTriangle(ray.origin, ray.direction,
                                                         nearest ? nearest->distance : maxDistance,
                                                         mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
            }
            continue;
        }
        if (node.first + std::size_t(1) >= nodeCount) continue;  // children out of range: the loader refuses these
        if (top + 2 > kMaxMeshDepth) {
            overflow = true;
            return std::nullopt;
        }
        // Nearer child last, so it is popped first and its hit can rule out the other.
        const MeshNode& left = mesh.nodes[node.first];
        const MeshNode& right = mesh.nodes[node.first + 1];
        const std::optional<Real> toLeft = rayEntersBox(ray, left.lower, left.upper, reach);
        const std::optional<Real> toRight = rayEntersBox(ray, right.lower, right.upper, reach);
        const bool leftFirst = toLeft && (!toRight || *toLeft <= *toRight);
        const std::uint32_t nearChild = leftFirst ? node.first : node.first + 1;
        const std::uint32_t farChild = leftFirst ? node.first + 1 : node.first;
        if (leftFirst ? toRight.has_value() : toLeft.has_value()) stack[top++] = farChild;
        if (toLeft || toRight) stack[top++] = nearChild;
    }
    return nearest;
}

}  // namespace

std::optional<RayShapeHit> intersectRaySphere(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                              const Vec3& centre, Real radius) {
    const Vec3 m = origin - centre;
    const Real b = glm::dot(m, direction);
    const Real c = glm::dot(m, m) - radius * radius;
    if (c <= 0) return startsInside(direction);
    if (b > 0) return std::nullopt;  // outside and heading away
    const Real discriminant = b * b - c;
    if (discriminant < 0) return std::nullopt;  // the line passes the sphere by
    const Real t = -b - std::sqrt(discriminant);
    if (t > maxDistance) return std::nullopt;
    return RayShapeHit{t, (origin + t * direction - centre) / radius};
}

std::optional<RayShapeHit> intersectRayBox(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                           const Vec3& centre, const Quat& orientation, const Vec3& halfExtents) {
    const Quat toBody = glm::conjugate(orientation);
    const Vec3 o = toBody * (origin - centre);
    const Vec3 d = toBody * direction;
    Real enter = 0;  // entries behind the origin do not count: t ≥ 0
    Real exit = maxDistance;
    int enterAxis = -1;  // stays −1 when the origin is inside every slab
    Real enterSign = 0;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d[i]) < kRayParallelTolerance) {
            if (std::abs(o[i]) > halfExtents[i]) return std::nullopt;  // parallel to the slab and outside it
            continue;
        }
        const Real near = (-std::copysign(halfExtents[i], d[i]) - o[i]) / d[i];  // the face the ray meets first
        const Real far = (std::copysign(halfExtents[i], d[i]) - o[i]) / d[i];
        if (near > enter) {
            enter = near;
            enterAxis = i;
            enterSign = d[i] > 0 ? Real(-1) : Real(1);  // that face's outward normal is against the ray
        }
        if (far < exit) exit = far;
        if (enter > exit) return std::nullopt;
    }
    if (enterAxis < 0) return startsInside(direction);
    Vec3 normal(0);
    normal[enterAxis] = enterSign;
    return RayShapeHit{enter, orientation * normal};
}

std::optional<RayShapeHit> intersectRayCapsule(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                               const Vec3& centre, const Quat& orientation, Real radius,
                                               Real halfHeight) {
    const LocalRay ray = toShapeFrame(origin, direction, centre, orientation);
    // Inside when the origin is within r of the segment: its nearest point has y clamped to [−h, h].
    const Vec3 nearestOnSegment(0, glm::clamp(ray.origin.y, -halfHeight, halfHeight), 0);
    const Vec3 fromSegment = ray.origin - nearestOnSegment;
    if (glm::dot(fromSegment, fromSegment) <= radius * radius) return startsInside(direction);

    std::optional<RayShapeHit> hit;  // in the capsule's frame until the end
    if (const std::optional<Crossings> side = roundSideCrossings(ray, radius)) {
        const Real t = side->enter;
        const Vec3 p = ray.origin + t * ray.direction;
        if (t >= 0 && t <= maxDistance && std::abs(p.y) <= halfHeight) hit = RayShapeHit{t, roundSideNormal(p, radius)};
    }
    for (const Real end : {-halfHeight, halfHeight}) {
        keepNearer(hit, intersectRaySphere(ray.origin, ray.direction, maxDistance, Vec3(0, end, 0), radius));
    }
    if (hit) hit->normal = orientation * hit->normal;
    return hit;
}

std::optional<RayShapeHit> intersectRayCylinder(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                                const Vec3& centre, const Quat& orientation, Real radius,
                                                Real halfHeight) {
    const LocalRay ray = toShapeFrame(origin, direction, centre, orientation);
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    Real enter = 0;  // entries behind the origin do not count: t ≥ 0
    Real exit = maxDistance;
    bool throughCap = false;  // which surface the latest entry crossed
    bool entered = false;     // false while the origin is inside both the slab and the round side
    // The slab |y| ≤ h
    if (std::abs(d.y) < kRayParallelTolerance) {
        if (std::abs(o.y) > halfHeight) return std::nullopt;  // parallel to the caps and beyond one
    } else {
        const Real near = (-std::copysign(halfHeight, d.y) - o.y) / d.y;
        const Real far = (std::copysign(halfHeight, d.y) - o.y) / d.y;
        if (near > enter) {
            enter = near;
            throughCap = true;
            entered = true;
        }
        exit = std::min(exit, far);
    }
    // The round side x² + z² ≤ r²
    if (const std::optional<Crossings> side = roundSideCrossings(ray, radius)) {
        if (side->enter > enter) {
            enter = side->enter;
            throughCap = false;
            entered = true;
        }
        exit = std::min(exit, side->exit);
    } else if (o.x * o.x + o.z * o.z > radius * radius) {
        return std::nullopt;  // along the axis outside the side, or the line passes by
    }
    if (enter > exit) return std::nullopt;
    if (!entered) return startsInside(direction);
    const Vec3 normal = throughCap ? Vec3(0, d.y > 0 ? Real(-1) : Real(1), 0)
                                   : roundSideNormal(o + enter * d, radius);
    return RayShapeHit{enter, orientation * normal};
}

std::optional<RayShapeHit> intersectRayHull(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                            const Vec3& centre, const Quat& orientation, const ConvexHull& hull) {
    if (hull.faces.empty()) return std::nullopt;
    const LocalRay ray = toShapeFrame(origin, direction, centre, orientation);
    Real enter = 0;
    Real exit = maxDistance;
    const HullFace* enteredBy = nullptr;  // stays null when the origin is inside every face's half-space
    for (const HullFace& face : hull.faces) {
        const Real approach = glm::dot(face.normal, ray.direction);            // n·d'
        const Real room = face.offset - glm::dot(face.normal, ray.origin);      // e − n·o': ≥ 0 inside
        if (std::abs(approach) < kRayParallelTolerance) {
            if (room < 0) return std::nullopt;  // parallel to the face and outside it
            continue;
        }
        const Real t = room / approach;
        if (approach < 0) {  // heading in through this face
            if (t > enter) {
                enter = t;
                enteredBy = &face;
            }
        } else if (t < exit) {  // heading out through it
            exit = t;
        }
        if (enter > exit) return std::nullopt;
    }
    if (enteredBy == nullptr) return startsInside(direction);
    return RayShapeHit{enter, orientation * enteredBy->normal};
}

std::optional<RayShapeHit> intersectRayTriangle(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                                const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 e1 = b - a;
    const Vec3 e2 = c - a;
    const Vec3 p = glm::cross(direction, e2);
    const Real det = glm::dot(e1, p);
    // det = d·(e₁ × e₂) scaled: compared with the triangle's own size, so the test does not depend on units
    const Vec3 area = glm::cross(e1, e2);
    const Real areaLength = glm::length(area);
    if (areaLength <= 0 || std::abs(det) < kRayParallelTolerance * areaLength) return std::nullopt;
    const Real inverse = Real(1) / det;
    const Vec3 s = origin - a;
    const Real u = glm::dot(s, p) * inverse;
    if (u < 0 || u > 1) return std::nullopt;
    const Vec3 q = glm::cross(s, e1);
    const Real v = glm::dot(direction, q) * inverse;
    if (v < 0 || u + v > 1) return std::nullopt;
    const Real t = glm::dot(e2, q) * inverse;
    if (t < 0 || t > maxDistance) return std::nullopt;
    const Vec3 normal = area / areaLength;
    return RayShapeHit{t, glm::dot(normal, direction) > 0 ? -normal : normal};
}

std::optional<RayShapeHit> intersectRayMesh(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                            const Vec3& centre, const Quat& orientation, const TriangleMesh& mesh) {
    const LocalRay ray = toShapeFrame(origin, direction, centre, orientation);
    std::optional<RayShapeHit> hit;
    bool overflow = false;
    if (!mesh.nodes.empty()) hit = descend(ray, maxDistance, mesh, overflow);
    if (mesh.nodes.empty() || overflow) hit = everyTriangle(ray, maxDistance, mesh);
    if (hit) hit->normal = orientation * hit->normal;
    return hit;
}

std::optional<RayShapeHit> intersectRayGeometry(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                                const Geometry& g) {
    switch (g.type) {
        case GeometryType::Sphere: return intersectRaySphere(origin, direction, maxDistance, g.centre, g.radius);
        case GeometryType::Box:
            return intersectRayBox(origin, direction, maxDistance, g.centre, g.orientation, g.halfExtents);
        case GeometryType::Plane: return intersectRayPlane(origin, direction, maxDistance, g.centre, g.normal);
        case GeometryType::Capsule:
            return intersectRayCapsule(origin, direction, maxDistance, g.centre, g.orientation, g.radius, g.halfHeight);
        case GeometryType::Cylinder:
            return intersectRayCylinder(origin, direction, maxDistance, g.centre, g.orientation, g.radius, g.halfHeight);
        case GeometryType::Hull:
            if (g.hull == nullptr) return std::nullopt;
            return intersectRayHull(origin, direction, maxDistance, g.centre, g.orientation, *g.hull);
        case GeometryType::Mesh:
            if (g.mesh == nullptr) return std::nullopt;
            return intersectRayMesh(origin, direction, maxDistance, g.centre, g.orientation, *g.mesh);
        case GeometryType::Count: break;
    }
    return std::nullopt;
}

std::optional<RayShapeHit> intersectRayPlane(const Vec3& origin, const Vec3& direction, Real maxDistance,
                                             const Vec3& point, const Vec3& normal) {
    const Real height = glm::dot(origin - point, normal);
    if (height <= 0) return startsInside(direction);  // in the solid half-space
    const Real approach = -glm::dot(direction, normal);
    if (approach <= 0) return std::nullopt;  // parallel, or heading away
    const Real t = height / approach;
    if (t > maxDistance) return std::nullopt;
    return RayShapeHit{t, normal};
}

}  // namespace stepwise
