/// @file mesh_contacts.cpp
/// @brief Convex shapes against triangle meshes: triangles near the shape, each tested, edges checked, points gathered (mesh_contacts.hpp).
#include "collision/mesh_contacts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "collision/aabb.hpp"
#include "collision/closest_points.hpp"
#include "collision/convex_manifold.hpp"
#include "collision/epa.hpp"
#include "collision/gjk.hpp"
#include "collision/mesh_query.hpp"
#include "collision/support.hpp"

namespace stepwise {

namespace {

/// Points one manifold gathers from its triangles before it is cut down to the best four
/// (a box over a corner where 6 triangles meet brings up to 6 × 4).
constexpr int kGatheredPoints = 16;

/// Cores closer than this, m, touch: no direction between them (GJK and EPA decide instead).
constexpr Real kCoincident = Real(1e-9);

/// Two points of one manifold closer than this, m, are one point met from two triangles
/// (a ball exactly over a shared edge): the deeper is kept.
constexpr Real kSamePoint = kTouchTolerance;

/// Depths within this of the deepest, m, count as equally deep when a manifold is cut down to
/// four points: a box lying flat on a floor is flat to round-off, and the solver does not
/// resolve a micrometre.
constexpr Real kDepthTie = kTouchTolerance;

/// One triangle of the mesh, in the world.
struct WorldTriangle {
    ConvexShape shape;               // the three corners, counter-clockwise seen from the front
    Vec3 normal{0, 1, 0};            // the front's unit normal, (p₁ − p₀) × (p₂ − p₀) normalised
    std::array<bool, 3> active{};    // edges p₀p₁, p₁p₂, p₂p₀: may a contact push across them?
};

/// What closest points, GJK or EPA found between A and one triangle.
struct TriangleHit {
    Vec3 normal{0, 1, 0};  // unit, from A towards the triangle
    Vec3 onA{0, 0, 0};     // deepest (or closest) point of A, m
    Vec3 onB{0, 0, 0};     // deepest (or closest) point of the triangle, m
    Real depth = 0;        // along normal, m (negative: a gap)
    Real weights[3] = {};  // barycentric weights of onB on the triangle's corners
};

/// What the test of one triangle came to.
enum class Found { None, Hit, CoresOverlap };

/// Triangle @p index of @p mesh turned into the world. False when its corners are out of range or
/// it has no area (a hand-made mesh gone wrong: buildTriangleMesh() lets neither through).
bool worldTriangle(const TriangleMesh& mesh, std::uint32_t index, const Vec3& centre, const Mat3& rotation,
                   WorldTriangle& out) {
    const std::array<std::uint32_t, 3>& t = mesh.triangles[index];
    const std::size_t vertexCount = mesh.vertices.size();
    if (t[0] >= vertexCount || t[1] >= vertexCount || t[2] >= vertexCount) return false;
    out.shape = convexShapeOfTriangle(centre + rotation * mesh.vertices[t[0]], centre + rotation * mesh.vertices[t[1]],
                                      centre + rotation * mesh.vertices[t[2]]);
    const Vec3* p = out.shape.corners;
    const Vec3 twiceArea = glm::cross(p[1] - p[0], p[2] - p[0]);
    const Real length = glm::length(twiceArea);
    if (!(length > 0)) return false;
    out.normal = twiceArea / length;
    // A mesh without flags (hand-made) counts every edge as active: the safe side, no push is lost.
    out.active = index < mesh.activeEdges.size() ? mesh.activeEdges[index] : std::array<bool, 3>{true, true, true};
    return true;
}

/// Barycentric weights (u, v, w) of a point @p p of the triangle's plane: p = u·a + v·b + w·c
/// (Ericson §3.4, from the two equations (p − a)·ab and (p − a)·ac by Cramer's rule).
void barycentric(const Vec3& p, const Vec3* corners, Real (&weights)[3]) {
    const Vec3 ab = corners[1] - corners[0];
    const Vec3 ac = corners[2] - corners[0];
    const Vec3 ap = p - corners[0];
    const Real d00 = glm::dot(ab, ab);
    const Real d01 = glm::dot(ab, ac);
    const Real d11 = glm::dot(ac, ac);
    const Real d20 = glm::dot(ap, ab);
    const Real d21 = glm::dot(ap, ac);
    const Real denominator = d00 * d11 - d01 * d01;  // |ab × ac|² > 0 for a triangle with an area
    weights[1] = (d11 * d20 - d01 * d21) / denominator;
    weights[2] = (d00 * d21 - d01 * d20) / denominator;
    weights[0] = 1 - weights[1] - weights[2];
}

/// A sphere of radius @p radius about @p core, whose nearest point of the triangle is @p closest.
Found fromClosestPoint(const Vec3& core, Real radius, const TriangleClosestPoint& closest, Real maxGap,
                       TriangleHit& hit) {
    const Vec3 between = core - closest.point;  // from the triangle out to the core
    const Real distance = glm::length(between);
    if (distance - radius > maxGap) return Found::None;
    if (distance <= kCoincident) return Found::CoresOverlap;
    const Vec3 out = between / distance;
    hit.normal = -out;
    hit.onA = core - radius * out;
    hit.onB = closest.point;
    hit.depth = radius - distance;
    for (int i = 0; i < 3; ++i) hit.weights[i] = closest.weights[i];
    return Found::Hit;
}

/// Sphere against triangle: the triangle's point nearest the centre (Ericson §5.1.5).
Found sphereAgainstTriangle(const Geometry& sphere, const WorldTriangle& t, Real maxGap, TriangleHit& hit) {
    const Vec3* p = t.shape.corners;
    return fromClosestPoint(sphere.centre, sphere.radius, closestPointOnTriangle(sphere.centre, p[0], p[1], p[2]),
                            maxGap, hit);
}

/// Capsule against triangle: the nearest of the segment's ends to the triangle and of the segment to
/// the triangle's three edges (Ericson §5.1.9). A segment that passes through the triangle has no
/// nearest pair: its cores overlap.
Found capsuleAgainstTriangle(const Geometry& capsule, const WorldTriangle& t, Real maxGap, TriangleHit& hit) {
    const Vec3 axis = glm::mat3_cast(capsule.orientation)[1];
    const Vec3 from = capsule.centre - axis * capsule.halfHeight;
    const Vec3 to = capsule.centre + axis * capsule.halfHeight;
    const Vec3* p = t.shape.corners;
    const Real heightFrom = glm::dot(t.normal, from - p[0]);
    const Real heightTo = glm::dot(t.normal, to - p[0]);
    if (heightFrom * heightTo <= 0 && heightFrom != heightTo) {
        // The segment meets the triangle's plane: where, and is that inside the triangle?
        const Vec3 crossing = from + (to - from) * (heightFrom / (heightFrom - heightTo));
        Real weights[3];
        barycentric(crossing, p, weights);
        if (weights[0] >= -kOnEdgeWeight && weights[1] >= -kOnEdgeWeight && weights[2] >= -kOnEdgeWeight) {
            return Found::CoresOverlap;
        }
    }
    // The nearest of five candidate pairs: each end against the triangle, the segment against each edge.
    Real best = std::numeric_limits<Real>::max();
    Vec3 onSegment = from;
    TriangleClosestPoint onTriangle;
    for (const Vec3& end : {from, to}) {
        const TriangleClosestPoint q = closestPointOnTriangle(end, p[0], p[1], p[2]);
        const Real d2 = glm::dot(end - q.point, end - q.point);
        if (d2 < best) {
            best = d2;
            onSegment = end;
            onTriangle = q;
        }
    }
    for (int edge = 0; edge < 3; ++edge) {
        const int next = (edge + 1) % 3;
        const SegmentClosestPoints c = closestPointsOfSegments(from, to, p[edge], p[next]);
        const Real d2 = glm::dot(c.onFirst - c.onSecond, c.onFirst - c.onSecond);
        if (d2 < best) {
            best = d2;
            onSegment = c.onFirst;
            onTriangle.point = c.onSecond;
            onTriangle.weights[edge] = 1 - c.t;
            onTriangle.weights[next] = c.t;
            onTriangle.weights[(edge + 2) % 3] = 0;
        }
    }
    return fromClosestPoint(onSegment, capsule.radius, onTriangle, maxGap, hit);
}

/// Any convex shape against triangle: GJK, then EPA if the cores overlap.
Found convexAgainstTriangle(const ConvexShape& a, const WorldTriangle& t, Real maxGap, TriangleHit& hit) {
    const GjkResult g = gjk(a, t.shape);
    if (!g.overlap) {
        if (g.distance > maxGap) return Found::None;
        hit.normal = g.normal;
        hit.onA = g.onA;
        hit.onB = g.onB;
        hit.depth = -g.distance;
    } else {
        const EpaResult e = epa(a, t.shape, g.simplex);
        if (!e.valid) return Found::None;
        hit.normal = e.normal;
        hit.onA = e.onA;
        hit.onB = e.onB;
        hit.depth = e.depth;
    }
    barycentric(hit.onB, t.shape.corners, hit.weights);
    return Found::Hit;
}

/// The nearest points of A and the triangle, by the closed form for spheres and capsules, else by GJK and EPA.
bool touch(const Geometry& a, const ConvexShape& shapeA, const WorldTriangle& t, Real maxGap, TriangleHit& hit) {
    Found found = Found::CoresOverlap;
    if (a.type == GeometryType::Sphere) found = sphereAgainstTriangle(a, t, maxGap, hit);
    if (a.type == GeometryType::Capsule) found = capsuleAgainstTriangle(a, t, maxGap, hit);
    if (found == Found::CoresOverlap) found = convexAgainstTriangle(shapeA, t, maxGap, hit);
    return found == Found::Hit;
}

/// What the active-edge rule makes of one triangle's contact (step 2 of the file comment).
struct EdgeRule {
    bool toFace = false;    // push along the face normal, with what lies over the triangle
    bool fallBack = false;  // …and if nothing lies over it, keep the contact as found (an active edge)
    bool turned = false;    // the normal was turned (a corner with one active edge): new depth needed
    Vec3 normal{0, 1, 0};   // the normal to keep when !toFace, from A towards the triangle
};

EdgeRule edgeRule(const TriangleHit& hit, const WorldTriangle& t) {
    EdgeRule rule;
    rule.normal = hit.normal;
    const Vec3 out = -hit.normal;  // the push on A, away from the triangle
    // Edge e runs from corner e to corner e + 1; the point lies on it when the weight of the
    // corner opposite, e + 2, is zero.
    int onEdges = 0;
    int activeEdges = 0;
    int activeEdge = 0;
    for (int e = 0; e < 3; ++e) {
        if (hit.weights[(e + 2) % 3] > kOnEdgeWeight) continue;
        ++onEdges;
        if (t.active[static_cast<std::size_t>(e)]) {
            ++activeEdges;
            activeEdge = e;
        }
    }
    const Real alongFace = glm::dot(out, t.normal);
    if (alongFace >= kFaceNormalCosine) {
        rule.toFace = true;
        rule.fallBack = activeEdges > 0;  // e.g. a ball hanging just past the mesh's border
        return rule;
    }
    // A triangle never pulls a body towards its back, and its inside pushes only along its normal;
    // an inactive edge, or a corner of two inactive edges, never pushes across.
    if (alongFace < 0 || onEdges == 0 || activeEdges == 0) {
        rule.toFace = true;
        return rule;
    }
    if (onEdges >= 2 && activeEdges < onEdges) {
        // A corner with one active edge: keep the part of the push across that edge only.
        const Vec3* p = t.shape.corners;
        const Vec3 along = glm::normalize(p[(activeEdge + 1) % 3] - p[activeEdge]);
        const Vec3 across = out - glm::dot(out, along) * along;
        const Real length = glm::length(across);
        if (length <= kCoincident || glm::dot(across, t.normal) < 0) {
            rule.toFace = true;
            return rule;
        }
        rule.normal = -across / length;
        rule.turned = true;
    }
    return rule;
}

/// One triangle's points after the active-edge rule, with the normal they share (from A).
struct TrianglePoints {
    Vec3 normal{0, -1, 0};
    int count = 0;
    ContactPoint points[kMaxTriangleFacePoints];
};

/// One triangle's contact, after the active-edge rule.
bool triangleContact(const Geometry& a, const ConvexShape& shapeA, const WorldTriangle& t, const TriangleHit& hit,
                     Real maxGap, TrianglePoints& out) {
    const EdgeRule rule = edgeRule(hit, t);
    ContactManifold manifold;
    bool found = false;
    if (rule.toFace) {
        out.normal = -t.normal;
        out.count = triangleFacePoints(a, t.shape, maxGap, out.points);
        if (out.count > 0) return true;
        if (!rule.fallBack) return false;
        found = triangleManifold(a, t.shape, hit.normal, hit.onA, hit.onB, hit.depth, maxGap, manifold);
    } else if (!rule.turned) {
        found = triangleManifold(a, t.shape, hit.normal, hit.onA, hit.onB, hit.depth, maxGap, manifold);
    } else {
        // The depth along the turned normal n: how far A's support point along n passes the triangle's along −n.
        const Vec3& n = rule.normal;
        const Vec3 deepestOfA = support(shapeA, n);
        const Real depth = glm::dot(n, deepestOfA - support(t.shape, -n));
        if (-depth > maxGap) return false;
        found = triangleManifold(a, t.shape, n, deepestOfA, deepestOfA - depth * n, depth, maxGap, manifold);
    }
    if (!found) return false;
    out.normal = manifold.normal;
    out.count = manifold.pointCount;
    std::copy(manifold.points, manifold.points + manifold.pointCount, out.points);
    return out.count > 0;
}

/// A feature id that also names the triangle (mixFeatureBits(), contact.hpp), as narrowphase.cpp
/// mixes in a compound's parts: warm starting does not match points of two triangles.
std::uint32_t withTriangle(std::uint32_t featureId, std::uint32_t triangle) {
    return mixFeatureBits(featureId ^ ((triangle + 1u) * kGoldenRatioBits));
}

/// The points gathered under one normal, before they are cut down to four.
struct Gathered {
    Vec3 normal{0, 1, 0};
    int count = 0;
    ContactPoint points[kGatheredPoints];
};

/// Cuts @p group down to kMaxManifoldPoints: keepSpreadContactPoints() (the deepest, then the
/// widest spread), started from the right point. Points gathered from several triangles are not
/// all corners of the contact area: a box over a diagonal brings the points where the diagonal
/// crosses its edges, and triangle corners inside its face. When several points are equally
/// deep (a box lying flat), the first of them would start the spread, and it may be one of
/// those; the one farthest from the points' centroid is a corner of the area, so it starts
/// instead. keepSpreadContactPoints() is run on copies whose depths within kDepthTie of the
/// deepest are made equal, that corner first, each copy's featureId holding its index.
void cutToFour(Gathered& group) {
    if (group.count <= kMaxManifoldPoints) return;
    Real deepest = group.points[0].depth;
    Vec3 centroid(0);
    for (int i = 0; i < group.count; ++i) {
        deepest = std::max(deepest, group.points[i].depth);
        centroid += group.points[i].position;
    }
    centroid /= Real(group.count);
    ContactPoint copies[kGatheredPoints];
    int start = 0;
    Real farthest = -1;
    for (int i = 0; i < group.count; ++i) {
        copies[i] = group.points[i];
        copies[i].featureId = static_cast<std::uint32_t>(i);
        if (copies[i].depth < deepest - kDepthTie) continue;
        copies[i].depth = deepest;
        const Real d2 = glm::dot(copies[i].position - centroid, copies[i].position - centroid);
        if (d2 > farthest) {
            farthest = d2;
            start = i;
        }
    }
    std::swap(copies[0], copies[start]);
    const int kept = std::min(keepSpreadContactPoints(copies, group.count, group.normal), kMaxManifoldPoints);
    ContactPoint chosen[kMaxManifoldPoints];
    for (int k = 0; k < kept; ++k) chosen[k] = group.points[copies[k].featureId];
    std::copy(chosen, chosen + kept, group.points);
    group.count = kept;
}

/// Every normal's points, for one shape against one mesh.
struct Gathering {
    int count = 0;
    Gathered groups[kMaxMeshManifolds];

