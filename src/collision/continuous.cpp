/// @file continuous.cpp
/// @brief Time of impact by conservative advancement along the tangent of a convex separation.
///
/// For every pair the separation d and its growth direction u come from the
/// same geometry as the narrowphase (Ericson, *Real-Time Collision
/// Detection*: closest point on a box §5.1.4, plane distance §5.1.1,
/// separating axes of two boxes §4.4.1). The advancement is in
/// timeOfImpact(); the derivation is in continuous.hpp.
#include "collision/continuous.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "collision/aabb.hpp"
#include "collision/closest_points.hpp"
#include "collision/epa.hpp"
#include "collision/gjk.hpp"

namespace stepwise {

namespace {

/// A cross product of two box axes shorter than this is two parallel edges:
/// that axis is skipped (the face axes already cover it), as in box_box.cpp.
constexpr Real kParallelAxesEpsilon = Real(1e-6);

Separation sphereFromSphere(const Geometry& a, const Geometry& b) {
    const Vec3 offset = a.centre - b.centre;
    const Real length = glm::length(offset);
    // Concentric spheres have no direction: any unit vector is a valid subgradient.
    const Vec3 direction = length > Real(0) ? offset / length : Vec3(0, 1, 0);
    return {length - a.radius - b.radius, direction};
}

Separation sphereFromPlane(const Geometry& sphere, const Geometry& plane) {
    return {glm::dot(sphere.centre - plane.centre, plane.normal) - sphere.radius, plane.normal};
}

/// Sphere A against box B: the gap from the box's closest point (outside), or
/// minus the way out through the nearest face (inside), as in sphere_box.cpp.
Separation sphereFromBox(const Geometry& sphere, const Geometry& box) {
    const PointFromBox seen = pointFromBox(sphere.centre, box.centre, box.orientation, box.halfExtents);
    const Real length = glm::length(seen.offset);
    if (length > Real(0)) return {length - sphere.radius, seen.rotation * (seen.offset / length)};
    const NearestFace face = nearestFace(seen.local, box.halfExtents);
    return {-face.inside - sphere.radius, seen.rotation * face.normal};
}

/// Box A against a plane: the deepest corner's height, n·(c − p) − Σ eᵢ|n·axisᵢ|.
Separation boxFromPlane(const Geometry& box, const Geometry& plane) {
    const Mat3 rotation = glm::mat3_cast(box.orientation);
    Real reach = 0;
    for (int i = 0; i < 3; ++i) reach += box.halfExtents[i] * std::abs(glm::dot(plane.normal, rotation[i]));
    return {glm::dot(box.centre - plane.centre, plane.normal) - reach, plane.normal};
}

/// Box A against box B: the largest separation over the 15 candidate axes L,
/// s(L) = |L·(c_A − c_B)| − Σ e_Ai|L·a_i| − Σ e_Bj|L·b_j|.
Separation boxFromBox(const Geometry& a, const Geometry& b) {
    const Mat3 ra = glm::mat3_cast(a.orientation);
    const Mat3 rb = glm::mat3_cast(b.orientation);
    const Vec3 offset = a.centre - b.centre;
    Separation best{-std::numeric_limits<Real>::infinity(), Vec3(0, 1, 0)};
    auto tryAxis = [&](const Vec3& axis) {
        Real extent = 0;
        for (int i = 0; i < 3; ++i) {
            extent += a.halfExtents[i] * std::abs(glm::dot(axis, ra[i]));
            extent += b.halfExtents[i] * std::abs(glm::dot(axis, rb[i]));
        }
        const Real along = glm::dot(axis, offset);
        const Real gap = std::abs(along) - extent;
        if (gap > best.distance) best = {gap, along >= Real(0) ? axis : -axis};
    };
    for (int i = 0; i < 3; ++i) tryAxis(ra[i]);
    for (int j = 0; j < 3; ++j) tryAxis(rb[j]);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const Vec3 cross = glm::cross(ra[i], rb[j]);
            const Real length = glm::length(cross);
            if (length > kParallelAxesEpsilon) tryAxis(cross / length);
        }
    }
    return best;
}

