/// @file region.hpp
/// @brief A volume of the world with an effect on the bodies inside: drag, wind, a
/// different gravity, buoyancy, random pushes, a conveyor, or removal.
///
/// Game engines put their field forces in volumes (a pond, a wind tunnel, a
/// low-gravity room, the kill plane under a level) rather than on bodies: the
/// body does not know it is in water, the water acts on whatever is in it. A
/// Region is that volume. Each effect is one force law, in its own file:
///
/// | `Effect=`     | file                  | acts on a body whose … is inside | law |
/// |---------------|-----------------------|-----------------------------------|-----|
/// | `Drag`        | drag.cpp              | centre | F = −c·v or −c·|v|·v, τ = −c_ω·ω |
/// | `Wind`        | wind.cpp              | centre | the drag law in the moving air: v → v − w |
/// | `Gravity`     | region_gravity.cpp    | centre | a = g_region instead of the World's g |
/// | `Buoyancy`    | buoyancy.cpp          | any part (the submerged part) | F = −ρ·V_sub·g at the centre of buoyancy |
/// | `RandomForce` | random_force.cpp      | centre | a seeded force of at most Strength, new every step |
/// | `Kill`        | kill_region.cpp       | centre | the body is removed at the end of the step |
/// | `Conveyor`    | conveyor.cpp          | centre | no force: its contacts with static surfaces take v_s = u − (u·n)·n as the surface's velocity |
///
/// Which bodies are inside is decided once a step, from where they are at its
/// start (the World asks its broadphase for the bodies whose boxes meet the
/// region's box, then tests each exactly: regionHolds()). A velocity- or
/// pose-dependent force is then evaluated in every substep with the body's
/// state of that moment, like a spring's: a body dropping into water feels the
/// drag grow within the step, and starts to feel it the step after its centre
/// crossed the surface.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "objects/game_object.hpp"

