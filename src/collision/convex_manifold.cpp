/// @file convex_manifold.cpp
/// @brief Features along the normal, reference and incident, clipping, and the spread points (convex_manifold.hpp).
#include "collision/convex_manifold.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "collision/box_features.hpp"
#include "collision/clip_polygon.hpp"
#include "collision/support.hpp"

namespace stepwise {

namespace {

/// The reference face's bias, as SAT's (box_box.cpp section 2): a challenger
/// (B's face over A's, an edge over the face) must separate more than this
/// fraction of the incumbent's separation…
constexpr Real kFaceBiasRelative = Real(0.95);
/// …plus this fraction of the smaller shape's inner size (innerSize()).
constexpr Real kFaceBiasAbsolute = Real(0.01);

/// Labels of the reference face's side planes start here; the incident
/// polygon's own edges are 0 … kMaxFeatureVertices − 1.
constexpr std::uint8_t kFirstSideLabel = kMaxFeatureVertices;

/// The incident polygon plus one vertex per reference side plane.
constexpr int kMaxClipped = 2 * kMaxFeatureVertices;

/// Feature-id layout of a clipped point (bit 0 lowest):
/// bits 0–6 label of the edge arriving at the point, 7–13 the edge leaving it,
/// 14–21 incident feature, 22–29 reference feature, 30 reference is B's, 31 set.
constexpr int kOutLabelShift = 7;
constexpr int kIncidentShift = 14;
constexpr int kReferenceShift = 22;
constexpr std::uint32_t kReferenceIsB = 1u << 30;
constexpr std::uint32_t kClippedPoint = 1u << 31;
/// A single-point contact's id: A's feature in bits 0–7, B's in bits 8–15, and bit 16 set.
constexpr int kSecondFeatureShift = 8;
constexpr std::uint32_t kSinglePoint = 1u << 16;
constexpr std::uint32_t kByte = 0xFFu;
constexpr std::uint32_t kLabelMask = 0x7Fu;

/// What one shape shows along a direction: a point, a segment or a face.
struct Feature {
    int count = 0;                     // 1 point, 2 segment, ≥ 3 face (counter-clockwise seen from outside)
    Vec3 points[kMaxFeatureVertices];  // world, m
    Vec3 normal{0, 0, 0};              // a face's outward unit normal
    Real margin = 0;                   // radius around the points (capsule, sphere), m
    std::uint32_t id = 0;              // which face, segment or point of the shape
};

void pointFeature(const Vec3& p, std::uint32_t id, Feature& f) {
    f.count = 1;
    f.points[0] = p;
    f.id = id;
}

void boxFeature(const Geometry& box, const Vec3& direction, Feature& f) {
    const OrientedBox b = orientedBoxOf(box);
    int axis = 0;
    Real sign = 1;
    Real best = -2;
    for (int i = 0; i < 3; ++i) {
        const Real along = glm::dot(b.axes[i], direction);
        if (std::abs(along) > best) {
            best = std::abs(along);
            axis = i;
            sign = along >= 0 ? Real(1) : Real(-1);
        }
    }
    const int j = (axis + 1) % 3;
    const int k = (axis + 2) % 3;
    const Vec3 centre = b.centre + b.axes[axis] * (sign * b.halfExtents[axis]);
    const Vec3 alongJ = b.axes[j] * b.halfExtents[j];
    const Vec3 alongK = b.axes[k] * b.halfExtents[k];
    // Corners (−,−), (+,−), (+,+), (−,+) on (j, k) run counter-clockwise seen from +axis (u_j × u_k = u_axis).
    constexpr Real kSignJ[4] = {-1, 1, 1, -1};
    constexpr Real kSignK[4] = {-1, -1, 1, 1};
    for (int m = 0; m < 4; ++m) {
        const int corner = sign > 0 ? m : 3 - m;  // seen from −axis the loop runs the other way
        f.points[m] = centre + alongJ * kSignJ[corner] + alongK * kSignK[corner];
    }
    f.count = 4;
    f.normal = b.axes[axis] * sign;
    f.id = static_cast<std::uint32_t>(faceIndex(axis, sign));
}

void hullFeature(const Geometry& hullGeometry, const Vec3& direction, Feature& f) {
    const ConvexHull& hull = *hullGeometry.hull;
    const Mat3 rotation = glm::mat3_cast(hullGeometry.orientation);
    const Vec3 local = glm::transpose(rotation) * direction;
    std::size_t bestFace = 0;
    Real best = -2;
    for (std::size_t i = 0; i < hull.faces.size(); ++i) {
        const Real along = glm::dot(hull.faces[i].normal, local);
        if (along > best) {
            best = along;
            bestFace = i;
        }
    }
    const HullFace& face = hull.faces[bestFace];
    if (face.indexCount > static_cast<std::uint32_t>(kMaxFeatureVertices)) {
        pointFeature(coreSupport(convexShapeOf(hullGeometry), direction), static_cast<std::uint32_t>(bestFace), f);
        return;
    }
    f.count = static_cast<int>(face.indexCount);
    for (int m = 0; m < f.count; ++m) {
        f.points[m] = hullGeometry.centre + rotation * hull.vertices[hull.faceIndices[face.firstIndex + static_cast<std::uint32_t>(m)]];
    }
    f.normal = rotation * face.normal;
    f.id = static_cast<std::uint32_t>(bestFace);
}

/// Feature ids of a cylinder: its two caps, its side line, one rim point.
enum CylinderFeature : std::uint32_t { kTopCap = 0, kBottomCap = 1, kSide = 2, kRimPoint = 3 };

void cylinderFeature(const Geometry& cylinder, const Vec3& direction, Feature& f) {
    const Mat3 r = glm::mat3_cast(cylinder.orientation);
    const Vec3 axis = r[1];
    const Real along = glm::dot(axis, direction);
    if (std::abs(along) >= kFaceContactCosine) {
        const Real sign = along >= 0 ? Real(1) : Real(-1);
        const Vec3 centre = cylinder.centre + axis * (sign * cylinder.halfHeight);
        // Counter-clockwise seen from outside: from +y, z then x (z × x = y); from −y, x then z.
        const Vec3 first = sign > 0 ? r[2] : r[0];
        const Vec3 second = sign > 0 ? r[0] : r[2];
        for (int m = 0; m < kCylinderCapVertices; ++m) {
            const Real angle = Real(2) * kPi * Real(m) / Real(kCylinderCapVertices);
            f.points[m] = centre + cylinder.radius * (std::cos(angle) * first + std::sin(angle) * second);
        }
        f.count = kCylinderCapVertices;
        f.normal = axis * sign;
        f.id = sign > 0 ? kTopCap : kBottomCap;
        return;
    }
    if (std::abs(along) <= kSideContactSine) {
        const Vec3 radial = glm::normalize(direction - axis * along) * cylinder.radius;
        f.count = 2;
        f.points[0] = cylinder.centre + radial - axis * cylinder.halfHeight;
        f.points[1] = cylinder.centre + radial + axis * cylinder.halfHeight;
        f.id = kSide;
        return;
    }
    pointFeature(coreSupport(convexShapeOf(cylinder), direction), kRimPoint, f);
}

void featureOf(const Geometry& g, const Vec3& direction, Feature& f) {
    switch (g.type) {
        case GeometryType::Box: boxFeature(g, direction, f); return;
        case GeometryType::Hull:
            if (g.hull != nullptr && !g.hull->faces.empty()) {
                hullFeature(g, direction, f);
                return;
            }
            break;
        case GeometryType::Cylinder: cylinderFeature(g, direction, f); return;
        case GeometryType::Capsule: {
            const Vec3 axis = glm::mat3_cast(g.orientation)[1];
            f.count = 2;
            f.points[0] = g.centre - axis * g.halfHeight;
            f.points[1] = g.centre + axis * g.halfHeight;
            f.margin = g.radius;
            return;
        }
        case GeometryType::Sphere:
        case GeometryType::Plane:
        case GeometryType::Mesh:
        case GeometryType::Count: break;
    }
    pointFeature(g.centre, 0, f);
    f.margin = g.radius;
}

/// A length that scales with the shape: half its thinnest extent (box), its
/// radius (sphere, capsule), the nearer of radius and half length (cylinder),
/// the nearest face plane (hull), m.
Real innerSize(const Geometry& g) {
    switch (g.type) {
        case GeometryType::Box: return std::min({g.halfExtents.x, g.halfExtents.y, g.halfExtents.z});
        case GeometryType::Cylinder: return std::min(g.radius, g.halfHeight);
        case GeometryType::Hull: {
            Real nearest = std::numeric_limits<Real>::max();
            if (g.hull != nullptr) {
                for (const HullFace& face : g.hull->faces) nearest = std::min(nearest, face.offset);
            }
            return g.hull != nullptr && !g.hull->faces.empty() ? nearest : Real(0);
        }
        default: return g.radius;
    }
}

/// Separation of A and B along the unit direction @p n (A → B): −(n·(s_A(n) − s_B(−n))),
/// the gap between their shadows on that axis (negative: they overlap by that much).
Real separationAlong(const ConvexShape& a, const ConvexShape& b, const Vec3& n) {
    return -glm::dot(n, support(a, n) - support(b, -n));
}

/// One side plane of the reference face: outward unit normal and offset (normal·x ≤ offset inside).
struct SidePlane {
    Vec3 normal;
    Real offset;
};

SidePlane sidePlane(const Feature& reference, int edge) {
    const Vec3 from = reference.points[edge];
    const Vec3 to = reference.points[(edge + 1) % reference.count];
    const Vec3 outward = glm::normalize(glm::cross(to - from, reference.normal));
    return {outward, glm::dot(outward, from)};
}

/// Keeps the incident point if it lies inside every side plane of the reference face (a sphere's centre over a triangle).
int clipPoint(const Feature& reference, const Feature& incident, ClipVertex* out) {
    for (int side = 0; side < reference.count; ++side) {
        const SidePlane plane = sidePlane(reference, side);
        if (glm::dot(plane.normal, incident.points[0]) - plane.offset > kTouchTolerance) return 0;
    }
    out[0] = {incident.points[0], 0, 0};
    return 1;
}

/// Clips the incident segment by the reference face's side planes (a two-point Sutherland–Hodgman).
int clipSegment(const Feature& reference, const Feature& incident, ClipVertex* out) {
    out[0] = {incident.points[0], 0, 0};
    out[1] = {incident.points[1], 1, 1};
    for (int side = 0; side < reference.count; ++side) {
        const SidePlane plane = sidePlane(reference, side);
        const Real d0 = glm::dot(plane.normal, out[0].position) - plane.offset;
        const Real d1 = glm::dot(plane.normal, out[1].position) - plane.offset;
        if (d0 > kTouchTolerance && d1 > kTouchTolerance) return 0;
        const auto label = static_cast<std::uint8_t>(kFirstSideLabel + side);
        if (d0 > kTouchTolerance) {
            out[0].position += (out[1].position - out[0].position) * (d0 / (d0 - d1));
            out[0].inEdge = out[0].outEdge = label;
        } else if (d1 > kTouchTolerance) {
            out[1].position += (out[0].position - out[1].position) * (d1 / (d1 - d0));
            out[1].inEdge = out[1].outEdge = label;
        }
    }
    return 2;
}

/// Clips the incident polygon by the reference face's side planes (clip_polygon.hpp).
int clipFace(const Feature& reference, const Feature& incident, ClipVertex* polygon) {
    ClipVertex clipped[kMaxClipped];
    int count = incident.count;
    for (int m = 0; m < count; ++m) {
        polygon[m] = {incident.points[m], static_cast<std::uint8_t>((m + count - 1) % count), static_cast<std::uint8_t>(m)};
    }
    for (int side = 0; side < reference.count && count > 0; ++side) {
        const SidePlane plane = sidePlane(reference, side);
        count = clipPolygon(polygon, count, plane.normal, plane.offset, static_cast<std::uint8_t>(kFirstSideLabel + side),
                            kTouchTolerance, clipped);
        std::copy(clipped, clipped + count, polygon);
    }
    return count;
}

/// The single point of a contact that is no face contact: midway between the deepest points.
bool singlePoint(const Feature& fa, const Feature& fb, const Vec3& normal, const Vec3& onA, const Vec3& onB, Real depth,
                 Real maxGap, ContactManifold& out) {
    if (-depth > maxGap) return false;
    out.normal = normal;
    out.pointCount = 0;
    out.add(Real(0.5) * (onA + onB), depth, kSinglePoint | (fa.id & kByte) | ((fb.id & kByte) << kSecondFeatureShift));
    return true;
}

/// Signed area (times 2) of the triangle p, q, r seen along n.
Real signedArea(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& n) {
    return glm::dot(glm::cross(q - p, r - p), n);
}

}  // namespace

int keepSpreadContactPoints(ContactPoint* points, int count, const Vec3& normal) {
    if (count <= kMaxManifoldPoints) return count;
    int kept[kMaxManifoldPoints];
    int keptCount = 0;
    auto isKept = [&](int i) { return std::find(kept, kept + keptCount, i) != kept + keptCount; };
    // The best not-yet-kept point by score (first on ties); −1 when no score is ≥ 0.
    auto best = [&](auto score) {
        int chosen = -1;
        Real chosenScore = 0;
        for (int i = 0; i < count; ++i) {
            if (isKept(i)) continue;
            const Real s = score(i);
            if (s >= 0 && (chosen < 0 || s > chosenScore)) {
                chosen = i;
                chosenScore = s;
            }
        }
        return chosen;
    };
    auto distance2 = [&](int i, int j) {
        const Vec3 d = points[i].position - points[j].position;
        return glm::dot(d, d);
    };
    auto nearestKept = [&](int i) {
        Real nearest = std::numeric_limits<Real>::max();
        for (int k = 0; k < keptCount; ++k) nearest = std::min(nearest, distance2(i, kept[k]));
        return nearest;
    };
    // 1. The deepest (depths can be negative gaps: compare them shifted by the lowest).
    Real lowest = points[0].depth;
    for (int i = 1; i < count; ++i) lowest = std::min(lowest, points[i].depth);
    kept[keptCount++] = best([&](int i) { return points[i].depth - lowest; });
    // 2. The farthest from it.
    const int second = best([&](int i) { return distance2(i, kept[0]); });
    if (second >= 0) kept[keptCount++] = second;
    if (keptCount == 2) {
        // 3. The farthest from the line through the two; 4. the farthest on its other side.
        const Vec3 p1 = points[kept[0]].position;
        const Vec3 p2 = points[kept[1]].position;
        auto area = [&](int i) { return signedArea(p1, p2, points[i].position, normal); };
        const int third = best([&](int i) { return std::abs(area(i)); });
        if (third >= 0) {
            kept[keptCount++] = third;
            const Real side = area(third);
            int fourth = best([&](int i) { return area(i) * side < 0 ? std::abs(area(i)) : Real(-1); });
            if (fourth < 0) fourth = best(nearestKept);
            if (fourth >= 0) kept[keptCount++] = fourth;
        }
    }
    // Back into their original order (at most four indices: insertion sort).
    for (int i = 1; i < keptCount; ++i) {
        for (int j = i; j > 0 && kept[j - 1] > kept[j]; --j) std::swap(kept[j - 1], kept[j]);
    }
    ContactPoint chosen[kMaxManifoldPoints];
    for (int k = 0; k < keptCount; ++k) chosen[k] = points[kept[k]];
    std::copy(chosen, chosen + keptCount, points);
    return keptCount;
}

namespace {

/// Steps 3 and 4: the incident feature clipped by the reference face's side planes, and the
/// points within @p maxGap at the middle of the overlap (all of them: the caller cuts them down).
/// @return how many points @p found holds
int clipAndKeep(const Feature& reference, const Feature& incident, bool referenceIsB, Real maxGap, ContactPoint* found) {
    ClipVertex polygon[kMaxClipped];
    const int count = incident.count == 1   ? clipPoint(reference, incident, polygon)
                      : incident.count == 2 ? clipSegment(reference, incident, polygon)
                                            : clipFace(reference, incident, polygon);
    const Vec3 referenceNormal = reference.normal;  // points at the incident shape
    const Vec3 onReference = reference.points[0];
    int foundCount = 0;
    const std::uint32_t faces = (referenceIsB ? kReferenceIsB : 0u) | ((reference.id & kByte) << kReferenceShift) |
                                ((incident.id & kByte) << kIncidentShift) | kClippedPoint;
    for (int i = 0; i < count; ++i) {
        const Real gap = glm::dot(polygon[i].position - onReference, referenceNormal) - incident.margin;
        if (gap > maxGap) continue;
        const Vec3 surface = polygon[i].position - referenceNormal * incident.margin;
        const std::uint32_t labels = (polygon[i].inEdge & kLabelMask) | ((polygon[i].outEdge & kLabelMask) << kOutLabelShift);
        found[foundCount++] = {surface - referenceNormal * (Real(0.5) * gap), -gap, faces | labels};
    }
    return foundCount;
}

/// Steps 2 to 4 on the features @p fa and @p fb the two shapes show along the normal.
/// @param tolerance the absolute part of the face bias, kFaceBiasAbsolute × the smaller shape's innerSize(), m
bool manifoldOfFeatures(const Feature& fa, const Feature& fb, const ConvexShape& sa, const ConvexShape& sb,
                        Real tolerance, const Vec3& normal, const Vec3& onA, const Vec3& onB, Real depth, Real maxGap,
                        ContactManifold& out) {
    // Step 2: the reference face. SAT's rule (box_box.cpp section 2) on the two faces most
    // aligned with the normal: B's face only if it separates the shapes clearly more than A's,
    // and a face at all only if the algorithm's own direction (an edge against an edge, a rim)
    // does not separate them clearly more than that face.
    const bool faceOfA = fa.count >= 3;
    const bool faceOfB = fb.count >= 3;
    if (!faceOfA && !faceOfB) return singlePoint(fa, fb, normal, onA, onB, depth, maxGap, out);
    const Real separationA = faceOfA ? separationAlong(sa, sb, fa.normal) : std::numeric_limits<Real>::lowest();
    const Real separationB = faceOfB ? separationAlong(sa, sb, -fb.normal) : std::numeric_limits<Real>::lowest();
    const bool referenceIsB = !faceOfA || (faceOfB && separationB > kFaceBiasRelative * separationA + tolerance);
    const Real faceSeparation = referenceIsB ? separationB : separationA;
    const Feature& reference = referenceIsB ? fb : fa;
    const Feature& incident = referenceIsB ? fa : fb;
    if (-depth > kFaceBiasRelative * faceSeparation + tolerance || incident.count < 2) {
        return singlePoint(fa, fb, normal, onA, onB, depth, maxGap, out);
    }

    // Steps 3 and 4: clip, and keep the points within reach.
    ContactPoint found[kMaxClipped];
    const int foundCount =
        keepSpreadContactPoints(found, clipAndKeep(reference, incident, referenceIsB, maxGap, found), reference.normal);
    if (foundCount == 0) return singlePoint(fa, fb, normal, onA, onB, depth, maxGap, out);
    out.normal = referenceIsB ? -reference.normal : reference.normal;
    out.pointCount = 0;
    for (int i = 0; i < foundCount; ++i) out.add(found[i].position, found[i].depth, found[i].featureId);
    return true;
}

/// What a triangle shows along @p direction: its face seen from that side, counter-clockwise
/// seen from there (id 0 the front, whose normal is (p₁ − p₀) × (p₂ − p₀); id 1 the back).
void triangleFeature(const ConvexShape& triangle, const Vec3& direction, Feature& f) {
    const Vec3* p = triangle.corners;
    const Vec3 front = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    const bool seenFromFront = glm::dot(front, direction) >= 0;
    f.count = 3;
    f.points[0] = p[0];
    f.points[1] = seenFromFront ? p[1] : p[2];
    f.points[2] = seenFromFront ? p[2] : p[1];
    f.normal = seenFromFront ? front : -front;
    f.id = seenFromFront ? 0u : 1u;
}

}  // namespace

bool convexManifold(const Geometry& a, const Geometry& b, const Vec3& normal, const Vec3& onA, const Vec3& onB,
                    Real depth, Real maxGap, ContactManifold& out) {
    Feature fa, fb;
    featureOf(a, normal, fa);
    featureOf(b, -normal, fb);
    const Real tolerance = kFaceBiasAbsolute * std::min(innerSize(a), innerSize(b));
    return manifoldOfFeatures(fa, fb, convexShapeOf(a), convexShapeOf(b), tolerance, normal, onA, onB, depth, maxGap, out);
}

bool triangleManifold(const Geometry& a, const ConvexShape& triangle, const Vec3& normal, const Vec3& onA,
                      const Vec3& onB, Real depth, Real maxGap, ContactManifold& out) {
    Feature fa, fb;
    featureOf(a, normal, fa);
    triangleFeature(triangle, -normal, fb);
    // A triangle has no thickness: the bias scales with A alone.
    const Real tolerance = kFaceBiasAbsolute * innerSize(a);
    return manifoldOfFeatures(fa, fb, convexShapeOf(a), triangle, tolerance, normal, onA, onB, depth, maxGap, out);
}

int triangleFacePoints(const Geometry& a, const ConvexShape& triangle, Real maxGap, ContactPoint* points) {
    Feature fa, fb;
    const Vec3* p = triangle.corners;
    const Vec3 front = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    triangleFeature(triangle, front, fb);
    featureOf(a, -front, fa);  // what A shows towards the triangle
    return clipAndKeep(fb, fa, true, maxGap, points);
}

}  // namespace stepwise