/// Is @p t one of the shapes only GJK measures (capsule, cylinder, hull)?
bool isGjkShape(GeometryType t) {
    return t == GeometryType::Capsule || t == GeometryType::Cylinder || t == GeometryType::Hull;
}

/// A convex shape A against a plane: the height of A's support point in −n, n·(s_A(−n) − q).
Separation convexFromPlane(const Geometry& a, const Geometry& plane) {
    const Vec3 deepest = support(convexShapeOf(a), -plane.normal);
    return {glm::dot(deepest - plane.centre, plane.normal), plane.normal};
}

/// Two convex shapes by GJK's distance (gjk.hpp): the gap, and −n, the way A moves
/// away from B. Cores that overlap are measured by EPA (epa.hpp): −depth along −n.
Separation convexFromConvex(const Geometry& a, const Geometry& b) {
    const ConvexShape sa = convexShapeOf(a);
    const ConvexShape sb = convexShapeOf(b);
    const GjkResult g = gjk(sa, sb);
    if (!g.overlap) return {g.distance, -g.normal};
    const EpaResult e = epa(sa, sb, g.simplex);
    if (!e.valid) return {0, Vec3(0, 1, 0)};  // shapes of no volume: touching, no direction to prefer
    return {-e.depth, -e.normal};
}

}  // namespace

Separation separation(const Geometry& a, const Geometry& b) {
    if (isGjkShape(a.type) || isGjkShape(b.type)) {
        if (b.type == GeometryType::Plane) return convexFromPlane(a, b);
        if (b.type != GeometryType::Mesh && a.type < GeometryType::Count && b.type < GeometryType::Count) {
            return convexFromConvex(a, b);
        }
    }
    const bool aSphere = a.type == GeometryType::Sphere;
    switch (b.type) {
        case GeometryType::Sphere:
            if (aSphere) return sphereFromSphere(a, b);
            {
                // Box A, sphere B: the sphere's separation from the box, seen from the other side.
                const Separation s = sphereFromBox(b, a);
                return {s.distance, -s.direction};
            }
        case GeometryType::Box: return aSphere ? sphereFromBox(a, b) : boxFromBox(a, b);
        case GeometryType::Plane: return aSphere ? sphereFromPlane(a, b) : boxFromPlane(a, b);
        case GeometryType::Capsule:
        case GeometryType::Cylinder:
        case GeometryType::Hull:
        case GeometryType::Mesh:
        case GeometryType::Count: break;
    }
    return {std::numeric_limits<Real>::infinity(), Vec3(0, 1, 0)};
}

std::optional<Real> timeOfImpact(const Geometry& a, const Vec3& start, const Geometry& b) {
    const Vec3 motion = a.centre - start;  // Δ: A's centre is start + t·Δ
    Geometry moving = a;
    Real t = 0;
    for (int iteration = 0; iteration < kMaxAdvancementIterations; ++iteration) {
        moving.centre = start + t * motion;
        const Separation s = separation(moving, b);
        if (s.distance <= kTimeOfImpactTolerance) {
            // Touching at t = 0: a resting or sliding contact the solver already holds.
            if (iteration == 0 && s.distance <= kTouchTolerance) return std::nullopt;
            return t;
        }
        const Real slope = glm::dot(s.direction, motion);  // d′(t) = u·Δ
        if (slope >= Real(0)) return std::nullopt;        // convex d: it only grows from here
        const Real next = t - s.distance / slope;         // the tangent's root: still before the impact
        if (next >= Real(1)) return std::nullopt;          // the tangent, below d, stays positive to t = 1
        t = next;
    }
    return t;  // not converged (grazing): stop here, still short of the impact
}

void recordStartPositions(const BodySet& bodies, SweepWorkspace& workspace) {
    workspace.startPositions.resize(bodies.dynamics.size());  // allocates only when bodies are added
    for (std::size_t i = 0; i < bodies.dynamics.size(); ++i) workspace.startPositions[i] = bodies.dynamics[i].position;
}

