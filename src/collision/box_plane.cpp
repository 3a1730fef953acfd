/// @file box_plane.cpp
/// @brief Oriented box against an infinite plane: test the eight corners.
///
/// A box is convex, so the part of it deepest behind a plane is always a
/// corner (or an edge or face of corners at the same depth). Each corner
/// \f[ p_k = c + \sum_{i=0}^{2} \sigma_{k,i}\, e_i\, u_i, \qquad \sigma_{k,i} = \pm 1 \f]
/// (centre c, unit body axes uᵢ, half extents eᵢ; corner numbering in
/// box_features.hpp: bit i of k set ⇒ σ = +1) has signed distance
/// \f[ s_k = (p_k - q)\cdot n \f]
/// from the plane through q with unit normal n. Every corner with
/// s_k < kSpeculativeDistance is a contact point (up to 1 cm above the plane:
/// a speculative point, see contact.hpp):
///
/// * depth = −s_k,
/// * position midway between the corner and its projection on the plane,
///   p_k − n·s_k/2,
/// * feature id = k: the corner is the only feature of the box involved, and
///   it keeps its number while the box rests.
///
/// The manifold normal runs from the box towards the plane: −n.
///
/// A box lying flat gives its 4 bottom corners; resting on an edge, 2; on a
/// corner, 1. More than 4 corners can be behind the plane only when the
/// box's centre is too: corners come in pairs opposite through the centre,
/// k and 7 − k, with s_k + s_{7−k} = 2·s_centre, so while the centre is in
/// front at most one of each pair is behind. A box sunk that deep (it fell
/// through in one step, or was placed there) keeps its 4 deepest corners,
/// the ones the response must push out first.
///
/// Reference: Ericson, *Real-Time Collision Detection*, §5.2.3 (testing a
/// box against a plane), here with every corner kept instead of a yes/no.
#include <algorithm>

#include "collision/box_features.hpp"
#include "collision/narrowphase.hpp"

namespace stepwise {

bool collideBoxPlane(const Geometry& box, const Geometry& plane, ContactManifold& out) {
    const OrientedBox oriented = orientedBoxOf(box);

    struct Candidate {
        int corner;
        Real distance;  // signed, negative behind the plane
    };
    Candidate below[8];
    int count = 0;
    for (int k = 0; k < 8; ++k) {
        const Real distance = glm::dot(cornerOf(oriented, k) - plane.centre, plane.normal);
        if (distance < kSpeculativeDistance) below[count++] = {k, distance};
    }
    if (count == 0) return false;

    if (count > kMaxManifoldPoints) {
        // Deepest first; equal depths keep corner order, so the choice is repeatable.
        std::stable_sort(below, below + count,
                         [](const Candidate& x, const Candidate& y) { return x.distance < y.distance; });
        count = kMaxManifoldPoints;
        std::sort(below, below + count, [](const Candidate& x, const Candidate& y) { return x.corner < y.corner; });
    }

    out.normal = -plane.normal;
    out.pointCount = 0;
    for (int i = 0; i < count; ++i) {
        const Vec3 corner = cornerOf(oriented, below[i].corner);
        out.add(corner - plane.normal * (Real(0.5) * below[i].distance), -below[i].distance,
                static_cast<std::uint32_t>(below[i].corner));
    }
    return true;
}

}  // namespace stepwise
