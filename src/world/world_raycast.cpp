/// @file world_raycast.cpp
/// @brief World::raycast: the first body along a ray, for picking, line of sight and `stepwise raycast`.
#include <cmath>
#include <stdexcept>

#include "world/world.hpp"

namespace stepwise {

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
    auto shapeHit = [&](const auto& body) {
        return body.shape == Shape::Sphere
                   ? intersectRaySphere(origin, d, maxDistance, body.position, body.radius)
                   : intersectRayBox(origin, d, maxDistance, body.position, body.orientation, body.halfExtents());
    };
    for (std::size_t i = 0; i < dynamics_.size(); ++i) consider(BodyKind::Dynamic, i, shapeHit(dynamics_[i]));
    for (std::size_t i = 0; i < kinematics_.size(); ++i) consider(BodyKind::Kinematic, i, shapeHit(kinematics_[i]));
    for (std::size_t i = 0; i < planes_.size(); ++i) {
        consider(BodyKind::Plane, i, intersectRayPlane(origin, d, maxDistance, planes_[i].position, planes_[i].normal));
    }
    return best;
}

}  // namespace stepwise
