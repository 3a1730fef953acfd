/// @file step_plan.hpp
/// @brief The step plan: which stages and sub-steps a scene needs, decided once from what it holds.
///
/// A step runs the same fixed pipeline for every scene (src/world/world.cpp),
/// but much of it has nothing to do in many scenes: a scene of spheres never
/// needs the box–box separating-axis test, a lone planet with no floor never
/// collides, a world where everything sleeps has nothing to integrate. Before
/// the first step the World looks at its contents and writes down, stage by
/// stage, whether each one runs and why, in a StepPlan; `stepwise run FILE
/// --explain` prints it.
///
/// **Skipping never changes the result.** Each rule skips work only when the
/// work provably leaves every body exactly as it was (a loop over an empty
/// array, an impulse of zero, a rotation by zero), or takes another road to
/// the same numbers (the packed substeps), so the trajectory with the
/// plan is bit for bit the one without it (`World, StepPlan=Off`; the test
/// "[plan]" compares both on the scenes of config/). The rules are listed at
/// makeStepPlan().
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "dynamics/joints/joint.hpp"
#include "dynamics/substep_rule.hpp"
#include "forces/attractor.hpp"
#include "forces/region.hpp"
#include "forces/spring.hpp"
#include "objects/game_object.hpp"
#include "objects/materials.hpp"
#include "objects/soft_body.hpp"
#include "core/stages.hpp"
#include "core/world_settings.hpp"

namespace stepwise {

/// @brief One decision of the plan: does it run, and the one-line reason why (or why not).
struct PlanDecision {
    bool runs = true;        ///< true: the stage (or sub-step) runs every step.
    const char* reason = ""; ///< One line for a person, e.g. "skipped: no boxes in the scene, so no SAT".
};

/// @brief How often a stage of a pipeline runs in one step.
enum class StageRepeat : std::uint8_t {
    OncePerStep,    ///< Once per step.
    EverySubstep,   ///< Once in each substep (sequential impulse).
    LaterSubsteps,  ///< In each substep but the first (apply-forces: the first substep uses the step's forces).
};

/// @brief One stage at its place in a pipeline.
struct PipelineSlot {
    Stage stage;         ///< Which stage.
    StageRepeat repeat;  ///< How often it runs there.
};

/// @brief The stages of @p solver's pipeline in the order World::step() runs them
/// (World::stepWithImpulses(), World::stepWithSequentialImpulses(), src/world/world.cpp).
///
/// A stage may appear twice (the sequential impulse runs apply-forces once
/// before the broadphase and again in every substep after the first); a stage
/// of the other pipeline does not appear. `stepwise run --explain` prints the
/// plan in this order, and "[plan]" checks it against the stages the World reports.
std::span<const PipelineSlot> pipelineOrder(SolverKind solver);

/// @brief What the World does in each step of this scene, and why (see makeStepPlan() for the rules).
///
/// The reasons are string literals, so building a plan allocates nothing:
/// the World can rebuild it whenever a body may have been changed from
/// outside (World::dynamics() gives write access) without breaking the rule
/// that a step allocates no memory.
struct StepPlan {
    bool enabled = true;                          ///< false under `World, StepPlan=Off`: every stage of the pipeline runs.
    std::array<PlanDecision, kStageCount> stages; ///< One per Stage, indexed by it.
    PlanDecision collisions;       ///< Can any two objects touch at all (broadphase, narrowphase, contact solve)?
    PlanDecision boxBoxSat;        ///< Will the narrowphase ever run the box–box separating-axis test?
    PlanDecision manifoldClipping; ///< Will it clip a box face against another (the second half of box–box)?
    PlanDecision rotation;         ///< Can any body start to turn? If not, still spheres skip the angular update.
    PlanDecision substepForces;    ///< Sequential impulse: are the forces worked out again in every substep after the first?
    PlanDecision jointSolver;      ///< Do the joint calls (prepare, warm start, solve, break) run?
    PlanDecision idleSkip;         ///< Does a step with nothing awake and nothing moving return at once?
    PlanDecision fastPath;         ///< Sequential impulse: do the substeps run on the fast path (src/fast/fast_path.hpp)?
    PlanDecision packedSubsteps;   ///< On the fast path: may a step of balls run its substeps on packed records (src/fast/packed_substeps.hpp)?
    PlanDecision islandSubsteps;   ///< Sequential impulse: does each island get its own count (`SubstepsPerIsland=true`, src/dynamics/substep_rule.hpp)?
    PlanDecision colourOrder;      ///< Sequential impulse: do the passes take the contacts colour by colour (`ContactOrder`, src/dynamics/contact_colours.hpp)?
    PlanDecision regions;          ///< Do regions push the bodies inside them (src/forces/region.hpp)?
    PlanDecision killRegions;      ///< Are bodies that end a step in a Kill region removed (src/forces/kill_region.hpp)?
    PlanDecision softBodies;       ///< Does the soft bodies' stage run (src/soft/soft_step.hpp)?
    PlanDecision conveyors;        ///< Do contacts read the belt velocities of Conveyor regions (src/forces/conveyor.hpp)?
    SolverKind solver = SolverKind::SequentialImpulse; ///< The pipeline the scene runs (pipelineOrder()).
    int substeps = 1;              ///< Substeps of a sequential-impulse step.
    BroadphaseKind broadphase = BroadphaseKind::Auto; ///< The broadphase the scene asks for.
    PlanDecision broadphaseChoice; ///< Which broadphase will run and why (Auto decides on the first step).

