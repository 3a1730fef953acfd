/// @file capsule_contacts.cpp
/// @brief Capsule against capsule and against sphere: closest points of segments, then spheres.
///
/// A capsule is every point within r of a segment, so two capsules (or a
/// capsule and a sphere, a segment of length 0) touch exactly when their
/// segments come within r_A + r_B of each other. With p_A, p_B the closest
/// points of the two segments (closest_points.hpp, Ericson §5.1.9) and
/// d = |p_B − p_A|, this is sphere against sphere at p_A and p_B:
/// \f[ n = \frac{p_B - p_A}{d}, \qquad \text{depth} = r_A + r_B - d, \f]
/// with the contact point midway between the two surfaces,
/// ½((p_A + r_A n) + (p_B − r_B n)).
///
/// **Side by side.** Two parallel capsules lying on each other touch along
/// a line, and one point in its middle would let them roll about it. When
/// the segments are within kParallelCapsuleSine of parallel, the part of B's
/// segment that lies over A's (B's ends projected on A's axis, clamped to
/// A's ends) gives two points, one at each end of the overlap, both with
/// the normal n found above.
///
/// **Crossing segments** (d = 0: the cores overlap) have no direction:
/// GJK and EPA are asked instead (collideConvex()), which find the way out
/// from the capsules' surfaces.
#include <cmath>

#include "collision/closest_points.hpp"
#include "collision/convex_pairs.hpp"

namespace stepwise {

namespace {

/// Segments closer than this, m, cross: no normal between them.
constexpr Real kCrossingSegments = Real(1e-9);

/// Segments at less than this sine of an angle (about 1.1°) count as
/// parallel: two points. A capsule lying on another rolls by a hair as it
/// settles; the two points must survive that, and at 1° the ends of a 1 m
/// capsule are 2 cm apart in height, already beyond the contact's reach.
constexpr Real kParallelCapsuleSine = Real(0.02);

/// The overlap of B's segment over A's is two points only if longer than this, m.
constexpr Real kShortestOverlap = Real(1e-6);

/// Feature ids: the one closest pair, or the two ends of a side-by-side overlap.
constexpr std::uint32_t kClosestPair = 0;
constexpr std::uint32_t kOverlapStart = 1;
constexpr std::uint32_t kOverlapEnd = 2;

struct Segment {
    Vec3 from;
    Vec3 to;
};

Segment segmentOf(const Geometry& g) {
    if (g.type != GeometryType::Capsule) return {g.centre, g.centre};  // a sphere: a segment of length 0
    const Vec3 axis = glm::mat3_cast(g.orientation)[1];
    return {g.centre - axis * g.halfHeight, g.centre + axis * g.halfHeight};
}

/// Adds the point where the surfaces around @p onA and @p onB meet along @p n.
void addPair(const Vec3& onA, const Vec3& onB, const Vec3& n, Real radiusA, Real radiusB, Real maxGap,
             std::uint32_t id, ContactManifold& out) {
    const Real gap = glm::dot(onB - onA, n) - radiusA - radiusB;
    if (gap > maxGap) return;
    out.add(Real(0.5) * ((onA + n * radiusA) + (onB - n * radiusB)), -gap, id);
}

}  // namespace

bool capsuleContacts(const Geometry& a, const Geometry& b, Real maxGap, ContactManifold& out) {
    const Segment sa = segmentOf(a);
    const Segment sb = segmentOf(b);
    const SegmentClosestPoints closest = closestPointsOfSegments(sa.from, sa.to, sb.from, sb.to);
    const Vec3 between = closest.onSecond - closest.onFirst;
    const Real distance = glm::length(between);
    if (distance - a.radius - b.radius > maxGap) return false;
    if (distance <= kCrossingSegments) return collideConvex(a, b, NarrowphaseKind::GjkEpa, maxGap, out);
    const Vec3 n = between / distance;
    out.normal = n;
    out.pointCount = 0;

    const Vec3 dA = sa.to - sa.from;
    const Vec3 dB = sb.to - sb.from;
    const Real lengthA2 = glm::dot(dA, dA);
    const Real crossLength = glm::length(glm::cross(dA, dB));
    const bool parallel = lengthA2 > 0 && glm::dot(dB, dB) > 0 &&
                          crossLength <= kParallelCapsuleSine * std::sqrt(lengthA2 * glm::dot(dB, dB));
    if (parallel) {
        // B's ends projected on A's axis, as parameters s of A's segment, clamped to it.
        Real s0 = glm::dot(sb.from - sa.from, dA) / lengthA2;
        Real s1 = glm::dot(sb.to - sa.from, dA) / lengthA2;
        if (s0 > s1) std::swap(s0, s1);
        s0 = std::max(s0, Real(0));
        s1 = std::min(s1, Real(1));
        if ((s1 - s0) * std::sqrt(lengthA2) > kShortestOverlap) {
            for (const auto& [s, id] : {std::pair{s0, kOverlapStart}, std::pair{s1, kOverlapEnd}}) {
                const Vec3 onA = sa.from + dA * s;
                const SegmentClosestPoints c = closestPointsOfSegments(onA, onA, sb.from, sb.to);
                addPair(onA, c.onSecond, n, a.radius, b.radius, maxGap, id, out);
            }
            if (out.pointCount > 0) return true;
        }
    }
    addPair(closest.onFirst, closest.onSecond, n, a.radius, b.radius, maxGap, kClosestPair, out);
    return out.pointCount > 0;
}

bool collideCapsuleCapsule(const Geometry& a, const Geometry& b, ContactManifold& out) {
    return collideConvex(a, b, NarrowphaseKind::Auto, kSpeculativeDistance, out);
}

bool collideCapsuleSphere(const Geometry& a, const Geometry& b, ContactManifold& out) {
    return collideConvex(a, b, NarrowphaseKind::Auto, kSpeculativeDistance, out);
}

bool collideSphereCapsule(const Geometry& a, const Geometry& b, ContactManifold& out) {
    return collideConvex(a, b, NarrowphaseKind::Auto, kSpeculativeDistance, out);
}

}  // namespace stepwise
