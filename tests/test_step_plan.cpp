// The step plan (src/world/step_plan.hpp): what it decides for small scenes,
// that skipping changes nothing (bit for bit, against World, StepPlan=Off),
// and that a step where nothing is awake runs no stage. Tag: [plan].
#include <catch2/catch.hpp>

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "config/scene_loader.hpp"
#include "fast/fast_path_counts.hpp"
#include "objects/inertia.hpp"
#include "integrators/integrators.hpp"
#include "command_runner.hpp"
#include "shape_fixtures.hpp"
#include "test_support.hpp"

using namespace stepwise;

namespace {

Scene configScene(const std::string& file) { return loadSceneFile(std::string(STEPWISE_SOURCE_DIR) + "/config/" + file); }

StepPlan planOf(Scene scene) { return World(std::move(scene)).plan(); }


/// Runs @p scene with and without the plan, comparing the whole state after every step.
/// Returns how many stage runs the plan saved.
std::uint64_t requireSameTrajectory(const Scene& scene, int steps) {
    REQUIRE(scene.settings.stepPlan);
    Scene off = scene;
    off.settings.stepPlan = false;
    World planned(scene);
    World unplanned(off);
    REQUIRE(planned.plan().enabled);
    REQUIRE_FALSE(unplanned.plan().enabled);
    for (int i = 0; i < steps; ++i) {
        planned.step();
        unplanned.step();
        test::requireSameState(planned, unplanned);
    }
    std::uint64_t saved = 0;
    for (std::size_t s = 0; s < kStageCount; ++s) {
        REQUIRE(planned.stageRecords()[s].runs <= unplanned.stageRecords()[s].runs);
        saved += unplanned.stageRecords()[s].runs - planned.stageRecords()[s].runs;
    }
    return saved;
}

/// Frictionless spheres meeting at oblique angles, on a floor and against a wall: rotation is impossible,
/// and the sphere–sphere lever arms are not exactly parallel to the normals in floating point.
Scene frictionlessSpheres(SolverKind solver, IntegratorKind integrator) {
    Scene scene = test::emptyScene(integrator);
    scene.settings.solver = solver;
    CollisionPlane floor = test::ground();
    floor.friction = 0;
    CollisionPlane wall = test::ground("wall");
    wall.position = Vec3(3, 0, 0);
    wall.normal = glm::normalize(Vec3(-1, 0.2, 0.1));
    wall.friction = 0;
    scene.planes = {floor, wall};
    for (int i = 0; i < 6; ++i) {
        const Real x = Real(0.37) * Real(i), y = Real(0.6) + Real(0.45) * Real(i), z = Real(0.13) * Real(i % 3);
        scene.dynamics.push_back(test::sphere("s" + std::to_string(i), Vec3(x, y, z), Vec3(Real(1.5) - x, 0, z),
                                              Real(0.3), Real(1) + Real(i), Real(0.6), Real(0)));
    }
    // Far from the others, bouncing on the floor only: its lever arm −r·(0, 1, 0) is exact, so its L stays 0.
    scene.dynamics.push_back(test::sphere("loner", Vec3(-20, 1, 0), Vec3(0), Real(0.3), 1, Real(0.6), Real(0)));
    return scene;
}

}  // namespace

TEST_CASE("The plan skips SAT, clipping and rotation for frictionless spheres, and runs them for boxes", "[plan]") {
    const StepPlan spheres = planOf(frictionlessSpheres(SolverKind::SequentialImpulse, IntegratorKind::SymplecticEuler));
    CHECK_FALSE(spheres.boxBoxSat.runs);
    CHECK(std::string(spheres.boxBoxSat.reason).find("no boxes") != std::string::npos);
    CHECK_FALSE(spheres.manifoldClipping.runs);
    CHECK_FALSE(spheres.rotation.runs);
    CHECK_FALSE(spheres.jointSolver.runs);
    CHECK(spheres.collisions.runs);
    CHECK(spheres.runs(Stage::Broadphase));
    CHECK_FALSE(spheres.runs(Stage::MoveKinematics));  // there is no kinematic body
    CHECK_FALSE(spheres.runs(Stage::ResolveImpulses));  // not in the sequential-impulse pipeline

    Scene boxes = test::emptyScene();
    boxes.planes = {test::ground()};
    boxes.dynamics = {test::dynamicBox("a", Vec3(0, 0.5, 0), Vec3(1), 1, 0.5),
                      test::dynamicBox("b", Vec3(0, 1.5, 0), Vec3(1), 1, 0.5)};
    const StepPlan stack = planOf(boxes);
    CHECK(stack.boxBoxSat.runs);
    CHECK(stack.manifoldClipping.runs);
    CHECK(stack.rotation.runs);

    // One box on the floor: SAT needs two boxes.
    boxes.dynamics.pop_back();
    CHECK_FALSE(planOf(boxes).boxBoxSat.runs);
}

