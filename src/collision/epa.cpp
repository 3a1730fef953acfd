/// @file epa.cpp
/// @brief EPA: a polytope in fixed arrays, grown face by face towards the boundary of A − B (epa.hpp has the maths).
#include "collision/epa.hpp"

#include <cmath>
#include <limits>

namespace stepwise {

namespace {

/// Faces whose normal is shorter than this (twice their area, m²) have no
/// direction: they are kept for the polytope's shape but never chosen.
constexpr Real kSliverArea = Real(1e-24);

/// Horizon edges an iteration can collect: three per removed face.
constexpr int kMaxEpaEdges = 3 * kMaxEpaFaces;

// No default member values in these three: a Polytope holds some 16 kB of
// them, and only the entries below the counts are ever read, so zeroing the
// arrays on every call would be work for nothing.
struct PolytopeVertex {
    Vec3 w;    // point of A − B
    Vec3 onA;  // support point of A
    Vec3 onB;  // support point of B
};

struct Face {
    int v[3];       // counter-clockwise seen from outside
    Vec3 normal;    // unit outward (zero for a sliver)
    Real distance;  // normal·w₀: distance of its plane from the origin
};

struct Edge {
    int from;
    int to;
};

/// Everything EPA keeps, in fixed arrays.
struct Polytope {
    PolytopeVertex vertices[kMaxEpaVertices];
    Face faces[kMaxEpaFaces];
    Edge horizon[kMaxEpaEdges];
    int vertexCount = 0;
    int faceCount = 0;
    int edgeCount = 0;
};

PolytopeVertex supportOfDifference(const ConvexShape& a, const ConvexShape& b, const Vec3& direction) {
    PolytopeVertex p{};
    p.onA = support(a, direction);
    p.onB = support(b, -direction);
    p.w = p.onA - p.onB;
    return p;
}

Face makeFace(const Polytope& poly, int i, int j, int k) {
    Face f{};
    f.v[0] = i;
    f.v[1] = j;
    f.v[2] = k;
    const Vec3 a = poly.vertices[i].w;
    const Vec3 n = glm::cross(poly.vertices[j].w - a, poly.vertices[k].w - a);
    const Real length = glm::length(n);
    if (length <= kSliverArea) {
        f.distance = std::numeric_limits<Real>::max();
        return f;
    }
    f.normal = n / length;
    f.distance = glm::dot(f.normal, a);
    return f;
}

/// Adds the edge from → to of a removed face. If its twin to → from is
/// already listed, both faces that share it are removed and it is no
/// horizon edge: the twin is dropped instead.
bool addHorizonEdge(Polytope& poly, int from, int to) {
    for (int e = 0; e < poly.edgeCount; ++e) {
        if (poly.horizon[e].from == to && poly.horizon[e].to == from) {
            poly.horizon[e] = poly.horizon[--poly.edgeCount];
            return true;
        }
    }
    if (poly.edgeCount == kMaxEpaEdges) return false;
    poly.horizon[poly.edgeCount++] = {from, to};
    return true;
}

/// Adds support points across GJK's simplex until it is a tetrahedron (epa.hpp, "Starting tetrahedron").
bool growToTetrahedron(const ConvexShape& a, const ConvexShape& b, Polytope& poly) {
    const Real distinct2 = kEpaAbsoluteTolerance * kEpaAbsoluteTolerance;
    if (poly.vertexCount == 0) poly.vertices[poly.vertexCount++] = supportOfDifference(a, b, Vec3(1, 0, 0));
    if (poly.vertexCount == 1) {
        // Any direction whose support point differs from the first one.
        const Vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (const Vec3& d : axes) {
            const PolytopeVertex p = supportOfDifference(a, b, d);
            const Vec3 offset = p.w - poly.vertices[0].w;
            if (glm::dot(offset, offset) > distinct2) {
                poly.vertices[poly.vertexCount++] = p;
                break;
            }
        }
        if (poly.vertexCount == 1) return false;
    }
    if (poly.vertexCount == 2) {
        // Directions around the segment, every 60°, until one leaves its line.
        const Vec3 along = glm::normalize(poly.vertices[1].w - poly.vertices[0].w);
        const Vec3 least = std::abs(along.x) < std::abs(along.y)
                               ? (std::abs(along.x) < std::abs(along.z) ? Vec3(1, 0, 0) : Vec3(0, 0, 1))
                               : (std::abs(along.y) < std::abs(along.z) ? Vec3(0, 1, 0) : Vec3(0, 0, 1));
        const Vec3 e1 = glm::normalize(glm::cross(along, least));
        const Vec3 e2 = glm::cross(along, e1);
        constexpr int kDirections = 6;
        for (int m = 0; m < kDirections && poly.vertexCount == 2; ++m) {
            const Real angle = Real(2) * kPi * Real(m) / Real(kDirections);
            const PolytopeVertex p = supportOfDifference(a, b, std::cos(angle) * e1 + std::sin(angle) * e2);
            const Vec3 offset = p.w - poly.vertices[0].w;
            const Vec3 across = offset - along * glm::dot(offset, along);
            if (glm::dot(across, across) > distinct2) poly.vertices[poly.vertexCount++] = p;
        }
        if (poly.vertexCount == 2) return false;
    }
    if (poly.vertexCount == 3) {
        // Off the triangle's plane, on whichever side A − B reaches.
        const Vec3 w0 = poly.vertices[0].w;
        const Vec3 n = glm::normalize(glm::cross(poly.vertices[1].w - w0, poly.vertices[2].w - w0));
        PolytopeVertex p = supportOfDifference(a, b, n);
        if (std::abs(glm::dot(p.w - w0, n)) <= kEpaAbsoluteTolerance) p = supportOfDifference(a, b, -n);
        if (std::abs(glm::dot(p.w - w0, n)) <= kEpaAbsoluteTolerance) return false;  // A − B is flat
        poly.vertices[poly.vertexCount++] = p;
    }
    return true;
}

/// Barycentric weights of @p p in the triangle a, b, c (Ericson §3.4, by dot products).
void barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Real weights[3]) {
    const Vec3 v0 = b - a;
    const Vec3 v1 = c - a;
    const Vec3 v2 = p - a;
    const Real d00 = glm::dot(v0, v0);
    const Real d01 = glm::dot(v0, v1);
    const Real d11 = glm::dot(v1, v1);
    const Real d20 = glm::dot(v2, v0);
    const Real d21 = glm::dot(v2, v1);
    const Real denominator = d00 * d11 - d01 * d01;
    if (denominator <= kSliverArea * kSliverArea) {
        weights[0] = 1;
        weights[1] = weights[2] = 0;
        return;
    }
    weights[1] = (d11 * d20 - d01 * d21) / denominator;
    weights[2] = (d00 * d21 - d01 * d20) / denominator;
    weights[0] = 1 - weights[1] - weights[2];
}

EpaResult resultOf(const Polytope& poly, const Face& face, int iterations) {
    EpaResult result;
    result.valid = true;
    result.depth = face.distance;
    result.normal = face.normal;
    result.iterations = iterations;
    const PolytopeVertex& p0 = poly.vertices[face.v[0]];
    const PolytopeVertex& p1 = poly.vertices[face.v[1]];
    const PolytopeVertex& p2 = poly.vertices[face.v[2]];
    Real lambda[3];
    barycentric(face.normal * face.distance, p0.w, p1.w, p2.w, lambda);
    result.onA = lambda[0] * p0.onA + lambda[1] * p1.onA + lambda[2] * p2.onA;
    result.onB = lambda[0] * p0.onB + lambda[1] * p1.onB + lambda[2] * p2.onB;
    return result;
}

}  // namespace

