/// @file soft_step.hpp
/// @brief The soft bodies' stage of World::step(): the one call the World makes (soft_step.cpp).
#pragma once

#include <span>

#include "core/types.hpp"
#include "core/world_settings.hpp"
#include "objects/body_set.hpp"
#include "objects/finite_state.hpp"
#include "objects/soft_body.hpp"

namespace stepwise {

/// @brief What the soft step reads from the World.
struct SoftStepSettings {
    Vec3 gravity{0, 0, 0};                                    ///< m/s², on every node.
    IntegratorKind integrator = IntegratorKind::SymplecticEuler; ///< The scene's `Integrator`.
    Real timeStep = 0;                                        ///< h_s, s: how far this call moves the nodes (soft_step.cpp says which).
    bool startsStep = true;                                   ///< The World's step starts here: the touch lists start empty.
    StageAtStep where;                                        ///< The stage and step, to name them in an error.
};

/// @brief Advances every soft body by one substep of `timeStep`: the springs, the volume, the gas,
/// the move and the collisions with @p rigid (soft_stages.hpp).
/// An asleep body is not moved; an awake one notes the bodies it touched (SoftBody::touchedDynamics,
/// touchedSoftBodies, carried), for the islands.
/// @throws SimulationError naming the body, the soft stage and the step when a node's position or
///         velocity stops being finite, or the surface turns inside out (V ≤ 0 with a gas inside).
void stepSoftBodies(std::span<SoftBody> bodies, const BodySet& rigid, const SoftStepSettings& settings);

/// @brief Sets @p body's volume, pressure, centre of mass and its velocity from its nodes, as the
/// step leaves them (for a body just built, before any step).
void measureSoftBody(SoftBody& body);

}  // namespace stepwise
