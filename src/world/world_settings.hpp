/// @file world_settings.hpp
/// @brief The simulation parameters a scene's `World` record sets.
#pragma once

#include "core/types.hpp"

namespace stepwise {

/// @brief Which time integrator advances the bodies (see src/integrators/).
enum class IntegratorKind : std::uint8_t {
    ExplicitEuler,    ///< x ← x + h·v, v ← v + h·a, both from the old state. First order; gains energy.
    SymplecticEuler,  ///< v ← v + h·a, then x ← x + h·v_new. First order; energy bounded.
    Verlet,           ///< Velocity Verlet. Second order; energy bounded; exact for constant a.
};

/// @brief Scene-file spelling of an integrator ("Euler", "SymplecticEuler", "Verlet").
const char* toString(IntegratorKind kind);

/// @brief Which broadphase finds the candidate pairs (src/collision/broadphase.hpp).
///
/// Every broadphase returns the same pairs in the same order, so the choice
/// changes how long a step takes, never the trajectory.
enum class BroadphaseKind : std::uint8_t {
    Auto,           ///< Chosen from the scene on the first step (chooseBroadphase(), which says why).
    BruteForce,     ///< Every pair of bodies, O(n²): the reference.
    SweepAndPrune,  ///< Sort the boxes along the axis of greatest spread and sweep.
    AabbTree,       ///< Dynamic tree of fattened boxes, inserted by the surface-area heuristic.
    Grid,           ///< Uniform grid, cells sized from the bodies.
};

/// @brief Scene-file spelling of a broadphase ("Auto", "BruteForce", "SweepAndPrune", "AabbTree", "Grid").
const char* toString(BroadphaseKind kind);

/// @brief Default time step, s: 60 steps per second, the usual display rate.
inline constexpr Real kDefaultTimeStep = Real(1) / Real(60);
/// @brief Default run length of `stepwise run`, s.
inline constexpr Real kDefaultDuration = Real(10);
/// @brief Default number of passes over all contacts in the impulse stage.
/// One pass settles a lone contact whose impulses do not couple (a sphere:
/// its normal passes through the centre); an off-centre contact, or a box on
/// a plane (four contacts on one body), needs several for its impulses to agree.
inline constexpr int kDefaultImpulseIterations = 10;

/// @brief Global simulation settings: one per World.
struct WorldSettings {
    Vec3 gravity{0, -kStandardGravity, 0};             ///< Uniform gravitational acceleration, m/s².
    Real timeStep = kDefaultTimeStep;                  ///< Fixed step h, s; > 0.
    IntegratorKind integrator = IntegratorKind::SymplecticEuler; ///< Time integrator.
    Real duration = kDefaultDuration;                  ///< Default run length, s; > 0.
    int impulseIterations = kDefaultImpulseIterations; ///< Passes over the contacts per step, ≥ 1.
    bool warmStarting = true;                          ///< Start each persisting contact from last step's impulses.
    BroadphaseKind broadphase = BroadphaseKind::Auto;  ///< Which broadphase finds the candidate pairs.
};

}  // namespace stepwise