TEST_CASE("Friction, spin, an off-centre spring or a joint make rotation possible", "[plan]") {
    const Scene base = frictionlessSpheres(SolverKind::SequentialImpulse, IntegratorKind::SymplecticEuler);
    REQUIRE_FALSE(planOf(base).rotation.runs);

    Scene rough = base;
    rough.dynamics[0].friction = Real(0.5);
    rough.planes[0].friction = 1;
    CHECK(planOf(rough).rotation.runs);
    rough.planes[0].friction = 0;  // the one rough sphere meets only frictionless things: μ_A·μ_B = 0
    CHECK_FALSE(planOf(rough).rotation.runs);
    rough.dynamics[1].friction = Real(0.5);  // two rough spheres can rub against each other
    CHECK(planOf(rough).rotation.runs);

    Scene spinning = base;
    spinning.dynamics[2].angularVelocity = Vec3(0, 0, 1);
    CHECK(planOf(spinning).rotation.runs);

    Scene sprung = base;
    Spring spring;
    spring.name = "centred";
    spring.bodyA = 0;
    spring.anchorB = Vec3(0, 3, 0);
    sprung.springs = {spring};
    CHECK_FALSE(planOf(sprung).rotation.runs);  // pulls through the centre
    sprung.springs[0].anchorA = Vec3(0.1, 0, 0);
    CHECK(planOf(sprung).rotation.runs);

    Scene jointed = configScene("lesson08_pendulum.scene");
    CHECK(planOf(jointed).jointSolver.runs);
    CHECK(planOf(jointed).rotation.runs);
}

TEST_CASE("A lone body with nothing to hit skips every collision stage", "[plan]") {
    const StepPlan kepler = planOf(configScene("reference_kepler_circular.scene"));
    CHECK_FALSE(kepler.collisions.runs);
    for (Stage stage : {Stage::Broadphase, Stage::Narrowphase, Stage::ResolveImpulses, Stage::CorrectPositions}) {
        INFO(stageName(stage));
        CHECK_FALSE(kepler.runs(stage));
    }
    CHECK(kepler.runs(Stage::ApplyForces));
    CHECK(kepler.runs(Stage::Integrate));

    Scene sequential = configScene("reference_kepler_circular.scene");
    sequential.settings.solver = SolverKind::SequentialImpulse;
    const StepPlan plan = planOf(sequential);
    for (Stage stage : {Stage::PrepareConstraints, Stage::SolveConstraints, Stage::RelaxConstraints,
                        Stage::Restitution}) {
        INFO(stageName(stage));
        CHECK_FALSE(plan.runs(stage));
    }
}

TEST_CASE("StepPlan=Off runs every stage of the pipeline", "[plan]") {
    Scene scene = configScene("reference_kepler_circular.scene");
    scene.settings.stepPlan = false;
    const StepPlan plan = planOf(scene);
    CHECK_FALSE(plan.enabled);
    for (Stage stage : {Stage::ApplyForces, Stage::Integrate, Stage::MoveKinematics, Stage::Broadphase,
                        Stage::Narrowphase, Stage::ResolveImpulses, Stage::CorrectPositions}) {
        INFO(stageName(stage));
        CHECK(plan.runs(stage));
    }
    CHECK(plan.rotation.runs);
    CHECK_FALSE(plan.idleSkip.runs);
    CHECK(describeStepPlan(plan).find("StepPlan=Off") != std::string::npos);
}

