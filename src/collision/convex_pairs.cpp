/// @file convex_pairs.cpp
/// @brief collideConvex(): a convex pair to its plane test, closed form, GJK + EPA or MPR, then its manifold.
#include "collision/convex_pairs.hpp"

#include "collision/convex_manifold.hpp"
#include "collision/epa.hpp"
#include "collision/gjk.hpp"
#include "collision/mpr.hpp"

namespace stepwise {

namespace {

bool isCapsuleOrSphere(GeometryType t) { return t == GeometryType::Capsule || t == GeometryType::Sphere; }

/// GJK, and EPA if the cores overlap; then the manifold around the normal found.
bool byGjkEpa(const Geometry& a, const Geometry& b, const ConvexShape& sa, const ConvexShape& sb, Real maxGap,
              ContactManifold& out, ConvexIterations& iterations) {
    const GjkResult g = gjk(sa, sb);
    iterations.gjk = g.iterations;
    if (!g.overlap) {
        if (g.distance > maxGap) return false;
        return convexManifold(a, b, g.normal, g.onA, g.onB, -g.distance, maxGap, out);
    }
    const EpaResult e = epa(sa, sb, g.simplex);
    iterations.epa = e.iterations;
    if (!e.valid) return false;  // a flat Minkowski difference: shapes of no volume, nothing to push apart
    return convexManifold(a, b, e.normal, e.onA, e.onB, e.depth, maxGap, out);
}

}  // namespace

bool collideConvex(const Geometry& a, const Geometry& b, NarrowphaseKind kind, Real maxGap, ContactManifold& out,
                   ConvexIterations* iterations) {
    ConvexIterations counts;
    ConvexIterations& n = iterations != nullptr ? *iterations : counts;
    n = {};
    out.pointCount = 0;
    if (b.type == GeometryType::Plane) {
        switch (a.type) {
            case GeometryType::Capsule: return capsulePlaneContacts(a, b, maxGap, out);
            case GeometryType::Cylinder: return cylinderPlaneContacts(a, b, maxGap, out);
            case GeometryType::Hull: return hullPlaneContacts(a, b, maxGap, out);
            default: return false;  // sphere and box have their own plane tests (narrowphase.hpp)
        }
    }
    if (kind == NarrowphaseKind::Auto && isCapsuleOrSphere(a.type) && isCapsuleOrSphere(b.type)) {
        return capsuleContacts(a, b, maxGap, out);
    }
    const ConvexShape sa = convexShapeOf(a);
    const ConvexShape sb = convexShapeOf(b);
    if (kind == NarrowphaseKind::Mpr) {
        const MprResult m = mpr(sa, sb);
        n.mpr = m.iterations;
        if (m.overlap) return convexManifold(a, b, m.normal, m.onA, m.onB, m.depth, maxGap, out);
    }
    return byGjkEpa(a, b, sa, sb, maxGap, out, n);
}

bool collideConvexPair(const Geometry& a, const Geometry& b, ContactManifold& out) {
    return collideConvex(a, b, NarrowphaseKind::Auto, kSpeculativeDistance, out);
}

}  // namespace stepwise
