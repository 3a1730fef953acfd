/// @file pressure_forces.cpp
/// @brief Soft step, stage 3: the gas inside pushes every face outward, P·A·n, with P = nRT / V.
///
/// The ideal-gas law P·V = n·R·T gives the pressure from the volume the
/// surface encloses now (enclosed_volume.cpp): squeeze the ball and P rises
/// as 1/V. The gas pushes on each face with the force P·A·n, normal to the
/// face, outward; with the face wound outward
/// \f[ A\,n = \tfrac12\,(b - a)\times(c - a), \qquad F_{face} = P\,A\,n , \f]
/// and a third of it goes to each corner (Matyka & Ollila 2003, §3).
///
/// Why a third: on a flat triangle the pressure is uniform, and a third to
/// each corner is the share that keeps the face's total force and its
/// moment about the centroid. It is also the gradient of the gas's energy:
/// the pressure force on the nodes is −∂U/∂x_i with U = −nRT·ln V, and
/// ∂V/∂x_i = Σ over the faces round node i of (1/6)·(the other two corners'
/// cross product) — which, summed over a closed surface, is the same as a
/// third of each face's A·n (docs/soft-bodies.md works it through). So the
/// springs and the gas together are a conservative system, whose energy a
/// symplectic integrator keeps bounded.
///
/// Over a closed surface Σ A·n = 0 and Σ c × A·n = 0: the gas pushes the
/// body in no direction and turns it about no axis, so it keeps the total
/// momentum and angular momentum as the springs do.
#include <cmath>

#include "soft/soft_stages.hpp"

namespace stepwise {

void addPressureForces(SoftBody& body) {
    body.volume = enclosedVolume(body.nodePositions, body.faces);
    // A surface turned inside out has V ≤ 0 and no pressure the law can give: the soft step stops on it.
    body.pressure = body.nRT == 0 ? Real(0) : body.nRT / body.volume;
    if (body.nRT == 0) return;
    const std::vector<Vec3>& x = body.nodePositions;
    std::vector<Vec3>& force = body.nodeForces;
    const Real third = Real(1) / Real(3);
    for (const SoftFace& f : body.faces) {
        const Vec3 areaNormal = Real(0.5) * glm::cross(x[f.b] - x[f.a], x[f.c] - x[f.a]);  // A·n, m²
        const Vec3 share = (third * body.pressure) * areaNormal;                            // N
        force[f.a] += share;
        force[f.b] += share;
        force[f.c] += share;
    }
}

}  // namespace stepwise
