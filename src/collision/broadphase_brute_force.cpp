/// @file broadphase_brute_force.cpp
/// @brief Stage 4: the O(n²) broadphase, the reference the faster ones are checked against.
#include "collision/broadphase.hpp"

#include <cmath>

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

/// Bounds grown by kSpeculativeDistance plus the body's sweep (how far it can
/// move this step): the narrowphase reports contacts that close (touching, or
/// speculative), so the broadphase must not rule such pairs out.
template <class Body>
Aabb boundsOf(const Body& body) {
    Aabb box = body.shape == Shape::Sphere ? sphereAabb(body.position, body.radius)
                                           : boxAabb(body.position, body.orientation, body.halfExtents());
    box.min -= Vec3(kSpeculativeDistance + body.sweep);
    box.max += Vec3(kSpeculativeDistance + body.sweep);
    return box;
}

/// A box is clear of a plane when its corner deepest along −n is still in
/// front: the support distance of an AABB along n is Σ |n_i|·e_i.
bool aabbTouchesPlane(const Aabb& box, const CollisionPlane& plane) {
    const Vec3 centre = Real(0.5) * (box.min + box.max);
    const Vec3 halfSize = Real(0.5) * (box.max - box.min);
    const Real reach = glm::dot(glm::abs(plane.normal), halfSize);
    return plane.signedDistance(centre) <= reach;
}

}  // namespace

void findPairsBruteForce(const BodySet& bodies, std::vector<Aabb>& boxes, std::vector<CandidatePair>& pairs) {
    pairs.clear();
    const std::size_t dynamicCount = bodies.dynamics.size();
    boxes.resize(dynamicCount + bodies.kinematics.size());
    for (std::size_t i = 0; i < dynamicCount; ++i) boxes[i] = boundsOf(bodies.dynamics[i]);
    for (std::size_t k = 0; k < bodies.kinematics.size(); ++k) boxes[dynamicCount + k] = boundsOf(bodies.kinematics[k]);

    for (std::uint32_t i = 0; i < dynamicCount; ++i) {
        for (std::uint32_t j = i + 1; j < dynamicCount; ++j) {
            if (boxes[i].overlaps(boxes[j])) pairs.push_back({i, {BodyKind::Dynamic, j}});
        }
        for (std::uint32_t k = 0; k < bodies.kinematics.size(); ++k) {
            if (boxes[i].overlaps(boxes[dynamicCount + k])) pairs.push_back({i, {BodyKind::Kinematic, k}});
        }
        for (std::uint32_t p = 0; p < bodies.planes.size(); ++p) {
            if (aabbTouchesPlane(boxes[i], bodies.planes[p])) pairs.push_back({i, {BodyKind::Plane, p}});
        }
    }
}

}  // namespace stepwise