TEST_CASE("Trajectories are bit-identical with and without the plan on the config scenes", "[plan]") {
    struct Case {
        const char* file;
        int steps;
    };
    // Spheres and a moving paddle; impulse-solver spheres and boxes; joints; a lone planet.
    const Case cases[] = {{"default.scene", 240},          {"lesson03_collisions.scene", 240},
                          {"lesson05_sat.scene", 240},     {"lesson07_tipping.scene", 240},
                          {"lesson07_bowling.scene", 240}, {"lesson08_pendulum.scene", 240},
                          {"lesson08_hinge_motor.scene", 240}, {"lesson08_cradle.scene", 240},
                          {"reference_kepler_eccentric.scene", 240}, {"reference_spring.scene", 240}};
    for (const Case& c : cases) {
        INFO(c.file);
        requireSameTrajectory(configScene(c.file), c.steps);
    }
}

TEST_CASE("Balls on the packed substeps end bit for bit where the plain path leaves them", "[plan][fast]") {
    // The fast path's packed substeps do the plain path's operations on the solver's records
    // (src/fast/packed_substeps.hpp); StepPlan=Off takes the plain path. Compared after every step,
    // with and without friction (rotation planned or skipped), and with a box that makes some steps
    // take the fast path's road on the objects (its contacts have stored rows).
    Scene scene = frictionlessSpheres(SolverKind::SequentialImpulse, IntegratorKind::SymplecticEuler);
    SECTION("frictionless: the plan skips rotation") { REQUIRE_FALSE(planOf(scene).rotation.runs); }
    SECTION("rough and spinning: every ball turns") {
        for (CollisionPlane& plane : scene.planes) plane.friction = Real(0.6);
        for (DynamicObject& body : scene.dynamics) body.friction = Real(0.4);
        scene.dynamics[2].angularVelocity = Vec3(0, 3, 7);
        REQUIRE(planOf(scene).rotation.runs);
    }
    SECTION("a box drops among the balls: its steps take the fast path on the objects") {
        for (DynamicObject& body : scene.dynamics) body.friction = Real(0.4);
        scene.dynamics.push_back(test::dynamicBox("crate", Vec3(1, 4, 0.2), Vec3(0.6), 2, Real(0.5)));
    }
    scene.settings.fastPath = true;  // whatever this build's default (STEPWISE_FAST_PATH)
    REQUIRE(planOf(scene).packedSubsteps.runs);
    Scene off = scene;
    off.settings.stepPlan = false;
    World packed(scene);
    World objects(off);
    for (int i = 0; i < 240; ++i) {
        packed.step();
        objects.step();
        test::requireSameState(packed, objects);
    }
    REQUIRE(objects.fastPathCounts().steps == 0);
    const auto stepsOnRecords = packed.fastPathCounts().packedSteps;
    const auto stepsOnObjects = packed.fastPathCounts().steps - stepsOnRecords;
    INFO(stepsOnRecords << " steps on the records, " << stepsOnObjects << " on the objects");
    CHECK(stepsOnRecords > 30);  // the comparison above is not empty
    if (packed.findDynamic("crate") != nullptr) CHECK(stepsOnObjects > 30);
}

