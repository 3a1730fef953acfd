/// @file enclosed_volume.cpp
/// @brief Soft step, stage 2: the volume inside the surface, by the divergence theorem.
///
/// The divergence theorem turns the volume into a sum over the surface.
/// The field F(x) = x/3 has divergence 1, so
/// \f[ V = \int_V \nabla\cdot F\,dV = \oint_S F\cdot n\,dA
///       = \tfrac13 \sum_f A_f\,(c_f \cdot n_f), \f]
/// where for a flat triangle x·n is the same at every point (the distance
/// of its plane from the origin), so its integral is A_f times the value at
/// the centroid c_f. With A_f·n_f = ½ (b − a) × (c − a) and c_f = (a + b + c)/3,
/// each triangle's term is the signed volume of the tetrahedron it makes
/// with the origin:
/// \f[ V = \tfrac16 \sum_f a\cdot(b \times c) . \f]
/// The origin can be anywhere: moving it adds to each term a part that
/// cancels over a closed surface. The sum is exact for the polyhedron the
/// nodes make (no approximation but rounding), positive when the faces are
/// wound outward, and it does not need the body to be convex.
/// The terms are taken about the first node rather than the world's origin,
/// so that a ball far from the origin does not lose digits to
/// differences of large numbers.
#include "soft/soft_stages.hpp"

namespace stepwise {

Real enclosedVolume(std::span<const Vec3> positions, std::span<const SoftFace> faces) {
    if (positions.empty()) return 0;
    const Vec3 origin = positions[0];
    Real sixTimesVolume = 0;
    for (const SoftFace& f : faces) {
        const Vec3 a = positions[f.a] - origin;
        const Vec3 b = positions[f.b] - origin;
        const Vec3 c = positions[f.c] - origin;
        sixTimesVolume += glm::dot(a, glm::cross(b, c));
    }
    return sixTimesVolume / Real(6);
}

}  // namespace stepwise
