/// @file broadphase.hpp
/// @brief Stage 4 of the step: find the pairs worth an exact test.
#pragma once

#include <vector>

#include "collision/contact.hpp"
#include "world/body_set.hpp"

namespace stepwise {

/// @brief Axis-aligned bounding box: the smallest box with faces along x, y, z that holds a shape.
struct Aabb {
    Vec3 min{0, 0, 0};  ///< Lowest corner, m.
    Vec3 max{0, 0, 0};  ///< Highest corner, m.

    /// @brief True when the two boxes overlap or touch on every axis (the
    /// separating-axis test restricted to x, y and z).
    bool overlaps(const Aabb& other) const {
        return min.x <= other.max.x && other.min.x <= max.x &&
               min.y <= other.max.y && other.min.y <= max.y &&
               min.z <= other.max.z && other.min.z <= max.z;
    }
};

/// @brief Bounding box of a sphere of @p radius at @p centre.
Aabb sphereAabb(const Vec3& centre, Real radius);

/// @brief Bounding box of an oriented box: centre ± |R|·halfExtents (Ericson, RTCD §4.2.6).
Aabb boxAabb(const Vec3& centre, const Quat& orientation, const Vec3& halfExtents);

/// @brief The brute-force broadphase: test every dynamic body against every other object.
///
/// O(n²) bounding-box tests: the reference every faster broadphase must
/// agree with. Pairs come out in a fixed order (dynamic–dynamic by index,
/// then dynamic–kinematic, then dynamic–plane), so runs are repeatable.
/// @param bodies the world's objects
/// @param boxes  scratch array of bounding boxes, reused between steps (no allocation once sized)
/// @param pairs  output, cleared first
void findPairsBruteForce(const BodySet& bodies, std::vector<Aabb>& boxes, std::vector<CandidatePair>& pairs);

}  // namespace stepwise
