/// @file apply_forces.hpp
/// @brief Stage 1 of the step: what accelerates and what turns each body.
#pragma once

#include <functional>
#include <span>

#include "forces/attractor.hpp"
#include "forces/region.hpp"
#include "forces/spring.hpp"
#include "objects/game_object.hpp"

namespace stepwise {

/// @brief Computes every body's acceleration and torque from the bodies' current state.
///
/// It writes DynamicObject::acceleration (m/s²) and DynamicObject::torque
/// (N·m, world frame, about the centre of mass) of every body, from nothing:
/// nothing carries over from the previous step. An integrator that needs
/// them at a new position and orientation (velocity Verlet) calls it again
/// after moving the bodies. Tests pass their own
/// function (a spring, an orbit) to check an integrator against a known
/// solution.
using AccelerationFunction = std::function<void(std::span<DynamicObject>)>;

/// @brief Sets each body's `acceleration` to gravity plus its own constant acceleration,
/// and its `torque` to zero.
///
/// Newton's second law with F = m·g + m·a_obj gives a = F/m = g + a_obj:
/// in a uniform field the mass cancels, which is why a feather and a hammer
/// fall together on the Moon. A uniform field acts at the centre of mass, so
/// its torque about the centre is zero: τ = Σ rᵢ × mᵢ·g = (Σ mᵢ·rᵢ) × g = 0,
/// because Σ mᵢ·rᵢ = 0 about the centre of mass. The torque is reset here
/// every step, and the forces applied after it (springs hooked off the
/// centre, see SceneForces) add theirs.
/// @param bodies  the dynamic bodies (acceleration is written)
/// @param gravity the World's gravitational acceleration, m/s²
void applyUniformForces(std::span<DynamicObject> bodies, const Vec3& gravity);

/// @brief The AccelerationFunction of a World whose only forces are uniform fields.
AccelerationFunction uniformForces(const Vec3& gravity);

/// @brief Stage 1 as World::step() runs it: the uniform fields, then every spring, every attractor, every region.
///
/// A function object, so that it can be an AccelerationFunction and velocity
/// Verlet evaluates exactly the same forces at the new positions. The World
/// wraps it by reference (`std::cref`), so building the callback every step
/// allocates nothing. The order matters only in that applyUniformForces()
/// *sets* the accelerations and torques, and the others add to them.
struct SceneForces {
    Vec3 gravity{0, 0, 0};                   ///< The World's uniform gravity, m/s².
    std::span<const Spring> springs;         ///< The World's springs (src/forces/spring.hpp).
    std::span<const Attractor> attractors;   ///< The World's attractors (src/forces/attractor.hpp).
    RegionForces regions;                    ///< The World's regions and who is inside (src/forces/region.hpp).

    /// @brief Writes every body's acceleration (m/s²) and torque (N·m) from the bodies' current state.
    void operator()(std::span<DynamicObject> bodies) const;
};

}  // namespace stepwise