TEST_CASE("The fast path and its packed substeps are planned only where they carry the scene", "[plan][fast]") {
    Scene scene = test::emptyScene();
    scene.dynamics = {test::sphere("a", Vec3(0, 0.5, 0)), test::sphere("b", Vec3(0, 1.5, 0))};
    scene.planes = {test::ground()};
    scene.settings.fastPath = true;  // whatever this build's default (STEPWISE_FAST_PATH)
    CHECK(planOf(scene).fastPath.runs);
    CHECK(planOf(scene).packedSubsteps.runs);
    SECTION("another integrator") {
        scene.settings.integrator = IntegratorKind::Verlet;
        CHECK_FALSE(planOf(scene).packedSubsteps.runs);
    }
    SECTION("impulses not accumulated") {
        scene.settings.accumulateImpulses = false;
        CHECK_FALSE(planOf(scene).packedSubsteps.runs);
    }
    SECTION("forces that follow the bodies") {
        scene.attractors = {Attractor{"sun", Vec3(2, 1, 0), 40}};
        CHECK_FALSE(planOf(scene).packedSubsteps.runs);
    }
    SECTION("no ball: a box's contacts take the fast path's lanes, not the packed substeps") {
        // (The packed substeps stay planned: whether a step's contacts all hold balls is decided
        // each step, and a box's contacts keep that step on the objects.)
        scene.dynamics = {test::dynamicBox("crate", Vec3(0, 0.5, 0), Vec3(1), 1, Real(0.5))};
        CHECK(planOf(scene).fastPath.runs);
    }
    SECTION("no ball and no box: the fast path has nothing faster for a capsule") {
        scene.dynamics = {test::shapedBody("rod", Shape::Capsule, Vec3(0, 0.5, 0))};
        CHECK_FALSE(planOf(scene).fastPath.runs);
        CHECK_FALSE(planOf(scene).packedSubsteps.runs);
    }
    SECTION("StepPlan=Off") {
        scene.settings.stepPlan = false;
        CHECK_FALSE(planOf(scene).packedSubsteps.runs);
    }
    SECTION("FastPath=false: the plain path, which has no packed substeps") {
        scene.settings.fastPath = false;
        CHECK_FALSE(planOf(scene).fastPath.runs);
        CHECK_FALSE(planOf(scene).packedSubsteps.runs);
    }
    SECTION("the Impulse solver") {
        scene.settings.solver = SolverKind::Impulse;
        CHECK_FALSE(planOf(scene).packedSubsteps.runs);
    }
}

TEST_CASE("Forces are worked out once a step unless a spring or an attractor follows the bodies", "[plan]") {
    // Two balls dropping onto a floor under the sequential impulse (4 substeps), one of them on a
    // spring or both pulled by an attractor. Gravity alone gives a = g and τ = 0 whatever the state,
    // so the substeps after the first need not work them out again; a spring's or an attractor's pull
    // changes as the bodies move, and skipping it would change the trajectory (requireSameTrajectory
    // compares it bit for bit with StepPlan=Off, which works the forces out in every substep).
    constexpr int kSubsteps = 4;
    constexpr int kSteps = 90;  // 1.5 s: both balls land and roll
    Scene scene = test::emptyScene();
    scene.settings.substeps = kSubsteps;
    scene.planes = {test::ground()};
    scene.dynamics = {test::sphere("a", Vec3(0, 2, 0), Vec3(1, 0, 0)), test::sphere("b", Vec3(0.3, 3.2, 0.1))};
    std::uint64_t forceRunsPerStep = 0;
    SECTION("gravity only: once a step") {
        CHECK_FALSE(planOf(scene).substepForces.runs);
        forceRunsPerStep = 1;
    }
    SECTION("a spring: every substep") {
        Spring spring;
        spring.name = "spring";
        spring.bodyA = 1;
        spring.anchorB = Vec3(0.3, 4, 0.1);
        spring.stiffness = 2000;
        spring.restLength = 1;
        scene.springs = {spring};
        CHECK(planOf(scene).substepForces.runs);
        forceRunsPerStep = kSubsteps;
    }
    SECTION("an attractor: every substep") {
        scene.attractors = {Attractor{"sun", Vec3(2, 1, 0), 40}};
        CHECK(planOf(scene).substepForces.runs);
        forceRunsPerStep = kSubsteps;
    }
    requireSameTrajectory(scene, kSteps);
    World world(scene);
    for (int i = 0; i < kSteps; ++i) world.step();
    CHECK(world.stageRecords()[static_cast<std::size_t>(Stage::ApplyForces)].runs == forceRunsPerStep * kSteps);
}

TEST_CASE("A sleeping tower is bit-identical with and without the plan, and the plan saves its idle steps", "[plan]") {
    Scene tower = configScene("lesson08_tower.scene");
    tower.settings.sleeping = true;  // the file turns sleep off so every step is solved
    // 4 s: the tower settles and falls asleep within about 2 s (tests/test_solver.cpp); the rest are idle steps.
    const std::uint64_t saved = requireSameTrajectory(tower, 240);
    CHECK(saved > 0);
}

