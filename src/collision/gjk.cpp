/// @file gjk.cpp
/// @brief GJK's loop and Johnson's sub-algorithm by Voronoi regions (gjk.hpp has the maths).
#include "collision/gjk.hpp"

#include <cmath>
#include <limits>

namespace stepwise {

namespace {

/// Squared lengths and areas (m², m⁴) below this are a simplex that has
/// collapsed (two equal points, three on a line): the smaller simplex is used.
constexpr Real kCollapsed = Real(1e-30);

/// A tetrahedron whose fourth point lies within this sine² of a face's
/// plane is flat: the face cannot say on which side the origin is, so the
/// face is searched anyway (a flat tetrahedron holds no volume and so no origin).
constexpr Real kFlatSineSquared = Real(1e-20);

/// The closest point found on one face of the simplex: which points hold it, with which weights.
struct Closest {
    int index[3] = {0, 0, 0};
    Real weight[3] = {1, 0, 0};
    int count = 1;
    Vec3 point{0, 0, 0};
};

Closest vertexRegion(const Simplex& s, int i) {
    Closest c;
    c.index[0] = i;
    c.point = s.vertices[i].w;
    return c;
}

Closest edgeRegion(const Simplex& s, int i, int j, Real t) {
    Closest c;
    c.index[0] = i;
    c.index[1] = j;
    c.weight[0] = 1 - t;
    c.weight[1] = t;
    c.count = 2;
    c.point = s.vertices[i].w + t * (s.vertices[j].w - s.vertices[i].w);
    return c;
}

/// Closest point of the segment w_i w_j to the origin: t = −a·(b − a)/|b − a|², clamped to [0, 1].
Closest closestOnSegment(const Simplex& s, int i, int j) {
    const Vec3 a = s.vertices[i].w;
    const Vec3 ab = s.vertices[j].w - a;
    const Real length2 = glm::dot(ab, ab);
    if (length2 <= kCollapsed) return vertexRegion(s, i);
    const Real t = -glm::dot(a, ab) / length2;
    if (t <= 0) return vertexRegion(s, i);
    if (t >= 1) return vertexRegion(s, j);
    return edgeRegion(s, i, j, t);
}

/// The closer of two candidates to the origin.
const Closest& closer(const Closest& x, const Closest& y) {
    return glm::dot(x.point, x.point) <= glm::dot(y.point, y.point) ? x : y;
}

/// Closest point of the triangle w_i w_j w_k to the origin (Ericson §5.1.5 with p = 0).
///
/// With ab = b − a, ac = c − a and the dot products d₁ … d₆ of ab and ac with
/// the vectors from a, b, c to the origin, the origin's Voronoi region is
/// found in the order vertex a, vertex b, edge ab, vertex c, edge ac, edge
/// bc, face; each test is a sign of a dot product or of a 2×2 determinant
/// (the barycentric coordinates v_a, v_b, v_c times twice the area).
Closest closestOnTriangle(const Simplex& s, int i, int j, int k) {
    const Vec3 a = s.vertices[i].w;
    const Vec3 b = s.vertices[j].w;
    const Vec3 c = s.vertices[k].w;
    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    const Real d1 = -glm::dot(ab, a);
    const Real d2 = -glm::dot(ac, a);
    if (d1 <= 0 && d2 <= 0) return vertexRegion(s, i);
    const Real d3 = -glm::dot(ab, b);
    const Real d4 = -glm::dot(ac, b);
    if (d3 >= 0 && d4 <= d3) return vertexRegion(s, j);
    const Real vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return edgeRegion(s, i, j, d1 / (d1 - d3));
    const Real d5 = -glm::dot(ab, c);
    const Real d6 = -glm::dot(ac, c);
    if (d6 >= 0 && d5 <= d6) return vertexRegion(s, k);
    const Real vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return edgeRegion(s, i, k, d2 / (d2 - d6));
    const Real va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        return edgeRegion(s, j, k, (d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    const Real sum = va + vb + vc;
    if (sum <= kCollapsed) {
        // A triangle of no area: its closest point is on one of its edges.
        return closer(closer(closestOnSegment(s, i, j), closestOnSegment(s, j, k)), closestOnSegment(s, i, k));
    }
    Closest face;
    face.index[0] = i;
    face.index[1] = j;
    face.index[2] = k;
    face.weight[1] = vb / sum;
    face.weight[2] = vc / sum;
    face.weight[0] = 1 - face.weight[1] - face.weight[2];
    face.count = 3;
    face.point = a + ab * face.weight[1] + ac * face.weight[2];
    return face;
}

/// Is the origin on the far side of the face (w_i, w_j, w_k) from w_l (Ericson §5.1.6)?
bool originOutsideFace(const Simplex& s, int i, int j, int k, int l) {
    const Vec3 a = s.vertices[i].w;
    const Vec3 n = glm::cross(s.vertices[j].w - a, s.vertices[k].w - a);
    const Vec3 toOther = s.vertices[l].w - a;
    const Real otherSide = glm::dot(toOther, n);
    const Real originSide = -glm::dot(a, n);
    if (otherSide * otherSide <= kFlatSineSquared * glm::dot(n, n) * glm::dot(toOther, toOther)) return true;
    return originSide * otherSide < 0;
}

/// Keeps the points and weights of @p c, in that order, as the new simplex.
void keep(Simplex& s, const Closest& c) {
    SimplexVertex kept[3];
    for (int m = 0; m < c.count; ++m) {
        kept[m] = s.vertices[c.index[m]];
        kept[m].weight = c.weight[m];
    }
    for (int m = 0; m < c.count; ++m) s.vertices[m] = kept[m];
    s.count = c.count;
    s.closest = c.point;
}

}  // namespace

bool reduceToClosest(Simplex& s) {
    switch (s.count) {
        case 1: keep(s, vertexRegion(s, 0)); return false;
        case 2: keep(s, closestOnSegment(s, 0, 1)); return false;
        case 3: keep(s, closestOnTriangle(s, 0, 1, 2)); return false;
        default: break;
    }
    // Tetrahedron: the closest point is on a face the origin lies outside of;
    // if it is outside none, it is inside and the shapes overlap.
    constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
    bool found = false;
    Closest best;
    for (const auto& f : kFaces) {
        if (!originOutsideFace(s, f[0], f[1], f[2], f[3])) continue;
        const Closest candidate = closestOnTriangle(s, f[0], f[1], f[2]);
        if (!found || glm::dot(candidate.point, candidate.point) < glm::dot(best.point, best.point)) best = candidate;
        found = true;
    }
    if (found) {
        keep(s, best);
        return false;
    }
    for (int m = 0; m < 4; ++m) s.vertices[m].weight = Real(0.25);  // the origin is inside: no single closest point
    s.closest = Vec3(0);
    return true;
}

GjkResult gjk(const ConvexShape& a, const ConvexShape& b, std::vector<Simplex>* record) {
    GjkResult result;
    Simplex& simplex = result.simplex;
    // Any point of A − B starts the search: the difference of the two centres.
    Vec3 v = a.centre - b.centre;
    if (glm::dot(v, v) <= kGjkOverlapTolerance * kGjkOverlapTolerance) v = Vec3(1, 0, 0);

    for (int iteration = 0; iteration < kMaxGjkIterations; ++iteration) {
        const Vec3 onA = coreSupport(a, -v);
        const Vec3 onB = coreSupport(b, v);
        const Vec3 w = onA - onB;
        result.iterations = iteration + 1;
        const Real vv = glm::dot(v, v);
        // Step 3: no progress towards the origin (within the tolerance), or a point already held.
        if (simplex.count > 0 && vv - glm::dot(v, w) <= kGjkRelativeTolerance * vv) break;
        bool repeated = false;
        for (int m = 0; m < simplex.count; ++m) repeated = repeated || simplex.vertices[m].w == w;
        if (repeated) break;

        simplex.vertices[simplex.count++] = {w, onA, onB, 0};
        const bool inside = reduceToClosest(simplex);
        if (record != nullptr) record->push_back(simplex);
        const Real closest2 = glm::dot(simplex.closest, simplex.closest);
        if (inside || closest2 <= kGjkOverlapTolerance * kGjkOverlapTolerance) {
            result.overlap = true;
            return result;
        }
        // Round-off can stop the distance from falling; past that point the simplex only wobbles.
        if (simplex.count > 1 && closest2 >= vv) {
            v = simplex.closest;
            break;
        }
        v = simplex.closest;
    }

    // v = pA − pB with pA = Σλᵢaᵢ, pB = Σλᵢbᵢ: the closest points of the cores.
    Vec3 coreA(0), coreB(0);
    for (int m = 0; m < simplex.count; ++m) {
        coreA += simplex.vertices[m].weight * simplex.vertices[m].onA;
        coreB += simplex.vertices[m].weight * simplex.vertices[m].onB;
    }
    const Real coreDistance = glm::length(v);
    result.normal = -v / coreDistance;  // pB − pA, unit
    result.distance = coreDistance - a.margin - b.margin;
    result.onA = coreA + result.normal * a.margin;
    result.onB = coreB - result.normal * b.margin;
    return result;
}

}  // namespace stepwise
