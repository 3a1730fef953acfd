/// @file narrowphase.cpp
/// @brief Stage 5: dispatch each candidate pair to its exact test.
///
/// One table says which test handles which pair of shapes. Adding a shape
/// means adding a row and a column here and one file per new pair; nothing
/// else in the step changes.
#include "collision/narrowphase.hpp"

#include <algorithm>

#include "collision/continuous.hpp"

namespace stepwise {

namespace {

constexpr std::size_t kGeometryTypes = static_cast<std::size_t>(GeometryType::Count);

/// The dispatch table, [shape of A][shape of B]. A is always a dynamic
/// body, B any body (dynamic, kinematic or a plane), so the Plane row is
/// never used: a plane is never A. Box–sphere is sphere–box with the
/// roles swapped and the normal flipped (box_sphere.cpp).
constexpr PairTest kPairTests[kGeometryTypes][kGeometryTypes] = {
    //              B: Sphere               Box               Plane
    /* A: Sphere */ {collideSphereSphere, collideSphereBox, collideSpherePlane},
    /* A: Box    */ {collideBoxSphere,    collideBoxBox,    collideBoxPlane},
    /* A: Plane  */ {nullptr,             nullptr,          nullptr},
};

Geometry geometryOfShape(Shape shape, const GameObject& object, Real radius) {
    Geometry g;
    g.type = shape == Shape::Sphere ? GeometryType::Sphere : GeometryType::Box;
    g.centre = object.position;
    g.orientation = object.orientation;
    g.halfExtents = object.scale * Real(0.5);
    g.radius = radius;
    return g;
}

}  // namespace

PairTest pairTestFor(GeometryType a, GeometryType b) {
    return kPairTests[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
}

Geometry geometryOf(const DynamicObject& body) { return geometryOfShape(body.shape, body, body.radius); }

Geometry geometryOf(const KinematicsObject& body) { return geometryOfShape(body.shape, body, body.radius); }

Geometry geometryOf(const CollisionPlane& plane) {
    Geometry g;
    g.type = GeometryType::Plane;
    g.centre = plane.position;
    g.normal = plane.normal;
    return g;
}

Geometry geometryOf(const BodySet& bodies, const BodyRef& ref) {
    switch (ref.kind) {
        case BodyKind::Dynamic: return geometryOf(bodies.dynamics[ref.index]);
        case BodyKind::Kinematic: return geometryOf(bodies.kinematics[ref.index]);
        case BodyKind::Plane: return geometryOf(bodies.planes[ref.index]);
    }
    return {};
}

namespace {

Real sweepOf(const BodySet& bodies, const BodyRef& ref) {
    switch (ref.kind) {
        case BodyKind::Dynamic: return bodies.dynamics[ref.index].sweep;
        case BodyKind::Kinematic: return bodies.kinematics[ref.index].sweep;
        case BodyKind::Plane: return bodies.planes[ref.index].sweep;
    }
    return 0;
}

}  // namespace

namespace {

/// The exact test of one candidate pair; its contacts are appended to @p contacts.
void collidePair(const BodySet& bodies, const CandidatePair& pair, bool continuousCollision,
                 Real speculativeDistance, std::vector<Contact>& contacts) {
    Geometry a = geometryOf(bodies.dynamics[pair.a]);
    Geometry b = geometryOf(bodies, pair.b);
    // Every pair of shapes that can meet has a test; nullptr is left only
    // for a plane as A, which the broadphase never produces.
    const PairTest test = pairTestFor(a.type, b.type);
    if (test == nullptr) return;

    // Sweep: a sphere's test reaches as far as the two bodies can close
    // this step (GameObject::sweep), found by testing a sphere grown by
    // that much; depths and points are then given back for the real one.
    Real reach = bodies.dynamics[pair.a].sweep + sweepOf(bodies, pair.b);
    Geometry& grown = a.type == GeometryType::Sphere ? a : b;
    // Past a fraction of the sphere's radius the continuous stage follows the path
    // with the exact shapes; a plane cannot be tunnelled through (continuous.hpp).
    if (continuousCollision && b.type != GeometryType::Plane) {
        reach = std::min(reach, kFastMotionFraction * grown.radius);
    }
    // Plus a fixed margin, when the solver asks for one (findContacts() in narrowphase.hpp says why).
    reach += speculativeDistance;
    const bool grows = reach > 0 && grown.type == GeometryType::Sphere;
    if (grows) grown.radius += reach;

    ContactManifold found;
    if (!test(a, b, found)) return;
    for (int i = 0; i < found.pointCount; ++i) {
        ContactPoint p = found.points[i];
        if (grows) {
            p.depth -= reach;
            // The point sat on the grown surface: move it back onto the real one.
            p.position += (&grown == &a ? -reach : reach) * found.normal;
        }
        contacts.push_back({pair.a, pair.b, found.normal, p.position, p.depth, p.featureId});
    }
}

}  // namespace

void findContacts(const BodySet& bodies, const std::vector<CandidatePair>& pairs, std::vector<Contact>& contacts) {
    contacts.clear();
    for (const CandidatePair& pair : pairs) collidePair(bodies, pair, false, 0, contacts);
}

void findContacts(const BodySet& bodies, const std::vector<CandidatePair>& pairs, std::vector<Contact>& contacts,
                  bool continuousCollision, Real speculativeDistance, ThreadPool& pool,
                  NarrowphaseWorkspace& workspace) {
    if (pool.threadCount() == 1 || pairs.size() <= kPairsPerChunk) {
        // One chunk: the merge below would only copy.
        contacts.clear();
        for (const CandidatePair& pair : pairs) collidePair(bodies, pair, continuousCollision, speculativeDistance, contacts);
        return;
    }
    // Chunk c holds pairs [c·k, (c+1)·k), k = kPairsPerChunk, whatever the
    // number of threads: the chunks depend only on the pair list, each
    // chunk's contacts come out in its pairs' order, and concatenating the
    // chunks in order gives exactly the serial list above.
    const std::size_t chunks = (pairs.size() + kPairsPerChunk - 1) / kPairsPerChunk;
    if (workspace.chunkContacts.size() < chunks) workspace.chunkContacts.resize(chunks);  // grows, never shrinks
    auto runChunk = [&](std::size_t c) {
        std::vector<Contact>& out = workspace.chunkContacts[c];
        out.clear();  // keeps its capacity: no allocation once the scene has settled
        const std::size_t end = std::min(pairs.size(), (c + 1) * kPairsPerChunk);
        for (std::size_t i = c * kPairsPerChunk; i < end; ++i) collidePair(bodies, pairs[i], continuousCollision, speculativeDistance, out);
    };
    pool.run(chunks, runChunk);

    contacts.clear();
    for (std::size_t c = 0; c < chunks; ++c) {
        const std::vector<Contact>& part = workspace.chunkContacts[c];
        contacts.insert(contacts.end(), part.begin(), part.end());
    }
}

}  // namespace stepwise
