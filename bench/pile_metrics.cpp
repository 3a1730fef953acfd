/// @file pile_metrics.cpp
/// @brief The box pile's meter (pile_metrics.hpp).
#include "pile_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace stepwise::bench {

std::vector<Vec3> boxHalfExtentsOf(const Scene& scene) {
    std::vector<Vec3> half;
    half.reserve(scene.dynamics.size());
    for (const DynamicObject& body : scene.dynamics) {
        if (body.shape != Shape::Box) {
            throw std::invalid_argument(body.name + ": the box pile's meter measures boxes only, found a " +
                                        toString(body.shape));
        }
        half.push_back(body.halfExtents());
    }
    return half;
}

BoxPileMeter::BoxPileMeter(std::vector<Vec3> halfExtents, std::vector<OrientedBox> walls,
                           std::vector<CollisionPlane> planes)
    : half_(std::move(halfExtents)), walls_(std::move(walls)), planes_(std::move(planes)) {
    for (const Vec3& h : half_) {
        reach_.push_back(glm::length(h));
        largestReach_ = std::max(largestReach_, reach_.back());
    }
    order_.resize(half_.size());
}

void BoxPileMeter::observe(std::span<const BodyState> bodies) {
    const std::size_t n = std::min(bodies.size(), half_.size());
    Real box = 0, wall = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const OrientedBox b{bodies[i].position, bodies[i].orientation, half_[i]};
        for (const OrientedBox& w : walls_) wall = std::max(wall, boxBoxOverlap(b, w));
        for (const CollisionPlane& p : planes_) {
            // The deepest corner: the box's half shadow on n minus its centre's height above the plane.
            const Mat3 r = glm::mat3_cast(b.orientation);
            const Vec3 normal = glm::normalize(p.normal);
            const Real shadow = b.halfExtents.x * std::abs(glm::dot(r[0], normal)) +
                                b.halfExtents.y * std::abs(glm::dot(r[1], normal)) +
                                b.halfExtents.z * std::abs(glm::dot(r[2], normal));
            wall = std::max(wall, shadow - glm::dot(b.centre - p.position, normal));
        }
    }
    // Sweep and prune along x: sorted by centre x, box j can touch box i only
    // while x_j − x_i ≤ reach_i + largest reach.
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), std::uint32_t(0));
    std::sort(order_.begin(), order_.end(),
              [&](std::uint32_t a, std::uint32_t b) { return bodies[a].position.x < bodies[b].position.x; });
    for (std::size_t s = 0; s < n; ++s) {
        const std::uint32_t i = order_[s];
        const Vec3& pi = bodies[i].position;
        for (std::size_t t = s + 1; t < n; ++t) {
            const std::uint32_t j = order_[t];
            const Vec3& pj = bodies[j].position;
            if (pj.x - pi.x > reach_[i] + largestReach_) break;
            const Real touching = reach_[i] + reach_[j];
            const Vec3 between = pj - pi;
            if (glm::dot(between, between) > touching * touching) continue;  // bounding spheres apart
            box = std::max(box, boxBoxOverlap({pi, bodies[i].orientation, half_[i]},
                                              {pj, bodies[j].orientation, half_[j]}));
        }
    }
    // A body at NaN has blown up; every comparison with NaN is false, so the loops
    // above skipped it: count it as an infinite overlap.
    const bool blownUp = std::any_of(bodies.begin(), bodies.begin() + static_cast<std::ptrdiff_t>(n), [](const BodyState& b) {
        return std::isnan(b.position.x) || std::isnan(b.position.y) || std::isnan(b.position.z);
    });
    if (blownUp) box = wall = std::numeric_limits<Real>::infinity();
    lastBox_ = box;
    lastWall_ = wall;
    worstBox_ = std::max(worstBox_, box);
    worstWall_ = std::max(worstWall_, wall);
}

std::size_t BoxPileMeter::escaped(std::span<const BodyState> bodies) const {
    return static_cast<std::size_t>(std::count_if(bodies.begin(), bodies.end(), [&](const BodyState& b) {
        return outsideLevel(b.position, walls_) ||
               std::any_of(planes_.begin(), planes_.end(),
                           [&](const CollisionPlane& p) { return p.signedDistance(b.position) < 0; });
    }));
}

Real largestSpeed(std::span<const BodyState> bodies) {
    Real fastest = 0;
    for (const BodyState& b : bodies) fastest = std::max(fastest, glm::length(b.velocity));
    return fastest;
}

Real largestSpin(std::span<const BodyState> bodies) {
    Real fastest = 0;
    for (const BodyState& b : bodies) fastest = std::max(fastest, glm::length(b.angularVelocity));
    return fastest;
}

}  // namespace stepwise::bench