    /// Adds triangle @p triangle's points to the group of their normal (a new one if none agrees).
    void add(const TrianglePoints& manifold, std::uint32_t triangle) {
        int chosen = -1;
        Real nearest = -2;
        for (int g = 0; g < count; ++g) {
            const Real agreement = glm::dot(groups[g].normal, manifold.normal);
            if (agreement > nearest) {
                nearest = agreement;
                chosen = g;
            }
        }
        if (nearest < kSameNormalCosine && count < kMaxMeshManifolds) {
            chosen = count++;
            groups[chosen].normal = manifold.normal;
            groups[chosen].count = 0;
        }
        Gathered& group = groups[chosen];
        for (int i = 0; i < manifold.count; ++i) {
            ContactPoint p = manifold.points[i];
            p.featureId = withTriangle(p.featureId, triangle);
            addPoint(group, p);
        }
    }

    static void addPoint(Gathered& group, const ContactPoint& p) {
        for (int k = 0; k < group.count; ++k) {
            const Vec3 apart = group.points[k].position - p.position;
            if (glm::dot(apart, apart) <= kSamePoint * kSamePoint) {
                if (p.depth > group.points[k].depth) group.points[k] = p;
                return;
            }
        }
        if (group.count == kGatheredPoints) cutToFour(group);
        group.points[group.count++] = p;
    }
};

}  // namespace

bool meshContacts(const Geometry& a, const Geometry& mesh, Real maxGap, MeshContacts& out) {
    out.count = 0;
    if (mesh.type != GeometryType::Mesh || mesh.mesh == nullptr) return false;
    if (a.type == GeometryType::Plane || a.type == GeometryType::Mesh || a.type >= GeometryType::Count) return false;
    const TriangleMesh& triangles = *mesh.mesh;

    // The triangles within reach: A's box grown by the reach, in the mesh's frame.
    Aabb box = geometryAabb(a);
    const Vec3 grow(std::max(maxGap, Real(0)));
    box.min -= grow;
    box.max += grow;
    const Aabb local = meshFrameBox(box, mesh.centre, mesh.orientation);

    const Mat3 rotation = glm::mat3_cast(mesh.orientation);
    const ConvexShape shapeA = convexShapeOf(a);
    Gathering gathering;
    std::uint32_t index = 0;
    for (TrianglesInBox query(triangles, local); query.next(index);) {
        WorldTriangle t;
        if (!worldTriangle(triangles, index, mesh.centre, rotation, t)) continue;
        if (glm::dot(t.normal, a.centre - t.shape.corners[0]) < 0) continue;  // behind it: one-sided
        TriangleHit hit;
        if (!touch(a, shapeA, t, maxGap, hit)) continue;
        TrianglePoints points;
        if (!triangleContact(a, shapeA, t, hit, maxGap, points)) continue;
        gathering.add(points, index);
    }

    for (int g = 0; g < gathering.count; ++g) {
        Gathered& group = gathering.groups[g];
        cutToFour(group);
        ContactManifold& manifold = out.manifolds[out.count++];
        manifold.normal = group.normal;
        manifold.pointCount = 0;
        for (int i = 0; i < group.count; ++i) {
            manifold.add(group.points[i].position, group.points[i].depth, group.points[i].featureId);
        }
    }
    return out.count > 0;
}

bool collideConvexMesh(const Geometry& a, const Geometry& b, ContactManifold& out) {
    MeshContacts found;
    if (!meshContacts(a, b, kSpeculativeDistance, found)) return false;
    int deepest = 0;
    Real deepestDepth = std::numeric_limits<Real>::lowest();
    for (int m = 0; m < found.count; ++m) {
        for (int i = 0; i < found.manifolds[m].pointCount; ++i) {
            if (found.manifolds[m].points[i].depth > deepestDepth) {
                deepestDepth = found.manifolds[m].points[i].depth;
                deepest = m;
            }
        }
    }
    out = found.manifolds[deepest];
    return true;
}

}  // namespace stepwise
