/// @file broadphase_brute_force.cpp
/// @brief YOUR brute-force broadphase (lecture 3): a student template (lectures/student-template/README.md).
///
/// Copied to student/collision/broadphase_brute_force.cpp, it replaces
/// src/collision/broadphase_brute_force.cpp in the student preset's build. It
/// defines the function src/collision/broadphase.hpp declares:
///
///     void findPairsBruteForce(const BodySet& bodies, std::vector<Aabb>& boxes,
///                              std::vector<CandidatePair>& pairs);
///
/// Stage 4 keeps every pair whose bounding boxes touch, so that the exact
/// tests of stage 5 never miss one (lecture 3, "1. Where the contact comes
/// from", and "Where the code is", stage 4). The boxes are given: boxes[i]
/// for dynamic body i, boxes[dynamicCount + k] for kinematic body k, each
/// grown by kSpeculativeDistance. Test every dynamic body i against
///
///     every dynamic body j > i      boxes[i].overlaps(boxes[j])
///     every kinematic body k        boxes[i].overlaps(boxes[dynamicCount + k])
///     every plane p                 aabbTouchesPlane(boxes[i], bodies.planes[p])
///
/// in that order (the faster broadphases are checked against it, pair for
/// pair), and push_back {i, {BodyKind::Dynamic, j}}, {i, {BodyKind::Kinematic, k}}
/// or {i, {BodyKind::Plane, p}}. Until you write it, the stage stops with
/// "student stage not written yet: stepwise::findPairsBruteForce".
/// Test it: ctest --preset student -L broadphase
#include "collision/broadphase.hpp"
#include "core/student_todo.hpp"

namespace stepwise {

void findPairsBruteForce(const BodySet& bodies, std::vector<Aabb>& boxes, std::vector<CandidatePair>& pairs) {
    pairs.clear();
    const std::size_t dynamicCount = bodies.dynamics.size();
    boxes.resize(dynamicCount + bodies.kinematics.size());
    for (std::size_t i = 0; i < dynamicCount; ++i) boxes[i] = broadphaseBounds(bodies.dynamics[i]);
    for (std::size_t k = 0; k < bodies.kinematics.size(); ++k) {
        boxes[dynamicCount + k] = broadphaseBounds(bodies.kinematics[k]);
    }

    // ==== YOUR CODE BEGINS: lecture 3, stage 4, the broadphase ====
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
    // ==== YOUR CODE ENDS ====
}

}  // namespace stepwise
