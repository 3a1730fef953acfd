// The step observer: the World reports every stage, in pipeline order, and
// watching does not change what happens. Tag: [observer].
#include <catch2/catch.hpp>

#include <vector>

#include "fast/fast_path_counts.hpp"
#include "test_support.hpp"

using namespace stepwise;

namespace {

/// Writes down every call it gets, and one thing a stage produced.
struct Recorder : StepObserver {
    std::vector<StageEvent> before;
    std::vector<StageEvent> after;
    std::vector<Real> velocityYAfterIntegrate;  ///< The first body's v_y after each Integrate, m/s.
    int steps = 0;

    void beforeStage(const StageEvent& event, const World&) override { before.push_back(event); }
    void afterStage(const StageEvent& event, const World& world) override {
        after.push_back(event);
        if (event.stage == Stage::Integrate) velocityYAfterIntegrate.push_back(world.dynamics()[0].velocity.y);
    }
    void afterStep(const World&) override { ++steps; }
};

/// A ball 10 m above the ground, falling from rest: nothing touches for the steps the tests take.
Scene fallingBall(SolverKind solver) {
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler);
    scene.settings.solver = solver;
    scene.dynamics.push_back(test::sphere("ball", Vec3(0, 10, 0)));
    scene.planes.push_back(test::ground());
    return scene;
}

}  // namespace

TEST_CASE("The observer sees the foundation's stages in pipeline order", "[observer]") {
    Scene scene = fallingBall(SolverKind::Impulse);
    scene.settings.stepPlan = false;  // with the plan, move-kinematics is skipped: no kinematic bodies
    World world(scene);
    Recorder recorder;
    world.setObserver(&recorder);
    world.step();

    // The foundation's seven, with continuous collision (on by default) after the moves, and the
    // soft bodies' stage last (it runs over none here: StepPlan=Off runs every stage of the pipeline).
    const std::vector<Stage> expected = {Stage::ApplyForces,  Stage::Integrate,   Stage::MoveKinematics,
                                         Stage::Continuous,   Stage::Broadphase,  Stage::Narrowphase,
                                         Stage::ResolveImpulses, Stage::CorrectPositions, Stage::SoftBodies};
    REQUIRE(recorder.before.size() == expected.size());
    REQUIRE(recorder.after.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        CHECK(recorder.before[i].stage == expected[i]);
        CHECK(recorder.after[i].stage == expected[i]);
        CHECK(recorder.after[i].step == 1);
        CHECK(recorder.after[i].substep == -1);
        CHECK(recorder.after[i].stepStartTime == 0);
    }
    CHECK(recorder.steps == 1);
}

TEST_CASE("The observer sees every substep of the sequential-impulse step", "[observer]") {
    Scene scene = fallingBall(SolverKind::SequentialImpulse);
    scene.settings.substeps = 4;
    World world(scene);
    Recorder recorder;
    world.setObserver(&recorder);
    world.step();
    world.step();

    // Symplectic Euler adds g·h_s to v_y at each substep, from rest:
    // after k substeps in all, v_y = −g·k·h/4 (exact up to rounding).
    const Real hs = scene.settings.timeStep / 4;
    REQUIRE(recorder.velocityYAfterIntegrate.size() == 8);
    for (std::size_t k = 0; k < 8; ++k) {
        CHECK(recorder.velocityYAfterIntegrate[k] == Approx(-kStandardGravity * hs * Real(k + 1)).epsilon(1e-12));
    }
    int integrates = 0;
    for (const StageEvent& event : recorder.after) {
        if (event.stage != Stage::Integrate) continue;
        CHECK(event.substep == integrates % 4);
        CHECK(event.substeps == 4);
        CHECK(event.step == std::uint64_t(integrates / 4 + 1));
        ++integrates;
    }
    CHECK(recorder.steps == 2);
}

TEST_CASE("Watching a step does not change it", "[observer]") {
    Scene scene = test::emptyScene();
    scene.dynamics.push_back(test::sphere("a", Vec3(0, 1, 0), Vec3(1, 0, 0.5)));
    scene.dynamics.push_back(test::sphere("b", Vec3(0.3, 2.1, 0), Vec3(-0.5, 0, 0)));
    scene.planes.push_back(test::ground());
    scene.settings.fastPath = true;  // whatever this build's default: unwatched, the fast path runs
    World watched(scene);
    World unwatched(scene);
    Recorder recorder;
    watched.setObserver(&recorder);
    for (int i = 0; i < 120; ++i) {
        watched.step();
        unwatched.step();
    }
    for (std::size_t i = 0; i < scene.dynamics.size(); ++i) {
        CHECK(watched.dynamics()[i].position == unwatched.dynamics()[i].position);
        CHECK(watched.dynamics()[i].velocity == unwatched.dynamics()[i].velocity);
        CHECK(watched.dynamics()[i].orientation == unwatched.dynamics()[i].orientation);
        CHECK(watched.dynamics()[i].angularVelocity == unwatched.dynamics()[i].angularVelocity);
        CHECK(watched.dynamics()[i].angularMomentum == unwatched.dynamics()[i].angularMomentum);
    }
    // Two roads to the same bits: watched, the substeps take the plain path, so that the observer sees
    // the objects current between the stages; unwatched, these balls take the fast path, on its packed
    // records (src/fast/fast_path.hpp).
    CHECK(watched.fastPathCounts().steps == 0);
    CHECK(unwatched.fastPathCounts().packedSteps > 0);
    CHECK(recorder.steps == 120);
}

TEST_CASE("The observer is not called for a stage the step plan skips", "[observer][plan]") {
    // No kinematic bodies: the plan skips move-kinematics, so it never runs and is never reported.
    World world(fallingBall(SolverKind::Impulse));
    Recorder recorder;
    world.setObserver(&recorder);
    world.step();
    REQUIRE_FALSE(world.plan().runs(Stage::MoveKinematics));
    CHECK(recorder.after.size() == 7);
    for (const StageEvent& event : recorder.after) CHECK(event.stage != Stage::MoveKinematics);
}
