/// @file velocity_change_drift.hpp
/// @brief Sequential impulse, within a substep: the bodies move by what the constraints did to their velocities.
///
/// The integrator has already carried each body through the substep with its
/// free-flight velocity; the constraint solve then changed that velocity by
/// Δv (and the angular velocity by Δω). Had those impulses been there from
/// the substep's start, the body would also have moved by h_s·Δv and turned
/// by h_s·Δω, so that is added here:
/// \f[ x \leftarrow x + h_s\,\Delta v, \qquad
///     q \leftarrow \frac{q + \tfrac12 h_s\,(0, \Delta\omega)\otimes q}{\lVert\cdot\rVert}. \f]
/// The turn is the first-order update Box2D makes for every rotation
/// (turnBySmallAngle()): h_s·Δω is the solver's correction of one substep, a
/// milliradian or less, and the update misses the exact turn exp(½h_s Δω)·q
/// by (h_s|Δω|)³/12, far below what splitting the substep into a free-flight
/// turn and this one already costs, O(h_s²·|ω|·|Δω|); it is one quaternion
/// product, where the exact turn needs a series for cos and sin.
///
/// **A ball under symplectic Euler turns with its new ω.** For a body
/// with three equal moments of inertia the free rotation is exact:
/// q(t + h) = exp(½h·ω̂)·q(t) with ω constant (rotateByAngularVelocity()).
/// So a ball the constraints turned need not add a correction to the
/// integrator's turn: its substep's turn is h_s·ω_{n+1}, by the solved ω,
/// the rotational twin of x_n + h_s·v_{n+1}. A box's free rotation depends
/// on how its axes lie (rotateTorqueFree()), so it keeps the correction above.
///
/// **A ball turns once a step.** Nothing inside a step reads a ball's
/// orientation: its contacts are measured from its centre (a sphere's
/// surface point is the centre plus R·n however it is turned) and its
/// inertia is the same about every axis. Only a joint's or a spring's
/// anchor turns with its ball, so in a scene without joints and springs
/// (SolverWorkspace::ballsTurnOnce) the drift keeps each ball at the step's
/// orientation q_n, adds each
/// substep's ω to a sum, and in the last substep turns it once:
/// \f[ q_{n+1} = \exp\!\Big(\tfrac12 h_s \sum_{k=1}^{S} \hat\omega_k\Big)\, q_n
///     \quad\text{instead of}\quad
///     \prod_{k=1}^{S} \exp\!\big(\tfrac12 h_s\, \hat\omega_k\big)\, q_n . \f]
/// While the spin keeps its axis, the two are the same rotation. When
/// contacts tip the axis within the step, the product and the exponential
/// of the sum differ by the commutators of the substeps' turns (the
/// Baker–Campbell–Hausdorff series), ½Σ_{j<k} h_s²·ω_j × ω_k: of order
/// h²·|ω|·|Δω|, the order of the error symplectic Euler makes with one
/// substep, and a turn of a ball that nothing in the physics can see. It
/// saves S − 1 of the S turns, each a chain of some forty operations. With
/// one substep nothing changes. An observer watching the substeps sees a
/// ball's orientation held until the last one.
///
/// For symplectic Euler the result is exactly x_n + h_s·v_{n+1}, the
/// position update every sequential-impulse engine makes after its solve
/// (Box2D's "integrate positions"). Without this drift a resting body would
/// sink by g·h_s² each substep and be pushed back out by the soft bias: jitter.
///
/// The other integrators moved the position with a different velocity u
/// than the v they ended with: u = v − (1 − s)·h_s·a, with s the share from
/// positionShareOfVelocityChange() (explicit Euler moved with the old
/// velocity, s = 0; Verlet with the mean, s = ½). A constraint force acts
/// *implicitly*, on the end-of-substep velocity, whatever the integrator, so
/// a constrained body ends at x_n + h_s·v_{n+1}:
/// \f[ x \leftarrow x + h_s\,\Delta v + (1 - s)\,h_s^2\,a. \f]
/// A body the constraints did not touch (Δv = 0, Δω = 0) keeps its
/// integrator's free flight exactly. Check: a resting ball (v_n = 0) ends
/// where it started with every integrator, because Δv = −h_s·a.
#pragma once

#include <cstdint>
#include <span>

#include "core/world_settings.hpp"
#include "dynamics/contact_solver.hpp"

namespace stepwise {

/// @brief Sequential impulse, the "move" of a substep: moves each body the constraints pushed by
/// h·Δv + (1 − s)·h²·a and turns it by h·Δω, Δv and Δω being what the solve changed since
/// recordSubstepStart(); then records its pose for the relax passes (SolverWorkspace::poses).
/// A ball under symplectic Euler turns by h·ω with the solved ω instead; in a scene without joints
/// and springs it is held at the step's orientation and turns once, in the @p lastSubstep, by
/// h·Σω over the substeps (SolverWorkspace::turnSums).
///
/// Visits only the bodies with a solver record, those in a contact or a
/// joint: no other body's velocity can have changed. Each one's solved
/// velocities are first written back to its object (copyVelocitiesOut() for
/// that record), in the same pass over the bodies.
void driftByVelocityChange(SolverWorkspace& workspace, Real h, IntegratorKind integrator, bool lastSubstep);

/// @brief driftByVelocityChange() for the solver records @p records alone (one group of islands,
/// substep_rule.hpp): each record's drift reads and writes that record and its body only.
void driftByVelocityChange(SolverWorkspace& workspace, std::span<const std::uint32_t> records, Real h,
                           IntegratorKind integrator, bool lastSubstep);

}  // namespace stepwise