TEST_CASE("Frictionless spheres skip the angular update and still match StepPlan=Off bit for bit", "[plan]") {
    for (const SolverKind solver : {SolverKind::Impulse, SolverKind::SequentialImpulse}) {
        for (const IntegratorKind integrator : test::kAllIntegrators) {
            INFO(toString(solver) << " " << toString(integrator));
            const Scene scene = frictionlessSpheres(solver, integrator);
            REQUIRE_FALSE(planOf(scene).rotation.runs);
            requireSameTrajectory(scene, 300);
            // The skip was taken for the loner, whose L stayed exactly 0. (The others' oblique contacts leave
            // an L of rounding size, from lever arms not exactly parallel to the normal: they get the full update.)
            World planned(scene);
            for (int i = 0; i < 300; ++i) planned.step();
            const DynamicObject* loner = planned.findDynamic("loner");
            REQUIRE(loner != nullptr);
            CHECK(skipsRotation(*loner));  // the integrators' test (integrators.hpp)
            CHECK(loner->orientation == Quat(1, 0, 0, 0));
            std::size_t turned = 0;  // how many took the full update at the end (reported when the check fails)
            for (const DynamicObject& body : planned.dynamics()) turned += skipsRotation(body) ? 0 : 1;
            INFO(turned << " of " << planned.dynamics().size() << " spheres have an L of rounding size");
            CHECK(turned < planned.dynamics().size());
        }
    }
}

TEST_CASE("A push off a sphere's centre from outside the step still turns it with the plan on", "[plan]") {
    // What the viewer's mouse does (src/viewer/simulation.cpp): change a body through World::dynamics().
    const Scene scene = frictionlessSpheres(SolverKind::SequentialImpulse, IntegratorKind::SymplecticEuler);
    Scene off = scene;
    off.settings.stepPlan = false;
    World planned(scene);
    World unplanned(off);
    for (World* world : {&planned, &unplanned}) {
        world->step();
        DynamicObject& ball = world->dynamics()[0];
        applyImpulseAt(ball, Vec3(0, 0, 2), ball.position + Vec3(ball.radius, 0, 0));  // L = r × P ≠ 0
    }
    for (int i = 0; i < 60; ++i) {
        planned.step();
        unplanned.step();
        test::requireSameState(planned, unplanned);
    }
    // The push gave it L = r × P = 0.3 m × 2 N·s = 0.6 kg·m²/s about −y, and a sphere keeps turning.
    CHECK(planned.dynamics()[0].orientation != Quat(1, 0, 0, 0));
}

TEST_CASE("A step where nothing is awake and nothing moves runs no stage, and time still advances", "[plan]") {
    Scene scene = test::emptyScene();
    scene.planes = {test::ground()};
    scene.dynamics = {test::sphere("ball", Vec3(0, Real(0.5), 0), Vec3(0), Real(0.5), 1, 0, Real(0.5))};
    Scene off = scene;
    off.settings.stepPlan = false;
    World planned(scene);
    World unplanned(off);
    // At rest on the floor from the start: asleep after TimeToSleep (0.5 s = 30 steps) and a few to settle.
    constexpr int kStepsToSleep = 120;
    for (int i = 0; i < kStepsToSleep; ++i) {
        planned.step();
        unplanned.step();
    }
    REQUIRE(planned.dynamics()[0].asleep);
    const StageRecords before = planned.stageRecords();
    const StageRecords beforeOff = unplanned.stageRecords();
    constexpr int kIdleSteps = 100;
    for (int i = 0; i < kIdleSteps; ++i) {
        planned.step();
        unplanned.step();
    }
    std::uint64_t runsPlanned = 0, runsOff = 0;
    for (std::size_t s = 0; s < kStageCount; ++s) {
        runsPlanned += planned.stageRecords()[s].runs - before[s].runs;
        runsOff += unplanned.stageRecords()[s].runs - beforeOff[s].runs;
        CHECK_FALSE(planned.stageRecords()[s].ranLastStep);
    }
    CHECK(runsPlanned == 0);
    CHECK(runsOff >= std::uint64_t(kIdleSteps));  // without the plan every idle step still runs its stages
    CHECK(planned.stepCount() == std::uint64_t(kStepsToSleep + kIdleSteps));
    CHECK(planned.time() == unplanned.time());
    test::requireSameState(planned, unplanned);

    // A moving kinematic body can wake a sleeper: then the step is not skipped.
    scene.kinematics = {test::kinematicBox("pusher", Vec3(-5, 0.5, 0), Vec3(1), Vec3(1, 0, 0))};
    World withPusher(scene);
    for (int i = 0; i < kStepsToSleep; ++i) withPusher.step();
    REQUIRE(withPusher.dynamics()[0].asleep);
    const std::uint64_t integrateRuns = withPusher.stageRecords()[static_cast<std::size_t>(Stage::MoveKinematics)].runs;
    withPusher.step();
    CHECK(withPusher.stageRecords()[static_cast<std::size_t>(Stage::MoveKinematics)].runs > integrateRuns);
}