namespace stepwise {

/// @brief The volume of a Region.
enum class RegionShape : std::uint8_t {
    Box,        ///< An axis-aligned box: centre `position`, half edges `halfExtents`.
    Sphere,     ///< A ball: centre `position`, `radius`.
    HalfSpace,  ///< Everything below a plane: (p − position)·normal ≤ 0; `normal` points out of the region.
};

/// @brief What a Region does to the bodies inside it.
enum class RegionEffect : std::uint8_t {
    Drag,         ///< Resistance of a still fluid (drag.hpp).
    Wind,         ///< Drag in air that moves at `velocity` (wind.hpp).
    Gravity,      ///< A different gravitational acceleration inside (region_gravity.hpp).
    Buoyancy,     ///< Archimedes' push on the submerged part, with the fluid's drag (buoyancy.hpp).
    RandomForce,  ///< A seeded random push, new every step (random_force.hpp).
    Kill,         ///< Bodies entering are removed from the world (kill_region.hpp).
    Conveyor,     ///< The static surfaces under the bodies move at `velocity`, for friction (conveyor.hpp).
};

/// @brief How drag grows with speed.
enum class DragLaw : std::uint8_t {
    Linear,     ///< F = −c·v: slow, small bodies in a viscous fluid (Stokes); c in N·s/m.
    Quadratic,  ///< F = −c·|v|·v: fast or large bodies (c = ½·ρ·C_d·A); c in N·s²/m² = kg/m.
};

/// @brief A volume and the effect it has on the dynamic bodies inside.
struct Region {
    std::string name;                         ///< Unique within a scene.
    RegionShape shape = RegionShape::Box;     ///< Its volume.
    Vec3 position{0, 0, 0};                   ///< Box and Sphere: the centre; HalfSpace: a point of the plane, m.
    Vec3 halfExtents{0.5, 0.5, 0.5};          ///< Box: half its edges, m (the file gives the full edges, `Scale`).
    Real radius = Real(0.5);                  ///< Sphere: its radius, m.
    Vec3 normal{0, 1, 0};                     ///< HalfSpace: unit normal, pointing out of the region (up, out of water).
    RegionEffect effect = RegionEffect::Drag; ///< What it does.
    DragLaw law = DragLaw::Linear;            ///< Drag, Wind, Buoyancy: how the drag grows with speed.
    Real coefficient = 0;                     ///< Drag, Wind, Buoyancy: c, N·s/m (Linear) or kg/m (Quadratic).
    Real angularCoefficient = 0;              ///< Drag, Wind, Buoyancy: c_ω of the torque −c_ω·ω, N·m·s.
    Vec3 velocity{0, 0, 0};                   ///< Drag, Buoyancy: the fluid's velocity (a current); Wind: the air's; Conveyor: the belt's, m/s.
    Vec3 gravity{0, 0, 0};                    ///< Gravity: the acceleration inside, m/s².
    Real density = 0;                         ///< Buoyancy: the fluid's density, kg/m³ (water 1000).
    Real strength = 0;                        ///< RandomForce: the largest force, N.
    std::uint64_t seed = 0;                   ///< RandomForce: the same seed gives the same pushes.
};

/// @brief True when the point @p p is inside the region's volume (its surface counts as inside).
bool regionContains(const Region& region, const Vec3& p);

/// @brief True when the region acts on @p body: its centre is inside, or for Buoyancy any part of it.
///
/// Buoyancy acts on the part of a body under the surface, so a box floating
/// with its centre above the water is still pushed: the test there is whether
/// the body's bounding sphere reaches into the region.
bool regionHolds(const Region& region, const DynamicObject& body);

/// @brief Lowest and highest corners of a box holding the region, m; a half-space reaches
/// ±kRegionFar on the axes it is unbounded along.
void regionBounds(const Region& region, Vec3& lowest, Vec3& highest);

/// @brief How far a half-space region's bounding box reaches, m: far beyond any scene.
inline constexpr Real kRegionFar = Real(1e12);

/// @brief Which bodies each region holds this step: the body indices of region r are
/// `bodies[start[r]]` to `bodies[start[r + 1] − 1]`, ascending.
///
/// Filled once a step by the World (after the broadphase, which finds them);
/// read by every force evaluation of the step. Kept between steps, so a running
/// scene allocates nothing once the lists have grown.
struct RegionMembers {
    std::vector<std::uint32_t> start;   ///< One more entry than there are regions.
    std::vector<std::uint32_t> bodies;  ///< Indices into the World's dynamic bodies.

    /// @brief The bodies region @p r holds.
    std::span<const std::uint32_t> of(std::size_t r) const {
        if (r + 1 >= start.size()) return {};
        return {bodies.data() + start[r], bodies.data() + start[r + 1]};
    }
};

/// @brief What the force evaluations of one step need to know about the regions.
struct RegionForces {
    std::span<const Region> regions;        ///< The World's regions.
    const RegionMembers* members = nullptr; ///< Who is inside this step (nullptr: nobody yet).
    Vec3 worldGravity{0, 0, 0};             ///< The World's gravity, m/s² (Gravity regions replace it; buoyancy uses it).
    std::uint64_t step = 0;                 ///< The step's number, which seeds RandomForce.
    Real substepTime = 0;                   ///< h_s, s: how long each evaluation's forces act (drag's cap, drag.hpp).
};

/// @brief Adds each region's force and torque to the accelerations and torques of the bodies it holds.
///
/// Run after applyUniformForces(), springs and attractors, which start and add to them.
/// A Kill region adds nothing here: the World removes its bodies at the end of the step.
/// Nor does a Conveyor region: it acts through the contacts' friction (conveyor.hpp).
void applyRegions(std::span<DynamicObject> bodies, const RegionForces& in);

/// @brief The word a scene file uses for an effect ("Drag", "Wind", ...).
const char* toString(RegionEffect effect);

}  // namespace stepwise
