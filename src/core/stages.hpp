/// @file stages.hpp
/// @brief The named stages of one step, and what the World records about each.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>

namespace stepwise {

/// @brief Stages of World::step(), in the order they run.
enum class Stage : std::uint8_t {
    ApplyForces,       ///< Gravity and per-object accelerations → DynamicObject::acceleration.
    Integrate,         ///< Advance dynamic bodies by one time step (Euler, symplectic Euler or Verlet).
    MoveKinematics,    ///< Advance kinematic bodies along their prescribed motion.
    Broadphase,        ///< Cheap bounding-box tests → candidate pairs.
    Narrowphase,       ///< Exact shape tests on candidate pairs → contacts.
    ResolveImpulses,   ///< Normal (restitution) and friction impulses change velocities.
    CorrectPositions,  ///< Push overlapping bodies apart (positions only).
    PrepareConstraints,///< Sequential impulse: contacts and joints → anchors, effective masses, warm start.
    SolveConstraints,  ///< Sequential impulse, per substep: warm start, soft solve, move by h·Δv.
    RelaxConstraints,  ///< Sequential impulse, per substep: solve without the push-out bias.
    Restitution,       ///< Sequential impulse, after the substeps: bounces.
    Sleep,             ///< Islands; still islands fall asleep.
    Continuous,        ///< Fast bodies moved back to their first time of impact (src/collision/continuous.cpp).
    SoftBodies,        ///< Soft bodies: springs, gas pressure, nodes moved and collided (src/soft/soft_step.cpp).
    Count              ///< Number of stages (not a stage).
};

/// @brief Number of stages in a step.
inline constexpr std::size_t kStageCount = static_cast<std::size_t>(Stage::Count);

/// @brief Short name of a stage, as printed in summaries and errors ("integrate", …).
const char* stageName(Stage stage);

/// @brief What the World measured about one stage.
struct StageRecord {
    bool ranLastStep = false;    ///< Did the stage run in the most recent step?
    std::uint64_t runs = 0;      ///< Times it ran (a substep stage runs several times a step).
    double lastSeconds = 0;      ///< Wall-clock time it took in the most recent step (all its runs), s; 0 untimed.
    double totalSeconds = 0;     ///< Wall-clock time summed over all runs, s; 0 untimed (World::timeStages()).
};

/// @brief One record per stage, indexed by Stage, and whether their wall-clock times are measured.
struct StageRecords : std::array<StageRecord, kStageCount> {
    bool timed = false;  ///< Measure each run's time (World::timeStages()); false: only the runs are counted.
};

/// @brief Whether a timed piece of work is a run of its stage of its own, or more of the last one.
enum class StageRun : std::uint8_t {
    New,        ///< A run of the stage: counted in StageRecord::runs.
    Continued,  ///< More work of the stage's last run (its time is added, no run is counted).
};

/// @brief Runs @p body, marking the stage as run in @p records[@p stage], and, when @p records are
/// timed, adds its wall-clock time. Timing reads the clock twice a run: in a scene of a few bodies,
/// whose substep stages each take well under a microsecond, that is a large share of the step, so
/// the World times its stages only when asked (World::timeStages()).
template <class Body>
void timeStage(StageRecords& records, Stage stage, Body&& body, StageRun run = StageRun::New) {
    StageRecord& record = records[static_cast<std::size_t>(stage)];
    if (records.timed) {
        using Clock = std::chrono::steady_clock;
        const auto start = Clock::now();
        body();
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        record.lastSeconds += seconds;
        record.totalSeconds += seconds;
    } else {
        body();
    }
    record.ranLastStep = true;
    if (run == StageRun::New) record.runs += 1;
}

}  // namespace stepwise