EpaResult epa(const ConvexShape& a, const ConvexShape& b, const Simplex& start) {
    Polytope poly;
    for (int m = 0; m < start.count; ++m) {
        const SimplexVertex& s = start.vertices[m];
        poly.vertices[poly.vertexCount++] = {s.w, s.onA, s.onB};
    }
    if (!growToTetrahedron(a, b, poly)) return {};

    // The tetrahedron's four faces, each turned to face away from its centroid.
    const Vec3 centroid =
        (poly.vertices[0].w + poly.vertices[1].w + poly.vertices[2].w + poly.vertices[3].w) * Real(0.25);
    constexpr int kTetrahedron[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    for (const auto& t : kTetrahedron) {
        Face f = makeFace(poly, t[0], t[1], t[2]);
        if (glm::dot(glm::cross(poly.vertices[t[1]].w - poly.vertices[t[0]].w, poly.vertices[t[2]].w - poly.vertices[t[0]].w),
                     poly.vertices[t[0]].w - centroid) < 0) {
            f = makeFace(poly, t[0], t[2], t[1]);
        }
        poly.faces[poly.faceCount++] = f;
    }

    for (int iteration = 0;; ++iteration) {
        // Step 1: the face nearest the origin.
        int nearest = 0;
        for (int f = 1; f < poly.faceCount; ++f) {
            if (poly.faces[f].distance < poly.faces[nearest].distance) nearest = f;
        }
        const Face face = poly.faces[nearest];
        if (face.distance == std::numeric_limits<Real>::max()) return {};  // only slivers left

        // Steps 2–3: how much farther does A − B reach along its normal?
        const PolytopeVertex p = supportOfDifference(a, b, face.normal);
        const Real gain = glm::dot(p.w, face.normal) - face.distance;
        const bool full = poly.vertexCount == kMaxEpaVertices || poly.faceCount + poly.vertexCount >= kMaxEpaFaces;
        if (gain <= kEpaAbsoluteTolerance + kEpaRelativeTolerance * std::abs(face.distance) || full ||
            iteration == kMaxEpaIterations) {
            return resultOf(poly, face, iteration + 1);
        }

        // Step 4: remove what the new point sees, close the hole with faces to it.
        const int added = poly.vertexCount;
        poly.vertices[poly.vertexCount++] = p;
        poly.edgeCount = 0;
        for (int f = 0; f < poly.faceCount;) {
            const Face& candidate = poly.faces[f];
            if (glm::dot(candidate.normal, p.w - poly.vertices[candidate.v[0]].w) > 0) {
                for (int e = 0; e < 3; ++e) {
                    if (!addHorizonEdge(poly, candidate.v[e], candidate.v[(e + 1) % 3])) return resultOf(poly, face, iteration + 1);
                }
                poly.faces[f] = poly.faces[--poly.faceCount];
            } else {
                ++f;
            }
        }
        for (int e = 0; e < poly.edgeCount; ++e) {
            poly.faces[poly.faceCount++] = makeFace(poly, poly.horizon[e].from, poly.horizon[e].to, added);
        }
    }
}

}  // namespace stepwise