TEST_CASE("The explanation names every stage with its decision", "[plan]") {
    const StepPlan plan = planOf(frictionlessSpheres(SolverKind::SequentialImpulse, IntegratorKind::Verlet));
    const std::string text = describeStepPlan(plan);
    for (std::size_t s = 0; s < kStageCount; ++s) {
        INFO(stageName(static_cast<Stage>(s)));
        CHECK(text.find(stageName(static_cast<Stage>(s))) != std::string::npos);
    }
    CHECK(text.find("skipped: no boxes in the scene, so no SAT") != std::string::npos);
    CHECK(text.find("rotation") != std::string::npos);
}

TEST_CASE("stepwise run --explain prints the plan, and with --steps 0 nothing else", "[plan][cli]") {
    const std::string cli = std::string("'") + STEPWISE_CLI_PATH + "' run '" + STEPWISE_SOURCE_DIR + "/config/";
    const test::CommandResult only = test::shell(cli + "reference_kepler_circular.scene' --explain --steps 0");
    CHECK(only.exitCode == 0);
    CHECK(only.output.find("Step plan") != std::string::npos);
    CHECK(only.output.find("broadphase") != std::string::npos);
    CHECK(only.output.find("skipped: a single body and nothing to hit") != std::string::npos);
    CHECK(only.output.find("Simulated") == std::string::npos);  // no step was run

    const test::CommandResult run = test::shell(cli + "lesson05_sat.scene' --explain --steps 3");
    CHECK(run.exitCode == 0);
    CHECK(run.output.find("box-box SAT") != std::string::npos);
    CHECK(run.output.find("Simulated") != std::string::npos);

    // --steps 0 alone is still a usage error: a run of no steps only makes sense to explain.
    CHECK(test::shell(cli + "lesson05_sat.scene' --steps 0").exitCode == 2);
}

namespace {

/// Writes down every stage the World runs, with its substep.
struct StageOrderRecorder : StepObserver {
    std::vector<std::pair<Stage, int>> runs;
    void beforeStage(const StageEvent& event, const World&) override { runs.emplace_back(event.stage, event.substep); }
};

}  // namespace

