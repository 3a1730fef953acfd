/// @file world.hpp
/// @brief The World: owns the objects and runs the step pipeline.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "collision/broadphase.hpp"
#include "collision/contact.hpp"
#include "collision/continuous.hpp"
#include "collision/narrowphase.hpp"
#include "collision/raycast.hpp"
#include "core/stages.hpp"
#include "core/thread_pool.hpp"
#include "core/world_settings.hpp"
#include "dynamics/contact_solver.hpp"
#include "dynamics/impulse_resolver.hpp"
#include "dynamics/islands.hpp"
#include "dynamics/joints/joint.hpp"
#include "dynamics/substep_rule.hpp"
#include "forces/apply_forces.hpp"
#include "forces/kill_region.hpp"
#include "forces/region.hpp"
#include "objects/body_set.hpp"
#include "world/scene.hpp"
#include "world/step_observer.hpp"
#include "world/step_plan.hpp"

namespace stepwise {

struct FastWorkspace;   // src/fast/fast_workspace.hpp: the fast path's own arrays
struct FastPathCounts;  // src/fast/fast_path_counts.hpp: how many steps took it

/// @brief A running simulation: the objects of a Scene plus the clock and the step pipeline.
///
/// Call step() to advance by one fixed time step. The World keeps one
/// contiguous array per kind of object; everything a stage produces
/// (candidate pairs, contacts, impulses) lives in arrays that are reused from
/// step to step, so a step allocates no memory once the scene has settled.
class World {
public:
    /// @brief Takes the objects and settings of @p scene.
    /// @throws std::invalid_argument naming the object when a value is impossible
    ///         (mass ≤ 0, radius ≤ 0, non-finite numbers, zero plane normal, time step ≤ 0,
    ///         a spring joining a missing body or a body to itself, negative stiffness, μ ≤ 0),
    ///         or the joint when it cannot be built (makeJoints()).
    explicit World(Scene scene);
    ~World();
    World(World&&) noexcept;             ///< A World can be moved (not copied: it owns a thread pool).
    World& operator=(World&&) noexcept;  ///< Moves another World in.

    /// @brief Advances the simulation by one time step (see world.cpp for the stages).
    /// @throws SimulationError when a stage leaves a non-finite state, naming object, stage and step.
    void step();

    const WorldSettings& settings() const { return settings_; }  ///< The scene's World record.
    Real time() const { return time_; }                           ///< Simulated time, s.
    std::uint64_t stepCount() const { return stepCount_; }        ///< Steps completed: N − 1 while step N runs.

    /// @brief Simulated bodies, to change: the step plan is rebuilt before the next step.
    std::vector<DynamicObject>& dynamics() {
        planStale_ = true;
        return dynamics_;
    }
    const std::vector<DynamicObject>& dynamics() const { return dynamics_; }  ///< Simulated bodies.
    /// @brief Prescribed-motion bodies, to change: the step plan is rebuilt before the next step.
    std::vector<KinematicsObject>& kinematics() {
        planStale_ = true;
        return kinematics_;
    }
    const std::vector<KinematicsObject>& kinematics() const { return kinematics_; }  ///< Prescribed-motion bodies.
    const std::vector<CollisionPlane>& planes() const { return planes_; }     ///< Infinite planes.
    const std::vector<Spring>& springs() const { return springs_; }           ///< Springs (src/forces/spring.hpp).
    const std::vector<Attractor>& attractors() const { return attractors_; }  ///< Central forces (src/forces/attractor.hpp).
    const std::vector<Region>& regions() const { return regions_; }  ///< Volumes with effects (src/forces/region.hpp).
    /// @brief Which bodies each region held in the last step (src/forces/region.hpp, RegionMembers).
    const RegionMembers& regionMembers() const { return regionMembers_; }
    /// @brief Each dynamic body's conveyor belt velocity in the last step, m/s (zero: on no belt;
    /// src/forces/conveyor.hpp); empty in a scene without a Conveyor region.
    std::span<const Vec3> beltVelocities() const;  // world_regions.cpp
    /// @brief The bodies Kill regions have removed so far, in the order they went (src/forces/kill_region.hpp).
    const std::vector<RemovedBody>& removedBodies() const { return removedBodies_; }
    const IslandWorkspace& islands() const { return islandWorkspace_; }  ///< Islands of the last step (islandOf()).
    const std::vector<Joint>& joints() const { return joints_; }              ///< Joints, broken ones included.
    const std::vector<SoftBody>& softBodies() const { return softBodies_; }  ///< Pressure soft bodies (src/soft/).

