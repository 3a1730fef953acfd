/// @file conveyor.hpp
/// @brief Conveyor belts (Effect=Conveyor): a surface that moves along itself.
///
/// A conveyor belt, a moving walkway or a treadmill is a surface whose
/// material moves while its shape stays put. Modelling the belt as a body
/// that travels would carry it away; what matters to what lies on it is only
/// the velocity of its surface at the contact, so that is all a Conveyor
/// region changes: no force of its own, a different target for friction.
///
/// **The law.** A dynamic body whose centre is inside the region (the
/// membership of the other effects, regionHolds()) touches a static or
/// kinematic surface (a plane, a kinematic object) at a contact of unit
/// normal n. That surface is taken to move, in the contact's tangent plane,
/// at the region's velocity u with its normal part dropped,
/// \f[ v_s = u - (u\cdot n)\,n, \f]
/// added to the surface's own velocity (a kinematic body's v + ω × r; zero
/// for a plane). A belt slides along itself; it does not push into the body
/// or pull it down, so the normal row and the bounce are as without it. The
/// friction rows of the contact then drive the relative tangential velocity
/// of the two surfaces to zero,
/// \f[ \big(v_B + v_s - (v_A + \omega_A\times r_A)\big)\cdot t_k = 0, \quad k = 1, 2, \f]
/// with the impulse kept inside Coulomb's circle |λ_t| ≤ μ·λ_n as always.
/// So friction alone carries the body, and never harder than μ·N: a box of
/// friction μ set down at rest on a belt of speed u under gravity g slides,
/// accelerated at μ·g, until it moves with the belt at t = u/(μ·g), and then
/// rides it at u; a ball rolls up to (2/7)·u, where its lowest point moves
/// with the belt (v + ω·r = u with I = (2/5)·m·r²), at t = 2u/(7·μ·g).
/// The energy the body gains comes from the belt's motor, outside the model.
///
/// **Dynamic–dynamic contacts are not affected.** The belt is the machinery
/// under the bodies, not a property of the bodies on it: two crates riding
/// a belt side by side move with it together, and giving their contact the
/// belt's speed would make them shear each other. So only a contact with a
/// static or kinematic surface takes v_s; a box stacked on a box on the belt
/// is carried by the friction of the box under it.
///
/// Where two Conveyor regions hold the same body, the first in the scene
/// file's order gives its belt velocity (conveyorVelocities()).
///
/// **Where it acts.** In the contact preparation of both solvers, once a
/// step, when the contact's rows are made: the sequential impulse adds
/// v_s·t_k to the contact's tangent surface speeds (ContactRows, the numbers
/// a moving kinematic body's contact already carries, which the plain passes
/// and the fast path's lanes both read), and the Impulse pipeline adds v_s to
/// the surface velocity its friction compares against. The solvers read a
/// number per contact and know nothing of belts. Box2D v3 gives a shape the
/// same thing as a "tangent speed"; Bullet lets a contact callback set a
/// point's "contact motion" along its friction directions.
#pragma once

#include <span>
#include <vector>

#include "forces/region.hpp"

namespace stepwise {

/// @brief The belt velocity @p belt as a surface of unit normal @p normal moves with it:
/// its part in the tangent plane, v_s = u − (u·n)·n, m/s.
Vec3 conveyorSurfaceVelocity(const Vec3& belt, const Vec3& normal);

/// @brief True when any of @p regions is a Conveyor region.
bool anyConveyor(std::span<const Region> regions);

/// @brief Each dynamic body's belt velocity u this step, m/s: the Velocity of the first
/// Conveyor region (in the scene's order) that holds it, zero for a body on no belt.
///
/// Filled once a step from the regions' members, after findRegionMembers();
/// the contact preparation reads @p velocities at each contact's dynamic body A.
/// @param bodyCount  the number of dynamic bodies (the size @p velocities is given)
void conveyorVelocities(std::span<const Region> regions, const RegionMembers& members, std::size_t bodyCount,
                        std::vector<Vec3>& velocities);

/// @brief The belt velocity a contact of dynamic body @p bodyA with a static or kinematic
/// surface takes from @p velocities (conveyorVelocities(); empty when the scene has no belt),
/// or nullptr when it has none: a dynamic B, no belt, or a belt at rest.
inline const Vec3* beltUnder(std::span<const Vec3> velocities, std::uint32_t bodyA, bool dynamicB) {
    if (dynamicB || velocities.empty() || velocities[bodyA] == Vec3(0)) return nullptr;
    return &velocities[bodyA];
}

}  // namespace stepwise
