/// @file box_box.cpp
/// @brief Oriented box against oriented box: the separating-axis test, then a contact manifold.
///
/// ### 1. Separating axes (Ericson §4.4.1; Gregorius, GDC 2013)
/// Two convex shapes do not touch exactly when some line L exists on which
/// their shadows (projections) do not overlap. Project box X (centre c,
/// unit axes uᵢ, half extents eᵢ) onto a unit axis L: its shadow is the
/// interval c·L ± r_X(L) with
/// \f[ r_X(L) = \sum_{i=0}^{2} e_i\,|u_i\cdot L| . \f]
/// With t = c_B − c_A the gap between the two shadows is the *separation*
/// \f[ s(L) = |t\cdot L| - \big(r_A(L) + r_B(L)\big) \f]
/// (positive: a gap; negative: the shadows overlap by −s). For two boxes it
/// is enough to try 15 axes: the 3 face normals of A, the 3 of B, and the
/// 9 cross products a_i × b_j of an edge direction of each. If every one of
/// them overlaps, the boxes intersect; and the axis with the *largest*
/// separation (least overlap) is the direction to push them apart, with
/// the overlap as the depth. Here an axis separates when s > g, the
/// *reach* of the test: boxes up to g apart still report speculative
/// contact points (contact.hpp says why). collideBoxBox() reaches
/// kSpeculativeDistance (1 cm); the sequential-impulse solver's narrowphase
/// asks collideBoxBoxWithin() for as far as the two boxes can close this
/// step (findContacts(), narrowphase.hpp), so a box falling onto another
/// meets a contact before it sinks in rather than after.
///
/// The normal reported is ±L, signed so that it points from A towards B
/// (the sign of t·L).
///
/// ### 2. Choosing the axis: prefer faces, prefer A
/// Three kinds of contact come out: a face of A against B, a face of B
/// against A, an edge of A across an edge of B. Taking the plain minimum
/// would let the choice jump between kinds when two axes are nearly tied, as
/// they are for a box resting flat (A's bottom face and B's top face give
/// the same overlap, and so does an edge axis such as aₓ × b_z = ±y). A
/// jumping reference face makes the contact points and their feature ids
/// change every step, and a box never settles. So (as Box2D, qu3e and
/// Gregorius do) the choice is biased:
///
/// * B's face is used only if s_B > kFaceBiasRelative·s_A + tolerance,
/// * an edge axis only if s_edge > kFaceBiasRelative·s_face + tolerance,
///
/// where tolerance = kFaceBiasAbsolute × the smallest half extent of the two
/// boxes (a length that scales with the boxes). Since separations are ≤ 0
/// while overlapping, kFaceBiasRelative·s is *less* negative than s: the
/// challenger must be better by 5 % of the overlap plus 1 % of the box
/// size. Edges get the bias as well because an edge axis from two nearly
/// parallel edges has a normal that swings with tiny rotations, and a
/// single edge point is a poor support compared with a face's clipped points.
/// For boxes still apart (s > 0: a speculative contact, section 3a) the bar
/// is 1.05·s + tolerance instead: again the challenger must be better by 5 %,
/// now of the gap (0.95·s would let a *worse* axis win, and two boxes above
/// each other would get one edge point instead of their faces' four).
///
/// ### 3a. Face contact: clip the incident face (Catto, GDC 2007; Ericson §5 and §8.3.4)
/// The *reference face* is the face of the chosen box whose outward normal
/// is the axis. The *incident face* is the face of the other box most
/// anti-parallel to it (largest |u_j·n|). Its four corners, clipped by the
/// four side planes of the reference face (clip_polygon.cpp), are the part
/// of the incident face lying over the reference face. Of these, the points
/// behind the reference face plane or at most the reach g in front
/// of it are contacts: depth −d (negative for a speculative gap), position midway between the point and the face,
/// p − n_ref·d/2.
///
/// Clipping a quad by a rectangle can leave up to 8 points; the manifold
/// keeps 4 (keepSpreadPoints below): the deepest, the one farthest from it, the
/// one farthest from the line through those two, and the farthest on the
/// other side of that line: nearly the largest area four of the points can
/// span, and a wide base is what keeps a box from rocking.
///
/// ### 3b. Edge contact (Ericson §5.1.9)
/// The edge of A that reaches furthest along n and the edge of B that
/// reaches furthest along −n are the ones meeting. Their closest points
/// (closest_points.cpp) are one on each box; the contact point is midway,
/// the depth is the overlap on the axis.
///
/// ### Feature ids
/// See box_features.hpp: a face contact names the reference face, the
/// incident face and the two polygon edges that meet at the point; an edge
/// contact names the two edges. None of them depends on positions, so they
/// stay the same while the boxes rest on each other.
///
/// Further reading: Gaul's qu3e (src/collision/q3Collide.cpp) does the same
/// in the reference box's frame with the 15 axes written out by hand.
#include <algorithm>
#include <cmath>
#include <limits>

#include "collision/box_features.hpp"
#include "collision/clip_polygon.hpp"
#include "collision/closest_points.hpp"
#include "collision/narrowphase.hpp"

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

/// r_X(L): half the length of box X's shadow on the unit axis L.
Real projectedRadius(const OrientedBox& box, const Vec3& axis) {
    return box.halfExtents.x * std::abs(glm::dot(box.axes[0], axis)) +
           box.halfExtents.y * std::abs(glm::dot(box.axes[1], axis)) +
           box.halfExtents.z * std::abs(glm::dot(box.axes[2], axis));
}

/// Tests one unit axis. Returns false when it separates the boxes by more
/// than @p reach (m); otherwise keeps it in @p best if it separates them least so far.
bool testAxis(const OrientedBox& a, const OrientedBox& b, const Vec3& between, const Vec3& axis, int axisOfA,
              int axisOfB, Real reach, AxisQuery& best) {
    const Real distance = glm::dot(between, axis);
    const Real separation = std::abs(distance) - (projectedRadius(a, axis) + projectedRadius(b, axis));
    if (separation > reach) return false;
    if (separation > best.separation) {
        best.separation = separation;
        best.axisOfA = axisOfA;
        best.axisOfB = axisOfB;
        best.normal = distance < 0 ? -axis : axis;
    }
    return true;
}

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
/// original order, so the manifold is repeatable. @p reach is the test's
/// (no point's gap is larger: every depth is at least −reach).
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