    /// @brief The dynamic body called @p name, or nullptr.
    const DynamicObject* findDynamic(std::string_view name) const;

    /// @brief Wakes dynamic body @p body and everything that fell asleep in its island, soft bodies
    /// included (src/dynamics/islands.hpp): what a tool that pushes a body does first (the viewer's mouse).
    /// @return the number of bodies and soft bodies woken.
    std::size_t wakeIsland(std::uint32_t body);

    const std::vector<CandidatePair>& candidatePairs() const { return pairs_; }  ///< Last broadphase output.
    const std::vector<Contact>& contacts() const { return contacts_; }           ///< Last narrowphase output.
    const std::vector<ImpulseReport>& impulses() const { return impulses_; }     ///< One per contact, last step.
    const StageRecords& stageRecords() const { return stageRecords_; }           ///< Per-stage runs, and times when timed.
    /// @brief Measure the wall-clock time of every stage run from now on (true), or only count the
    /// runs (false, the default). Timing costs two clock reads a stage run, a large share of the
    /// step of a scene of a few bodies: `stepwise run`'s stage table, the viewer's overlay and the
    /// stage-cost benchmarks switch it on.
    void timeStages(bool on) { stageRecords_.timed = on; }
    /// @brief The sequential-impulse solver's constraints of the last step (effective masses, accumulated impulses).
    ///
    /// Current between steps and in a StepObserver's afterStage() (with an observer the step takes
    /// the plain path, which solves them where they are).
    const std::vector<SolverContact>& solverContacts() const { return solverWorkspace_.contacts; }
    /// @brief Where each of those constraints came from (bodies, lever arms, start gap) and its bounce; same order.
    const std::vector<ContactStart>& solverContactStarts() const { return solverWorkspace_.starts; }
    /// @brief The bytes of the contact solver's arrays in the last step: what its passes read, and all of
    /// them (the fast path's too, when the plan runs it: fastFootprint(), src/fast/fast_path.hpp).
    SolverFootprint solverFootprint() const;
    const Broadphase& broadphase() const { return broadphase_; }  ///< Stage 4's state: which kind ran, Auto's reason.
    /// @brief What each step runs and why (src/world/step_plan.hpp), as of the last step
    /// (or construction); `stepwise run --explain` prints it.
    const StepPlan& plan() const { return plan_; }
    /// @brief How many steps so far ran their substeps on the fast path, and how many of those on
    /// its packed records (src/fast/fast_path.hpp); the plain path took the others.
    FastPathCounts fastPathCounts() const;
    /// @brief The islands of the last step and the substeps each ran (`SubstepsPerIsland=true`,
    /// src/dynamics/substep_rule.hpp); empty when the rule did not run in that step.
    std::span<const IslandSubsteps> islandSubsteps() const {
        return islandRuleRan_ ? std::span<const IslandSubsteps>(substepGroups_.islands) : std::span<const IslandSubsteps>{};
    }
    /// @brief Threads the narrowphase uses (the World's `Threads`, 0 resolved to the hardware's count).
    unsigned threadCount() const { return threadPool_->threadCount(); }
    /// @brief Fast bodies the continuous stage moved back to their time of impact in the last step.
    std::size_t bodiesStoppedAtImpact() const { return sweepWorkspace_.lastClamped; }

    /// @brief The first body the ray from @p origin along @p direction meets within @p maxDistance
    /// (src/world/world_raycast.cpp); nothing when it meets none.
    /// @param origin      start of the ray, m
    /// @param direction   any non-zero vector (normalised here)
    /// @param maxDistance how far to look, m (≥ 0)
    /// @throws std::invalid_argument when @p direction is zero or a value is not finite.
    std::optional<RayHit> raycast(const Vec3& origin, const Vec3& direction, Real maxDistance) const;

