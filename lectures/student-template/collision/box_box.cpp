/// @file box_box.cpp
/// @brief YOUR separating-axis test (lecture 5): a student template (lectures/student-template/README.md).
///
/// Copied to student/collision/box_box.cpp, it replaces src/collision/box_box.cpp
/// in the student preset's build. It defines the pair test
/// src/collision/narrowphase.hpp declares,
///
///     bool collideBoxBox(const Geometry& a, const Geometry& b, ContactManifold& out);
///     bool collideBoxBoxWithin(const Geometry& a, const Geometry& b, Real reach, ContactManifold& out);
///
/// (the second reports boxes up to `reach` apart: the sequential-impulse
/// solver looks as far ahead as two boxes can close in a step),
/// and you write its test of one axis, testAxis() (lecture 5, "1. The shadow
/// of a box on a line" and "3. From whether to how far"). Box X has centre c,
/// unit axes u_i (box.axes[i]) and half extents e_i (box.halfExtents[i]); its
/// shadow on a unit axis L is c.L +- r_X(L), and with t = c_B - c_A (between)
///
///     r_X(L) = e_0 |u_0 . L| + e_1 |u_1 . L| + e_2 |u_2 . L|
///     s(L)   = |t . L| - (r_A(L) + r_B(L))        the separation: > 0 is a gap
///
/// The rest is given, as lectures 5 and 6 read it: collideBoxBox() tries the
/// 15 axes with your testAxis() (lecture 5, section 2; "Section 1" in the
/// code), picks one with a bias for faces (lecture 5, section 4), and builds
/// the contact points by clipping (lecture 6).
/// Until you write it, the test stops with
/// "student stage not written yet: stepwise::testAxis".
/// Test it: ctest --preset student -L 'sat|contacts'
#include <algorithm>
#include <cmath>
#include <limits>

#include "collision/box_features.hpp"
#include "collision/clip_polygon.hpp"
#include "collision/closest_points.hpp"
#include "collision/narrowphase.hpp"
#include "core/student_todo.hpp"