TEST_CASE("pipelineOrder() is the order World::step runs the stages, substeps included", "[plan]") {
    // With StepPlan=Off, continuous collision and sleep on, every stage of the
    // pipeline runs: the recorded order must be pipelineOrder() expanded over the substeps.
    const SolverKind solver = GENERATE(SolverKind::Impulse, SolverKind::SequentialImpulse);
    INFO(toString(solver));
    Scene scene = test::emptyScene();
    scene.settings.solver = solver;
    scene.settings.stepPlan = false;
    scene.settings.continuousCollision = true;
    scene.settings.sleeping = true;
    scene.settings.substeps = 3;
    scene.dynamics = {test::sphere("ball", Vec3(0, 1, 0))};
    scene.planes = {test::ground()};
    World world(scene);
    StageOrderRecorder recorder;
    world.setObserver(&recorder);
    world.step();

    const int substeps = solver == SolverKind::SequentialImpulse ? 3 : 1;
    std::vector<std::pair<Stage, int>> expected;
    const std::span<const PipelineSlot> order = pipelineOrder(solver);
    for (std::size_t i = 0; i < order.size();) {
        if (order[i].repeat == StageRepeat::OncePerStep) {
            expected.emplace_back(order[i].stage, -1);
            ++i;
            continue;
        }
        std::size_t end = i;  // the run of substep slots [i, end)
        while (end < order.size() && order[end].repeat != StageRepeat::OncePerStep) ++end;
        for (int substep = 0; substep < substeps; ++substep) {
            for (std::size_t k = i; k < end; ++k) {
                if (order[k].repeat == StageRepeat::LaterSubsteps && substep == 0) continue;
                expected.emplace_back(order[k].stage, substep);
            }
        }
        i = end;
    }
    REQUIRE(recorder.runs.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        INFO("run " << i << ": " << stageName(recorder.runs[i].first) << " in substep " << recorder.runs[i].second);
        CHECK(recorder.runs[i] == expected[i]);
    }
}

TEST_CASE("The explanation lists the stages in pipeline order, substeps indented, the other pipeline apart", "[plan]") {
    Scene scene = test::emptyScene();
    scene.settings.continuousCollision = true;
    scene.dynamics = {test::sphere("ball", Vec3(0, 1, 0))};
    scene.planes = {test::ground()};
    SECTION("Impulse: continuous after move-kinematics, before the broadphase") {
        scene.settings.solver = SolverKind::Impulse;
        const std::string text = describeStepPlan(planOf(scene));
        CHECK(text.find("move-kinematics") < text.find("continuous"));
        CHECK(text.find("continuous") < text.find("broadphase"));
        CHECK(text.find("broadphase") < text.find("correct-positions"));
        CHECK(text.find("substeps:") == std::string::npos);  // no substep loop (only the "packed substeps" line)
        CHECK(text.find("Not in this pipeline") < text.find("prepare-constraints"));
    }
    SECTION("SequentialImpulse: collision first, then the substep loop, then continuous, restitution, sleep") {
        scene.settings.solver = SolverKind::SequentialImpulse;
        scene.settings.substeps = 4;
        const std::string text = describeStepPlan(planOf(scene));
        const std::size_t loop = text.find("each of the 4 substeps:");
        REQUIRE(loop != std::string::npos);
        CHECK(text.find("prepare-constraints") < loop);
        CHECK(text.find("\n    integrate") > loop);
        CHECK(text.find("\n    solve-constraints") < text.find("\n  continuous"));
        CHECK(text.find("\n  continuous") < text.find("\n  restitution"));
        CHECK(text.find("Not in this pipeline") < text.find("resolve-impulses"));
    }
}

TEST_CASE("The viewer's skipped-stages line names only stages of the scene's own pipeline", "[plan][viewer]") {
    // A lone ball on a floor, no kinematic bodies: move-kinematics is skipped in either
    // pipeline; the other solver's stages are not skipped, they are not in the step.
    Scene scene = test::emptyScene();
    scene.dynamics = {test::sphere("ball", Vec3(0, 1, 0))};
    scene.planes = {test::ground()};
    SECTION("Impulse") {
        scene.settings.solver = SolverKind::Impulse;
        World world(scene);
        CHECK(skippedStagesLine(world.plan(), world.stageRecords(), false) ==
              "skipped stages: move-kinematics");
        world.step();
        CHECK(skippedStagesLine(world.plan(), world.stageRecords(), true) ==
              "skipped stages: move-kinematics");
    }
    SECTION("SequentialImpulse") {
        scene.settings.solver = SolverKind::SequentialImpulse;
        scene.settings.sleeping = true;
        World world(scene);
        world.step();
        const std::string line = skippedStagesLine(world.plan(), world.stageRecords(), true);
        CHECK(line == "skipped stages: move-kinematics");
        CHECK(line.find("resolve-impulses") == std::string::npos);
    }
}
