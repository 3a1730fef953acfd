/// @file world.cpp
/// @brief The step pipeline, read top to bottom in World::step().
#include "world/world.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "collision/narrowphase.hpp"
#include "core/errors.hpp"
#include "objects/inertia.hpp"
#include "dynamics/islands.hpp"
#include "forces/apply_forces.hpp"
#include "integrators/integrators.hpp"

namespace stepwise {

namespace {

void require(bool condition, const std::string& object, const std::string& what) {
    if (!condition) throw std::invalid_argument("object '" + object + "': " + what);
}

bool isFinite(Real x) { return std::isfinite(x); }

/// The parts of a dynamic body's state a stage may write. checkFinite() reads
/// only those after the stage: a stage that sets forces, or only velocities,
/// does not pay for reading the whole body, which at 64k bodies is tens of
/// megabytes several times a substep. A stage that writes a quantity outside
/// its set would have a non-finite value named late, never missed: a non-finite
/// force reaches the velocity at the next integrate, and the stages that run
/// once a step check everything.
enum StateParts : unsigned {
    kPose = 1u << 0,    ///< position, orientation
    kMotion = 1u << 1,  ///< velocity, angular velocity, angular momentum
    kForces = 1u << 2,  ///< acceleration, torque
    kEverything = kPose | kMotion | kForces,
};

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
        default: return kEverything;  // the once-a-step stages
    }
}

/// Bodies integrated between two finite probes in World::integrate(): 32 objects of
/// 400 bytes are 12.8 kB, well inside a 32 kB L1 data cache.
constexpr std::size_t kIntegrateBlock = 32;

/// Zero exactly when the @p parts of the body's state are finite. checkFinite()
/// runs after every stage, several times per substep, so it first takes this
/// branch-free sum and searches component by component only when it fails.
Real finiteProbe(const DynamicObject& body, unsigned parts) {
    Real probe = 0;
    if (parts & kPose) probe += zeroIfFinite(body.position) + zeroIfFinite(body.orientation);
    if (parts & kMotion) {
        probe += zeroIfFinite(body.velocity) + zeroIfFinite(body.angularVelocity) + zeroIfFinite(body.angularMomentum);
    }
    if (parts & kForces) probe += zeroIfFinite(body.acceleration) + zeroIfFinite(body.torque);
    return probe;
}

/// The same probe over the contact solver's packed copies: each record's v and
/// ω, and (with kPose in @p parts) the pose the drift recorded for its body.
/// After the solve and relax stages these are the numbers just written to the
/// objects, and the records are the only bodies those stages move
/// (prepareContacts()), so the check reads two contiguous arrays instead of
/// every object. (The angular momentum is I·ω for a ball and L + I·Δω for a box, with
/// a finite ω: the next stage that checks it, integrate or restitution, names it if it
/// overflowed.)
/// On the packed substeps (@p packed) the poses are the records' own centres,
/// orientations and summed turns (World::substepOnRecords()).
Real finiteProbe(const SolverWorkspace& workspace, unsigned parts, bool packed) {
    Real probe = 0;
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) {
        const SolverBody& record = workspace.bodies[i];
        probe += zeroIfFinite(record.velocity) + zeroIfFinite(record.angularVelocity);
        if ((parts & kPose) && packed) {
            probe += zeroIfFinite(workspace.centres[i].position) + zeroIfFinite(workspace.turnSums[i].sum) +
                     zeroIfFinite(workspace.orientations[i]);
        } else if (parts & kPose) {
            const Pose& pose = workspace.poses[workspace.recordBody[i]];
            probe += zeroIfFinite(pose.position) + zeroIfFinite(pose.orientation);
        }
    }
    return probe;
}

}  // namespace

