/// @file fast_path.hpp
/// @brief The fast path: the substeps of the soft step, with the plain path's numbers, bit for bit.
///
/// **What it computes.** The same as the plain substep loop in
/// World::stepWithSequentialImpulses() (integrate, warm start, solve, move,
/// relax; dynamics/warm_start_contacts.cpp, solve_contacts.cpp, velocity_change_drift.cpp),
/// bit for bit. A student never needs to read this folder: every number the
/// engine computes, the plain path computes too. Nothing here is new physics.
///
/// **How it is faster.** Three things, each a file of this folder:
/// 1. *Contacts four at a time* (contact_waves.hpp, round_contact_lanes.hpp,
///    box_contact_lanes.hpp). Contacts are put in waves of contacts that
///    share no body and solved four at a time in SIMD lanes (lanes.hpp): the
///    round ones (between balls, or a ball and a plane or a kinematic body at rest) with rows computed
///    from the normal, then the others (a box's, a kinematic body's) with
///    their stored rows. Each body meets its contacts in the plain pass's
///    order, and each lane rounds as a scalar does, so the velocities are the
///    plain pass's.
/// 2. *Packed substeps* (packed_substeps.hpp). In a step whose contacts all
///    hold awake balls, under symplectic Euler, with no joints and only
///    uniform forces, a ball's whole state stays in arrays beside its solver
///    record for the step: the objects are read once at its start and written
///    once at its end, instead of four times a substep.
///
/// 3. *Threads* (parallel_waves.hpp). The contacts of one wave share no
///    body, so a large wave is cut into pieces that the World's threads
///    (`Threads=`) solve at once; the next wave waits for all of them. The
///    numbers are the same with any number of threads.
///
/// **When it runs.** The step plan decides (StepPlan::fastPath,
/// world/step_plan.hpp): sequential impulse, the plan on, `FastPath=true`, and
/// a dynamic ball or box in the scene. With a StepObserver attached (the trace, the
/// viewer's stage walk-through) the World takes the plain path, so what a
/// student watches is the textbook step. The tests tagged "[fast]" run both
/// roads and compare every bit.
///
/// **Its own checks.** The plain path checks the objects after every stage.
/// On the packed substeps the objects are not current until the last relax,
/// so the fast path checks what it writes, as it writes it (the probes of
/// packed_substeps.hpp), and names the body when a number is not finite.
#pragma once

#include <cstdint>
#include <span>

#include "core/stages.hpp"
#include "core/thread_pool.hpp"
#include "core/world_settings.hpp"
#include "dynamics/contact_solver.hpp"
#include "dynamics/joints/joint.hpp"
#include "fast/fast_path_counts.hpp"
#include "fast/fast_workspace.hpp"
#include "forces/apply_forces.hpp"

namespace stepwise {

/// @brief Everything the fast path's substeps read and write, handed over by the World once a step.
struct FastSubsteps {
    std::span<DynamicObject> dynamics;            ///< The World's dynamic bodies.
    std::span<KinematicsObject> kinematics;       ///< Its kinematic bodies (moved every substep).
    std::span<const CollisionPlane> planes;       ///< Its planes.
    SolverWorkspace& contacts;                    ///< The contacts and records prepareContacts() made this step.
    JointWorkspace& joints;                       ///< The joints prepareJoints() made (empty without joints).
    const AccelerationFunction& forces;           ///< The scene's forces (again in every substep if they follow the bodies).
    IntegratorKind integrator = IntegratorKind::SymplecticEuler;  ///< The scene's integrator.
    int substeps = 1;                             ///< Substeps per step.
    int velocityIterations = 1;                   ///< Solve passes per substep.
    int relaxIterations = 1;                      ///< Relax passes per substep.
    bool accumulateImpulses = true;               ///< Warm start from accumulated impulses.
    ContactSolverSettings contactSettings;        ///< The contacts' softness at h_s.
    JointSolverSettings jointSettings;            ///< The joints' softness at h_s.
    bool forcesEverySubstep = false;              ///< The plan: apply-forces again in substeps 2, 3, …
    bool moveKinematics = false;                  ///< The plan: a kinematic body moves.
    bool jointSolver = false;                     ///< The plan: the joint calls run.
    bool canTurn = true;                          ///< The plan: a body can start to turn.
    bool packedSubsteps = false;                  ///< The plan: a step of balls may run on packed records.
    StageRecords& records;                        ///< Where each stage's time goes (World::stageRecords()).
    ThreadPool& pool;                             ///< The World's threads: large waves are split between them (parallel_waves.hpp).
    std::uint64_t step = 0;                       ///< The step being taken, from 1 (StageAtStep::step), to name in an error.
    double time = 0;                              ///< Simulated time at the step's start, s.
};

/// @brief Runs the substeps (stages 5 to 7 of the soft step) on the fast path, leaving the objects,
/// the contacts' impulses and the records where the plain loop would leave them, to the bit.
/// @throws SimulationError naming the body, the stage and the step when a number is not finite.
void runFastSubsteps(const FastSubsteps& step, FastWorkspace& workspace);

/// @brief The bytes of the contact solver's arrays the fast path's passes read, and of all
/// arrays of both workspaces, as the last step left them (`stepwise-bench stage-costs`).
SolverFootprint fastFootprint(const SolverWorkspace& contacts, const FastWorkspace& workspace);

}  // namespace stepwise
