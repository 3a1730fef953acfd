/// @file fast_workspace.hpp
/// @brief The fast path's own arrays: the contacts in lanes, and the packed copies of the balls.
///
/// The plain solver's arrays (SolverWorkspace, dynamics/contact_solver.hpp)
/// are shared with the plain path and mean the same there; what is here only
/// the fast path reads or writes. The World owns one FastWorkspace and hands
/// it to runFastSubsteps() (fast_path.hpp) every step; its arrays keep their
/// capacity from step to step, so a settled scene allocates nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "dynamics/contact_solver.hpp"
#include "fast/box_contact_lanes.hpp"
#include "fast/fast_path_counts.hpp"
#include "fast/round_contact_lanes.hpp"

namespace stepwise {

/// @brief A record's centre, padded to four Reals: where a round contact's separation is measured.
///
/// The separation of a ball contact needs only the two centres (contact_solver.hpp,
/// currentSeparation()). The batched pass reads them by the same record
/// indices as the velocities, four at a time, one aligned load each, instead
/// of the bodies' full poses (a position and a quaternion, 56 bytes) by
/// another pair of indices.
struct alignas(4 * sizeof(Real)) SolverCentre {
    Vec3 position{0, 0, 0};  ///< The body's centre at the poses last recorded, m (record 0: the origin).
    Real unused = 0;         ///< Padding to four Reals.
};

/// @brief What free flight needs of a ball on the packed substeps, for the whole step (packed_substeps.hpp).
struct FreeFlight {
    Vec3 acceleration{0, 0, 0};   ///< a from the apply-forces stage, m/s² (the same in every substep).
    Vec3 torque{0, 0, 0};         ///< τ from the apply-forces stage, N·m.
};

/// @brief The fast path's arrays, indexed like the solver's records (SolverWorkspace::bodies) or its round contacts.
struct FastWorkspace {
    /// The round contacts, four of one wave per batch (round_contact_lanes.hpp). Through the
    /// substeps their impulses live here; syncRoundContacts() copies them back to the contacts.
    std::vector<RoundBatch> roundBatches;
    /// The contacts with stored rows (boxes, kinematic bodies), four of one wave per batch
    /// (box_contact_lanes.hpp); their impulses too live here through the substeps (syncBoxContacts()).
    std::vector<BoxBatch> boxBatches;
    std::vector<BoxAnchorBatch> boxAnchors;  ///< Per box batch: what its separations are measured from.
    /// Per wave of the box batches, the index of its first batch, and one more entry: the batch
    /// count (empty when the box contacts are solved one at a time).
    std::vector<std::uint32_t> boxWaveBatches;
    /// A list in the order found put in waves (contactWaves(), contact_waves.hpp; scratch).
    ContactWaveSchedule schedule;
    std::uint32_t waves = 0;               ///< How many waves the batching opened: colours or scheduled (scratch).
    /// Per wave, the index of its first batch in roundBatches, and one more entry: the batch count.
    /// The threads split a wave's batches between them (parallel_waves.hpp).
    std::vector<std::uint32_t> waveBatches;
    /// Per record: its body's centre at the poses last recorded (record 0: the origin), where the
    /// lanes measure a round contact's separation.
    std::vector<SolverCentre> centres;
    /// Per record, on the packed substeps only: its ball's orientation at the step's start, turned
    /// there by the last substep's drift (SolverWorkspace::turnSums).
    std::vector<Quat> orientations;
    std::vector<FreeFlight> freeFlight;    ///< Per record, on the packed substeps only: its a and τ.
    /// Every record's FreeFlight is record 1's, bit for bit (gravity alone: a = g, τ = 0): then the
    /// kick reads that one entry for every ball, and each substep walks 48 bytes a record less
    /// (set by packRecords()).
    bool sharedFlight = false;
    /// Per record, on the packed substeps only: its L at the start of the step, kg·m²/s, which the first
    /// substep's kick starts from (later ones take L = I·ω, as copyVelocitiesOut() writes it).
    std::vector<Vec3> startMomentum;

    bool packedStep = false;  ///< The last step ran on the packed records (for fastFootprint()).

    FastPathCounts counts;  ///< How many steps took the fast path, and how many of those the packed substeps.
};

}  // namespace stepwise