World::World(Scene scene)
    : settings_(scene.settings),
      dynamics_(std::move(scene.dynamics)),
      kinematics_(std::move(scene.kinematics)),
      planes_(std::move(scene.planes)),
      springs_(std::move(scene.springs)),
      attractors_(std::move(scene.attractors)) {
    require(isFinite(settings_.timeStep) && settings_.timeStep > 0, "World", "time step must be > 0 s");
    require(stepwise::isFinite(settings_.gravity), "World", "gravity must be finite");
    require(settings_.impulseIterations >= 1, "World", "impulse iterations must be at least 1");
    require(settings_.substeps >= 1, "World", "substeps must be at least 1");
    require(settings_.velocityIterations >= 1, "World", "iterations must be at least 1");
    require(settings_.relaxIterations >= 0, "World", "relax iterations must not be negative");
    require(settings_.threads >= 0, "World", "threads must not be negative (0: one per hardware thread)");
    threadPool_ = std::make_unique<ThreadPool>(settings_.threads == kAutoThreads ? autoThreadCount()
                                                                                 : static_cast<unsigned>(settings_.threads));
    for (DynamicObject& body : dynamics_) {
        require(isFinite(body.mass) && body.mass > 0, body.name, "mass must be > 0 kg");
        require(isFinite(body.radius) && body.radius > 0, body.name, "radius must be > 0 m");
        require(stepwise::isFinite(body.position) && stepwise::isFinite(body.velocity), body.name,
                "position and velocity must be finite");
        body.inverseMass = Real(1) / body.mass;
        initialiseMassProperties(body);
    }
    for (CollisionPlane& plane : planes_) {
        const Real length = glm::length(plane.normal);
        require(isFinite(length) && length > 0, plane.name, "plane normal must not be zero");
        plane.normal /= length;
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
    joints_ = makeJoints(scene.joints, dynamics_, settings_.solver);  // src/dynamics/joints/joint.cpp
    jointLinks(joints_, links_);
    replan();
}

/// The step plan from what the World holds now (src/world/step_plan.cpp); it allocates nothing.
void World::replan() {
    plan_ = makeStepPlan({settings_, dynamics_, kinematics_, planes_, springs_, attractors_, joints_});
    asleep_ = 0;
    for (DynamicObject& body : dynamics_) {
        body.canTurn = plan_.rotation.runs;  // read by the integrators
        if (body.asleep) ++asleep_;
    }
    planStale_ = false;
}

/// Nothing can change this step: no dynamic body is awake (a sleeper is only
/// woken by an awake body or a moving kinematic one) and no kinematic body moves.
bool World::idle() const {
    for (const DynamicObject& body : dynamics_) {
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

BodySet World::bodies() { return {dynamics_, kinematics_, planes_}; }

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

/// Runs @p move over the runs of dynamic bodies that @p picks, each run at most
/// kIntegrateBlock long (with every body picked: the objects in blocks), and
/// probes each run for non-finite numbers straight after, while it is still
/// in cache; true when all were finite.
template <class Picks, class Move>
bool World::inProbedObjectRuns(Picks&& picks, Move&& move) {
    const std::span<DynamicObject> all(dynamics_);
    Real probe = 0;
    for (std::size_t first = 0; first < all.size();) {
        if (!picks(first)) {
            ++first;
            continue;
        }
        std::size_t end = first + 1;
        while (end < all.size() && end - first < kIntegrateBlock && picks(end)) ++end;
        const std::span<DynamicObject> run = all.subspan(first, end - first);
        move(run);
        for (const DynamicObject& body : run) probe += finiteProbe(body, kPose | kMotion);
        first = end;
    }
    return probe == Real(0);
}

/// Advances the dynamic bodies by h with the scene's integrator.
///
/// The Euler integrators move each body by itself, so they run over blocks of
/// kIntegrateBlock bodies, and each block is probed for non-finite numbers
/// (finiteProbe()) straight after, while its bodies are still in the L1 cache.
/// Checking afterwards would read every body again: at 64k bodies of 400 bytes
/// that is 26 MB from main memory per substep, a tenth of the step's time in
/// the 64k sphere rain (bench/solver_performance.md, ninth round). Verlet
/// evaluates the forces of all bodies at once between its two half kicks
/// (springs join bodies anywhere in the array), so it runs whole and
/// checkFinite() reads the bodies afterwards as for any other stage.
void World::integrate(Real h, const AccelerationFunction& forces) {
    integratedFinite_ = false;
    if (settings_.integrator == IntegratorKind::Verlet) {
        integrateVerlet(dynamics_, h, forces);
        return;
    }
    const auto everyBody = [](std::size_t) { return true; };
    integratedFinite_ = inProbedObjectRuns(everyBody, [&](std::span<DynamicObject> block) {
        if (settings_.integrator == IntegratorKind::ExplicitEuler) {
            integrateExplicitEuler(block, h);
        } else {
            integrateSymplecticEuler(block, h);
        }
    });
}

/// Symplectic Euler for h over the bodies without a solver record, in runs
/// probed as they go: on the packed substeps the balls with a record are
/// kicked on their records instead (substepOnRecords()).
void World::integrateBodiesWithoutRecord(Real h) {
    const std::vector<std::uint32_t>& recordOf = solverWorkspace_.bodyRecord;
    integratedFinite_ = inProbedObjectRuns([&](std::size_t i) { return recordOf[i] == kStaticSolverBody; },
                                           [&](std::span<DynamicObject> run) { integrateSymplecticEuler(run, h); });
}

/// `Solver=Impulse`, the foundation's step: move, then find and repair the
/// collisions the move made. Each line is one stage, in its own file.
void World::stepWithImpulses() {
    const Real h = settings_.timeStep;
    const SceneForces sceneForces{settings_.gravity, springs_, attractors_};  // gravity, springs, attractors
    const AccelerationFunction forces = std::cref(sceneForces);  // by reference: no allocation per step

    // 1. Forces → accelerations (src/forces/apply_forces.cpp)
    runStage(Stage::ApplyForces, [&] { forces(dynamics_); });

    // 2. Advance dynamic bodies by h (src/integrators/*.cpp)
    runStage(Stage::Integrate, [&] {
        if (settings_.continuousCollision) recordStartPositions(bodies(), sweepWorkspace_);  // for stage 3b
        integrate(h, forces);
    });

    // 3. Advance kinematic bodies along their prescribed motion (src/integrators/kinematic_motion.cpp)
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
                     narrowphaseWorkspace_);
    });

    // 6. Impulses: bounce and friction change velocities (src/dynamics/impulse_resolver.cpp)
    runStage(Stage::ResolveImpulses, [&] {
        impulses_.resize(contacts_.size());
        resolveImpulses(bodies(), contacts_, h, settings_.impulseIterations, settings_.warmStarting, contactWorkspace_,
                        impulses_);
    });

    // 7. Push overlapping bodies apart (src/dynamics/impulse_resolver.cpp, correctPositions)
    const Real supportStep = positionShareOfVelocityChange(settings_.integrator) * h;
    runStage(Stage::CorrectPositions, [&] { correctPositions(bodies(), contacts_, h, supportStep, contactWorkspace_); });
}

