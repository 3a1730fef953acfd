/// @file broadphase_brute_force.cpp
/// @brief Stage 4: the O(n²) broadphase, the reference the faster ones are checked against.
#include "collision/broadphase.hpp"

namespace stepwise {

void findPairsBruteForce(const BodySet& bodies, std::vector<Aabb>& boxes, std::vector<CandidatePair>& pairs) {
    pairs.clear();
    const std::size_t dynamicCount = bodies.dynamics.size();
    boxes.resize(dynamicCount + bodies.kinematics.size());
    for (std::size_t i = 0; i < dynamicCount; ++i) boxes[i] = broadphaseBounds(bodies.dynamics[i]);
    for (std::size_t k = 0; k < bodies.kinematics.size(); ++k) {
        boxes[dynamicCount + k] = broadphaseBounds(bodies.kinematics[k]);
    }

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
