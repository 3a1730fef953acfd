/// @file mesh_contacts.hpp
/// @brief A convex shape against a static triangle mesh: each nearby triangle as a convex shape, active edges, manifolds by normal.
///
/// A mesh is not convex, so GJK cannot take it whole. It is a set of
/// triangles, and each triangle is convex: meshContacts() asks the mesh's
/// hierarchy for the triangles near shape A (mesh_query.hpp: A's bounding box,
/// grown by the reach, taken into the mesh's frame) and tests A against each
/// one as a convex shape (support.hpp's triangle core):
///
/// - **sphere and capsule** by closest points: the point of the triangle
///   nearest the centre (Ericson §5.1.5, closestPointOnTriangle()), or for a
///   capsule the nearest of its two ends' and of its segment against the
///   three edges (Ericson §5.1.9, closestPointsOfSegments()); a segment that
///   passes through the triangle goes to GJK and EPA;
/// - **box, cylinder, hull** by GJK, then EPA if they overlap.
///
/// Each gives a normal and the deepest (or closest) points; the manifold is
/// then built with the triangle's face as a face (triangleManifold()).
///
/// **One-sided.** A triangle pushes only towards its front (counter-clockwise
/// seen from there): a shape whose centre is behind a triangle's plane is not
/// tested against it. A floor holds what lands on it from above, and the far
/// side of a cliff (its face turned away from a body on top) never pulls a
/// body over the edge.
///
/// ### Inner edges, and why a ball would snag on them
///
/// A ball rolls across a flat floor of two triangles T1 and T2 that share an
/// edge E. It sits over T1, but it is also within reach of T2, and T2 alone
/// sees the ball beside it: the closest point of T2 is on E, and the normal
/// from there to the centre leans back towards T1:
///
/// ```
///              ball (centre over T1, rolling →)
///               .-"-.
///              /     \      n from T2's closest point (on E) to the centre:
///              \  c  /      leans back ↖, a push against the motion
///               '-.-'
///   ============E=========  floor
///        T1     ↑   T2
///               E: T2's closest point to c
/// ```
///
/// The solver would push the ball back along that leaning normal and the
/// ball snags, although the floor is flat. The edge E is *inactive*
/// (TriangleMesh::activeEdges, set by buildTriangleMesh(): shared with a
/// neighbour in a flat or concave fold), and no body can ever be pushed off
/// an inactive edge: across it lies more floor. So (the rule of Jolt's
/// "active edges" and of Box2D's chain shapes' ghost vertices, here written
/// from the geometry):
///
/// 1. Which feature of the triangle is touched: its face, one edge, or a
///    corner (two edges), read from the barycentric weights of the
///    triangle's closest or deepest point (a weight of zero, to within
///    kOnEdgeWeight: the point lies on the opposite edge).
/// 2. A normal within kFaceNormalCosine of the face normal, or a touch on the
///    face itself, is the face's. A touch on an inactive edge, or on a corner
///    whose two edges are both inactive, is turned to the face normal too.
///    A corner with one active edge keeps only the part of the normal across
///    that edge (the part along it would push a body sliding along a ridge
///    back or forth). A touch on active edges keeps its normal: a body
///    hanging over the mesh's border is pushed outwards, as it should be.
/// 3. A contact turned to the face normal keeps only what lies over the
///    triangle (triangleFacePoints(): A's feature clipped by the
///    triangle's side planes). In the picture T2's contact is dropped, as c
///    is not over T2, and T1 gives the contact, with the floor's normal. A
///    ball exactly over E is over both: the two equal points become one.
///
/// ### Many triangles, one list of manifolds
///
/// A box on a floor of small triangles touches many of them, and a body in a
/// valley touches triangles that face different ways. A manifold has one
/// normal and at most kMaxManifoldPoints points, so the points of all the
/// triangles are gathered by normal: triangles whose normals agree to within
/// kSameNormalCosine (the flat floor's) share one manifold, and its points
/// are cut down to the deepest and most spread four (keepSpreadContactPoints());
/// each other direction gets its own, up to kMaxMeshManifolds (a contact beyond
/// those joins the manifold of the nearest normal). The narrowphase appends
/// every manifold's points as contacts of the one pair (body, mesh), so the
/// solver sees a box on a 200-triangle floor as four points under one normal,
/// as on a plane. Each point's feature id mixes in its triangle's index, so
/// warm starting never matches a point of one triangle with a point of
/// another.
#pragma once

#include "collision/narrowphase.hpp"

namespace stepwise {

/// Most manifolds (distinct normals) one body keeps against one mesh: a box
/// in a corner of a room touches three faces, a ball in a crease two.
inline constexpr int kMaxMeshManifolds = 8;

/// Two triangle contacts share a manifold when their normals agree to within
/// this cosine (0.5°): the triangles of one flat floor, up to round-off.
inline constexpr Real kSameNormalCosine = Real(0.99996);

/// A contact normal within this cosine (about 0.25°) of a triangle's face
/// normal is the face's own: a body resting on the face.
inline constexpr Real kFaceNormalCosine = Real(0.99999);

/// A barycentric weight at most this counts as zero: the point lies on the
/// opposite edge. The closest and deepest points come out as weighted sums of
/// the corners, exact to round-off, so a millionth is far above the noise.
inline constexpr Real kOnEdgeWeight = Real(1e-6);

/// @brief The manifolds of one shape against one mesh, one per direction of push.
struct MeshContacts {
    int count = 0;                                 ///< Number of valid entries in manifolds.
    ContactManifold manifolds[kMaxMeshManifolds];  ///< Each with its normal (from A towards the mesh) and its points.
};

/// @brief Sphere, box, capsule, cylinder or hull A against the triangle mesh B (see the file comment).
/// @param maxGap points whose surfaces are farther apart than this are left out, m
/// @param out    the manifolds, one per normal
/// @return true when any point was found
bool meshContacts(const Geometry& a, const Geometry& mesh, Real maxGap, MeshContacts& out);

/// @brief The pair test of the Mesh column of the dispatch table: meshContacts() within
/// kSpeculativeDistance, reduced to the manifold of its deepest point.
///
/// One manifold is all a PairTest can hand back; that is enough to say
/// whether two shapes touch (the broadphase tracker's check). The step's
/// narrowphase calls meshContacts() and keeps every manifold.
bool collideConvexMesh(const Geometry& a, const Geometry& b, ContactManifold& out);

}  // namespace stepwise