namespace {

/// The inner radius of one convex shape: the largest ball about its centre that it holds.
/// A hull's is its nearest face plane's distance from the centre (HullFace::offset), which
/// lies inside the hull; an offset below 0 would mean the centre is outside, and counts as 0.
Real convexInnerRadius(Shape shape, Real radius, Real height, const Vec3& halfExtents, const ConvexHull* hull) {
    switch (shape) {
        case Shape::Sphere:
        case Shape::Capsule: return radius;  // every point of the segment has a ball of r around it
        case Shape::Cylinder: return glm::min(radius, Real(0.5) * height);  // the centre's distance to side or cap
        case Shape::Box: return glm::min(halfExtents.x, glm::min(halfExtents.y, halfExtents.z));
        case Shape::Hull: {
            if (hull == nullptr || hull->faces.empty()) return Real(0);
            Real nearest = std::numeric_limits<Real>::infinity();
            for (const HullFace& face : hull->faces) nearest = glm::min(nearest, face.offset);
            return glm::max(Real(0), nearest);
        }
        case Shape::Compound:
        case Shape::Mesh: break;
    }
    return Real(0);
}

}  // namespace

Real innerRadius(const DynamicObject& body) {
    if (body.shape != Shape::Compound) {
        return convexInnerRadius(body.shape, body.radius, body.height, body.halfExtents(), body.hull.get());
    }
    // A compound: each part can pass through a thin wall on its own, so the thinnest part
    // sets how far the body may move before it counts as fast (a choice on the safe side:
    // more bodies are checked, none is missed).
    if (!body.compound || body.compound->parts.empty()) return Real(0);
    Real thinnest = std::numeric_limits<Real>::infinity();
    for (const CompoundPart& part : body.compound->parts) {
        const Real inner = convexInnerRadius(part.shape, part.radius, part.height, Real(0.5) * part.scale, part.hull.get());
        thinnest = glm::min(thinnest, inner);
    }
    return thinnest;
}

namespace {

/// Everything the path of @p moving from @p start passes through, grown by the touching tolerance.
Aabb sweptBounds(const Geometry& moving, const Vec3& start) {
    Geometry atStart = moving;
    atStart.centre = start;
    Aabb swept = merged(geometryBounds(atStart), geometryBounds(moving));
    swept.min -= Vec3(kTouchTolerance);
    swept.max += Vec3(kTouchTolerance);
    return swept;
}

/// The earliest time of impact of @p moving, from @p start, against @p other,
/// if their boxes overlap; @p earliest otherwise. A minimum: the order in
/// which the candidates come does not change it.
Real earlierImpact(const Geometry& moving, const Vec3& start, const Aabb& swept, const Geometry& other, Real earliest) {
    if (!swept.overlaps(geometryBounds(other))) return earliest;
    const std::optional<Real> t = timeOfImpact(moving, start, other);
    return t && *t < earliest ? *t : earliest;
}

/// The centre of @p moving, on its way from @p start this step, reaches @p other (as a point:
/// a ball of radius 0 swept along the same path).
bool centrePasses(const Geometry& moving, const Vec3& start, const Aabb& swept, const Geometry& other) {
    if (!swept.overlaps(geometryBounds(other))) return false;
    Geometry centre;
    centre.type = GeometryType::Sphere;
    centre.centre = moving.centre;
    return timeOfImpact(centre, start, other).has_value();
}

/// Moves @p body back to @p start + t·Δ when t < 1; true when it did. Its velocity stays:
/// the contact found there next step stops it. (The restitution stage counts on this: after
/// this stage the solver's records still hold every body's velocity, World::stepWithSequentialImpulses().)
bool moveBack(DynamicObject& body, const Vec3& start, Real t) {
    if (t >= Real(1)) return false;
    body.position = start + t * (body.position - start);
    return true;
}

/// Dynamic bodies @p i and @p j are not swept against each other (SweepWorkspace::unsweptPairs).
bool unswept(const SweepWorkspace& workspace, std::size_t i, std::size_t j) {
    const std::span<const std::uint64_t> keys = workspace.unsweptPairs;
    return !keys.empty() && std::binary_search(keys.begin(), keys.end(),
                                               bodyPairKey(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)));
}