namespace stepwise {

namespace {

/// Edge pairs whose directions are parallel to within this sine (|a × b|,
/// about 0.06°) are skipped: their cross product is no direction at all
/// (0/0 after round-off). Nothing is lost for exactly parallel edges: seen
/// along their common direction both boxes are rectangles, and two
/// rectangles are always separated by one of their edge normals, which are
/// face axes here. For edges within 0.06° of parallel the face axes can miss
/// a gap of at most about sin θ × the edge length (under 1 mm for boxes of a
/// metre); the clipping in section 3a then usually finds no point behind the
/// reference face, and at worst a touch is reported that early.
constexpr Real kParallelEdgeSine = Real(1e-3);

/// The challenger (B's face over A's, an edge over the best face) must have
/// separation above this fraction of the incumbent's… (section 2).
constexpr Real kFaceBiasRelative = Real(0.95);
/// …plus this fraction of the smallest half extent of the two boxes.
constexpr Real kFaceBiasAbsolute = Real(0.01);

/// Side-plane labels 4–7 follow the incident face's own edge labels 0–3.
constexpr std::uint8_t kFirstSideLabel = 4;

/// The best axis of one kind found so far.
struct AxisQuery {
    Real separation = std::numeric_limits<Real>::lowest();  ///< s(L), m.
    int axisOfA = -1;  ///< A's axis index (face of A, or edge of A), −1 if not used.
    int axisOfB = -1;  ///< B's axis index (face of B, or edge of B), −1 if not used.
    Vec3 normal{0, 1, 0};  ///< ±L, from A towards B.
};

/// A contact point waiting for the manifold.
struct Candidate {
    Vec3 position;
    Real depth;
    std::uint32_t featureId;
};

// ==== YOUR CODE BEGINS: lecture 5, sections 1 and 3 (the shadow of a box; whether and how far) ====
// TODO: r_X(L) (a helper such as projectedRadius(box, axis) keeps it short), then testAxis().

/// Tests one unit axis. Returns false when it separates the boxes by more
/// than @p reach (m); otherwise keeps it in @p best if it separates them least so far.
bool testAxis(const OrientedBox& a, const OrientedBox& b, const Vec3& between, const Vec3& axis, int axisOfA,
              int axisOfB, Real reach, AxisQuery& best) {
    // TODO: s = |t.L| - (r_A(L) + r_B(L)) with t = between and L = axis. Return false when
    // s > reach (a gap wider than the test looks: the boxes are apart). Otherwise, if s > best.separation,
    // keep this axis in best: its separation, axisOfA, axisOfB, and the normal L or -L,
    // whichever points from A towards B (the sign of t.L). Return true.
    return studentTodo<bool>("stepwise::testAxis (collision/box_box.cpp): write s = |t.L| - (rA(L) + rB(L)), "
                             "false when s > reach, else keep the best axis (lecture 5, sections 1 and 3)",
                             a, b, between, axis, axisOfA, axisOfB, reach, best);
}
// ==== YOUR CODE ENDS ====

/// Section 2: does an axis of separation @p challenger replace the incumbent's @p incumbent? Only
/// if it is better by 5 % of the incumbent's overlap or gap (kFaceBiasRelative) plus @p tolerance:
/// for an overlap (s ≤ 0) the bar is 0.95·s + tolerance, for a gap 1.05·s + tolerance.
bool beats(Real challenger, Real incumbent, Real tolerance) {
    const Real bar = incumbent <= 0 ? kFaceBiasRelative * incumbent : (2 - kFaceBiasRelative) * incumbent;
    return challenger > bar + tolerance;
}

Real smallestHalfExtent(const OrientedBox& box) {
    return std::min({box.halfExtents.x, box.halfExtents.y, box.halfExtents.z});
}

/// Signed area (times 2) of the triangle p, q, r seen along n.
Real signedArea(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& n) {
    return glm::dot(glm::cross(q - p, r - p), n);
}

/// Index of the candidate with the largest score(i) among those not yet
/// @p taken (the first one on ties), or −1 when every score is negative.
template <class Score>
int bestCandidate(int count, const bool* taken, Score score) {
    int best = -1;
    Real bestScore = 0;
    for (int i = 0; i < count; ++i) {
        if (taken[i]) continue;
        const Real value = score(i);
        if (value >= 0 && (best < 0 || value > bestScore)) {
            best = i;
            bestScore = value;
        }
    }
    return best;
}

/// Keeps @p keep of the @p count candidates (section 3a), choosing in this order:
/// 1. the deepest point p₁;
/// 2. the point p₂ farthest from p₁;
/// 3. the point p₃ farthest from the line p₁p₂ (largest triangle p₁p₂p₃);
/// 4. the point farthest from that line on the *other* side (largest
///    quadrilateral); if p₁p₂ is an edge of the polygon and nothing is on
///    the other side, the point farthest from the points already kept;
/// 5. (only if more than 4 are wanted) again the point farthest from those kept.
/// With kMaxManifoldPoints = 4 that is steps 1–4; a smaller limit stops
/// early (1 keeps only the deepest point). The kept points stay in their
/// original order, so the manifold is repeatable.
/// @return the number kept, min(count, keep)
int keepSpreadPoints(Candidate* points, int count, const Vec3& normal, Real reach, int keep) {
    if (count <= keep) return count;
    bool taken[kMaxClipVertices] = {};
    int kept[kMaxClipVertices] = {};
    int keptCount = 0;
    auto take = [&](int i) {
        if (i < 0) return;  // no candidate scored: keep fewer points rather than index −1
        taken[i] = true;
        kept[keptCount++] = i;
    };
    auto distanceSquared = [&](int i, int j) {
        const Vec3 d = points[i].position - points[j].position;
        return glm::dot(d, d);
    };
    auto farthestFromKept = [&](int i) {
        Real nearest = std::numeric_limits<Real>::max();
        for (int k = 0; k < keptCount; ++k) nearest = std::min(nearest, distanceSquared(i, kept[k]));
        return nearest;
    };
    // Depth is negative for speculative points (down to −reach):
    // shift it so every score is ≥ 0 and the deepest is always found.
    take(bestCandidate(count, taken, [&](int i) { return points[i].depth + reach; }));
    if (keptCount < keep) take(bestCandidate(count, taken, [&](int i) { return distanceSquared(i, kept[0]); }));
    if (keptCount < keep) {
        const Vec3 p1 = points[kept[0]].position;
        const Vec3 p2 = points[kept[1]].position;
        auto area = [&](int i) { return signedArea(p1, p2, points[i].position, normal); };
        take(bestCandidate(count, taken, [&](int i) { return std::abs(area(i)); }));
        if (keptCount < keep) {
            const Real side = area(kept[2]);
            const int opposite =
                bestCandidate(count, taken, [&](int i) { return area(i) * side < 0 ? std::abs(area(i)) : Real(-1); });
            take(opposite >= 0 ? opposite : bestCandidate(count, taken, farthestFromKept));
        }
    }
    while (keptCount < keep) {
        const int next = bestCandidate(count, taken, farthestFromKept);
        if (next < 0) break;
        take(next);
    }

    // Back into their original order (a handful of indices: insertion sort).
    for (int i = 1; i < keptCount; ++i) {
        for (int j = i; j > 0 && kept[j - 1] > kept[j]; --j) std::swap(kept[j - 1], kept[j]);
    }
    Candidate chosen[kMaxClipVertices];
    for (int i = 0; i < keptCount; ++i) chosen[i] = points[kept[i]];
    std::copy(chosen, chosen + keptCount, points);
    return keptCount;
}

/// Section 3a. @p referenceNormal is the reference face's outward unit
/// normal (it points at the incident box); @p manifoldNormal is the same or
/// its opposite, whichever points from A to B.
bool faceContact(const OrientedBox& reference, int referenceAxis, const Vec3& referenceNormal,
                 const OrientedBox& incident, BoxContactKind kind, const Vec3& manifoldNormal, Real reach,
                 ContactManifold& out) {
    const Real referenceSign = glm::dot(referenceNormal, reference.axes[referenceAxis]) < 0 ? Real(-1) : Real(1);
    const int referenceFace = faceIndex(referenceAxis, referenceSign);

    // The incident face: the face of the other box whose outward normal is most anti-parallel to n_ref.
    int incidentAxis = 0;
    Real mostAligned = -1;
    for (int j = 0; j < 3; ++j) {
        const Real alignment = std::abs(glm::dot(incident.axes[j], referenceNormal));
        if (alignment > mostAligned) {
            mostAligned = alignment;
            incidentAxis = j;
        }
    }
    const Real incidentSign = glm::dot(incident.axes[incidentAxis], referenceNormal) > 0 ? Real(-1) : Real(1);
    const int incidentFace = faceIndex(incidentAxis, incidentSign);

    // Its corners in a fixed order around the face: (−,−), (+,−), (+,+), (−,+)
    // on its two other axes. Polygon edge m runs from corner m to corner m + 1.
    const int p = (incidentAxis + 1) % 3;
    const int q = (incidentAxis + 2) % 3;
    const Vec3 faceCentre = incident.centre + incident.axes[incidentAxis] * (incidentSign * incident.halfExtents[incidentAxis]);
    const Vec3 alongP = incident.axes[p] * incident.halfExtents[p];
    const Vec3 alongQ = incident.axes[q] * incident.halfExtents[q];
    constexpr Real kSignP[4] = {-1, 1, 1, -1};
    constexpr Real kSignQ[4] = {-1, -1, 1, 1};
    ClipVertex polygon[kMaxClipVertices];
    ClipVertex clipped[kMaxClipVertices];
    int count = 4;
    for (int m = 0; m < 4; ++m) {
        polygon[m].position = faceCentre + alongP * kSignP[m] + alongQ * kSignQ[m];
        polygon[m].inEdge = static_cast<std::uint8_t>((m + 3) % 4);
        polygon[m].outEdge = static_cast<std::uint8_t>(m);
    }

    // Clip by the reference face's four side planes: ±u·(x − c) ≤ e_u, ±v·(x − c) ≤ e_v.
    const int u = (referenceAxis + 1) % 3;
    const int v = (referenceAxis + 2) % 3;
    const int sideAxes[4] = {u, u, v, v};
    const Real sideSigns[4] = {1, -1, 1, -1};
    for (int side = 0; side < 4 && count > 0; ++side) {
        const Vec3 planeNormal = reference.axes[sideAxes[side]] * sideSigns[side];
        const Real offset = glm::dot(planeNormal, reference.centre) + reference.halfExtents[sideAxes[side]];
        count = clipPolygon(polygon, count, planeNormal, offset, static_cast<std::uint8_t>(kFirstSideLabel + side),
                            kTouchTolerance, clipped);
        std::copy(clipped, clipped + count, polygon);
    }

    // Keep the points behind the reference face.
    const Vec3 referenceCentre = reference.centre + referenceNormal * reference.halfExtents[referenceAxis];
    Candidate found[kMaxClipVertices];
    int foundCount = 0;
    for (int i = 0; i < count; ++i) {
        const Real distance = glm::dot(polygon[i].position - referenceCentre, referenceNormal);
        if (distance > reach) continue;
        found[foundCount++] = {polygon[i].position - referenceNormal * (Real(0.5) * distance), -distance,
                               faceFeatureId(kind, referenceFace, incidentFace, polygon[i].inEdge,
                                             polygon[i].outEdge)};
    }
    if (foundCount == 0) return false;
    foundCount = keepSpreadPoints(found, foundCount, referenceNormal, reach, kMaxManifoldPoints);

    out.normal = manifoldNormal;
    out.pointCount = 0;
    for (int i = 0; i < foundCount; ++i) out.add(found[i].position, found[i].depth, found[i].featureId);
    return true;
}

/// The edge of @p box along its axis @p axis that reaches furthest along
/// @p direction: its end points and its number.
int supportEdge(const OrientedBox& box, int axis, const Vec3& direction, Vec3& from, Vec3& to) {
    const int j = (axis + 1) % 3;
    const int k = (axis + 2) % 3;
    const Real signJ = glm::dot(box.axes[j], direction) >= 0 ? Real(1) : Real(-1);
    const Real signK = glm::dot(box.axes[k], direction) >= 0 ? Real(1) : Real(-1);
    const Vec3 middle =
        box.centre + box.axes[j] * (signJ * box.halfExtents[j]) + box.axes[k] * (signK * box.halfExtents[k]);
    from = middle - box.axes[axis] * box.halfExtents[axis];
    to = middle + box.axes[axis] * box.halfExtents[axis];
    return edgeIndex(axis, signJ, signK);
}

/// Section 3b.
bool edgeContact(const OrientedBox& a, const OrientedBox& b, const AxisQuery& edge, ContactManifold& out) {
    Vec3 fromA, toA, fromB, toB;
    const int edgeOfA = supportEdge(a, edge.axisOfA, edge.normal, fromA, toA);
    const int edgeOfB = supportEdge(b, edge.axisOfB, -edge.normal, fromB, toB);
    const SegmentClosestPoints closest = closestPointsOfSegments(fromA, toA, fromB, toB);
    out.normal = edge.normal;
    out.pointCount = 0;
    out.add(Real(0.5) * (closest.onFirst + closest.onSecond), -edge.separation, edgeFeatureId(edgeOfA, edgeOfB));
    return true;
}

}  // namespace

bool collideBoxBox(const Geometry& boxA, const Geometry& boxB, ContactManifold& out) {
    return collideBoxBoxWithin(boxA, boxB, kSpeculativeDistance, out);
}

bool collideBoxBoxWithin(const Geometry& boxA, const Geometry& boxB, Real reach, ContactManifold& out) {
    const OrientedBox a = orientedBoxOf(boxA);
    const OrientedBox b = orientedBoxOf(boxB);
    const Vec3 between = b.centre - a.centre;

    // Section 1: the 15 axes. Any one that separates by more than the reach ends the test.
    AxisQuery faceA, faceB, edge;
    for (int i = 0; i < 3; ++i) {
        if (!testAxis(a, b, between, a.axes[i], i, -1, reach, faceA)) return false;
    }
    for (int j = 0; j < 3; ++j) {
        if (!testAxis(a, b, between, b.axes[j], -1, j, reach, faceB)) return false;
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const Vec3 cross = glm::cross(a.axes[i], b.axes[j]);
            const Real length = glm::length(cross);  // sin of the angle between the edges
            if (length < kParallelEdgeSine) continue;
            if (!testAxis(a, b, between, cross / length, i, j, reach, edge)) return false;
        }
    }

    // Section 2: biased choice.
    const Real tolerance = kFaceBiasAbsolute * std::min(smallestHalfExtent(a), smallestHalfExtent(b));
    const bool useFaceOfB = beats(faceB.separation, faceA.separation, tolerance);
    const AxisQuery& face = useFaceOfB ? faceB : faceA;
    if (edge.axisOfA >= 0 && beats(edge.separation, face.separation, tolerance)) {
        return edgeContact(a, b, edge, out);
    }

    // Section 3a. B's reference face looks towards A, against the A → B normal.
    if (useFaceOfB) return faceContact(b, face.axisOfB, -face.normal, a, BoxContactKind::FaceOfB, face.normal, reach, out);
    return faceContact(a, face.axisOfA, face.normal, b, BoxContactKind::FaceOfA, face.normal, reach, out);
}

}  // namespace stepwise
