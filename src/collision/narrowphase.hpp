/// @file narrowphase.hpp
/// @brief Stage 5 of the step: exact shape tests, one file per shape pair, chosen from one table.
#pragma once

#include <vector>

#include "collision/contact.hpp"
#include "core/thread_pool.hpp"
#include "core/world_settings.hpp"
#include "objects/body_set.hpp"

namespace stepwise {

/// @brief Kinds of geometry the pair tests understand.
///
/// A compound body is not one of them: the narrowphase tests each of its
/// parts as a geometry of its own (collidePair()).
enum class GeometryType : std::uint8_t { Sphere, Box, Plane, Capsule, Cylinder, Hull, Mesh, Count };

/// @brief The shape of one object in world space, as the pair tests see it.
struct Geometry {
    GeometryType type = GeometryType::Sphere;  ///< Which fields below are meaningful.
    Vec3 centre{0, 0, 0};                      ///< Centre (centre of mass of a hull), or a point on a plane, m.
    Quat orientation{1, 0, 0, 0};              ///< Rotation from the shape's frame to the world (all but sphere, plane).
    Vec3 halfExtents{0, 0, 0};                 ///< Box half edge lengths, m.
    Real radius = 0;                           ///< Sphere, capsule, cylinder radius, m.
    Real halfHeight = 0;                       ///< Capsule: half its segment; cylinder: half its length, m (local y).
    Vec3 normal{0, 1, 0};                      ///< Plane unit normal.
    const ConvexHull* hull = nullptr;          ///< Hull: its polyhedron, in the shape's frame.
    const TriangleMesh* mesh = nullptr;        ///< Mesh: its triangles, in the shape's frame.
    std::uint32_t part = 0;                    ///< Which part of a compound body this is (0 otherwise).
};

/// Most points a manifold keeps: four corners are enough to hold a box
/// face steady on a plane (three would do, four keep it symmetric).
inline constexpr int kMaxManifoldPoints = 4;

/// @brief One point of a contact manifold.
struct ContactPoint {
    Vec3 position{0, 0, 0};    ///< World point midway through the overlap, m.
    Real depth = 0;            ///< Overlap along the manifold normal, m (negative: a gap, at most kSpeculativeDistance).
    std::uint32_t featureId = 0; ///< Which features of A and B meet here (stable from step to step, for warm starting).
};

/// @brief Result of a pair test: one normal shared by up to kMaxManifoldPoints points.
struct ContactManifold {
    Vec3 normal{0, 1, 0};      ///< Unit, from shape A towards shape B.
    int pointCount = 0;        ///< Number of valid entries in points.
    ContactPoint points[kMaxManifoldPoints];  ///< The contact points.

