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
#include "collision/convex_pairs.hpp"
#include "collision/mesh_contacts.hpp"
#include "core/prefetch.hpp"

namespace stepwise {

namespace {

constexpr std::size_t kGeometryTypes = static_cast<std::size_t>(GeometryType::Count);

/// The dispatch table, [shape of A][shape of B]. A is always a dynamic
/// body, B any body (dynamic, kinematic or a plane), so the Plane row is
/// never used: a plane is never A, nor is a mesh (only kinematic objects
/// have one). Box–sphere is sphere–box with the roles swapped and the normal
/// flipped (box_sphere.cpp). Capsules, cylinders and hulls meet the other
/// convex shapes by GJK + EPA (collideConvexPair(), convex_pairs.hpp), a
/// capsule meets a capsule or a sphere by closest points of segments. Every
/// convex shape meets a triangle mesh triangle by triangle (collideConvexMesh(),
/// mesh_contacts.hpp); the table's entry hands back one manifold, the step
/// keeps one per direction of push (collideMeshShapes()). These
/// are the tests of NarrowphaseKind::Auto; collidePair() sends a pair to
/// another algorithm when the World asks for one. nullptr: the pair never touches.
constexpr PairTest kPairTests[kGeometryTypes][kGeometryTypes] = {
    //                B: Sphere                Box                Plane                 Capsule                Cylinder           Hull               Mesh
    /* A: Sphere   */ {collideSphereSphere,  collideSphereBox,  collideSpherePlane,   collideSphereCapsule,  collideConvexPair, collideConvexPair, collideConvexMesh},
    /* A: Box      */ {collideBoxSphere,     collideBoxBox,     collideBoxPlane,      collideConvexPair,     collideConvexPair, collideConvexPair, collideConvexMesh},
    /* A: Plane    */ {nullptr,              nullptr,           nullptr,              nullptr,               nullptr,           nullptr,           nullptr},
    /* A: Capsule  */ {collideCapsuleSphere, collideConvexPair, collideCapsulePlane,  collideCapsuleCapsule, collideConvexPair, collideConvexPair, collideConvexMesh},
    /* A: Cylinder */ {collideConvexPair,    collideConvexPair, collideCylinderPlane, collideConvexPair,     collideConvexPair, collideConvexPair, collideConvexMesh},
    /* A: Hull     */ {collideConvexPair,    collideConvexPair, collideHullPlane,     collideConvexPair,     collideConvexPair, collideConvexPair, collideConvexMesh},
    /* A: Mesh     */ {nullptr,              nullptr,           nullptr,              nullptr,               nullptr,           nullptr,           nullptr},
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
    if (a >= GeometryType::Count || b >= GeometryType::Count) return nullptr;  // a compound: test its parts
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

/// Is @p t a sphere or a box, the shapes whose tests came first and keep their own reach?
bool isSphereOrBox(GeometryType t) { return t == GeometryType::Sphere || t == GeometryType::Box; }

/// Does the pair keep its closed-form test and the sphere and box reach of collideClassic()?
/// Always for a sphere or a box against a plane or for two spheres; for the other sphere and
/// box pairs only under Auto (GjkEpa and Mpr meet boxes by their algorithm, as the side by side asks).
bool isClassicPair(GeometryType a, GeometryType b, NarrowphaseKind narrowphase) {
    if (!isSphereOrBox(a)) return false;
    if (b == GeometryType::Plane) return true;
    if (!isSphereOrBox(b)) return false;
    return narrowphase == NarrowphaseKind::Auto || (a == GeometryType::Sphere && b == GeometryType::Sphere);
}

/// A feature id that also names the two parts (0 for a body that is no compound), so that warm
/// starting never matches a point of one part with a point of another (mixFeatureBits(), contact.hpp).
std::uint32_t withParts(std::uint32_t featureId, std::uint32_t partA, std::uint32_t partB) {
    constexpr std::uint32_t kPartMultiplier = 0x85EBCA6Bu;  // any odd number unlike kGoldenRatioBits
    return mixFeatureBits(featureId ^ (partA * kGoldenRatioBits) ^ ((partB + 1u) * kPartMultiplier));
}

/// Which parts of two compound bodies a pair of geometries is: their ids go into the feature ids.
struct PartPair {
    bool compound = false;  ///< Either body is a compound: mix the part numbers into the ids.
    std::uint32_t a = 0;    ///< Part of A (0 for a body that is no compound).
    std::uint32_t b = 0;    ///< Part of B.
};

/// Appends one manifold's points as contacts of @p pair.
void appendContacts(const CandidatePair& pair, const Vec3& normal, const ContactPoint& p, const PartPair& parts,
                    std::vector<Contact>& contacts) {
    const std::uint32_t id = parts.compound ? withParts(p.featureId, parts.a, parts.b) : p.featureId;
    // The parts' numbers, for a part's own material (contactCoefficients()); kNoPart past the 16 bits.
    const auto part = [&](std::uint32_t k) { return parts.compound && k < kNoPart ? std::uint16_t(k) : kNoPart; };
    contacts.push_back({pair.a, pair.b, normal, p.position, p.depth, id, part(parts.a), part(parts.b)});
}

/// How far apart two boxes may be and still get contact points, m: what each can move towards
/// the other this step (GameObject::sweep), a dynamic box's share capped where the continuous stage
/// takes over for it (kFastMotionFraction × its inner radius: past that it is a fast body, which
/// continuous.hpp follows along its path), plus the solver's fixed margin. Without it two boxes
/// looked only kSpeculativeDistance ahead: a box falling at 20 m/s (33 cm a step at 1/60 s, less
/// than its half-thickness, so not fast) onto another found no contact until it was 30–40 cm inside.
Real boxReachOf(const BodySet& bodies, const CandidatePair& pair, bool continuousCollision, Real speculativeDistance) {
    const auto share = [&](const BodyRef& ref) {
        if (ref.kind != BodyKind::Dynamic) return sweepOf(bodies, ref);  // a kinematic body's motion is given
        const DynamicObject& body = bodies.dynamics[ref.index];
        return continuousCollision ? std::min(body.sweep, kFastMotionFraction * innerRadius(body)) : body.sweep;
    };
    return share({BodyKind::Dynamic, pair.a}) + share(pair.b) + speculativeDistance;
}

/// The exact test of a sphere or box pair (isClassicPair()), with the reach it has always had.
void collideClassic(const BodySet& bodies, const CandidatePair& pair, Geometry a, Geometry b, bool continuousCollision,
                    Real speculativeDistance, const PartPair& parts, std::vector<Contact>& contacts) {
    const PairTest test = pairTestFor(a.type, b.type);
    if (test == nullptr) return;

    // Box on box: the separating-axis test itself reports points up to the reach apart. The
    // impulse solver (speculativeDistance 0) keeps the test's own kSpeculativeDistance.
    if (a.type == GeometryType::Box && b.type == GeometryType::Box && speculativeDistance > 0) {
        const Real reach = std::max(boxReachOf(bodies, pair, continuousCollision, speculativeDistance), kSpeculativeDistance);
        ContactManifold found;
        if (!collideBoxBoxWithin(a, b, reach, found)) return;
        for (int i = 0; i < found.pointCount; ++i) appendContacts(pair, found.normal, found.points[i], parts, contacts);
        return;
    }

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
        appendContacts(pair, found.normal, p, parts, contacts);
    }
}

/// The exact test of any other convex pair (convex_pairs.hpp). GJK measures distance, so
/// no shape is grown: the test keeps the points whose gap is at most what a box on a plane
/// reaches (collideClassic()), kSpeculativeDistance plus whatever more the sweeps can close.
void collideConvexShapes(const BodySet& bodies, const CandidatePair& pair, const Geometry& a, const Geometry& b,
                         NarrowphaseKind narrowphase, bool continuousCollision, Real speculativeDistance,
                         const PartPair& parts, std::vector<Contact>& contacts) {
    if (b.type == GeometryType::Mesh || pairTestFor(a.type, b.type) == nullptr) return;
    const Real reach = reachOf(bodies, pair, innerRadius(bodies.dynamics[pair.a]), b.type == GeometryType::Plane,
                               continuousCollision, speculativeDistance);
    const Real maxGap = kSpeculativeDistance + std::max(reach - speculativeDistance, Real(0));
    ContactManifold found;
    if (!collideConvex(a, b, narrowphase, maxGap, found)) return;
    for (int i = 0; i < found.pointCount; ++i) appendContacts(pair, found.normal, found.points[i], parts, contacts);
}

/// A convex shape against a triangle mesh (mesh_contacts.hpp), with a plane's reach: the continuous
/// stage sweeps bodies against convex shapes only, so a mesh, like a plane, gets contacts as far
/// ahead as the body can move this step, uncapped, and the solver stops a fast body at its surface.
/// The mesh test may find several manifolds, one per direction of push (a box in a corner of
/// two walls): all their points are appended as contacts of the one pair, each with its own normal.
void collideMeshShapes(const BodySet& bodies, const CandidatePair& pair, const Geometry& a, const Geometry& b,
                       bool continuousCollision, Real speculativeDistance, const PartPair& parts,
                       std::vector<Contact>& contacts) {
    if (pairTestFor(a.type, b.type) == nullptr) return;
    constexpr bool kUncappedLikeAPlane = true;
    const Real reach = reachOf(bodies, pair, innerRadius(bodies.dynamics[pair.a]), kUncappedLikeAPlane,
                               continuousCollision, speculativeDistance);
    const Real maxGap = kSpeculativeDistance + std::max(reach - speculativeDistance, Real(0));
    MeshContacts found;
    if (!meshContacts(a, b, maxGap, found)) return;
    for (int m = 0; m < found.count; ++m) {
        const ContactManifold& manifold = found.manifolds[m];
        for (int i = 0; i < manifold.pointCount; ++i) appendContacts(pair, manifold.normal, manifold.points[i], parts, contacts);
    }
}

/// One geometry of A against one of B, by the routine @p narrowphase gives their shapes.
/// A mesh has one routine whatever @p narrowphase says: triangle by triangle (mesh_contacts.hpp).
void collideGeometries(const BodySet& bodies, const CandidatePair& pair, const Geometry& a, const Geometry& b,
                       NarrowphaseKind narrowphase, bool continuousCollision, Real speculativeDistance,
                       const PartPair& parts, std::vector<Contact>& contacts) {
    if (b.type == GeometryType::Mesh) {
        collideMeshShapes(bodies, pair, a, b, continuousCollision, speculativeDistance, parts, contacts);
    } else if (isClassicPair(a.type, b.type, narrowphase)) {
        collideClassic(bodies, pair, a, b, continuousCollision, speculativeDistance, parts, contacts);
    } else {
        collideConvexShapes(bodies, pair, a, b, narrowphase, continuousCollision, speculativeDistance, parts, contacts);
    }
}

/// The compound shape of whichever object @p ref names, or nullptr when it is no compound.
const CompoundShape* compoundOf(const BodySet& bodies, const BodyRef& ref) {
    switch (ref.kind) {
        case BodyKind::Dynamic: {
            const DynamicObject& body = bodies.dynamics[ref.index];
            return body.shape == Shape::Compound ? body.compound.get() : nullptr;
        }
        case BodyKind::Kinematic: {
            const KinematicsObject& body = bodies.kinematics[ref.index];
            return body.shape == Shape::Compound ? body.compound.get() : nullptr;
        }
        case BodyKind::Plane: break;
    }
    return nullptr;
}

/// The exact test of one candidate pair; its contacts are appended to @p contacts.
///
/// A compound body is tested part by part (geometryOfPart()): every part of A against every
/// part of B (or B's one shape). The broadphase still hands over one pair per two bodies, and
/// all their contacts belong to that pair; the part numbers go into the feature ids (withParts()).
void collidePair(const BodySet& bodies, const CandidatePair& pair, NarrowphaseKind narrowphase, bool continuousCollision,
                 Real speculativeDistance, std::vector<Contact>& contacts) {
    const Geometry a = geometryOf(bodies.dynamics[pair.a]);
    const Geometry b = geometryOf(bodies, pair.b);
    const CompoundShape* compoundA = compoundOf(bodies, {BodyKind::Dynamic, pair.a});
    const CompoundShape* compoundB = compoundOf(bodies, pair.b);
    if (compoundA == nullptr && compoundB == nullptr) {
        collideGeometries(bodies, pair, a, b, narrowphase, continuousCollision, speculativeDistance, {}, contacts);
        return;
    }
    const std::size_t partsOfA = compoundA != nullptr ? compoundA->parts.size() : 1;
    const std::size_t partsOfB = compoundB != nullptr ? compoundB->parts.size() : 1;
    for (std::size_t i = 0; i < partsOfA; ++i) {
        const auto partA = static_cast<std::uint32_t>(i);
        const Geometry pieceA = compoundA != nullptr ? geometryOfPart(a, compoundA->parts[i], partA) : a;
        for (std::size_t j = 0; j < partsOfB; ++j) {
            const auto partB = static_cast<std::uint32_t>(j);
            const Geometry pieceB = compoundB != nullptr ? geometryOfPart(b, compoundB->parts[j], partB) : b;
            collideGeometries(bodies, pair, pieceA, pieceB, narrowphase, continuousCollision, speculativeDistance,
                              {true, partA, partB}, contacts);
        }
    }
}

/// How many pairs ahead collidePairs() asks for a body B's lines (core/prefetch.hpp): a main-memory
/// wait of some 100 ns against a ball pair's test of some 50 ns.
constexpr std::size_t kPrefetchPairsAhead = 8;

/// Asks for what a pair's test reads of a dynamic B: its sweep and centre, its shape and radius.
void prefetchBodyB(const BodySet& bodies, const CandidatePair& pair) {
    if (pair.b.kind != BodyKind::Dynamic) return;
    const DynamicObject& b = bodies.dynamics[pair.b.index];
    prefetchRange(&b.sweep, &b.position.z);
    prefetchRange(&b.shape, &b.radius);
}

/// collidePair() on each of @p pairs in order, ball–ball pairs by collideBalls().
void collidePairs(const BodySet& bodies, std::span<const CandidatePair> pairs, NarrowphaseKind narrowphase,
                  bool continuousCollision, Real speculativeDistance, std::vector<Contact>& contacts) {
    BallPairScratch scratch;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const CandidatePair& pair = pairs[i];
        if (i + kPrefetchPairsAhead < pairs.size()) prefetchBodyB(bodies, pairs[i + kPrefetchPairsAhead]);
        if (bodies.dynamics[pair.a].shape == Shape::Sphere && pair.b.kind == BodyKind::Dynamic &&
            bodies.dynamics[pair.b.index].shape == Shape::Sphere) {
            collideBalls(bodies, pair, continuousCollision, speculativeDistance, scratch, contacts);
        } else {
            collidePair(bodies, pair, narrowphase, continuousCollision, speculativeDistance, contacts);
        }
    }
}

}  // namespace