/// Dynamic body @p i is joined to another dynamic body (it is in a key of SweepWorkspace::unsweptPairs).
bool isJointed(const SweepWorkspace& workspace, std::size_t i) {
    for (const std::uint64_t key : workspace.unsweptPairs) {
        if ((key >> 32) == i || (key & 0xffffffffu) == i) return true;
    }
    return false;
}

bool isFast(const DynamicObject& body, const Vec3& start) {
    const Real moved = glm::length(body.position - start);
    return moved > kFastMotionFraction * innerRadius(body);  // slow: nothing can be skipped
}

}  // namespace

std::size_t stopFastBodiesAtImpact(const BodySet& bodies, SweepWorkspace& workspace) {
    const std::size_t count = std::min(bodies.dynamics.size(), workspace.startPositions.size());
    workspace.fast.resize(bodies.dynamics.size());  // allocates only when bodies are added
    std::size_t fastCount = 0;
    for (std::size_t i = 0; i < bodies.dynamics.size(); ++i) {
        workspace.fast[i] = i < count && isFast(bodies.dynamics[i], workspace.startPositions[i]) ? 1 : 0;
        fastCount += workspace.fast[i];
    }
    workspace.lastClamped = 0;
    if (fastCount == 0) {
        workspace.index.markStale();  // nothing to ask: the index is not kept up to date
        return 0;
    }
    // A body is fast or not by its own motion, which no other body's move-back changes:
    // the flags can be computed first, and the index built once for the whole loop.
    workspace.index.build(bodies, workspace.startPositions, workspace.fast);

    std::size_t clamped = 0;
    const std::size_t dynamicCount = bodies.dynamics.size();
    // In index order, each against the others as they are now (some already
    // moved back): the same scene gives the same result every run.
    for (std::size_t i = 0; i < count; ++i) {
        if (!workspace.fast[i]) continue;
        const Vec3 start = workspace.startPositions[i];
        const bool jointed = isJointed(workspace, i);
        const Geometry moving = geometryOf(bodies.dynamics[i]);
        const Aabb swept = sweptBounds(moving, start);
        workspace.index.query(swept, static_cast<std::uint32_t>(i), workspace.candidates);
        Real earliest = 1;
        for (const std::uint32_t p : workspace.candidates) {
            if (p < dynamicCount && (jointed || unswept(workspace, i, p))) continue;  // its joints hold it
            const Geometry other = p < dynamicCount ? geometryOf(bodies.dynamics[p])
                                                    : geometryOf(bodies.kinematics[p - dynamicCount]);
            if (jointed && !centrePasses(moving, start, swept, other)) continue;
            earliest = earlierImpact(moving, start, swept, other, earliest);
        }
        // No planes: a plane bounds a solid half-space, as thick as can be, so however deep
        // a step carries a body behind it, the push-out along its normal sends it back out.
        if (moveBack(bodies.dynamics[i], start, earliest)) ++clamped;
    }
    workspace.lastClamped = clamped;
    return clamped;
}

std::size_t stopFastBodiesAtImpactBruteForce(const BodySet& bodies, SweepWorkspace& workspace) {
    std::size_t clamped = 0;
    for (std::size_t i = 0; i < bodies.dynamics.size() && i < workspace.startPositions.size(); ++i) {
        const Vec3 start = workspace.startPositions[i];
        if (!isFast(bodies.dynamics[i], start)) continue;
        const Geometry moving = geometryOf(bodies.dynamics[i]);
        const Aabb swept = sweptBounds(moving, start);
        Real earliest = 1;
        for (std::size_t j = 0; j < bodies.dynamics.size(); ++j) {
            if (j != i && !isJointed(workspace, i) && !unswept(workspace, i, j)) {
                earliest = earlierImpact(moving, start, swept, geometryOf(bodies.dynamics[j]), earliest);
            }
        }
        for (const KinematicsObject& body : bodies.kinematics) {
            const Geometry other = geometryOf(body);
            if (isJointed(workspace, i) && !centrePasses(moving, start, swept, other)) continue;
            earliest = earlierImpact(moving, start, swept, other, earliest);
        }
        if (moveBack(bodies.dynamics[i], start, earliest)) ++clamped;
    }
    workspace.lastClamped = clamped;
    return clamped;
}

}  // namespace stepwise