    /// @brief The decision for @p stage.
    const PlanDecision& stage(Stage stage) const { return stages[static_cast<std::size_t>(stage)]; }
    /// @brief Does @p stage run in this scene?
    bool runs(Stage stage) const { return this->stage(stage).runs; }
};

/// @brief What makeStepPlan() reads: the World's objects and settings.
struct PlanInputs {
    const WorldSettings& settings;                ///< The World record (solver, sleep, broadphase, StepPlan).
    std::span<const DynamicObject> dynamics;      ///< Simulated bodies.
    std::span<const KinematicsObject> kinematics; ///< Prescribed-motion bodies.
    std::span<const CollisionPlane> planes;       ///< Infinite planes.
    std::span<const Spring> springs;              ///< Springs (their anchors may apply torque).
    std::span<const Attractor> attractors;        ///< Attractors (their pull depends on where a body is).
    std::span<const Region> regions;              ///< Regions (what they do depends on who is inside, and how it moves).
    std::span<const Joint> joints;                ///< Joints, broken ones included.
    const ContactMaterials* materials = nullptr;  ///< The material pairs (nullptr: none), for the friction rule.
    std::span<const SoftBody> softBodies;         ///< Pressure soft bodies (src/objects/soft_body.hpp).
};

/// @brief Builds the plan: a pure function of the scene's contents, allocating nothing.
///
/// The rules, and why each cannot change the result:
/// - **Collisions** need at least one dynamic body and some other object
///   (dynamic, kinematic or plane). Without, the broadphase finds no pair,
///   the narrowphase no contact, and every contact stage loops over nothing,
///   so the broadphase, narrowphase and contact stages are skipped.
/// - **Constraint stages** (sequential impulse: prepare, solve, relax,
///   restitution) run when collisions are possible or there are joints.
///   With neither, the solve changes no velocity, and driftByVelocityChange()
///   leaves a body whose velocity did not change where the integrator put it.
/// - **Box–box SAT** needs two boxes, one of them dynamic, and
///   `Narrowphase=Auto` (GjkEpa and Mpr take box pairs too). **Manifold
///   clipping** needs two bodies other than spheres (boxes, capsules,
///   cylinders, hulls, compounds, meshes), one of them dynamic. The
///   narrowphase picks the routine by the shape pair, so without them it
///   never reaches collideBoxBox() or a clip; the plan says so, it need not enforce it.
/// - **Rotation** is impossible when every dynamic body is a sphere with no
///   angular velocity (any other shape turns when a contact pushes it off
///   its centre), no contact has friction (μ = 0 for every
///   pair that can touch, by the World's FrictionCombine rule, and no MaterialPair gives any), no spring is hooked off a body's centre and there
///   are no joints: every force then acts through a sphere's centre, so
///   L = 0 for ever. The integrators then skip a sphere's angular update
///   (the inertia tensor turned into the world, the free-body rotation)
///   whenever its L and τ are *exactly* zero, which is what the full update
///   would leave untouched (a zero rotation returns the orientation as it
///   is, and I⁻¹·0 = 0). Because that check is made per body, a push from
///   outside (the viewer's mouse, which applies torque) or the rounding of
///   a lever arm cannot be lost: such a body gets the full update.
/// - **Forces in later substeps** (sequential impulse): apply-forces runs
///   before the broadphase, and again at the start of every substep after
///   the first, because a spring's or an attractor's pull depends on where
///   the bodies have moved to. With neither, every body's acceleration is
///   g + its ConstantAcceleration and its torque is zero, whatever its state,
///   so working them out again writes the very numbers already there; only
///   the step's first apply-forces runs. Nothing else in a step writes a or τ
///   (Verlet evaluates the same uniform forces inside its own step).
/// - **Joint solver**: with no joints, every joint call loops over nothing.
/// - **Moving kinematic bodies**: a kinematic body with zero velocity and
///   angular velocity moves by h·0 and turns by a zero rotation, so the stage is skipped.
/// - **Idle steps** (`Sleep=true`): when no dynamic body and no soft body is
///   awake and no kinematic body moves, nothing can wake a sleeper (only an
///   awake body or a moving kinematic body does), so the whole step is
///   skipped; the clock still advances. An asleep soft body's nodes are not
///   moved (src/dynamics/islands.hpp), so the skipped soft stage would have
///   left them as they are. Checked every step, since bodies wake and fall asleep.
/// - **Fast path** (sequential impulse): not a skip but another road to the
///   same numbers. The substeps run on the fast path (src/fast/fast_path.hpp:
///   contacts four at a time in SIMD lanes) when the plan is on,
///   `FastPath=true` (the default, except in the debug and student builds),
///   a dynamic ball or box makes contacts for the lanes possible, and there is
///   something to solve. It computes what the plain loop computes, bit for bit (the tests
///   "[fast]" and "[plan]" compare them). With a StepObserver attached the
///   World always takes the plain path, so that the objects are current
///   between the stages and what a student watches is the textbook step.
/// - **Packed substeps**, inside the fast path: when the scene integrates
///   with symplectic Euler, accumulates impulses, and has no joints and no
///   forces that follow the bodies through the substeps, a step whose
///   contacts all hold awake balls (no box, no moving kinematic body, no belt) runs its
///   substeps on the contact solver's packed records and writes the objects
///   once, at the end (src/fast/packed_substeps.hpp). Which road a step takes
///   is decided each step, after the contacts are found.
/// - **Substeps per island** (`SubstepsPerIsland=true`): not a skip, a
///   setting that changes the numbers of the islands it gives fewer than
///   `Substeps` (src/dynamics/substep_rule.hpp). It runs unless the scene has
///   springs or attractors, a moving kinematic body, or
///   `AccumulateImpulses=false`: those act inside every substep, and the
///   whole scene then keeps `Substeps`. A joint keeps only its own island at
///   `Substeps`. A step in which some island gets
///   fewer runs its groups of islands on the plain loop (the fast path then
///   waits for a step in which every island gets the full count).
/// - **Soft bodies**: their stage runs when the scene has one; without, it
///   would loop over nothing. It runs at the start of every substep, so a
///   scene with one takes the plain substeps: no fast path, and every island
///   the full `Substeps`. A soft body sleeps with its island, as a rigid
///   one does, and a scene whose soft bodies are all asleep can be idle.
/// - **Conveyors**: only a scene with a Conveyor region works out each body's
///   belt velocity (after the regions find their bodies) and hands it to the
///   contact preparation; without one, the preparation is given none, and
///   every contact is made exactly as before belts existed. A Conveyor region
///   pushes nothing, so alone it neither makes the forces run again in every
///   substep nor keeps the islands at Substeps.
/// - **Broadphase**: `Auto` takes brute force below kAutoBruteForceBelow
///   dynamic bodies (chooseBroadphase()); every broadphase returns the same
///   pairs in the same order.
///
/// With `settings.stepPlan == false` every stage of the solver's pipeline
/// runs and nothing is skipped, for comparison.
StepPlan makeStepPlan(const PlanInputs& inputs);

/// @brief The plan as text, one line per stage in the order the scene's pipeline
/// runs them (pipelineOrder(); the substep stages indented under "each of the
/// N substeps"), then the stages of the other pipeline, then one line per
/// sub-decision, each with its reason (what `stepwise run --explain` prints).
std::string describeStepPlan(const StepPlan& plan);

/// @brief The islands of one step and the substeps each got, with the rule's inputs and the
/// term that decided (what `stepwise run --explain` prints after the plan for the first step):
/// first how many islands got each count, then one line per island, at most @p maxLines of them.
/// @param islands  World::islandSubsteps() after a step
/// @param bodies   the World's dynamic bodies (an island is named by its first body)
/// @param cap      Substeps
std::string describeIslandSubsteps(std::span<const IslandSubsteps> islands, std::span<const DynamicObject> bodies,
                                   int cap, std::size_t maxLines);

/// @brief The viewer's "skipped stages: …" line: the stages of this scene's pipeline
/// (pipelineOrder(plan.solver), each once) that the plan skips or, once a step
/// was taken, that did not run in it (an idle step of sleepers runs none).
/// The other solver's stages are not named: they are not part of this step at all; nor is
/// `soft-bodies` in a scene without a soft body.
/// @param plan       the World's plan (World::plan())
/// @param records    the World's stage records (World::stageRecords())
/// @param stepTaken  false before the first step: only the plan's skips are known
std::string skippedStagesLine(const StepPlan& plan, const StageRecords& records, bool stepTaken);

}  // namespace stepwise