void findContacts(const BodySet& bodies, const std::vector<CandidatePair>& pairs, std::vector<Contact>& contacts,
                  NarrowphaseKind narrowphase) {
    contacts.clear();
    collidePairs(bodies, pairs, narrowphase, false, 0, contacts);
}

void findContacts(const BodySet& bodies, const std::vector<CandidatePair>& pairs, std::vector<Contact>& contacts,
                  bool continuousCollision, Real speculativeDistance, ThreadPool& pool,
                  NarrowphaseWorkspace& workspace, NarrowphaseKind narrowphase) {
    if (pool.threadCount() == 1 || pairs.size() <= kPairsPerChunk) {
        // One chunk: the merge below would only copy.
        contacts.clear();
        collidePairs(bodies, pairs, narrowphase, continuousCollision, speculativeDistance, contacts);
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
        collidePairs(bodies, std::span(pairs).subspan(c * kPairsPerChunk, end - c * kPairsPerChunk), narrowphase,
                     continuousCollision, speculativeDistance, out);
    };
    pool.run(chunks, runChunk);

    contacts.clear();
    for (std::size_t c = 0; c < chunks; ++c) {
        const std::vector<Contact>& part = workspace.chunkContacts[c];
        contacts.insert(contacts.end(), part.begin(), part.end());
    }
}

}  // namespace stepwise
