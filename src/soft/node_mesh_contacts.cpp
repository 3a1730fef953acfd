/// @file node_mesh_contacts.cpp
/// @brief Soft step, stage 5 against a triangle mesh: where a node overlaps the mesh deepest, and along which normal.
///
/// A node is a small sphere (node_collisions.cpp); a triangle mesh (a
/// KinematicsObject with `Shape=Mesh`: a floor, a ramp, a bowl, still or
/// moving) is the one rigid shape that is not convex. The sphere–mesh test
/// of the rigid bodies' narrowphase does the work (meshContacts(),
/// src/collision/mesh_contacts.hpp):
///
/// - the mesh's box hierarchy hands over only the triangles whose boxes
///   overlap the node's own box, in about log₂ n box tests (mesh_query.hpp),
///   so a node on a floor of thousands of triangles meets a handful;
/// - each is tested by the triangle's point nearest the node's centre
///   (Ericson, *Real-Time Collision Detection*, §5.1.5); a triangle pushes
///   only towards its front;
/// - a touch on an inactive edge (shared in a flat or concave fold) or on a
///   corner of two is turned to the face's normal, so a node rolling across
///   a flat floor of many triangles never snags on the seams.
///
/// Here the gap allowed is zero: only an overlap is a contact, as for the
/// other shapes' sphere tests, because respond() gives a node that
/// approaches a contact its impulse at once, and a node still short of the
/// floor must not bounce off the air above it.
///
/// **One push per node, the deepest.** A node over the shared edge of two
/// triangles of a flat floor is met by both, at the same point with the same
/// normal: meshContacts() keeps that point once (the deeper of the two), so
/// the node is pushed out once, not twice. A node in a concave crease (the
/// bottom of a bowl, the foot of a ramp) may overlap two faces that look
/// different ways; of those the deepest is the one handed back. Pushing the
/// node out of both by their own depths would overshoot where the pushes
/// share a direction (by d₁·(n₁·n₂)), and the push out of the deeper face
/// already takes most of the other's overlap away; what is left is met in
/// the next substep, as a node pressed between two rigid objects is.
#include <limits>

#include "collision/mesh_contacts.hpp"
#include "soft/soft_stages.hpp"

namespace stepwise {

bool collideNodeMesh(const Geometry& node, const Geometry& mesh, ContactManifold& out) {
    MeshContacts found;
    if (!meshContacts(node, mesh, Real(0), found)) return false;
    const ContactManifold* deepestManifold = nullptr;
    const ContactPoint* deepest = nullptr;
    Real deepestDepth = std::numeric_limits<Real>::lowest();
    for (int m = 0; m < found.count; ++m) {
        const ContactManifold& manifold = found.manifolds[m];
        for (int i = 0; i < manifold.pointCount; ++i) {
            if (manifold.points[i].depth <= deepestDepth) continue;
            deepestDepth = manifold.points[i].depth;
            deepestManifold = &manifold;
            deepest = &manifold.points[i];
        }
    }
    if (deepest == nullptr) return false;
    out.normal = deepestManifold->normal;
    out.pointCount = 0;
    out.add(deepest->position, deepest->depth, deepest->featureId);
    return true;
}

}  // namespace stepwise