    /// @brief Appends a point (ignored when the manifold is full).
    void add(const Vec3& position, Real depth, std::uint32_t featureId) {
        if (pointCount < kMaxManifoldPoints) points[pointCount++] = {position, depth, featureId};
    }
};

/// @brief A pair test: true (and @p out filled) when A and B touch or overlap.
using PairTest = bool (*)(const Geometry& a, const Geometry& b, ContactManifold& out);

/// @brief Sphere against sphere (src/collision/sphere_sphere.cpp).
bool collideSphereSphere(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief Sphere against plane (src/collision/sphere_plane.cpp).
bool collideSpherePlane(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief Sphere against oriented box (src/collision/sphere_box.cpp).
bool collideSphereBox(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief Oriented box against sphere: sphere–box with the normal flipped (src/collision/box_sphere.cpp).
bool collideBoxSphere(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief Oriented box against plane: the corners behind it, up to 4 (src/collision/box_plane.cpp).
bool collideBoxPlane(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief Oriented box against oriented box: separating axes, then a clipped manifold (src/collision/box_box.cpp).
bool collideBoxBox(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief collideBoxBox() with points reported for boxes up to @p reach apart (m, at least
/// kSpeculativeDistance): what the narrowphase asks when the two boxes can close more than that
/// this step (findContacts()). collideBoxBox() is this with reach = kSpeculativeDistance.
bool collideBoxBoxWithin(const Geometry& a, const Geometry& b, Real reach, ContactManifold& out);

/// @brief Capsule against plane: its two end spheres (src/collision/convex_plane.cpp).
bool collideCapsulePlane(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief Cylinder against plane: the rim points within reach, up to 4 (src/collision/convex_plane.cpp).
bool collideCylinderPlane(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief Hull against plane: the vertices within reach, up to 4 (src/collision/convex_plane.cpp).
bool collideHullPlane(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief Capsule against capsule: closest points of the segments (src/collision/capsule_contacts.cpp).
bool collideCapsuleCapsule(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief Capsule against sphere: closest point of the segment (src/collision/capsule_contacts.cpp).
bool collideCapsuleSphere(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief Sphere against capsule: closest point of the segment (src/collision/capsule_contacts.cpp).
bool collideSphereCapsule(const Geometry& a, const Geometry& b, ContactManifold& out);
/// @brief Any other pair of convex shapes: GJK, then EPA if they overlap, then a clipped manifold
/// (src/collision/convex_pairs.cpp).
bool collideConvexPair(const Geometry& a, const Geometry& b, ContactManifold& out);

/// @brief The pair test for shape A against shape B, or nullptr when there is none (a plane is never A).
PairTest pairTestFor(GeometryType a, GeometryType b);

/// @brief The geometry of a dynamic body, a kinematic body or a plane.
Geometry geometryOf(const DynamicObject& body);
Geometry geometryOf(const KinematicsObject& body);  ///< @copydoc geometryOf(const DynamicObject&)
Geometry geometryOf(const CollisionPlane& plane);   ///< @copydoc geometryOf(const DynamicObject&)
/// @brief The geometry of part @p index of a compound body whose own pose is @p body's.
Geometry geometryOfPart(const Geometry& body, const CompoundPart& part, std::uint32_t index);
/// @brief The geometry of whichever object @p ref names in @p bodies.
Geometry geometryOf(const BodySet& bodies, const BodyRef& ref);

/// @brief Runs the exact test on every candidate pair and collects the contacts.
/// @param contacts output, cleared first
/// @param narrowphase which algorithm meets two convex shapes (WorldSettings::narrowphase)
void findContacts(const BodySet& bodies, const std::vector<CandidatePair>& pairs, std::vector<Contact>& contacts,
                  NarrowphaseKind narrowphase = NarrowphaseKind::Auto);

/// Candidate pairs per chunk of the threaded narrowphase. A pair test takes
/// 0.1–1 µs, so a chunk is 50–500 µs of work: long enough that taking a chunk
/// (one atomic add) costs nothing, short enough that a 4k-body pile (about
/// 10k pairs) still makes twenty chunks to share out.
inline constexpr std::size_t kPairsPerChunk = 512;

/// @brief Per-chunk contact lists of the threaded findContacts(), kept between steps.
struct NarrowphaseWorkspace {
    std::vector<std::vector<Contact>> chunkContacts;  ///< Contacts of chunk c (pairs c·kPairsPerChunk …).
};

/// @brief findContacts() on the threads of @p pool: the pairs are cut into chunks of
/// kPairsPerChunk, each chunk's contacts go into its own list, and the lists are joined
/// in chunk order, so @p contacts is bit-identical to the one-thread result.
/// @param contacts output, cleared first
/// @param continuousCollision true when the World's continuous stage runs: a sphere's
///        contacts with another body are then looked for at most kFastMotionFraction × its radius
///        ahead of it, and each box's share of a box–box pair's reach is capped at
///        kFastMotionFraction × its inner radius (src/collision/continuous.hpp explains why);
///        planes keep the full sweep
/// @param speculativeDistance how far apart, m, beyond what the two bodies' sweeps can close,
///        a sphere's or a box's surfaces may be and still make a (speculative) contact. The
///        sequential-impulse solver passes kSpeculativeDistance: a body at rest at
///        the start of a step can be knocked, within the step, into a neighbour a
///        few millimetres away; without a contact between them nothing stops it
///        until the next step's collision pass (measured: 7 mm overlaps in a
///        1000-sphere rain), with one the solver lets it close the gap and no more.
///        The impulse solver passes 0: it resolves each contact once per step, so
///        an early contact would only be a gap it leaves alone (impulse_resolver.cpp).
/// @param pool        the threads
/// @param workspace   the per-chunk contact lists
/// @param narrowphase which algorithm meets two convex shapes (WorldSettings::narrowphase): under
///        Auto, spheres and boxes keep their own tests and GJK + EPA meets the other shapes;
///        GjkEpa and Mpr use that algorithm for every convex pair but sphere–sphere and
///        anything against a plane (src/collision/convex_pairs.hpp)
void findContacts(const BodySet& bodies, const std::vector<CandidatePair>& pairs, std::vector<Contact>& contacts,
                  bool continuousCollision, Real speculativeDistance, ThreadPool& pool,
                  NarrowphaseWorkspace& workspace, NarrowphaseKind narrowphase = NarrowphaseKind::Auto);

}  // namespace stepwise
