/// @file step_plan.cpp
/// @brief The rules of the step plan (step_plan.hpp): one small function per decision.
#include "world/step_plan.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "collision/broadphase.hpp"
#include "forces/conveyor.hpp"
#include "forces/kill_region.hpp"

namespace stepwise {

namespace {

/// A decision that runs, with its reason.
constexpr PlanDecision run(const char* reason) { return {true, reason}; }
/// A decision that is skipped, with its reason.
constexpr PlanDecision skip(const char* reason) { return {false, reason}; }

/// Two objects, one of them dynamic: the least a contact needs.
PlanDecision collisionsOf(const PlanInputs& in) {
    if (in.dynamics.empty()) return skip("skipped: no dynamic body, and nothing else moves under a contact");
    if (in.dynamics.size() + in.kinematics.size() + in.planes.size() < 2) {
        return skip("skipped: a single body and nothing to hit, so no pair can touch");
    }
    return run("runs: at least one dynamic body and something it can hit");
}

/// Bodies of @p shape among the dynamic and among the kinematic ones.
struct ShapeCount {
    std::size_t dynamic = 0;    ///< Dynamic bodies that match.
    std::size_t kinematic = 0;  ///< Kinematic bodies that match.
    /// Can two matching bodies meet (a contact needs a dynamic body on one side)?
    bool pairPossible() const { return dynamic > 0 && dynamic + kinematic >= 2; }
};

template <class Matches>
ShapeCount countShapes(const PlanInputs& in, Matches matches) {
    ShapeCount count;
    for (const DynamicObject& body : in.dynamics) count.dynamic += matches(body.shape) ? 1 : 0;
    for (const KinematicsObject& body : in.kinematics) count.kinematic += matches(body.shape) ? 1 : 0;
    return count;
}

/// Box–box SAT needs a dynamic box, a second box, and Narrowphase=Auto (GjkEpa and Mpr take box pairs too).
PlanDecision boxBoxSatOf(const PlanInputs& in) {
    const ShapeCount boxes = countShapes(in, [](Shape s) { return s == Shape::Box; });
    const ShapeCount unround = countShapes(in, [](Shape s) { return s != Shape::Sphere; });
    if (boxes.dynamic == 0 && boxes.kinematic == 0) {
        return unround.dynamic + unround.kinematic == 0
                   ? skip("skipped: no boxes in the scene, so no SAT")
                   : skip("skipped: no boxes in the scene; capsules, cylinders, hulls and meshes go through GJK/EPA or MPR");
    }
    if (!boxes.pairPossible()) {
        return skip("skipped: no two boxes can meet (box-box needs a dynamic box and a second box)");
    }
    if (in.settings.narrowphase == NarrowphaseKind::GjkEpa) {
        return skip("skipped: Narrowphase=GjkEpa, so box pairs go through GJK and EPA instead");
    }
    if (in.settings.narrowphase == NarrowphaseKind::Mpr) return skip("skipped: Narrowphase=Mpr, so box pairs go through MPR instead");
    return run("runs: two boxes can meet, and the narrowphase tests their 15 axes");
}

/// Clipping needs two bodies with flat faces or straight edges (anything but a sphere) that can meet.
PlanDecision clippingOf(const PlanInputs& in) {
    const ShapeCount boxes = countShapes(in, [](Shape s) { return s == Shape::Box; });
    const ShapeCount unround = countShapes(in, [](Shape s) { return s != Shape::Sphere; });
    if (unround.dynamic == 0 && unround.kinematic == 0) {
        return skip("skipped: only spheres (and planes), whose contacts are single points: nothing to clip");
    }
    if (!unround.pairPossible()) {
        return skip("skipped: no two bodies with faces or edges can meet, so no face is clipped against another");
    }
    if (boxes.dynamic == unround.dynamic && boxes.kinematic == unround.kinematic) {
        return run("runs: touching boxes clip a face against the other box to find up to 8 points");
    }
    return run("runs: touching faces and edges (boxes, hulls, cylinders, capsules, meshes) are clipped for their points");
}

/// Has a surface of @p body a μ other than 0: its own, or a compound's part with a Material of its own?
template <class Body>
bool hasRoughSurface(const Body& body) {
    if (body.friction != 0) return true;
    if (!body.compound) return false;
    return std::any_of(body.compound->parts.begin(), body.compound->parts.end(),
                       [](const CompoundPart& part) { return part.material != kNoMaterial && part.friction != 0; });
}

/// Can the combined μ be non-zero for some pair that can touch?
bool anyFriction(const PlanInputs& in) {
    // A MaterialPair may give any pair friction: assume one can touch.
    if (in.materials != nullptr && in.materials->hasPairs()) return true;
    std::size_t rough = 0;  // dynamic bodies with μ ≠ 0
    for (const DynamicObject& body : in.dynamics) rough += hasRoughSurface(body) ? 1 : 0;
    // Max and Average give μ > 0 when either side has some: a frictionless ball on a rough floor.
    const bool eitherSide =
        in.settings.frictionCombine == CombineRule::Max || in.settings.frictionCombine == CombineRule::Average;
    if (eitherSide && rough > 0) return true;
    if (eitherSide && !in.dynamics.empty()) {
        for (const KinematicsObject& body : in.kinematics) {
            if (hasRoughSurface(body)) return true;
        }
        for (const CollisionPlane& plane : in.planes) {
            if (plane.friction != 0) return true;
        }
    }
    // Product, Min and GeometricMean are 0 when either side is: one rough side is not enough.
    if (rough == 0) return false;
    if (rough >= 2) return true;  // two rough dynamic bodies can touch each other
    for (const KinematicsObject& body : in.kinematics) {
        if (hasRoughSurface(body)) return true;
    }
    for (const CollisionPlane& plane : in.planes) {
        if (plane.friction != 0) return true;
    }
    return false;  // the one rough body meets only frictionless things: every product is 0
}

/// Rotation is impossible when every force on every body acts through its centre.
PlanDecision rotationOf(const PlanInputs& in) {
    // Only a sphere's contact normals all pass through its centre; every other shape
    // (box, capsule, cylinder, hull, compound) is turned by a push at a corner, edge or side.
    for (const DynamicObject& body : in.dynamics) {
        if (body.shape == Shape::Box) return run("runs: boxes turn when a contact pushes a corner");
        if (body.shape != Shape::Sphere) {
            return run("runs: capsules, cylinders, hulls and compounds turn when a contact pushes off their centre");
        }
    }
    for (const DynamicObject& body : in.dynamics) {
        if (body.angularVelocity != Vec3(0)) return run("runs: a sphere starts spinning (AngularVelocity is set)");
    }
    if (!in.joints.empty()) return run("runs: joints pull at anchors away from the centres");
    for (const Spring& spring : in.springs) {
        const bool offCentreB = spring.bodyB != kFixedInWorld && spring.anchorB != Vec3(0);
        if (spring.anchorA != Vec3(0) || offCentreB) return run("runs: a spring is hooked off a body's centre");
    }
    if (anyFriction(in)) return run("runs: friction at a sphere's surface makes it roll");
    if (in.dynamics.empty()) return skip("skipped: no dynamic body");
    return skip("skipped: only spheres, no spin, no friction, no torque: still spheres skip the angular update");
}

/// Regions other than conveyors: a Conveyor region pushes nothing in a substep (it changes the
/// contacts' rows, fixed for the step: src/forces/conveyor.hpp).
bool regionsBesidesConveyors(const PlanInputs& in) {
    for (const Region& region : in.regions) {
        if (region.effect != RegionEffect::Conveyor) return true;
    }
    return false;
}

/// Forces that depend on where the bodies are must follow them through the substeps.
PlanDecision substepForcesOf(const PlanInputs& in) {
    if (in.settings.solver == SolverKind::Impulse) return skip("not in the Impulse pipeline (one step, one force evaluation)");
    if (!in.springs.empty()) return run("runs: springs pull by where their ends are, which changes every substep");
    if (!in.attractors.empty()) return run("runs: attractors pull by where a body is, which changes every substep");
    if (regionsBesidesConveyors(in)) return run("runs: regions push by where a body is and how it moves, which change every substep");
    return skip("skipped: only uniform forces (gravity, ConstantAcceleration): the step's a and torque hold for every substep");
}

PlanDecision jointSolverOf(const PlanInputs& in) {
    if (in.settings.solver == SolverKind::Impulse) return skip("skipped: the Impulse solver has no joints");
    if (in.joints.empty()) return skip("skipped: no joints in the scene");
    return run("runs: the scene has joints");
}

/// The fast path runs the substeps with the plain path's numbers; it has lanes for the contacts of
/// balls and boxes (and what they touch), nothing faster for a scene of other shapes only.
PlanDecision fastPathOf(const PlanInputs& in, const StepPlan& plan) {
    if (in.settings.solver == SolverKind::Impulse) return skip("not in the Impulse pipeline (it has no substeps)");
    if (!in.settings.fastPath) {
        return skip("off: FastPath=false (the default of the debug and student builds), so every step takes the plain path");
    }
    if (!plan.stage(Stage::SolveConstraints).runs) return skip("off: nothing to solve");
    if (!in.softBodies.empty()) return skip("off: soft bodies step between the substeps, which the plain path runs");
    bool anyBallOrBox = false;
    for (const DynamicObject& body : in.dynamics) {
        anyBallOrBox = anyBallOrBox || body.shape == Shape::Sphere || body.shape == Shape::Box;
    }
    if (!anyBallOrBox) return skip("off: no dynamic ball or box, whose contacts the lanes take; the plain path runs");
    return run("runs (src/fast/): contacts four at a time in SIMD lanes, the plain path's numbers bit for bit");
}

/// The packed substeps carry one integrator, the contact passes and nothing else (src/fast/packed_substeps.hpp).
PlanDecision packedSubstepsOf(const PlanInputs& in, const StepPlan& plan) {
    if (in.settings.solver == SolverKind::Impulse) return skip("not in the Impulse pipeline (it has no substeps)");
    if (!plan.fastPath.runs) return skip("off: they are part of the fast path, which does not run");
    if (in.settings.integrator != IntegratorKind::SymplecticEuler) {
        return skip("off: they carry symplectic Euler only; this integrator moves the objects");
    }
    if (!in.settings.accumulateImpulses) {
        return skip("off: AccumulateImpulses=false warm-starts every substep from the contacts, on the objects");
    }
    if (plan.jointSolver.runs) return skip("off: joint passes work on the objects");
    if (plan.substepForces.runs) return skip("off: forces that follow the bodies are worked out on the objects");
    return run("in a step whose contacts all hold balls (on balls, planes or kinematic bodies at rest): substeps on "
               "the solver's records, objects written once (same bits)");
}

/// Per-island substeps (src/dynamics/substep_rule.hpp): what acts inside every substep on what it
/// holds (forces that follow the bodies, a moving kinematic body) keeps the whole scene at Substeps;
/// a joint keeps its own island at Substeps, and the rule runs.
PlanDecision islandSubstepsOf(const PlanInputs& in) {
    if (in.settings.solver == SolverKind::Impulse) return skip("not in the Impulse pipeline (it has no substeps)");
    if (!in.settings.substepsPerIsland) return skip("off: SubstepsPerIsland=false, every island runs Substeps");
    if (!in.springs.empty() || !in.attractors.empty() || regionsBesidesConveyors(in)) {
        return skip("off: springs, attractors or regions act in every substep; every island runs Substeps");
    }
    for (const KinematicsObject& body : in.kinematics) {
        if (body.velocity != Vec3(0) || body.angularVelocity != Vec3(0)) {
            return skip("off: a kinematic body moves h_s at a time; every island runs Substeps");
        }
    }
    if (!in.settings.accumulateImpulses) return skip("off: AccumulateImpulses=false; every island runs Substeps");
    if (in.settings.substeps == 1) return skip("off: Substeps=1 leaves nothing to choose");
    if (!in.softBodies.empty()) return skip("off: soft bodies take every substep beside the rigid ones; every island runs Substeps");
    return run("runs (src/dynamics/substep_rule.hpp): each island max(height/P, 2*mass ratio, speed*h/(0.1*size), "
               "4*h*60 Hz), a power of two, at most Substeps; an island a joint holds runs Substeps");
}

/// The order of a pass (src/dynamics/contact_colours.hpp): a setting that changes the numbers, shown so
/// that a reader knows which sweep they are stepping through.
PlanDecision colourOrderOf(const PlanInputs& in) {
    if (in.settings.solver == SolverKind::Impulse) return skip("not in the Impulse pipeline (it resolves pairs one by one)");
    if (in.settings.contactOrder == ContactOrder::Found) {
        return skip("off: ContactOrder=Found, each pass takes the contacts in the order the narrowphase found them");
    }
    return run("runs (src/dynamics/contact_colours.hpp): each pass takes the contacts colour by colour, no two of a "
               "colour on one dynamic body, so a colour can be solved at once");
}

/// Regions push the bodies inside them (src/forces/region.hpp); a Kill region removes them.
PlanDecision regionsOf(const PlanInputs& in) {
    for (const Region& region : in.regions) {
        if (region.effect != RegionEffect::Kill && region.effect != RegionEffect::Conveyor) {
            return run("runs (src/forces/region.cpp): after the broadphase, each region finds the bodies inside it and "
                       "pushes them, again in every substep");
        }
    }
    if (anyConveyor(in.regions)) {
        return run("runs (src/world/world_regions.cpp): after the broadphase, each Conveyor region finds the bodies "
                   "inside it; it pushes nothing itself");
    }
    return skip("skipped: no region with a force (Drag, Wind, Gravity, Buoyancy, RandomForce)");
}

/// A Conveyor region moves the static surfaces under the bodies inside it, for friction (src/forces/conveyor.hpp).
PlanDecision conveyorsOf(const PlanInputs& in) {
    if (anyConveyor(in.regions)) {
        return run("runs (src/forces/conveyor.cpp): a contact of a body on a belt with a static or kinematic surface "
                   "takes the belt's velocity in its plane as the surface's, for friction (stored rows)");
    }
    return skip("skipped: no Conveyor region, so no contact's surface moves but a kinematic body's own");
}

PlanDecision killRegionsOf(const PlanInputs& in) {
    if (anyKillRegion(in.regions)) {
        return run("runs (src/world/world_regions.cpp): a body whose centre ends a step in a Kill region is removed");
    }
    return skip("skipped: no Kill region");
}

PlanDecision softBodiesOf(const PlanInputs& in) {
    if (in.softBodies.empty()) return skip("skipped: no soft bodies");
    return run("runs (src/soft/soft_step.cpp): springs, gas pressure P = nRT/V, nodes moved and collided, at the start of every substep, before the rigid move and solve");
}

PlanDecision idleSkipOf(const PlanInputs& in) {
    if (in.settings.solver == SolverKind::Impulse) {
        return run("on, rarely: the Impulse solver lets no body sleep, so only a world without an awake body is idle");
    }
    if (!in.settings.sleeping) return skip("off: Sleep=false, so bodies never fall asleep and every step is solved");
    return run("on: a step with no dynamic or soft body awake and no kinematic body moving returns at once");
}

static_assert(kAutoBruteForceBelow == 64, "the reason below quotes kAutoBruteForceBelow: update it");

PlanDecision broadphaseOf(const PlanInputs& in) {
    if (in.settings.broadphase != BroadphaseKind::Auto) return run("set by the scene (every broadphase finds the same pairs)");
    if (in.dynamics.size() < kAutoBruteForceBelow) {
        return run("Auto takes brute force, every pair, for fewer than 64 dynamic bodies");
    }
    return run("Auto chooses on the first step from sizes and speeds (stepwise run prints why)");
}

bool anyKinematicMoves(const PlanInputs& in) {
    for (const KinematicsObject& body : in.kinematics) {
        if (body.velocity != Vec3(0) || body.angularVelocity != Vec3(0)) return true;
    }
    return false;
}

/// "not in this pipeline": the stages of the other solver.
constexpr const char* kOtherImpulse = "not in the SequentialImpulse pipeline (Solver=Impulse has it)";
constexpr const char* kOtherSequential = "not in the Impulse pipeline (Solver=SequentialImpulse has it)";

void planStages(const PlanInputs& in, StepPlan& plan) {
    const bool sequential = in.settings.solver == SolverKind::SequentialImpulse;
    auto set = [&](Stage stage, PlanDecision decision) { plan.stages[static_cast<std::size_t>(stage)] = decision; };

    for (Stage stage : {Stage::ResolveImpulses, Stage::CorrectPositions}) {
        if (sequential) set(stage, skip(kOtherImpulse));
    }
    for (Stage stage : {Stage::PrepareConstraints, Stage::SolveConstraints, Stage::RelaxConstraints,
                        Stage::Restitution, Stage::Sleep}) {
        if (!sequential) set(stage, skip(kOtherSequential));
    }
    if (sequential && !in.settings.sleeping) set(Stage::Sleep, skip("skipped: Sleep=false in the World record"));
    if (!in.settings.continuousCollision) {
        set(Stage::Continuous, skip("skipped: ContinuousCollision=false in the World record"));
    }
    if (!plan.enabled) return;  // StepPlan=Off: every stage of the pipeline runs

    if (!plan.softBodies.runs) set(Stage::SoftBodies, plan.softBodies);

    if (in.dynamics.empty()) {
        set(Stage::ApplyForces, skip("skipped: no dynamic body to push"));
        set(Stage::Integrate, skip("skipped: no dynamic body to move"));
        if (sequential && in.settings.sleeping && in.softBodies.empty()) {
            set(Stage::Sleep, skip("skipped: no dynamic or soft body to fall asleep"));
        }
    }
    if (!anyKinematicMoves(in)) {
        set(Stage::MoveKinematics, in.kinematics.empty()
                                       ? skip("skipped: no kinematic bodies")
                                       : skip("skipped: every kinematic body has zero velocity and angular velocity"));
    }
    if (!plan.collisions.runs) {
        set(Stage::Broadphase, plan.collisions);
        set(Stage::Narrowphase, plan.collisions);
        if (!sequential) {
            set(Stage::ResolveImpulses, skip("skipped: no contact can occur"));
            set(Stage::CorrectPositions, skip("skipped: no contact can occur"));
        }
        if (in.settings.continuousCollision) set(Stage::Continuous, skip("skipped: no contact can occur"));
    }
    if (sequential && !plan.collisions.runs && !plan.jointSolver.runs) {
        for (Stage stage : {Stage::PrepareConstraints, Stage::SolveConstraints, Stage::RelaxConstraints,
                            Stage::Restitution}) {
            set(stage, skip("skipped: no contact can occur and there are no joints: nothing to solve"));
        }
    }
}

/// Why a stage runs, when no rule skipped it.
const char* runReason(Stage stage, bool enabled) {
    if (!enabled) return "runs: StepPlan=Off runs every stage of the pipeline";
    switch (stage) {
        case Stage::ApplyForces: return "runs: gravity, springs and attractors set every body's acceleration";
        case Stage::Integrate: return "runs: dynamic bodies move";
        case Stage::MoveKinematics: return "runs: a kinematic body moves";
        case Stage::Broadphase: return "runs: objects can touch";
        case Stage::Narrowphase: return "runs: candidate pairs need an exact test";
        case Stage::ResolveImpulses: return "runs: contacts need impulses";
        case Stage::CorrectPositions: return "runs: overlapping bodies are pushed apart";
        case Stage::PrepareConstraints: return "runs: contacts or joints become constraints";
        case Stage::SolveConstraints: return "runs: every substep solves the constraints";
        case Stage::RelaxConstraints: return "runs: every substep relaxes the push-out";
        case Stage::Restitution: return "runs: bounces, and joints that break";
        case Stage::Sleep: return "runs: islands at rest fall asleep";
        case Stage::Continuous:
            return "runs: a body that moves farther than its inner radius in a step stops at its first touch";
        case Stage::SoftBodies: return "runs: soft bodies move";
        case Stage::Count: break;
    }
    return "runs";
}

}  // namespace

std::span<const PipelineSlot> pipelineOrder(SolverKind solver) {
    using enum Stage;
    constexpr StageRepeat kOnce = StageRepeat::OncePerStep;
    constexpr StageRepeat kEach = StageRepeat::EverySubstep;
    // World::stepWithImpulses(): move, then find and repair the collisions the move made.
    static constexpr PipelineSlot kImpulse[] = {
        {ApplyForces, kOnce}, {Integrate, kOnce},   {MoveKinematics, kOnce},  {Continuous, kOnce},
        {Broadphase, kOnce},  {Narrowphase, kOnce}, {ResolveImpulses, kOnce}, {CorrectPositions, kOnce},
        {SoftBodies, kOnce},
    };
    // World::stepWithSequentialImpulses(): find the contacts first, then hold them through the substeps.
    static constexpr PipelineSlot kSequential[] = {
        {ApplyForces, kOnce},
        {Broadphase, kOnce},
        {Narrowphase, kOnce},
        {PrepareConstraints, kOnce},
        {ApplyForces, StageRepeat::LaterSubsteps},
        {SoftBodies, kEach},
        {Integrate, kEach},
        {MoveKinematics, kEach},
        {SolveConstraints, kEach},
        {RelaxConstraints, kEach},
        {Continuous, kOnce},
        {Restitution, kOnce},
        {Sleep, kOnce},
    };
    switch (solver) {
        case SolverKind::Impulse: return kImpulse;
        case SolverKind::SequentialImpulse: return kSequential;
    }
    return {};
}

StepPlan makeStepPlan(const PlanInputs& in) {
    StepPlan plan;
    plan.solver = in.settings.solver;
    plan.substeps = in.settings.solver == SolverKind::SequentialImpulse ? in.settings.substeps : 1;
    plan.enabled = in.settings.stepPlan;
    plan.broadphase = in.settings.broadphase;
    plan.broadphaseChoice = broadphaseOf(in);
    plan.jointSolver = jointSolverOf(in);
    plan.softBodies = softBodiesOf(in);
    if (!plan.enabled) {
        constexpr PlanDecision kOff = {true, "runs: StepPlan=Off"};
        plan.collisions = kOff;
        plan.boxBoxSat = boxBoxSatOf(in);  // what the narrowphase does, plan or not
        plan.manifoldClipping = clippingOf(in);
        plan.rotation = kOff;
        plan.substepForces = in.settings.solver == SolverKind::SequentialImpulse ? kOff : substepForcesOf(in);
        if (in.settings.solver == SolverKind::SequentialImpulse) plan.jointSolver = kOff;
        plan.idleSkip = skip("off: StepPlan=Off solves every step");
        plan.fastPath = skip("off: StepPlan=Off takes the plain path");
        plan.packedSubsteps = skip("off: StepPlan=Off takes the plain path");
    } else {
        plan.collisions = collisionsOf(in);
        plan.boxBoxSat = boxBoxSatOf(in);
        plan.manifoldClipping = clippingOf(in);
        plan.rotation = rotationOf(in);
        plan.substepForces = substepForcesOf(in);
        plan.idleSkip = idleSkipOf(in);
    }
    for (std::size_t i = 0; i < kStageCount; ++i) plan.stages[i] = run(runReason(static_cast<Stage>(i), plan.enabled));
    planStages(in, plan);
    if (plan.enabled) {  // the roads of the substeps, once the stages are known
        plan.fastPath = fastPathOf(in, plan);
        plan.packedSubsteps = packedSubstepsOf(in, plan);
    }
    plan.islandSubsteps = islandSubstepsOf(in);  // changes the numbers when it runs: a setting, not a skip
    plan.colourOrder = colourOrderOf(in);        // the same
    plan.regions = regionsOf(in);                // forces, not skips: they run whenever the scene has them
    plan.killRegions = killRegionsOf(in);
    plan.conveyors = conveyorsOf(in);
    return plan;
}

std::string describeStepPlan(const StepPlan& plan) {
    constexpr std::size_t kNameColumn = 22;  // wide enough for "prepare-constraints" and "box-box SAT"
    std::string text = plan.enabled ? "Step plan (what each step runs, and why)\n"
                                    : "Step plan: off (World, StepPlan=Off): every stage of the pipeline runs\n";
    auto line = [&](const char* name, const PlanDecision& decision) {
        const std::string label(name);
        text += "  " + label + std::string(label.size() < kNameColumn ? kNameColumn - label.size() : 1, ' ');
        text += decision.runs ? "yes  " : "no   ";
        text += decision.reason;
        text += '\n';
    };
    text += std::string("Stages, in the order a step runs them (Solver=") + toString(plan.solver) +
            ", src/world/world.cpp):\n";
    const std::span<const PipelineSlot> order = pipelineOrder(plan.solver);
    std::array<bool, kStageCount> inPipeline{};
    bool inSubsteps = false;
    for (const PipelineSlot& slot : order) {
        inPipeline[static_cast<std::size_t>(slot.stage)] = true;
        const bool substep = slot.repeat != StageRepeat::OncePerStep;
        if (substep && !inSubsteps) text += "  each of the " + std::to_string(plan.substeps) + " substeps:\n";
        inSubsteps = substep;
        const std::string name = std::string(substep ? "  " : "") + stageName(slot.stage);
        PlanDecision decision = plan.stage(slot.stage);
        // apply-forces again in later substeps: only when the forces can change within a step
        const bool laterSubsteps = slot.repeat == StageRepeat::LaterSubsteps;
        if (laterSubsteps && decision.runs && !plan.substepForces.runs) decision = plan.substepForces;
        std::string reason = decision.reason;
        if (laterSubsteps && decision.runs) reason += " (again from substep 2 on)";
        decision.reason = reason.c_str();
        line(name.c_str(), decision);
    }
    bool otherHeader = false;
    for (std::size_t i = 0; i < kStageCount; ++i) {
        if (inPipeline[i]) continue;
        if (!otherHeader) text += "Not in this pipeline:\n";
        otherHeader = true;
        line(stageName(static_cast<Stage>(i)), plan.stages[i]);
    }
    text += "Inside the stages:\n";
    line("collisions", plan.collisions);
    line("box-box SAT", plan.boxBoxSat);
    line("manifold clipping", plan.manifoldClipping);
    line("rotation", plan.rotation);
    line("forces per substep", plan.substepForces);
    line("joint solver", plan.jointSolver);
    line("idle step skip", plan.idleSkip);
    line("fast path", plan.fastPath);
    line("packed substeps", plan.packedSubsteps);
    line("substeps per island", plan.islandSubsteps);
    line("colour order", plan.colourOrder);
    line("regions", plan.regions);
    line("kill regions", plan.killRegions);
    line("soft bodies", plan.softBodies);
    line("conveyors", plan.conveyors);
    text += "  broadphase kind       ";
    text += toString(plan.broadphase);
    text += ": ";
    text += plan.broadphaseChoice.reason;
    text += '\n';
    return text;
}

std::string describeIslandSubsteps(std::span<const IslandSubsteps> islands, std::span<const DynamicObject> bodies,
                                   int cap, std::size_t maxLines) {
    std::string text = "Substeps per island in the first step (at most " + std::to_string(cap) +
                       "; src/dynamics/substep_rule.hpp):\n";
    if (islands.empty()) return text + "  none chosen: no island had a contact to solve, or every one got the full count\n";
    for (int count = cap; count >= 1; --count) {
        std::size_t islandCount = 0;
        std::size_t bodyCount = 0;
        for (const IslandSubsteps& island : islands) {
            if (island.count != count) continue;
            ++islandCount;
            bodyCount += island.bodies;
        }
        if (islandCount == 0) continue;
        text += "  " + std::to_string(count) + " substeps: " + std::to_string(islandCount) +
                (islandCount == 1 ? " island, " : " islands, ") + std::to_string(bodyCount) +
                (bodyCount == 1 ? " body\n" : " bodies\n");
    }
    char number[32];
    std::size_t lines = 0;
    for (const IslandSubsteps& island : islands) {
        if (lines++ == maxLines) {
            text += "  ... and " + std::to_string(islands.size() - maxLines) + " more islands\n";
            break;
        }
        text += "  island " + bodies[island.firstBody].name + ": " + std::to_string(island.bodies) +
                (island.bodies == 1 ? " body, " : " bodies, ") +
                std::to_string(island.contacts) + " contacts, height " + std::to_string(island.height);
        if (island.joints > 0) text += ", " + std::to_string(island.joints) + (island.joints == 1 ? " joint" : " joints");
        std::snprintf(number, sizeof number, "%.3g", double(island.massRatio));
        text += std::string(", mass ratio ") + number;
        std::snprintf(number, sizeof number, "%.3g", double(island.speed));
        text += std::string(", speed ") + number + " m/s -> " + std::to_string(island.count) + " (" +
                substepReasonName(island.reason) + ")\n";
    }
    return text;
}

std::string skippedStagesLine(const StepPlan& plan, const StageRecords& records, bool stepTaken) {
    std::string skipped;
    std::array<bool, kStageCount> listed{};
    for (const PipelineSlot& slot : pipelineOrder(plan.solver)) {
        const std::size_t i = static_cast<std::size_t>(slot.stage);
        if (listed[i]) continue;  // apply-forces has two places in the sequential-impulse step
        listed[i] = true;
        if (slot.stage == Stage::SoftBodies && !plan.softBodies.runs) continue;  // no soft body: not part of this step
        if (!plan.runs(slot.stage) || (stepTaken && !records[i].ranLastStep)) {
            skipped += std::string(skipped.empty() ? "" : ", ") + stageName(slot.stage);
        }
    }
    if (!skipped.empty()) return "skipped stages: " + skipped;
    return stepTaken ? "skipped stages: none (every stage ran in the last step)"
                     : "skipped stages: none planned (no step taken yet)";
}

}  // namespace stepwise
