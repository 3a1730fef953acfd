/// @file world.cpp
/// @brief The step pipeline, read top to bottom in World::step().
#include "world/world.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "collision/aabb.hpp"
#include "collision/narrowphase.hpp"
#include "core/errors.hpp"
#include "core/limits.hpp"
#include "dynamics/islands.hpp"
#include "dynamics/kinematic_motion.hpp"
#include "dynamics/substep_rule.hpp"
#include "dynamics/velocity_change_drift.hpp"
#include "fast/fast_path.hpp"  // the one door into the fast path (src/fast/)
#include "forces/apply_forces.hpp"
#include "integrators/integrators.hpp"
#include "objects/finite_state.hpp"
#include "objects/inertia.hpp"
#include "soft/soft_step.hpp"  // the soft bodies' stage (src/soft/)

namespace stepwise {

namespace {

void require(bool condition, const std::string& object, const std::string& what) {
    if (!condition) throw std::invalid_argument("object '" + object + "': " + what);
}

bool isFinite(Real x) { return std::isfinite(x); }

/// The parts of a dynamic body's state each stage may write (objects/finite_state.hpp): checkFinite()
/// reads only those after the stage. A stage that writes a quantity outside its set would have a
/// non-finite value named late, never missed: a non-finite force reaches the velocity at the next
/// integrate, and the stages that run once a step check everything.
unsigned statePartsWrittenBy(Stage stage, IntegratorKind integrator) {
    switch (stage) {
        case Stage::ApplyForces: return kForces;
        // Verlet works the forces out at the new positions inside its step; the others only move
        case Stage::Integrate: return integrator == IntegratorKind::Verlet ? kEverything : kPose | kMotion;
        case Stage::Broadphase:
        case Stage::Narrowphase:
        case Stage::PrepareConstraints:  // wakes islands: flags, not numbers
        case Stage::MoveKinematics: return 0;
        case Stage::SolveConstraints: return kPose | kMotion;  // the passes, then the drift by h·Δv
        case Stage::ResolveImpulses:
        case Stage::RelaxConstraints:
        case Stage::Restitution: return kMotion;
        case Stage::Continuous: return kPose;  // positions moved back along their paths (continuous.cpp)
        case Stage::Sleep: return 0;  // flags, a timer, and exact zeros for the velocities of a body that falls asleep
        case Stage::SoftBodies: return kMotion;  // a node's impulse on a dynamic body (its nodes are checked inside)
        default: return kEverything;  // the once-a-step stages
    }
}

}  // namespace

World::World(Scene scene)
    : settings_(scene.settings),
      dynamics_(std::move(scene.dynamics)),
      kinematics_(std::move(scene.kinematics)),
      planes_(std::move(scene.planes)),
      springs_(std::move(scene.springs)),
      attractors_(std::move(scene.attractors)),
      regions_(std::move(scene.regions)),
      softBodies_(std::move(scene.softBodies)),
      materials_(settings_, scene.materials.size(), scene.materialPairs) {
    require(scene.spaces.empty(), "World",
            "the scene has Space records: each space is a World of its own (src/world/spaces.hpp, Spaces), "
            "and only stepwise run, trace and view step them together so far");
    require(isFinite(settings_.timeStep) && settings_.timeStep > 0, "World", "time step must be > 0 s");
    require(stepwise::isFinite(settings_.gravity), "World", "gravity must be finite");
    // The limits of core/limits.hpp, which the loader reports at their line and column
    const auto repetitions = [](int n, int least) { return n >= least && n <= kMaxRepetitions; };
    require(repetitions(settings_.impulseIterations, 1), "World", "impulse iterations must be from 1 to 1024");
    require(repetitions(settings_.substeps, 1), "World", "substeps must be from 1 to 1024");
    require(repetitions(settings_.velocityIterations, 1), "World", "iterations must be from 1 to 1024");
    require(repetitions(settings_.relaxIterations, 0), "World", "relax iterations must be from 0 to 1024");
    require(settings_.threads >= 0 && settings_.threads <= kMaxThreads, "World",
            "threads must be from 0 to 256 (0: one per hardware thread)");
    threadPool_ = std::make_unique<ThreadPool>(settings_.threads == kAutoThreads ? autoThreadCount()
                                                                                 : static_cast<unsigned>(settings_.threads));
    for (DynamicObject& body : dynamics_) {
        require(body.mass >= kMinMass && body.mass <= kMaxMass, body.name, "mass must be from 1e-12 to 1e12 kg");
        require(body.radius >= kMinBodySize / 2 && body.radius <= kMaxBodySize / 2, body.name,
                "radius must be from 5e-7 to 5e5 m");
        for (int k = 0; k < 3; ++k) {
            require(body.scale[k] >= kMinBodySize && body.scale[k] <= kMaxBodySize, body.name,
                    "each edge (Scale) must be from 1e-6 to 1e6 m");
        }
        require(stepwise::isFinite(body.position) && stepwise::isFinite(body.velocity), body.name,
                "position and velocity must be finite");
        body.inverseMass = Real(1) / body.mass;
        initialiseMassProperties(body);
    }
    for (CollisionPlane& plane : planes_) {
        require(usableDirection(plane.normal), plane.name, "the plane's normal must be a direction of finite length > 0");
        plane.normal /= glm::length(plane.normal);
    }
    for (const Spring& spring : springs_) {
        const auto joins = [&](std::size_t index) { return index < dynamics_.size(); };
        require(joins(spring.bodyA), spring.name, "BodyA must be one of the dynamic bodies");
        require(spring.bodyB == kFixedInWorld || joins(spring.bodyB), spring.name,
                "BodyB must be one of the dynamic bodies, or kFixedInWorld");
        require(spring.bodyA != spring.bodyB, spring.name, "a spring must join two different bodies");
        require(isFinite(spring.stiffness) && spring.stiffness >= 0 && isFinite(spring.damping) &&
                    spring.damping >= 0 && isFinite(spring.restLength) && spring.restLength >= 0,
                spring.name, "stiffness, damping and rest length must be >= 0");
        require(stepwise::isFinite(spring.anchorA) && stepwise::isFinite(spring.anchorB), spring.name,
                "anchors must be finite");
    }
    for (const Attractor& attractor : attractors_) {
        require(isFinite(attractor.mu) && attractor.mu > 0, attractor.name, "Mu must be > 0 m^3/s^2");
        require(stepwise::isFinite(attractor.position), attractor.name, "position must be finite");
    }
    for (Region& region : regions_) {
        require(usableDirection(region.normal), region.name, "the region's normal must be a direction of finite length > 0");
        region.normal /= glm::length(region.normal);
        require(stepwise::isFinite(region.position) && stepwise::isFinite(region.halfExtents) && isFinite(region.radius),
                region.name, "position and size must be finite");
        require(stepwise::isFinite(region.velocity), region.name, "the velocity (a fluid's, the wind's, a belt's) must be finite");
    }
    for (SoftBody& body : softBodies_) {
        require(body.mass >= kMinMass && body.mass <= kMaxMass, body.name, "mass must be from 1e-12 to 1e12 kg");
        require(isFinite(body.nRT) && body.nRT >= 0, body.name, "Pressure (nRT) must be >= 0 J");
        require(!body.faces.empty() && body.nodeInverseMasses.size() == body.nodeCount() &&
                    body.nodeVelocities.size() == body.nodeCount() && body.nodeForces.size() == body.nodeCount(),
                body.name, "a soft body needs its nodes and faces (buildSoftBody(), src/objects/soft_mesh.hpp)");
        for (std::size_t i = 0; i < body.nodeCount(); ++i) {
            require(stepwise::isFinite(body.nodePositions[i]) && stepwise::isFinite(body.nodeVelocities[i]), body.name,
                    "node positions and velocities must be finite");
        }
        const auto isNode = [&](std::uint32_t i) { return i < body.nodeCount(); };
        for (const SoftFace& f : body.faces) require(isNode(f.a) && isNode(f.b) && isNode(f.c), body.name, "a face names a missing node");
        for (const SoftSpring& s : body.springs) {
            require(isNode(s.a) && isNode(s.b) && s.a != s.b, body.name, "a spring must join two different nodes");
            require(isFinite(s.stiffness) && s.stiffness >= 0 && isFinite(s.damping) && s.damping >= 0, body.name,
                    "stiffness and damping must be >= 0");
        }
        measureSoftBody(body);
        require(body.nRT == 0 || body.volume > 0, body.name, "the surface must enclose a volume > 0 (faces wound outward)");
    }
    joints_ = makeJoints(scene.joints, dynamics_, settings_.solver);  // src/dynamics/joints/joint.cpp
    jointLinks(joints_, links_);
    fastWorkspace_ = std::make_unique<FastWorkspace>();
    replan();
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

/// The step plan from what the World holds now (src/world/step_plan.cpp); it allocates nothing.
void World::replan() {
    plan_ = makeStepPlan(
        {settings_, dynamics_, kinematics_, planes_, springs_, attractors_, regions_, joints_, &materials_, softBodies_});
    asleep_ = 0;
    for (DynamicObject& body : dynamics_) {
        body.canTurn = plan_.rotation.runs;  // read by the integrators
        if (body.asleep) ++asleep_;
    }
    planStale_ = false;
}

/// Nothing can change this step: no dynamic body and no soft body is awake (a
/// sleeper is only woken by an awake body or a moving kinematic one), and no
/// kinematic body moves.
bool World::idle() const {
    for (const DynamicObject& body : dynamics_) {
        if (!body.asleep) return false;
    }
    for (const SoftBody& body : softBodies_) {
        if (!body.asleep) return false;
    }
    for (const KinematicsObject& body : kinematics_) {
        if (body.velocity != Vec3(0) || body.angularVelocity != Vec3(0)) return false;
    }
    return true;
}

const DynamicObject* World::findDynamic(std::string_view name) const {
    for (const DynamicObject& body : dynamics_) {
        if (body.name == name) return &body;
    }
    return nullptr;
}

std::size_t World::wakeIsland(std::uint32_t body) { return stepwise::wakeIsland(dynamics_, body, softBodies_); }

BodySet World::bodies() { return {dynamics_, kinematics_, planes_, &materials_, softBodies_}; }

void World::step() {
    for (StageRecord& record : stageRecords_) {
        record.ranLastStep = false;
        record.lastSeconds = 0;
    }
    if (planStale_) replan();  // a body was handed out for writing since the last step
    // The step plan's early-out (step_plan.hpp): with nothing awake and nothing moving, time alone advances.
    if (plan_.idleSkip.runs && idle()) {
        // What the skipped stages would have found: every pair is dropped (dropSleepingPairs), so nothing touches.
        pairs_.clear();
        contacts_.clear();
        impulses_.clear();
        time_ += settings_.timeStep;
        ++stepCount_;
        if (observer_) observer_->afterStep(*this);
        return;
    }
    switch (settings_.solver) {
        case SolverKind::Impulse: stepWithImpulses(); break;
        case SolverKind::SequentialImpulse: stepWithSequentialImpulses(); break;
    }
    time_ += settings_.timeStep;
    ++stepCount_;
    if (observer_) observer_->afterStep(*this);
}

/// `Solver=Impulse`, the foundation's step: move, then find and repair the
/// collisions the move made. Each line is one stage, in its own file.
void World::stepWithImpulses() {
    const Real h = settings_.timeStep;
    const SceneForces sceneForces{settings_.gravity, springs_, attractors_, regionForces(h)};  // gravity, springs, attractors, regions
    const AccelerationFunction forces = std::cref(sceneForces);  // by reference: no allocation per step

    // 1. Forces → accelerations (src/forces/apply_forces.cpp)
    if (!regions_.empty()) findRegionMembers(false);  // who is inside each region (src/world/world_regions.cpp)
    runStage(Stage::ApplyForces, [&] { forces(dynamics_); });

    // 2. Advance dynamic bodies by h (src/integrators/*.cpp)
    runStage(Stage::Integrate, [&] {
        if (settings_.continuousCollision) recordStartPositions(bodies(), sweepWorkspace_);  // for stage 3b
        integrateBodies(settings_.integrator, dynamics_, h, forces);
    });

    // 3. Advance kinematic bodies along their prescribed motion (src/dynamics/kinematic_motion.cpp)
    runStage(Stage::MoveKinematics, [&] { moveKinematics(kinematics_, h); });

    // 3b. A body that moved farther than its half-thickness goes back to where its path first
    //     touched something, so it cannot pass through a wall (src/collision/continuous.cpp)
    if (settings_.continuousCollision) {
        runStage(Stage::Continuous, [&] { stopFastBodiesAtImpact(bodies(), sweepWorkspace_); });
    }

    // 4. Which pairs might touch? (src/collision/broadphase.cpp → broadphase_*.cpp)
    runStage(Stage::Broadphase, [&] { broadphase_.findPairs(settings_.broadphase, bodies(), pairs_); });

    // 5. Which of them do, where, and how deep? (src/collision/narrowphase.cpp → sphere_*.cpp)
    runStage(Stage::Narrowphase, [&] {
        findContacts(bodies(), pairs_, contacts_, settings_.continuousCollision, 0, *threadPool_,
                     narrowphaseWorkspace_, settings_.narrowphase);
    });

    // 6. Impulses: bounce and friction change velocities (src/dynamics/impulse_resolver.cpp)
    runStage(Stage::ResolveImpulses, [&] {
        impulses_.resize(contacts_.size());
        resolveImpulses(bodies(), contacts_, h, settings_.impulseIterations, settings_.warmStarting, contactWorkspace_,
                        impulses_, beltVelocities());  // the belts of Conveyor regions (src/forces/conveyor.hpp)
    });

    // 7. Push overlapping bodies apart (src/dynamics/impulse_resolver.cpp, correctPositions)
    const Real supportStep = positionShareOfVelocityChange(settings_.integrator) * h;
    runStage(Stage::CorrectPositions, [&] { correctPositions(bodies(), contacts_, h, supportStep, contactWorkspace_); });

    // 7b. Soft bodies: springs, gas, nodes moved and pushed out of the rigid objects (src/soft/soft_step.cpp)
    runStage(Stage::SoftBodies, [&] { stepSoftBodies(settings_.timeStep, true); });

    // 8. Bodies that ended the step in a Kill region leave the world (src/world/world_regions.cpp)
    if (plan_.killRegions.runs) removeKilledBodies();
}

/// Sweep = |v|·h + ½|a|·h²: the distance free flight can carry a body in a
/// step (for a kinematic body, plus what its turning moves its farthest point).
///
/// A plane's sweep is the largest of the bodies' (GameObject::sweep). Contacts
/// are found once a step, from how far each body can move by itself; but a
/// body can be knocked within the step, and a collision passes its speed on
/// (a ball struck by an equal ball takes up to the striker's speed). A ball
/// at rest 2 cm from a wall, struck at 3 m/s, would cross those 2 cm and sink
/// into the wall before the next step found the contact, as happens in a
/// dense sphere rain. Walls are few and a contact with a gap costs nothing
/// until it closes, so every body gets its plane contacts that far ahead.
void World::measureSweeps(Real h) {
    Real fastest = 0;
    for (DynamicObject& body : dynamics_) {
        body.sweep = body.asleep ? Real(0)
                                 : glm::length(body.velocity) * h + Real(0.5) * glm::length(body.acceleration) * h * h;
        fastest = std::max(fastest, body.sweep);
    }
    for (KinematicsObject& body : kinematics_) {
        const Real reach = shapeReach(body);  // the farthest point's distance from the centre, any shape
        body.sweep = (glm::length(body.velocity) + glm::length(body.angularVelocity) * reach) * h;
        fastest = std::max(fastest, body.sweep);
    }
    for (CollisionPlane& plane : planes_) plane.sweep = fastest;
}

/// A knock passes on through bodies in touch: a ball struck within the step by a neighbour of
/// speed v leaves at up to 2·m_j/(m_i + m_j)·v (an elastic impact, the most a single impact gives),
/// the striker's own speed for equal masses. Its own sweep (free flight) misses that: in a dense
/// sphere rain a ball resting 6 cm from another, struck at 4 m/s from above, crossed those 6 cm and
/// sank 2 cm into it before the next step found the contact. So, once the broadphase has listed
/// who may meet whom, each body's sweep becomes the largest of its own and the knocks its
/// candidate partners can deliver, and the narrowphase looks that much further ahead for its
/// contacts (a contact with a gap costs a row in the solver, no push, until it closes).
///
/// The widened reach applies to the candidate pairs, found with the bodies' own sweeps (plus the
/// broadphase's fat margins); a knock that would carry a body further than those boxes reach is
/// still missed. Planes already reach as far as the fastest body (measureSweeps()).
void World::widenSweepsByKnocks() {
    knockSweeps_.resize(dynamics_.size());
    for (std::size_t i = 0; i < dynamics_.size(); ++i) knockSweeps_[i] = dynamics_[i].sweep;
    for (const CandidatePair& pair : pairs_) {
        if (pair.b.kind != BodyKind::Dynamic) continue;
        const DynamicObject& a = dynamics_[pair.a];
        const DynamicObject& b = dynamics_[pair.b.index];
        // 2·m_j/(m_i + m_j) written with inverse masses: 2·(1/m_i)/((1/m_i) + (1/m_j)).
        const Real sum = a.inverseMass + b.inverseMass;
        knockSweeps_[pair.a] = std::max(knockSweeps_[pair.a], 2 * a.inverseMass / sum * b.sweep);
        knockSweeps_[pair.b.index] = std::max(knockSweeps_[pair.b.index], 2 * b.inverseMass / sum * a.sweep);
    }
    for (std::size_t i = 0; i < dynamics_.size(); ++i) dynamics_[i].sweep = knockSweeps_[i];
}

/// `Solver=SequentialImpulse`, Catto's soft step: find the contacts first,
/// then hold them (and the joints) through `substeps` short substeps.
///
/// Each stage is a call into its own file. The substeps (5 to 7) run here, on
/// the objects, unless the step plan sends them to the fast path
/// (src/fast/fast_path.hpp), which computes the same numbers, bit for bit.
void World::stepWithSequentialImpulses() {
    const Real h = settings_.timeStep;
    const Real hs = h / Real(settings_.substeps);
    const SceneForces sceneForces{settings_.gravity, springs_, attractors_, regionForces(hs)};  // gravity, springs, attractors, regions
    const AccelerationFunction forces = std::cref(sceneForces);  // by reference: no allocation per step
    const ContactSolverSettings contactSettings = makeContactSolverSettings(settings_, hs);
    const JointSolverSettings jointSettings = jointSolverSettings(settings_, hs);

    // 1. Forces → accelerations (src/forces/apply_forces.cpp); again at every substep when
    //    springs or attractors make them depend on where the bodies are (step_plan.hpp).
    //    How far each body can move this step sets how far ahead contacts are looked for.
    runStage(Stage::ApplyForces, [&] {
        regionMembers_.start.clear();  // who is inside is found after the broadphase (1b)
        forces(dynamics_);
        measureSweeps(h);
        if (settings_.continuousCollision) recordStartPositions(bodies(), sweepWorkspace_);  // for stage 7b
    });

    // 2. Which pairs might touch? Sleepers against static objects cannot, jointed bodies do not.
    //    (src/collision/broadphase.cpp → broadphase_*.cpp, src/dynamics/islands.cpp, src/dynamics/joints/joint.cpp)
    runStage(Stage::Broadphase, [&] {
        broadphase_.findPairs(settings_.broadphase, bodies(), pairs_);
        if (asleep_ > 0) dropSleepingPairs(bodies(), pairs_);
        // What a joint holds does not collide (joint.hpp)
        if (plan_.jointSolver.runs) dropJointedPairs(joints_, jointWorkspace_, pairs_);
    });

    // 1b. The regions' pushes: who is inside each, asked of the broadphase, and what the region does
    //     to them (src/world/world_regions.cpp, src/forces/region.cpp). The bodies have not moved
    //     since stage 1, so these add to its accelerations what a full evaluation would.
    if (plan_.regions.runs) {
        runStage(Stage::ApplyForces, [&] {
            findRegionMembers(plan_.runs(Stage::Broadphase));  // a scene that cannot collide keeps no structure
            applyRegions(dynamics_, sceneForces.regions);
        });
    }

    // 3. Which of them touch, or are about to (src/collision/narrowphase.cpp → *_*.cpp)
    runStage(Stage::Narrowphase, [&] {
        widenSweepsByKnocks();
        findContacts(bodies(), pairs_, contacts_, settings_.continuousCollision, kSpeculativeDistance, *threadPool_,
                     narrowphaseWorkspace_, settings_.narrowphase);
    });

    const SubstepRuleInputs ruleInputs{settings_.substeps, settings_.velocityIterations, h, settings_.integrator,
                                       settings_.contactHertz};
    bool perIsland = false;  // some island runs fewer than Substeps this step

    // 4. Prepare: contacts and joints → constraints; an awake body wakes the islands it touches
    //    (src/dynamics/prepare_contacts.cpp, src/dynamics/joints/joint.cpp, src/dynamics/islands.cpp)
    runStage(Stage::PrepareConstraints, [&] {
        if (asleep_ > 0) wakeTouchedIslands(bodies(), contacts_, links_);
        solverWorkspace_.colourOrder = settings_.contactOrder == ContactOrder::Colours;
        prepareContacts(bodies(), contacts_, links_, h, settings_.warmStarting, solverWorkspace_, threadPool_.get(),
                        beltVelocities());  // a conveyor's belt: friction's target (src/forces/conveyor.hpp)
        // A joint's or a spring's anchor on a ball turns with it; nothing else inside a step reads how a ball is turned
        solverWorkspace_.ballsTurnOnce = links_.empty() && springs_.empty();
        if (plan_.jointSolver.runs) prepareJoints(bodies(), joints_, settings_.warmStarting, jointWorkspace_);
        // Each island's substeps, from this step's contacts and the joints (src/dynamics/substep_rule.hpp)
        islandRuleRan_ = plan_.islandSubsteps.runs;
        perIsland = islandRuleRan_ && chooseIslandSubsteps(bodies(), contacts_, links_, ruleInputs, substepGroups_);
        if (perIsland) splitSolverWork(solverWorkspace_, substepGroups_);
    });

    // 5–7. The substeps: integrate, warm start, solve, move, relax.
    //      The fast path runs them with the same numbers (src/fast/); with an observer the plain loop does,
    //      so that what a student watches is the textbook step.
    //      With an island given fewer than Substeps, each group of islands runs its own count (runIslandGroups()).
    if (perIsland) {
        runIslandGroups(forces, jointSettings);
    } else if (plan_.fastPath.runs && observer_ == nullptr) {
        runFastPath(forces, contactSettings, jointSettings);
    } else {
        for (int substep = 0; substep < settings_.substeps; ++substep) {
            substep_ = substep;  // for the observer's StageEvent
            // 5. Free flight for h_s (src/integrators/*.cpp, src/dynamics/kinematic_motion.cpp)
            if (substep > 0 && plan_.substepForces.runs) runStage(Stage::ApplyForces, [&] { forces(dynamics_); });
            // 5a. Soft bodies, one substep beside the rigid ones (src/soft/soft_step.cpp): springs, gas, nodes
            //     moved and pushed out of the rigid objects. A node's push on a dynamic body is a velocity,
            //     like a kick of the integrator: the body moves with it in this substep, and the solve holds
            //     it against the body's own contacts, so a box on a ball and a box under one both end at rest.
            runStage(Stage::SoftBodies, [&] { stepSoftBodies(hs, substep == 0); });
            runStage(Stage::Integrate, [&] {
                recordPoses(bodies(), solverWorkspace_);  // the solve measures separations from before the flight
                integrateBodies(settings_.integrator, dynamics_, hs, forces);
            });
            runStage(Stage::MoveKinematics, [&] { moveKinematics(kinematics_, hs); });

            // 6. Warm start, solve (joints, then contacts, in each pass), and move each body by what the solve
            //    changed (src/dynamics/warm_start_contacts.cpp, solve_contacts.cpp, joints/, velocity_change_drift.cpp)
            runStage(Stage::SolveConstraints, [&] {
                warmStart(substep);
                for (int pass = 0; pass < settings_.velocityIterations; ++pass) solvePass(contactSettings, jointSettings, true);
                driftByVelocityChange(solverWorkspace_, hs, settings_.integrator, substep + 1 == settings_.substeps);
            });

            // 7. Relax: the same passes without the push-out bias, so the push-out leaves no speed behind
            //    (contact_solver.hpp, "Position error without energy"). The separations are measured where
            //    the drift left the bodies; the kinematic ones are recorded here.
            runStage(Stage::RelaxConstraints, [&] {
                recordKinematicPoses(bodies(), solverWorkspace_);
                for (int pass = 0; pass < settings_.relaxIterations; ++pass) solvePass(contactSettings, jointSettings, false);
                copyVelocitiesOut(solverWorkspace_);
            });
        }
        substep_ = -1;
    }

    // 7b. A body that moved farther than its half-thickness, through a wall no contact of this
    //     step held, goes back to where its path first touched it (src/collision/continuous.cpp)
    if (settings_.continuousCollision) {
        runStage(Stage::Continuous, [&] {
            // A jointed pair is not swept against each other, as it is not collided (dropJointedPairs())
            sweepWorkspace_.unsweptPairs = plan_.jointSolver.runs ? std::span<const std::uint64_t>(jointWorkspace_.jointedPairs)
                                                                  : std::span<const std::uint64_t>();
            stopFastBodiesAtImpact(bodies(), sweepWorkspace_);
        });
    }

    // 8. Bounces, once per step, from the approach speed at touch (src/dynamics/restitution.cpp);
    //    the impulses kept for the next step's warm start; joints that pulled harder than their
    //    MaxForce break (src/dynamics/joints/joint.cpp)
    runStage(Stage::Restitution, [&] {
        // The last relax left the solver bodies' velocities and the objects' the same (the continuous
        // stage moves positions only): only a bounce changes them, and then they go out.
        if (applyRestitution(solverWorkspace_, threadPool_.get())) copyVelocitiesOut(solverWorkspace_);
        impulses_.resize(contacts_.size());
        storeContactImpulses(contacts_, solverWorkspace_, impulses_);
        if (plan_.jointSolver.runs) finishJoints(jointWorkspace_, joints_, hs, stepCount_ + 1, time_ + h, links_);
    });

    // 9. Islands at rest fall asleep (src/dynamics/islands.cpp)
    if (settings_.sleeping) {
        runStage(Stage::Sleep, [&] { asleep_ = updateSleep(bodies(), contacts_, links_, settings_, islandWorkspace_); });
    }

    // 10. Bodies that ended the step in a Kill region leave the world (src/world/world_regions.cpp)
    if (plan_.killRegions.runs) removeKilledBodies();
}

/// Stages 5–7 for each group of islands that share a count n (src/dynamics/substep_rule.hpp): the
/// plain loop above with h_s = h/n, on the group's bodies, solver records and contacts alone.
///
/// The groups share no body and no contact, and each stage of a substep reads only the state of
/// the bodies its group holds (and the kinematic bodies and planes, which do not move in a scene
/// the rule runs in: step_plan.hpp), so running one group's substeps after another's gives what
/// running them side by side would. Within a group every list keeps the order of the whole step's,
/// so an island given the full count computes the numbers of `SubstepsPerIsland=false`.
///
/// Every island a joint holds is in the group at the full count (substep_rule.hpp): that group runs
/// the joint passes too, and warm-starts every substep from the impulses, as warmStart() does with joints.
void World::runIslandGroups(const AccelerationFunction& forces, const JointSolverSettings& jointSettings) {
    const Real h = settings_.timeStep;
    SubstepGroups& g = substepGroups_;
    SolverWorkspace& w = solverWorkspace_;
    // The whole step's pass lists are set aside; each group's slice stands in for them in turn
    std::swap(w.roundContacts, g.allRound);
    std::swap(w.otherContacts, g.allOther);
    for (std::size_t group = 0; group < g.counts.size(); ++group) {
        const int count = g.counts[group];
        const Real hs = h / Real(count);
        // The contact frequency is capped at a quarter of this group's substep rate (contactHertzInUse())
        WorldSettings groupSettings = settings_;
        groupSettings.substeps = count;
        const ContactSolverSettings contactSettings = makeContactSolverSettings(groupSettings, hs);
        const std::span<const std::uint32_t> groupBodies = groupSlice(g.groupBodies, g.bodyStart, group);
        const std::span<const std::uint32_t> records = groupSlice(g.groupRecords, g.recordStart, group);
        const std::span<const std::uint32_t> round = groupSlice(g.groupRound, g.roundStart, group);
        const std::span<const std::uint32_t> other = groupSlice(g.groupOther, g.otherStart, group);
        w.roundContacts.assign(round.begin(), round.end());
        w.otherContacts.assign(other.begin(), other.end());
        groupSubsteps_ = count;
        const bool joints = plan_.jointSolver.runs && !jointWorkspace_.joints.empty() && count == settings_.substeps;
        for (int substep = 0; substep < count; ++substep) {
            substep_ = substep;
            runStage(Stage::Integrate, [&] {
                recordPoses(bodies(), w, groupBodies);
                for (const std::uint32_t i : groupBodies) {
                    integrateBodies(settings_.integrator, std::span(&dynamics_[i], 1), hs, forces);
                }
            });
            runStage(Stage::SolveConstraints, [&] {
                if (substep > 0 && !joints) {  // the plan runs the rule only with accumulated impulses
                    warmStartFromLastSubstep(w, records);
                } else {
                    recordSubstepStart(w, records);
                    if (joints) warmStartJoints(jointWorkspace_, w.poses);
                    copyVelocitiesIn(w, records);
                    warmStartContacts(w, settings_.accumulateImpulses);
                }
                for (int pass = 0; pass < settings_.velocityIterations; ++pass) {
                    if (joints) solveJointsBetweenContactPasses(jointWorkspace_, w, records, jointSettings, true);
                    solveContacts(w, contactSettings, true);
                }
                driftByVelocityChange(w, records, hs, settings_.integrator, substep + 1 == count);
            });
            runStage(Stage::RelaxConstraints, [&] {
                recordKinematicPoses(bodies(), w);
                for (int pass = 0; pass < settings_.relaxIterations; ++pass) {
                    if (joints) solveJointsBetweenContactPasses(jointWorkspace_, w, records, jointSettings, false);
                    solveContacts(w, contactSettings, false);
                }
                copyVelocitiesOut(w, records);
            });
        }
    }
    std::swap(w.roundContacts, g.allRound);
    std::swap(w.otherContacts, g.allOther);
    substep_ = -1;
    groupSubsteps_ = 0;
}

/// The warm start of a substep: the impulses the constraints ended the last substep (or step) with,
/// applied again before the first pass, so the passes start near the answer (Catto, GDC 2005).
///
/// From the second substep on, when only the contacts acted (no joints) and the impulses are
/// accumulated, the warm start is the velocity change the contact passes made in the last substep,
/// added per body (warmStartFromLastSubstep(), contact_solver.hpp says why it is the same sum).
/// Otherwise each constraint applies its impulses: the joints on the objects, the contacts on
/// the solver bodies' copies of the velocities, copied in first.
void World::warmStart(int substep) {
    if (substep > 0 && settings_.accumulateImpulses && jointWorkspace_.joints.empty()) {
        warmStartFromLastSubstep(solverWorkspace_);
        return;
    }
    recordSubstepStart(solverWorkspace_);  // what the drift measures Δv from
    if (plan_.jointSolver.runs) warmStartJoints(jointWorkspace_, solverWorkspace_.poses);
    copyVelocitiesIn(solverWorkspace_);
    warmStartContacts(solverWorkspace_, settings_.accumulateImpulses);
}

/// One Gauss–Seidel pass over every constraint: the joints (on the objects), then the contacts
/// (on the solver bodies); @p useBias true for the solve, false for the relax.
void World::solvePass(const ContactSolverSettings& contactSettings, const JointSolverSettings& jointSettings,
                      bool useBias) {
    if (plan_.jointSolver.runs) solveJointsBetweenContactPasses(jointWorkspace_, solverWorkspace_, jointSettings, useBias);
    solveContacts(solverWorkspace_, contactSettings, useBias);
}

/// Stages 5–7 on the fast path (src/fast/fast_path.hpp): the one call into it, with what it needs.
void World::runFastPath(const AccelerationFunction& forces, const ContactSolverSettings& contactSettings,
                        const JointSolverSettings& jointSettings) {
    const FastSubsteps step{.dynamics = dynamics_,
                            .kinematics = kinematics_,
                            .planes = planes_,
                            .contacts = solverWorkspace_,
                            .joints = jointWorkspace_,
                            .forces = forces,
                            .integrator = settings_.integrator,
                            .substeps = settings_.substeps,
                            .velocityIterations = settings_.velocityIterations,
                            .relaxIterations = settings_.relaxIterations,
                            .accumulateImpulses = settings_.accumulateImpulses,
                            .contactSettings = contactSettings,
                            .jointSettings = jointSettings,
                            .forcesEverySubstep = plan_.substepForces.runs,
                            .moveKinematics = plan_.runs(Stage::MoveKinematics),
                            .jointSolver = plan_.jointSolver.runs,
                            .canTurn = plan_.rotation.runs,
                            .packedSubsteps = plan_.packedSubsteps.runs,
                            .records = stageRecords_,
                            .pool = *threadPool_,
                            .step = stepCount_ + 1,
                            .time = static_cast<double>(time_)};
    runFastSubsteps(step, *fastWorkspace_);
}

/// The soft bodies' stage (src/soft/soft_step.hpp): one soft substep of @p h.
/// Under the sequential impulse it runs once at the start of every substep (stage 5a), so that the
/// rigid bodies move with the nodes' pushes and their solve holds them; under Impulse, once after
/// the step's collisions are repaired. A node pushes a dynamic body with an equal and opposite impulse.
///
/// An asleep soft body is not stepped, so it finds no contact of its own: at the step's first call
/// (@p startsStep), every one that an awake object may reach in this step wakes with its island; after
/// each call, every asleep rigid body that an awake soft body's nodes touched (and pushed) wakes with
/// its island (src/dynamics/islands.hpp).
void World::stepSoftBodies(Real h, bool startsStep) {
    SoftStepSettings soft;
    soft.gravity = settings_.gravity;
    soft.integrator = settings_.integrator;
    soft.timeStep = h;
    soft.startsStep = startsStep;
    soft.where = {Stage::SoftBodies, stepCount_ + 1, static_cast<double>(time_)};
    if (settings_.sleeping && startsStep) wakeSoftBodiesInReach(bodies(), settings_.timeStep, settings_.gravity);
    stepwise::stepSoftBodies(softBodies_, bodies(), soft);
    if (settings_.sleeping) wakeTouchedBySoftBodies(bodies());
}

FastPathCounts World::fastPathCounts() const { return fastWorkspace_->counts; }

SolverFootprint World::solverFootprint() const {
    return plan_.fastPath.runs ? fastFootprint(solverWorkspace_, *fastWorkspace_) : stepwise::solverFootprint(solverWorkspace_);
}

template <class StageBody>
void World::runStage(Stage stage, StageBody&& body) {
    if (!plan_.runs(stage)) return;  // the step plan skips what this scene cannot need (step_plan.hpp)
    StageEvent event;
    if (observer_) {
        event.stage = stage;
        event.step = stepCount_ + 1;
        event.substep = substep_;
        event.substeps = groupSubsteps_ > 0                                  ? groupSubsteps_
                         : settings_.solver == SolverKind::SequentialImpulse ? settings_.substeps
                                                                             : 1;
        event.stepStartTime = time_;
        event.timeStep = settings_.timeStep;
        observer_->beforeStage(event, *this);
    }
    timeStage(stageRecords_, stage, body);
    checkFinite(stage);
    if (observer_) observer_->afterStage(event, *this);
}

void StepObserver::beforeStage(const StageEvent&, const World&) {}
void StepObserver::afterStage(const StageEvent&, const World&) {}
void StepObserver::afterStep(const World&) {}

/// Every number the stage may have written into a body is finite, or the step stops naming the
/// body, the quantity, the stage and the step (objects/finite_state.hpp).
///
/// The solve, the relax and the bounce move only the bodies with a solver record, those in a
/// contact or a joint (prepareContacts()): only those are read after them, so a stage is never
/// named for a number it did not write.
void World::checkFinite(Stage stage) const {
    const StageAtStep where{stage, stepCount_ + 1, static_cast<double>(time_)};  // step 1 is the first
    const unsigned parts = statePartsWrittenBy(stage, settings_.integrator);
    const bool constraintStage = settings_.solver == SolverKind::SequentialImpulse &&
                                 (stage == Stage::SolveConstraints || stage == Stage::RelaxConstraints ||
                                  stage == Stage::Restitution);
    const std::vector<std::uint32_t>& recordBody = solverWorkspace_.recordBody;
    if (constraintStage && !recordBody.empty()) {
        requireFiniteState(dynamics_, std::span(recordBody).subspan(1), parts, where);  // record 0 is the static body
    } else {
        requireFiniteState(dynamics_, parts, where);
    }
    requireFiniteState(kinematics_, where);
}

}  // namespace stepwise
