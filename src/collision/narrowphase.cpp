/// @file narrowphase.cpp
/// @brief Stage 5: dispatch each candidate pair to its exact test.
///
/// One table says which test handles which pair of shapes. Adding a shape
/// means adding a row and a column here and one file per new pair; nothing
/// else in the step changes.
#include "collision/narrowphase.hpp"

#include <algorithm>
#include <span>

#include "collision/continuous.hpp"

namespace stepwise {

namespace {

constexpr std::size_t kGeometryTypes = static_cast<std::size_t>(GeometryType::Count);

/// The dispatch table, [shape of A][shape of B]. A is always a dynamic
/// body, B any body (dynamic, kinematic or a plane), so the Plane row is
/// never used: a plane is never A, nor is a mesh (only kinematic objects
/// have one). Box–sphere is sphere–box with the roles swapped and the normal
/// flipped (box_sphere.cpp). nullptr: no test yet, the pair never touches.
constexpr PairTest kPairTests[kGeometryTypes][kGeometryTypes] = {
    //                B: Sphere               Box               Plane               Capsule  Cylinder Hull     Mesh
    /* A: Sphere   */ {collideSphereSphere, collideSphereBox, collideSpherePlane, nullptr, nullptr, nullptr, nullptr},
    /* A: Box      */ {collideBoxSphere,    collideBoxBox,    collideBoxPlane,    nullptr, nullptr, nullptr, nullptr},
    /* A: Plane    */ {nullptr,             nullptr,          nullptr,            nullptr, nullptr, nullptr, nullptr},
    /* A: Capsule  */ {nullptr,             nullptr,          nullptr,            nullptr, nullptr, nullptr, nullptr},
    /* A: Cylinder */ {nullptr,             nullptr,          nullptr,            nullptr, nullptr, nullptr, nullptr},
    /* A: Hull     */ {nullptr,             nullptr,          nullptr,            nullptr, nullptr, nullptr, nullptr},
    /* A: Mesh     */ {nullptr,             nullptr,          nullptr,            nullptr, nullptr, nullptr, nullptr},
};

/// The pair tests' name for an object's shape (a compound's parts are looked up one by one).
GeometryType geometryType(Shape shape) {
    switch (shape) {
        case Shape::Sphere: return GeometryType::Sphere;
        case Shape::Box: return GeometryType::Box;
        case Shape::Capsule: return GeometryType::Capsule;
        case Shape::Cylinder: return GeometryType::Cylinder;
        case Shape::Hull: return GeometryType::Hull;
        case Shape::Mesh: return GeometryType::Mesh;
        case Shape::Compound: break;
    }
    return GeometryType::Count;  // a compound has no geometry of its own: geometryOfPart()
}

template <class Object>
Geometry geometryOfObject(const Object& object) {
    Geometry g;
    g.type = geometryType(object.shape);
    g.centre = object.position;
    g.orientation = object.orientation;
    g.halfExtents = object.scale * Real(0.5);
    g.radius = object.radius;
    g.halfHeight = Real(0.5) * object.height;
    g.hull = object.hull.get();
    return g;
}

}  // namespace

PairTest pairTestFor(GeometryType a, GeometryType b) {
    return kPairTests[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
}

Geometry geometryOf(const DynamicObject& body) { return geometryOfObject(body); }

Geometry geometryOf(const KinematicsObject& body) {
    Geometry g = geometryOfObject(body);
    g.mesh = body.mesh.get();
    return g;
}

Geometry geometryOfPart(const Geometry& body, const CompoundPart& part, std::uint32_t index) {
    Geometry g;
    g.type = geometryType(part.shape);
    g.centre = body.centre + body.orientation * part.position;
    g.orientation = body.orientation * part.orientation;
    g.halfExtents = part.scale * Real(0.5);
    g.radius = part.radius;
    g.halfHeight = Real(0.5) * part.height;
    g.hull = part.hull.get();
    g.part = index;
    return g;
}

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

/// How far beyond touching a pair's test looks, m: as far as the two bodies can close this step
/// (GameObject::sweep), capped where the continuous stage takes over (continuous.hpp), plus the
/// solver's fixed margin (findContacts() in narrowphase.hpp says why).
Real reachOf(const BodySet& bodies, const CandidatePair& pair, Real grownRadius, bool towardsPlane,
             bool continuousCollision, Real speculativeDistance) {
    Real reach = bodies.dynamics[pair.a].sweep + sweepOf(bodies, pair.b);
    // Past a fraction of the sphere's radius the continuous stage follows the path
    // with the exact shapes; a plane cannot be tunnelled through (continuous.hpp).
    if (continuousCollision && !towardsPlane) reach = std::min(reach, kFastMotionFraction * grownRadius);
    return reach + speculativeDistance;
}

/// Two sphere Geometry records and a manifold, set up once for a run of pairs and reused for
/// every ball–ball pair in it: only the centres and radii change from pair to pair.
struct BallPairScratch {
    Geometry a;  ///< type Sphere (the default); centre and radius set per pair
    Geometry b;
    ContactManifold found;
};

/// Ball on ball, most of a sphere rain's pairs: the same test, collideSphereSphere(), called
/// straight from the two bodies, A's radius grown by the reach as collidePair() grows it. It skips
/// what the general path does for any two shapes (a new Geometry from each body through its kind,
/// a zeroed four-point manifold, the table look-up, the loop over the points), which at one point
/// per pair cost more than the test itself. Same numbers as the general path.
void collideBalls(const BodySet& bodies, const CandidatePair& pair, bool continuousCollision, Real speculativeDistance,
                  BallPairScratch& scratch, std::vector<Contact>& contacts) {
    const DynamicObject& bodyA = bodies.dynamics[pair.a];
    const DynamicObject& bodyB = bodies.dynamics[pair.b.index];
    const Real reach = reachOf(bodies, pair, bodyA.radius, false, continuousCollision, speculativeDistance);
    const Real grown = reach > 0 ? reach : Real(0);
    scratch.a.centre = bodyA.position;
    scratch.a.radius = bodyA.radius + grown;
    scratch.b.centre = bodyB.position;
    scratch.b.radius = bodyB.radius;
    // Each test gets the manifold a fresh one would be (a student's collideSphereSphere() may only
    // add() to it); the points past pointCount are never read, so they are left as they are.
    ContactManifold& found = scratch.found;
    found.normal = ContactManifold{}.normal;
    found.pointCount = 0;
    if (!collideSphereSphere(scratch.a, scratch.b, found)) return;
    for (int i = 0; i < found.pointCount; ++i) {
        // The point sat on the grown surface: give the depth and the point back for the real one.
        const ContactPoint& p = found.points[i];
        contacts.push_back({pair.a, pair.b, found.normal, p.position + -grown * found.normal, p.depth - grown, p.featureId});
    }
}

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
    // this step, found by testing a sphere grown by that much; depths and
    // points are then given back for the real one. A box falling onto a
    // plane reaches as far too: the plane is moved towards it by the reach
    // (box_plane.cpp's corners within kSpeculativeDistance of the moved plane
    // are within reach of the real one). Without it a box faster than
    // kSpeculativeDistance per step sinks into a floor before its contact is
    // found, its centre behind the plane at 10 m/s.
    Geometry& grown = a.type == GeometryType::Sphere ? a : b;
    const bool boxOnPlane = a.type == GeometryType::Box && b.type == GeometryType::Plane;
    const Real reach = reachOf(bodies, pair, boxOnPlane ? Real(0) : grown.radius, b.type == GeometryType::Plane,
                               continuousCollision, speculativeDistance);
    const bool grows = reach > 0 && grown.type == GeometryType::Sphere;
    if (grows) grown.radius += reach;
    const Real planeShift = boxOnPlane && reach > speculativeDistance ? reach - speculativeDistance : Real(0);
    if (planeShift > 0) b.centre += planeShift * b.normal;

    ContactManifold found;
    if (!test(a, b, found)) return;
    for (int i = 0; i < found.pointCount; ++i) {
        ContactPoint p = found.points[i];
        if (grows) {
            p.depth -= reach;
            // The point sat on the grown surface: move it back onto the real one.
            p.position += (&grown == &a ? -reach : reach) * found.normal;
        }
        if (planeShift > 0) {
            // The point sat midway between the corner and the moved plane: midway to the real one.
            p.depth -= planeShift;
            p.position += (Real(0.5) * planeShift) * found.normal;
        }
        contacts.push_back({pair.a, pair.b, found.normal, p.position, p.depth, p.featureId});
    }
}

/// collidePair() on each of @p pairs in order, ball–ball pairs by collideBalls().
void collidePairs(const BodySet& bodies, std::span<const CandidatePair> pairs, bool continuousCollision,
                  Real speculativeDistance, std::vector<Contact>& contacts) {
    BallPairScratch scratch;
    for (const CandidatePair& pair : pairs) {
        if (bodies.dynamics[pair.a].shape == Shape::Sphere && pair.b.kind == BodyKind::Dynamic &&
            bodies.dynamics[pair.b.index].shape == Shape::Sphere) {
            collideBalls(bodies, pair, continuousCollision, speculativeDistance, scratch, contacts);
        } else {
            collidePair(bodies, pair, continuousCollision, speculativeDistance, contacts);
        }
    }
}

}  // namespace

void findContacts(const BodySet& bodies, const std::vector<CandidatePair>& pairs, std::vector<Contact>& contacts) {
    contacts.clear();
    collidePairs(bodies, pairs, false, 0, contacts);
}

void findContacts(const BodySet& bodies, const std::vector<CandidatePair>& pairs, std::vector<Contact>& contacts,
                  bool continuousCollision, Real speculativeDistance, ThreadPool& pool,
                  NarrowphaseWorkspace& workspace) {
    if (pool.threadCount() == 1 || pairs.size() <= kPairsPerChunk) {
        // One chunk: the merge below would only copy.
        contacts.clear();
        collidePairs(bodies, pairs, continuousCollision, speculativeDistance, contacts);
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
        collidePairs(bodies, std::span(pairs).subspan(c * kPairsPerChunk, end - c * kPairsPerChunk), continuousCollision,
                     speculativeDistance, out);
    };
    pool.run(chunks, runChunk);

    contacts.clear();
    for (std::size_t c = 0; c < chunks; ++c) {
        const std::vector<Contact>& part = workspace.chunkContacts[c];
        contacts.insert(contacts.end(), part.begin(), part.end());
    }
}

}  // namespace stepwise