/// Sweep = |v|·h + ½|a|·h²: the distance free flight can carry a body in a
/// step (for a kinematic body, plus what its turning moves its farthest point).
///
/// A plane's sweep is the largest of the bodies' (GameObject::sweep). Contacts
/// are found once a step, from how far each body can move by itself; but a
/// body can be knocked within the step, and a collision passes its speed on
/// (a ball struck by an equal ball takes up to the striker's speed). A ball
/// at rest 2 cm from a wall, struck at 3 m/s, would cross those 2 cm and sink
/// into the wall before the next step found the contact: in the 16k sphere
/// rain such a knock left a ball 10.6 mm inside a wall (bench/solver_performance.md,
/// eighth round). Walls are few and a contact with a gap costs nothing until
/// it closes, so every body gets its plane contacts that far ahead.
void World::measureSweeps(Real h) {
    Real fastest = 0;
    for (DynamicObject& body : dynamics_) {
        body.sweep = body.asleep ? Real(0)
                                 : glm::length(body.velocity) * h + Real(0.5) * glm::length(body.acceleration) * h * h;
        fastest = std::max(fastest, body.sweep);
    }
    for (KinematicsObject& body : kinematics_) {
        const Real reach = body.shape == Shape::Sphere ? body.radius : glm::length(body.halfExtents());
        body.sweep = (glm::length(body.velocity) + glm::length(body.angularVelocity) * reach) * h;
        fastest = std::max(fastest, body.sweep);
    }
    for (CollisionPlane& plane : planes_) plane.sweep = fastest;
}

