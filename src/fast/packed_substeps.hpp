/// @file packed_substeps.hpp
/// @brief The packed substeps: a step whose contacts all hold balls, run on the solver's records.
///
/// Between the contact passes of a substep the plain path hands every
/// record's body back and forth: the integrator moves the object, its
/// velocities are copied into the record, the passes change them, the drift
/// and the relax copy them out again, four passes over objects of some 400
/// bytes each. A ball needs little more than its record holds already: its
/// centre (FastWorkspace::centres), its orientation, and a, τ for free
/// flight, the same all step when no spring or attractor follows it. So in a
/// step where every contact holds awake balls, those are gathered once into
/// arrays indexed like the records (packRecords()), the substeps work there,
/// and the objects are written once at the end (unpackRecords()). It is
/// Box2D v3's layout (b2BodyState, b2BodySim), taken only as far as balls,
/// whose inertia is a number.
///
/// **The same operations.** Symplectic Euler's two lines are split around
/// the solve: the kick v + h·a (and L + h·τ, ω = L/I) before it,
/// kickPackedRecords(); the move x + h·v after it, with the kicked velocity
/// and then the solver's change, and the turn once a step,
/// driftPackedRecords(). Those are the plain path's operations
/// (integrateSymplecticEuler(), then driftByVelocityChange()) in the same
/// order, so a ball ends where the plain path leaves it, to the bit. The
/// warm start of a later substep rides along with the kick: what the
/// contacts did to the ball in the last substep is added to its kicked
/// velocity, as warmStartFromLastSubstep() adds it on the plain path.
#pragma once

#include <cstddef>

#include "dynamics/contact_solver.hpp"
#include "fast/fast_workspace.hpp"

namespace stepwise {

/// @brief Gathers what the packed substeps need (FastWorkspace::centres, `orientations`, `freeFlight`,
/// `startMomentum`) from the objects of the records; false when this step cannot take them: a contact
/// with stored rows (a box or a moving kinematic body), or a record whose body is not an awake ball with three
/// equal moments of inertia. (What it wrote before finding that out is scratch.)
bool packRecords(SolverWorkspace& solver, FastWorkspace& fast);

/// @brief Writes the packed substeps' results to the objects: v, ω, L = I·ω, centre and orientation.
///
/// The same numbers the plain path's copies and drift would have left there (copyVelocitiesOut()
/// writes a ball's L as I·ω for this reason), and idempotent: writing twice changes nothing.
void unpackRecords(SolverWorkspace& solver, const FastWorkspace& fast);

/// @brief Symplectic Euler's kick on the records: v ← v + h·a, L ← L + h·τ, ω = L/I for every ball.
///
/// In a later substep (@p firstSubstep false) the warm start rides along (above). @p canTurn: the
/// step plan's rotation decision (skipsRotation()).
/// Each record is kicked on its own: the records [@p first, @p end) may be kicked apart from the
/// others, on another thread (parallel_records.hpp).
/// @return The finite probe (zeroIfFinite(), core/types.hpp) of every velocity it wrote: zero
/// exactly when all are finite, summed as they are written instead of read again afterwards.
Real kickPackedRecords(SolverWorkspace& solver, const FastWorkspace& fast, Real h, bool canTurn, bool firstSubstep,
                       std::size_t first, std::size_t end);

/// @brief The drift on the records, after the kick and the passes: each ball moves by h·v with its
/// kicked v, as the integrator would have moved it, then by h·Δv (velocity_change_drift.hpp), and adds
/// to SolverWorkspace::turnSums the solved ω (or the kicked one, if the constraints left it as it was);
/// in the @p lastSubstep it turns once, from the step's orientation, by h·Σω. Writes
/// FastWorkspace::centres and `turnSums`, and in the last substep FastWorkspace::orientations; the
/// objects are not touched.
/// The records [@p first, @p end) only, each on its own; eight at a time from @p first on, so a range
/// that starts at 1 + 8k groups its records as the whole array does.
/// @return The finite probe of every record's solved velocities and of what it wrote.
Real driftPackedRecords(SolverWorkspace& solver, FastWorkspace& fast, Real h, bool lastSubstep, std::size_t first,
                        std::size_t end);

}  // namespace stepwise