    /// @brief Calls @p observer around every stage of every later step (nullptr: none).
    ///
    /// The World does not own it; it must outlive the steps it watches. See step_observer.hpp.
    void setObserver(StepObserver* observer) { observer_ = observer; }

private:
    /// Runs one stage, unless the step plan skips it: times it, records it, then checks the state it left.
    template <class StageBody>
    void runStage(Stage stage, StageBody&& body);
    void replan();
    bool idle() const;
    void checkFinite(Stage stage) const;
    void stepWithImpulses();
    void measureSweeps(Real h);
    void widenSweepsByKnocks();
    void stepWithSequentialImpulses();
    void warmStart(int substep);
    void solvePass(const ContactSolverSettings& contactSettings, const JointSolverSettings& jointSettings, bool useBias);
    void runFastPath(const AccelerationFunction& forces, const ContactSolverSettings& contactSettings,
                     const JointSolverSettings& jointSettings);
    void runIslandGroups(const AccelerationFunction& forces, const JointSolverSettings& jointSettings);
    void findRegionMembers(bool throughBroadphase);  // world_regions.cpp
    RegionForces regionForces(Real substepTime) const;  // world_regions.cpp
    void removeKilledBodies();                       // world_regions.cpp
    void stepSoftBodies(Real h, bool startsStep);
    BodySet bodies();

    WorldSettings settings_;
    std::vector<DynamicObject> dynamics_;
    std::vector<KinematicsObject> kinematics_;
    std::vector<CollisionPlane> planes_;
    std::vector<Spring> springs_;
    std::vector<Attractor> attractors_;
    std::vector<Region> regions_;              ///< Volumes with effects (src/forces/region.hpp).
    RegionMembers regionMembers_;              ///< Who each region holds this step.
    std::vector<std::uint32_t> regionCandidates_;  ///< Scratch: the broadphase's answer for one region.
    std::vector<Vec3> conveyorVelocities_;     ///< Each dynamic body's belt velocity this step (src/forces/conveyor.hpp).
    std::vector<RemovedBody> removedBodies_;   ///< What Kill regions took, for the run's summary.
    std::vector<Joint> joints_;
    std::vector<SoftBody> softBodies_;  ///< Pressure soft bodies, stepped by src/soft/soft_step.cpp.
    ContactMaterials materials_;  ///< The combine rules and material pairs every contact's preparation reads.

    Broadphase broadphase_;
    std::vector<CandidatePair> pairs_;
    std::vector<Contact> contacts_;
    std::vector<ImpulseReport> impulses_;
    ContactWorkspace contactWorkspace_;
    SolverWorkspace solverWorkspace_;
    IslandWorkspace islandWorkspace_;
    JointWorkspace jointWorkspace_;
    std::vector<BodyLink> links_;  ///< Bodies held together by joints (for islands).
    /// The fast path's arrays (src/fast/): the round contacts in lanes, the packed balls. Created
    /// once here; a pointer so that a reader of this header need not open the fast path.
    std::unique_ptr<FastWorkspace> fastWorkspace_;

    StepPlan plan_;
    bool planStale_ = false;  ///< A body may have changed through dynamics() or kinematics(): replan before stepping.
    /// Bodies asleep after the last sleep stage or replan(), or more (a body woken since still counts):
    /// with none, no candidate pair is dropped and no island woken, so those walks are skipped.
    std::size_t asleep_ = 0;
    std::unique_ptr<ThreadPool> threadPool_;  ///< Created once here; a pointer so that the World can be moved.
    NarrowphaseWorkspace narrowphaseWorkspace_;
    SweepWorkspace sweepWorkspace_;
    std::vector<Real> knockSweeps_;  ///< widenSweepsByKnocks(): each body's sweep with its neighbours' knocks.
    SubstepGroups substepGroups_;  ///< This step's islands, their counts and groups (src/dynamics/substep_rule.hpp).
    bool islandRuleRan_ = false;   ///< The rule chose the counts of the last step (islandSubsteps()).

    StageRecords stageRecords_{};
    StepObserver* observer_ = nullptr;
    int substep_ = -1;  ///< Substep being run, −1 outside the substep loop (for StageEvent).
    int groupSubsteps_ = 0;  ///< Substeps of the group of islands being run, 0 outside one (for StageEvent).
    Real time_ = 0;
    /// Steps completed before the one now running. Steps count from 1, so while step N runs
    /// (from t = (N − 1)·h) this is N − 1: in gdb, `p stepCount_` prints 27 inside step 28, the
    /// step `stepwise trace` prints as "step 28" and a SimulationError names "step 28".
    std::uint64_t stepCount_ = 0;
};

}  // namespace stepwise
