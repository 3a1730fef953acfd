/// @file world_raycast.cpp
/// @brief World::raycast: the first body along a ray, for picking, line of sight and `stepwise raycast`.
#include <cmath>
#include <stdexcept>

#include "collision/narrowphase.hpp"
#include "collision/raycast.hpp"
#include "world/world.hpp"

namespace stepwise {

namespace {

/// The ray against one body's shape (src/collision/raycast.hpp); a compound's
/// hit is the nearest of its parts' (a ray starting inside any part hits at 0).
template <class Body>
std::optional<RayShapeHit> rayAgainstBody(const Vec3& origin, const Vec3& d, Real maxDistance, const Body& body) {
    const Geometry shape = geometryOf(body);
    if (body.shape != Shape::Compound) return intersectRayGeometry(origin, d, maxDistance, shape);
    std::optional<RayShapeHit> nearest;
    if (!body.compound) return nearest;
    const std::vector<CompoundPart>& parts = body.compound->parts;
    for (std::uint32_t i = 0; i < parts.size(); ++i) {
        const Real reach = nearest ? nearest->distance : maxDistance;
        const std::optional<RayShapeHit> hit = intersectRayGeometry(origin, d, reach, geometryOfPart(shape, parts[i], i));
        if (hit && (!nearest || hit->distance < nearest->distance)) nearest = hit;
    }
    return nearest;
}

}  // namespace

/// Every body is tested (O(n)): a raycast is a query made now and then, not
/// a stage of every step. The nearest hit wins; an exact tie goes to the body
/// met first in the order dynamic, kinematic, planes, each by index.
std::optional<RayHit> World::raycast(const Vec3& origin, const Vec3& direction, Real maxDistance) const {
    const Real length = glm::length(direction);
    if (!stepwise::isFinite(origin) || !std::isfinite(length) || std::isnan(maxDistance)) {
        throw std::invalid_argument("raycast: origin, direction and distance must be finite numbers");
    }
    if (length <= 0) throw std::invalid_argument("raycast: the direction must not be zero");
    if (maxDistance < 0) throw std::invalid_argument("raycast: the distance must be >= 0");
    const Vec3 d = direction / length;

    std::optional<RayHit> best;
    auto consider = [&](BodyKind kind, std::size_t index, const std::optional<RayShapeHit>& hit) {
        if (!hit || (best && hit->distance >= best->distance)) return;
        best = RayHit{{kind, static_cast<std::uint32_t>(index)}, origin + hit->distance * d, hit->normal,
                      hit->distance};
    };
    auto shapeHit = [&](const auto& body) { return rayAgainstBody(origin, d, maxDistance, body); };
    for (std::size_t i = 0; i < dynamics_.size(); ++i) consider(BodyKind::Dynamic, i, shapeHit(dynamics_[i]));
    for (std::size_t i = 0; i < kinematics_.size(); ++i) consider(BodyKind::Kinematic, i, shapeHit(kinematics_[i]));
    for (std::size_t i = 0; i < planes_.size(); ++i) {
        consider(BodyKind::Plane, i, intersectRayPlane(origin, d, maxDistance, planes_[i].position, planes_[i].normal));
    }
    return best;
}

}  // namespace stepwise
