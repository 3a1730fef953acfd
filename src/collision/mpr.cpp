/// @file mpr.cpp
/// @brief Minkowski portal refinement: find a portal the ray v₀ → origin passes, then shrink it onto the boundary (mpr.hpp).
#include "collision/mpr.hpp"

#include <cmath>

namespace stepwise {

namespace {

/// Squared lengths below this (m², m⁴) are zero: two points that coincide, a direction that is none.
constexpr Real kTinySquared = Real(1e-24);

/// A point of A − B with the two support points it came from.
struct PortalPoint {
    Vec3 w;
    Vec3 onA;
    Vec3 onB;
};

struct Query {
    const ConvexShape& a;
    const ConvexShape& b;
    int supports = 0;

    PortalPoint operator()(const Vec3& direction) {
        ++supports;
        PortalPoint p{};
        p.onA = support(a, direction);
        p.onB = support(b, -direction);
        p.w = p.onA - p.onB;
        return p;
    }
};

/// Fills the result from the portal (v₁, v₂, v₃) and its unit normal n.
MprResult resultOf(const PortalPoint& v1, const PortalPoint& v2, const PortalPoint& v3, const Vec3& n, int supports) {
    MprResult result;
    result.overlap = true;
    result.normal = n;
    result.depth = glm::dot(n, v1.w);
    result.iterations = supports;
    // Barycentric weights of the origin's projection p = depth·n in the portal (by sub-triangle areas).
    const Vec3 p = n * result.depth;
    Real l1 = glm::dot(glm::cross(v2.w - p, v3.w - p), n);
    Real l2 = glm::dot(glm::cross(v3.w - p, v1.w - p), n);
    Real l3 = glm::dot(glm::cross(v1.w - p, v2.w - p), n);
    const Real sum = l1 + l2 + l3;
    if (std::abs(sum) <= kTinySquared) {
        l1 = 1;
        l2 = l3 = 0;
    } else {
        l1 /= sum;
        l2 /= sum;
        l3 /= sum;
    }
    result.onA = l1 * v1.onA + l2 * v2.onA + l3 * v3.onA;
    result.onB = l1 * v1.onB + l2 * v2.onB + l3 * v3.onB;
    return result;
}

/// No overlap, found after @p supports support queries.
MprResult miss(int supports) {
    MprResult result;
    result.iterations = supports;
    return result;
}

}  // namespace

MprResult mpr(const ConvexShape& a, const ConvexShape& b) {
    Query s{a, b};
    // Step 1: the interior point.
    PortalPoint v0{a.centre - b.centre, a.centre, b.centre};
    if (glm::dot(v0.w, v0.w) <= kTinySquared) v0.w = Vec3(kMprTolerance, 0, 0);  // centres coincide: any nudge

    // Step 2: the portal. v₁ towards the origin.
    Vec3 n = -v0.w;
    PortalPoint v1 = s(n);
    if (glm::dot(v1.w, n) <= 0) return miss(s.supports);  // A − B ends before the origin: a separating plane
    n = glm::cross(v1.w, v0.w);
    if (glm::dot(n, n) <= kTinySquared) {
        // The origin lies on the segment v₀v₁: it is inside, and the way out is along v₁ − v₀.
        const Vec3 out = glm::normalize(v1.w - v0.w);
        MprResult result;
        result.overlap = true;
        result.normal = out;
        result.depth = glm::dot(v1.w, out);
        result.onA = v1.onA;
        result.onB = v1.onB;
        result.iterations = s.supports;
        return result;
    }
    PortalPoint v2 = s(n);
    if (glm::dot(v2.w, n) <= 0) return miss(s.supports);
    // The normal of (v₀, v₁, v₂), turned to the origin's side.
    n = glm::cross(v1.w - v0.w, v2.w - v0.w);
    if (glm::dot(n, v0.w) > 0) {
        std::swap(v1, v2);
        n = -n;
    }
    PortalPoint v3{};
    for (;;) {
        if (s.supports > kMaxMprIterations) return miss(s.supports);
        v3 = s(n);
        if (glm::dot(v3.w, n) <= 0) return miss(s.supports);
        // Origin outside the plane (v₀, v₁, v₃)? Then v₂ is the wrong vertex: replace it.
        if (glm::dot(glm::cross(v1.w, v3.w), v0.w) < 0) {
            v2 = v3;
            n = glm::cross(v1.w - v0.w, v3.w - v0.w);
            continue;
        }
        // Origin outside the plane (v₀, v₃, v₂)? Then replace v₁.
        if (glm::dot(glm::cross(v3.w, v2.w), v0.w) < 0) {
            v1 = v3;
            n = glm::cross(v3.w - v0.w, v2.w - v0.w);
            continue;
        }
        break;  // the ray v₀ → origin passes through the portal (v₁, v₂, v₃)
    }

    // Step 3: refine the portal until it lies on the boundary.
    bool hit = false;
    for (;;) {
        n = glm::cross(v2.w - v1.w, v3.w - v1.w);
        const Real length2 = glm::dot(n, n);
        if (length2 <= kTinySquared) return hit ? resultOf(v1, v2, v3, Vec3(0, 1, 0), s.supports) : miss(s.supports);
        n /= std::sqrt(length2);
        // The origin behind the portal: inside the tetrahedron (v₀, v₁, v₂, v₃).
        if (!hit && glm::dot(n, v1.w) >= 0) hit = true;
        const PortalPoint v4 = s(n);
        const Real beyond = glm::dot(v4.w - v3.w, n);  // how far A − B reaches past the portal
        if (beyond <= kMprTolerance || s.supports > kMaxMprIterations) {
            return hit ? resultOf(v1, v2, v3, n, s.supports) : miss(s.supports);
        }
        if (!hit && glm::dot(v4.w, n) <= 0) return miss(s.supports);  // a separating plane found on the way
        // The new portal: of the three triangles (v₄, vᵢ, vⱼ) the ray passes through one.
        const Vec3 side = glm::cross(v4.w, v0.w);
        if (glm::dot(v1.w, side) > 0) {
            if (glm::dot(v2.w, side) > 0) v1 = v4; else v3 = v4;
        } else {
            if (glm::dot(v3.w, side) > 0) v2 = v4; else v1 = v4;
        }
    }
}

}  // namespace stepwise