/// `Solver=SequentialImpulse`, Catto's soft step: find the contacts first,
/// then hold them (and the joints) through `substeps` short substeps.
void World::stepWithSequentialImpulses() {
    const Real h = settings_.timeStep;
    const Real hs = h / Real(settings_.substeps);
    const SceneForces sceneForces{settings_.gravity, springs_, attractors_};  // gravity, springs, attractors
    const AccelerationFunction forces = std::cref(sceneForces);  // by reference: no allocation per step
    ContactSolverSettings contactSettings;
    contactSettings.substep = hs;
    contactSettings.accumulate = settings_.accumulateImpulses;
    contactSettings.positionCorrection = settings_.positionCorrection;
    contactSettings.relaxBallFriction = settings_.relaxBallFriction;
    contactSettings.softness = makeSoftness(contactHertzInUse(settings_),
                                            settings_.contactDampingRatio, hs);
    const JointSolverSettings jointSettings = jointSolverSettings(settings_, hs);

    // 1. Forces → accelerations (src/forces/apply_forces.cpp); again at every substep when
    //    springs or attractors make them depend on where the bodies are (step_plan.hpp).
    //    How far each body can move this step sets how far ahead contacts are looked for.
    runStage(Stage::ApplyForces, [&] {
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

    // 3. Which of them touch, or are about to (src/collision/narrowphase.cpp → *_*.cpp)
    runStage(Stage::Narrowphase, [&] {
        findContacts(bodies(), pairs_, contacts_, settings_.continuousCollision, kSpeculativeDistance, *threadPool_,
                     narrowphaseWorkspace_);
    });

    // 4. Contacts and joints → constraints; an awake body wakes the islands it touches
    //    (src/dynamics/contact_solver.cpp, src/dynamics/joints/joint.cpp, src/dynamics/islands.cpp).
    //    When every contact holds balls, they are packed into the solver's records for the substeps
    //    (step_plan.hpp, "packed substeps"); an observer looks at the objects, so then they are not.
    substepsOnRecords_ = false;
    runStage(Stage::PrepareConstraints, [&] {
        if (asleep_ > 0) wakeTouchedIslands(bodies(), contacts_, links_);
        prepareContacts(bodies(), contacts_, links_, h, settings_.warmStarting, solverWorkspace_);
        // A joint's or a spring's anchor on a ball turns with it; nothing else inside a step reads how a ball is turned
        solverWorkspace_.ballsTurnOnce = links_.empty() && springs_.empty();
        if (plan_.jointSolver.runs) prepareJoints(bodies(), joints_, settings_.warmStarting, jointWorkspace_);
        substepsOnRecords_ = plan_.packedSubsteps.runs && observer_ == nullptr && packRecords(solverWorkspace_);
    });

    // 5–7. The substeps: on the packed records (substepOnRecords(), below: the same operations on
    //      other arrays), or on the objects, here.
    if (substepsOnRecords_) substepOnRecords(hs, contactSettings);
    for (int substep = 0; substep < (substepsOnRecords_ ? 0 : settings_.substeps); ++substep) {
        substep_ = substep;  // for the observer's StageEvent
        // 5. Free flight for h_s (src/integrators/*.cpp, kinematic_motion.cpp)
        if (substep > 0 && plan_.substepForces.runs) runStage(Stage::ApplyForces, [&] { forces(dynamics_); });
        runStage(Stage::Integrate, [&] {
            // The solve measures separations from here (nothing to measure when it is skipped). From the
            // second substep on, the last relax recorded these very poses: nothing has moved since.
            const bool posesCurrent = substep > 0 && plan_.runs(Stage::RelaxConstraints);
            if (plan_.runs(Stage::SolveConstraints) && !posesCurrent) recordPoses(bodies(), solverWorkspace_);
            integrate(hs, forces);
        });
        runStage(Stage::MoveKinematics, [&] { moveKinematics(kinematics_, hs); });

        // 6. Warm start, soft solve (joints first, then contacts), and move by what the solve changed
        //    (src/dynamics/joints/*.cpp, src/dynamics/contact_solver.cpp, src/integrators/velocity_change_drift.cpp)
        //    The contact passes work on packed copies of the velocities (src/dynamics/solver_body.hpp),
        //    the joints and the drift on the objects: copied in before, out after.
        runStage(Stage::SolveConstraints, [&] {
            // From the second substep on, the warm start is what the contacts did in the last one (no joints)
            if (substep > 0 && settings_.accumulateImpulses && jointWorkspace_.joints.empty()) {
                warmStartFromLastSubstep(solverWorkspace_);
            } else {
                recordSubstepStart(solverWorkspace_);  // what the drift measures Δv from
                if (plan_.jointSolver.runs) warmStartJoints(jointWorkspace_, solverWorkspace_.poses);
                copyVelocitiesIn(solverWorkspace_);
                warmStartContacts(solverWorkspace_, settings_.accumulateImpulses);
            }
            for (int pass = 0; pass < settings_.velocityIterations; ++pass) {
                if (plan_.jointSolver.runs) solveJointsBetweenContactPasses(jointSettings, true);
                solveContacts(solverWorkspace_, contactSettings, true);
            }
            // The velocities back to the objects, each body moved by what they gained, its pose recorded
            driftByVelocityChange(solverWorkspace_, hs, settings_.integrator, substep + 1 == settings_.substeps);
        });

        // 7. Relax: the same passes without the push-out bias, so the push-out leaves no speed behind
        //    (a ball's contacts: their normal rows; contact_solver.hpp, "Friction in the relax").
        //    The drift moved the bodies but left their velocities alone: the copies are still current.
        runStage(Stage::RelaxConstraints, [&] {
            recordKinematicPoses(bodies(), solverWorkspace_);  // the drift recorded the dynamic bodies' poses
            for (int pass = 0; pass < settings_.relaxIterations; ++pass) {
                if (plan_.jointSolver.runs) solveJointsBetweenContactPasses(jointSettings, false);
                solveContacts(solverWorkspace_, contactSettings, false);
            }
            copyVelocitiesOut(solverWorkspace_);
        });
    }

    substep_ = -1;
    // 7b. A body that moved farther than its half-thickness, through a wall no contact of this
    //     step held, goes back to where its path first touched it (src/collision/continuous.cpp)
    if (settings_.continuousCollision) {
        runStage(Stage::Continuous, [&] { stopFastBodiesAtImpact(bodies(), sweepWorkspace_); });
    }

    // 8. Bounces, once per step, from the approach speed at touch (src/dynamics/contact_solver.cpp);
    //    joints that pulled harder than their MaxForce break (src/dynamics/joints/joint.cpp)
    runStage(Stage::Restitution, [&] {
        // The records hold the objects' velocities still: the last relax wrote them out, and the
        // continuous stage moves positions only. Only a bounce changes them, so only then do they go out.
        if (applyRestitution(solverWorkspace_)) copyVelocitiesOut(solverWorkspace_);
        impulses_.resize(contacts_.size());
        storeContactImpulses(contacts_, solverWorkspace_, impulses_);
        if (plan_.jointSolver.runs) finishJoints(jointWorkspace_, joints_, hs, stepCount_ + 1, time_ + h, links_);
    });

    // 9. Islands at rest fall asleep (src/dynamics/islands.cpp)
    if (settings_.sleeping) {
        runStage(Stage::Sleep, [&] { asleep_ = updateSleep(bodies(), contacts_, links_, settings_, islandWorkspace_); });
    }
}

/// Stages 5–7 of stepWithSequentialImpulses() for a step whose contacts all
/// hold balls: the same operations, in the same order, on the contact
/// solver's records instead of the objects (step_plan.hpp, "packed substeps";
/// contact_solver.hpp, packRecords()).
///
/// A ball's v and ω stay in its record all step, its centre and orientation
/// in the arrays beside it, so nothing is copied in or out between the
/// passes. Symplectic Euler's two lines are split around the solve: the kick
/// before it (with the warm start from the last substep, which also only adds
/// to v), the move by h·v after it, with the solver's change in the same pass,
/// and the turn in the last substep's (src/integrators/symplectic_euler.cpp,
/// velocity_change_drift.cpp: "A ball turns once a step"). The
/// bodies without a record fly free on their objects. After the last relax
/// the objects get their balls back, and from the bounce on the step goes on
/// as before.
void World::substepOnRecords(Real hs, const ContactSolverSettings& contactSettings) {
    SolverWorkspace& records = solverWorkspace_;
    for (int substep = 0; substep < settings_.substeps; ++substep) {
        substep_ = substep;  // for the observer's StageEvent
        // 5. Free flight: the kick on the records, whole flight for the bodies without one
        runStage(Stage::Integrate, [&] {
            recordsFinite_ = integrateSymplecticEulerOnRecords(records, hs, plan_.rotation.runs, substep == 0) == Real(0);
            integrateBodiesWithoutRecord(hs);
        });
        runStage(Stage::MoveKinematics, [&] { moveKinematics(kinematics_, hs); });

        // 6. Warm start (the first substep: from the contacts; later ones rode along with the kick), soft solve,
        //    and the move by the solved velocities
        runStage(Stage::SolveConstraints, [&] {
            if (substep == 0) warmStartContacts(records, settings_.accumulateImpulses);
            for (int pass = 0; pass < settings_.velocityIterations; ++pass) solveContacts(records, contactSettings, true);
            // The probe after the drift sees the passes' velocities too: the drift does not change them
            recordsFinite_ = driftRecordsByVelocityChange(records, hs, substep + 1 == settings_.substeps) == Real(0);
        });

        // 7. Relax; after the last one the objects get their balls' state back
        runStage(Stage::RelaxConstraints, [&] {
            for (int pass = 0; pass < settings_.relaxIterations; ++pass) solveContacts(records, contactSettings, false);
            if (substep + 1 == settings_.substeps) unpackRecords(records);
        });
    }
}

/// A joint pass works on the objects' velocities, a contact pass on the solver
/// bodies' copies: hand the velocities across around the joints. With no joint
/// acting there is nothing to hand across (and the copies stay as they are,
/// bit for bit, whether or not the step plan skips the joint solver).
void World::solveJointsBetweenContactPasses(const JointSolverSettings& jointSettings, bool useBias) {
    if (jointWorkspace_.joints.empty()) return;
    copyVelocitiesOut(solverWorkspace_);
    solveJoints(jointWorkspace_, solverWorkspace_.poses, jointSettings, useBias);
    copyVelocitiesIn(solverWorkspace_);
}

template <class StageBody>
void World::runStage(Stage stage, StageBody&& body) {
    if (!plan_.runs(stage)) return;  // the step plan skips what this scene cannot need (step_plan.hpp)
    using Clock = std::chrono::steady_clock;
    StageEvent event;
    if (observer_) {
        event.stage = stage;
        event.step = stepCount_ + 1;
        event.substep = substep_;
        event.substeps = settings_.solver == SolverKind::SequentialImpulse ? settings_.substeps : 1;
        event.stepStartTime = time_;
        event.timeStep = settings_.timeStep;
        observer_->beforeStage(event, *this);
    }
    const auto start = Clock::now();
    body();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();

    StageRecord& record = stageRecords_[static_cast<std::size_t>(stage)];
    record.ranLastStep = true;
    record.runs += 1;
    record.lastSeconds += seconds;
    record.totalSeconds += seconds;
    checkFinite(stage);
    if (observer_) {
        syncRoundContacts(solverWorkspace_);  // what solverContacts() shows: the impulses the lanes hold (round_contact_lanes.hpp)
        observer_->afterStage(event, *this);
    }
}

void StepObserver::beforeStage(const StageEvent&, const World&) {}
void StepObserver::afterStage(const StageEvent&, const World&) {}
void StepObserver::afterStep(const World&) {}

void World::checkFinite(Stage stage) const {
    auto fail = [&](const std::string& object, const char* quantity) {
        throw SimulationError(object, stageName(stage), stepCount_, static_cast<double>(time_),
                              std::string("non-finite ") + quantity +
                                  " (check masses, time step and forces in the scene)");
    };
    const unsigned parts = statePartsWrittenBy(stage, settings_.integrator);
    // The solve and relax stages move only the bodies with solver records: their packed copies say whether
    // anything is wrong, and only then are the objects searched, to name it. So does the bounce, which
    // writes the records' velocities to their objects, unless joints are finished there too (finishJoints()
    // sets a jointed body's ω from its L, on the object).
    const bool bounceOnRecords = stage == Stage::Restitution && !plan_.jointSolver.runs;
    const bool solverStage = settings_.solver == SolverKind::SequentialImpulse &&
                             (stage == Stage::SolveConstraints || stage == Stage::RelaxConstraints || bounceOnRecords);
    // On the packed substeps the balls with a record are current in the records, not in their objects,
    // until the last relax (substepOnRecords()): the records are probed (the kick writes only their v
    // and ω), and a record names its object. The other bodies are objects, probed as they flew.
    const bool onRecords = substepsOnRecords_ && substep_ >= 0;
    // The kick and the drift probed the records as they wrote them (their return values, substepOnRecords()).
    const bool probedAsWritten = recordsFinite_ && (stage == Stage::Integrate || stage == Stage::SolveConstraints);
    if (onRecords && parts != 0 && (solverStage || stage == Stage::Integrate) && !probedAsWritten) {
        const SolverWorkspace& w = solverWorkspace_;
        const unsigned recordParts = stage == Stage::Integrate ? unsigned(kMotion) : parts;
        if (finiteProbe(w, recordParts, true) != Real(0)) {
            for (std::size_t i = 1; i < w.bodies.size(); ++i) {
                const std::string& name = dynamics_[w.recordBody[i]].name;
                if (!stepwise::isFinite(w.bodies[i].velocity)) fail(name, "velocity");
                if (!stepwise::isFinite(w.bodies[i].angularVelocity)) fail(name, "angular velocity");
                if ((recordParts & kPose) && !stepwise::isFinite(w.centres[i].position)) fail(name, "position");
                if ((recordParts & kPose) && !(stepwise::isFinite(w.orientations[i]) && stepwise::isFinite(w.turnSums[i].sum))) {
                    fail(name, "orientation");
                }
            }
        }
    }
    // The Euler integrators probed each block of bodies as they moved it (World::integrate()).
    const bool probedWhileIntegrating = stage == Stage::Integrate && integratedFinite_;
    const bool recordsProbed = solverStage && (onRecords || finiteProbe(solverWorkspace_, parts, false) == Real(0));
    if (parts != 0 && !probedWhileIntegrating && !recordsProbed) {
        for (const DynamicObject& body : dynamics_) {
            if (finiteProbe(body, parts) == Real(0)) continue;  // all finite: nothing to name
            if (!stepwise::isFinite(body.position)) fail(body.name, "position");
            if (!stepwise::isFinite(body.velocity)) fail(body.name, "velocity");
            if (!stepwise::isFinite(body.acceleration)) fail(body.name, "acceleration");
            if (!stepwise::isFinite(body.orientation)) fail(body.name, "orientation");
            if (!stepwise::isFinite(body.angularVelocity)) fail(body.name, "angular velocity");
            if (!stepwise::isFinite(body.angularMomentum)) fail(body.name, "angular momentum");
            if (!stepwise::isFinite(body.torque)) fail(body.name, "torque");
        }
    }
    for (const KinematicsObject& body : kinematics_) {
        if (!stepwise::isFinite(body.position)) fail(body.name, "position");
        if (!stepwise::isFinite(body.orientation)) fail(body.name, "orientation");
    }
}

}  // namespace stepwise
