/// @file convex_plane.cpp
/// @brief Capsule, cylinder and hull against an infinite plane: the points of each that lie within reach of it.
///
/// A plane through q with unit normal n bounds the solid half-space behind
/// it; a point p is at signed height s = n·(p − q) (negative: behind).
/// As for a box (box_plane.cpp), the deepest part of a convex shape is
/// found among a few points of it, each kept when s ≤ the allowed gap,
/// with depth −s; the manifold normal runs from the shape to the plane, −n.
///
/// * **Capsule:** its two end spheres (centre e, radius r): s = n·(e − q) − r,
///   the point the sphere's deepest point e − r·n (as sphere_plane.cpp, so
///   friction acts with the lever arm r exactly: a capsule rolls as a
///   cylinder would). Feature ids 0 and 1.
/// * **Cylinder:** its rim. A cylinder standing within 5° of upright on a cap
///   gives that cap's four rim points along its own x and z axes (ids 0–7:
///   4·cap + corner), fixed on the body, so their ids stay the same while it
///   stands. Otherwise each cap's lowest rim point, at
///   \f[ c_k - r\,\frac{n - (n\cdot a)a}{|n - (n\cdot a)a|}, \f]
///   and the rim points 90° either side of it (ids 8 + 3·cap + 0, 1, 2): a
///   cylinder lying on its side gets two points, one on a tilted rim one.
///   Each point lies at the middle of the overlap, p − n·s/2.
/// * **Hull:** its vertices within reach (id = vertex number), the point
///   midway as for a box; more than kMaxManifoldPoints are cut down to the
///   deepest and the widest spread (keepSpreadContactPoints()).
#include <algorithm>
#include <cmath>

#include "collision/convex_manifold.hpp"
#include "collision/convex_pairs.hpp"

namespace stepwise {

namespace {

/// Most rim points tried: four per cap.
constexpr int kRimPoints = 8;
/// First feature id of the rim points of a tilted cylinder (after the 8 fixed ones).
constexpr std::uint32_t kTiltedRimIds = 8;

/// Keeps the @p count candidate points, cut down to the deepest and widest when too many.
bool finish(ContactPoint* found, int count, const Geometry& plane, ContactManifold& out) {
    if (count == 0) return false;
    count = keepSpreadContactPoints(found, count, plane.normal);
    out.normal = -plane.normal;
    out.pointCount = 0;
    for (int i = 0; i < count; ++i) out.add(found[i].position, found[i].depth, found[i].featureId);
    return true;
}

}  // namespace

bool capsulePlaneContacts(const Geometry& capsule, const Geometry& plane, Real maxGap, ContactManifold& out) {
    const Vec3 axis = glm::mat3_cast(capsule.orientation)[1];
    out.normal = -plane.normal;
    out.pointCount = 0;
    for (std::uint32_t end = 0; end < 2; ++end) {
        const Vec3 centre = capsule.centre + axis * (end == 0 ? -capsule.halfHeight : capsule.halfHeight);
        const Real height = glm::dot(centre - plane.centre, plane.normal) - capsule.radius;
        if (height <= maxGap) out.add(centre - plane.normal * capsule.radius, -height, end);
    }
    return out.pointCount > 0;
}

bool cylinderPlaneContacts(const Geometry& cylinder, const Geometry& plane, Real maxGap, ContactManifold& out) {
    const Mat3 r = glm::mat3_cast(cylinder.orientation);
    const Vec3 axis = r[1];
    const Real upright = glm::dot(axis, plane.normal);
    Vec3 rim[kRimPoints];
    std::uint32_t ids[kRimPoints];
    for (int cap = 0; cap < 2; ++cap) {
        const Vec3 centre = cylinder.centre + axis * (cap == 0 ? -cylinder.halfHeight : cylinder.halfHeight);
        if (std::abs(upright) >= kFaceContactCosine) {
            const Vec3 spokes[4] = {r[0], r[2], -r[0], -r[2]};
            for (int m = 0; m < 4; ++m) {
                rim[4 * cap + m] = centre + spokes[m] * cylinder.radius;
                ids[4 * cap + m] = static_cast<std::uint32_t>(4 * cap + m);
            }
        } else {
            const Vec3 down = -glm::normalize(plane.normal - axis * upright);  // across the axis, away from the plane's side
            const Vec3 across = glm::cross(axis, down);
            const Vec3 spokes[3] = {down, across, -across};
            for (int m = 0; m < 3; ++m) {
                rim[3 * cap + m] = centre + spokes[m] * cylinder.radius;
                ids[3 * cap + m] = kTiltedRimIds + static_cast<std::uint32_t>(3 * cap + m);
            }
        }
    }
    const int count = std::abs(upright) >= kFaceContactCosine ? 8 : 6;
    ContactPoint found[kRimPoints];
    int foundCount = 0;
    for (int i = 0; i < count; ++i) {
        const Real height = glm::dot(rim[i] - plane.centre, plane.normal);
        if (height <= maxGap) found[foundCount++] = {rim[i] - plane.normal * (Real(0.5) * height), -height, ids[i]};
    }
    return finish(found, foundCount, plane, out);
}

bool hullPlaneContacts(const Geometry& hull, const Geometry& plane, Real maxGap, ContactManifold& out) {
    if (hull.hull == nullptr) return false;
    const Mat3 r = glm::mat3_cast(hull.orientation);
    // Only the vertices within reach are kept; a hull has few of them near a plane at rest.
    constexpr int kMaxCandidates = 64;
    ContactPoint found[kMaxCandidates];
    int foundCount = 0;
    const std::vector<Vec3>& vertices = hull.hull->vertices;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vec3 p = hull.centre + r * vertices[i];
        const Real height = glm::dot(p - plane.centre, plane.normal);
        if (height > maxGap) continue;
        const ContactPoint point{p - plane.normal * (Real(0.5) * height), -height, static_cast<std::uint32_t>(i)};
        if (foundCount < kMaxCandidates) {
            found[foundCount++] = point;
        } else {
            // Full (a hull sunk deep, with many vertices): replace the shallowest.
            ContactPoint* shallowest = std::min_element(found, found + foundCount, [](const ContactPoint& x, const ContactPoint& y) {
                return x.depth < y.depth;
            });
            if (shallowest->depth < point.depth) *shallowest = point;
        }
    }
    return finish(found, foundCount, plane, out);
}

bool collideCapsulePlane(const Geometry& a, const Geometry& b, ContactManifold& out) {
    return capsulePlaneContacts(a, b, kSpeculativeDistance, out);
}

bool collideCylinderPlane(const Geometry& a, const Geometry& b, ContactManifold& out) {
    return cylinderPlaneContacts(a, b, kSpeculativeDistance, out);
}

bool collideHullPlane(const Geometry& a, const Geometry& b, ContactManifold& out) {
    return hullPlaneContacts(a, b, kSpeculativeDistance, out);
}

}  // namespace stepwise
