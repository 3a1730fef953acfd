/// @file test_soft_sleep.cpp
/// @brief Soft bodies in islands and asleep (src/dynamics/islands.hpp), and Expect records about a
/// soft body (src/world/expectations.hpp). Tags: [soft][sleep], [soft][expect].
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "config/scene_loader.hpp"
#include "expectation_runner.hpp"
#include "io/trace_writer.hpp"
#include "objects/soft_mesh.hpp"
#include "soft/soft_stages.hpp"
#include "test_support.hpp"
#include "world/expectations.hpp"
#include "world/world.hpp"

using namespace stepwise;
using Catch::Contains;

namespace {

/// A damped soft ball of radius 0.5 m and 1 kg, 42 nodes (Resolution=1), centred at @p centre.
/// Dampers of 4 N·s/m on springs of 100 N/m: dropped 0.3 m onto a floor, its fastest node is below
/// 5 cm/s within 2.5 s (c·h_s/m_node = 0.35 per spring at 8 substeps of 1/60 s, inside the limit).
SoftBody dampedBall(const std::string& name, Vec3 centre, Real nRT = 40) {
    SoftBodyMaking making;
    making.resolution = 1;
    making.position = centre;
    making.radius = Real(0.5);
    making.mass = 1;
    making.stiffness = 100;
    making.damping = 4;
    making.nRT = nRT;
    SoftBody body;
    body.name = name;
    body.elasticity = 0;
    body.friction = Real(0.8);
    buildSoftBody(making, body);
    return body;
}

/// Steps of 1/60 s in 8 substeps under gravity, with a floor at y = 0, Sleep=true.
Scene floorScene() {
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.settings.substeps = 8;
    scene.settings.sleeping = true;
    scene.planes.push_back(test::ground());
    return scene;
}

/// Steps @p world until @p done or @p most steps; the steps taken.
template <class Done>
int stepUntil(World& world, int most, Done done) {
    int steps = 0;
    while (steps < most && !done()) {
        world.step();
        ++steps;
    }
    return steps;
}

constexpr int kStepsPerSecond = 60;

}  // namespace

// ------------------------------------------------------------------ sleep

TEST_CASE("A damped soft ball dropped on a floor falls asleep within 4 s, and its nodes then stay put", "[soft][sleep]") {
    // Dropped from 0.3 m it lands after √(2·0.3/g) = 0.25 s; the dampers take the bounce and the
    // breathing out in about 2.5 s, and sleep needs every node slow for TimeToSleep = 0.5 s after that.
    Scene scene = floorScene();
    scene.softBodies.push_back(dampedBall("ball", Vec3(0, 0.85, 0)));
    World world(std::move(scene));
    const SoftBody& ball = world.softBodies()[0];
    const int steps = stepUntil(world, 4 * kStepsPerSecond, [&] { return ball.asleep; });
    INFO("steps " << steps);
    REQUIRE(ball.asleep);
    CHECK(steps > kStepsPerSecond / 2);  // not at once: it had to land and settle
    CHECK(ball.position.y < Real(0.53));  // on the floor, squashed a little by its weight

    // Asleep, the nodes are not moved at all: positions identical, bit for bit, and velocities zero
    const std::vector<Vec3> asleepAt = ball.nodePositions;
    for (int i = 0; i < kStepsPerSecond; ++i) world.step();
    CHECK(ball.asleep);
    CHECK(ball.nodePositions == asleepAt);
    for (const Vec3& v : ball.nodeVelocities) REQUIRE(v == Vec3(0));
}

TEST_CASE("With Sleep=false the soft ball never sleeps", "[soft][sleep]") {
    Scene scene = floorScene();
    scene.settings.sleeping = false;
    scene.softBodies.push_back(dampedBall("ball", Vec3(0, 0.85, 0)));
    World world(std::move(scene));
    for (int i = 0; i < 4 * kStepsPerSecond; ++i) world.step();
    CHECK_FALSE(world.softBodies()[0].asleep);
    CHECK_FALSE(world.plan().idleSkip.runs);
}

TEST_CASE("A rigid ball dropped on a sleeping soft ball wakes it, and its nodes move again", "[soft][sleep]") {
    Scene scene = floorScene();
    scene.softBodies.push_back(dampedBall("soft", Vec3(0, 0.85, 0)));
    // The rigid ball waits on the floor far away, asleep in an island of its own
    scene.dynamics.push_back(test::sphere("rigid", Vec3(5, 0.2, 0), Vec3(0), Real(0.2), Real(0.5)));
    World world(std::move(scene));
    const SoftBody& soft = world.softBodies()[0];
    stepUntil(world, 4 * kStepsPerSecond, [&] { return soft.asleep && world.dynamics()[0].asleep; });
    REQUIRE(soft.asleep);
    REQUIRE(world.dynamics()[0].asleep);
    CHECK(world.softBodies()[0].sleepIsland != world.dynamics()[0].sleepIsland);  // apart: two islands

    // Lift it over the soft ball's top, 0.3 m clear, and let it go (as a hand in the viewer would)
    const Real top = soft.position.y + Real(0.6);
    {
        DynamicObject& rigid = world.dynamics()[0];
        rigid.position = Vec3(0, top + Real(0.5), 0);
        rigid.asleep = false;
        rigid.stillTime = 0;
    }
    const std::vector<Vec3> before = soft.nodePositions;
    // It falls 0.3 m in √(2·0.3/g) = 0.25 s; within 0.5 s it has struck the soft ball
    const int steps = stepUntil(world, kStepsPerSecond / 2, [&] { return !soft.asleep; });
    INFO("woke after " << steps << " steps");
    REQUIRE_FALSE(soft.asleep);
    for (int i = 0; i < 10; ++i) world.step();
    Real moved = 0;
    for (std::size_t i = 0; i < before.size(); ++i) moved = std::max(moved, glm::length(soft.nodePositions[i] - before[i]));
    CHECK(moved > Real(1e-3));                            // struck: its nodes move again
    CHECK(world.dynamics()[0].position.y > soft.position.y);  // and hold the rigid ball up, on top
}

TEST_CASE("A soft ball resting on a heavy rigid block sleeps with it as one island, then the steps are idle",
          "[soft][sleep][plan]") {
    // The soft ball on a 10 kg block (1.2 × 0.3 × 1.2 m) on the floor. A light box resting on top of a
    // soft ball does not settle yet: it creeps at about 0.1 m/s on the nodes (node_collisions.cpp), so
    // the arrangement is turned over, and the block is heavy so that the nodes' push, given after the
    // rigid solve, moves it by less than the sleep speed: m_ball·g·h/m_block = 0.016 m/s.
    Scene scene = floorScene();
    scene.dynamics.push_back(test::dynamicBox("block", Vec3(0, 0.15, 0), Vec3(1.2, 0.3, 1.2), Real(10), Real(0.8)));
    scene.softBodies.push_back(dampedBall("ball", Vec3(0, 0.88, 0)));
    World world(std::move(scene));
    const SoftBody& ball = world.softBodies()[0];
    const DynamicObject& block = world.dynamics()[0];
    int ballAt = -1, blockAt = -1;
    for (int step = 1; step <= 6 * kStepsPerSecond && (ballAt < 0 || blockAt < 0); ++step) {
        world.step();
        if (ball.asleep && ballAt < 0) ballAt = step;
        if (block.asleep && blockAt < 0) blockAt = step;
    }
    INFO("ball asleep at step " << ballAt << ", block at step " << blockAt);
    REQUIRE(ballAt > 0);
    CHECK(ballAt == blockAt);                        // one island: both at the same step
    CHECK(ball.sleepIsland == block.sleepIsland);    // fallen asleep as one island, not two at one step
    CHECK(ball.position.y > block.position.y + Real(0.5));  // the ball is on the block, not beside it

    // Everything asleep, nothing moving: the step plan's idle skip returns at once, running no stage
    REQUIRE(world.plan().idleSkip.runs);
    const std::vector<Vec3> nodes = ball.nodePositions;
    const Vec3 blockAt0 = block.position;
    world.step();
    for (const StageRecord& record : world.stageRecords()) CHECK_FALSE(record.ranLastStep);
    CHECK(ball.nodePositions == nodes);
    CHECK(block.position == blockAt0);

    // Waking the block (a push from the viewer's mouse) wakes the ball that rests on it: one island
    CHECK(world.wakeIsland(0) == 2);
    CHECK_FALSE(ball.asleep);
    CHECK_FALSE(block.asleep);
}

TEST_CASE("stepwise trace shows a soft body awake, falling asleep and asleep, as a rigid one", "[soft][sleep][trace]") {
    // The ball on the block of the test above: find the step they fall asleep at, then trace the
    // sleep stage of that step and the one before, and the soft stage of the step after.
    Scene scene = floorScene();
    scene.dynamics.push_back(test::dynamicBox("block", Vec3(0, 0.15, 0), Vec3(1.2, 0.3, 1.2), Real(10), Real(0.8)));
    scene.softBodies.push_back(dampedBall("ball", Vec3(0, 0.88, 0)));
    std::uint64_t asleepAt = 0;
    {
        World world{Scene(scene)};
        while (world.stepCount() < 6 * kStepsPerSecond && !world.softBodies()[0].asleep) world.step();
        REQUIRE(world.softBodies()[0].asleep);
        asleepAt = world.stepCount();
    }
    TraceOptions options;
    options.from = asleepAt - 1;
    options.steps = 2;
    options.stages = {Stage::Sleep};
    std::ostringstream out;
    REQUIRE(writeTrace(scene, options, out, {}));
    const std::string step = "step " + std::to_string(asleepAt);
    const std::string before = "step " + std::to_string(asleepAt - 1);
    CHECK_THAT(out.str(), Contains(before + "  sleep  ball  awake  island 0  still ") &&
                              Contains("fastest node |v| ") &&
                              Contains(step + "  sleep  ball  falls asleep (its island was still for 0.5") &&
                              Contains(step + "  sleep  block  falls asleep"));
    // Asleep, it is left out of the soft stage, as an asleep rigid body is from integrate: the
    // next step is idle and runs no stage at all
    options.from = asleepAt + 1;
    options.steps = 1;
    options.stages = {Stage::SoftBodies};
    std::ostringstream after;
    REQUIRE(writeTrace(scene, options, after, {}));
    CHECK_THAT(after.str(), !Contains("soft-bodies  ball"));
}

// ------------------------------------------------------------------ Expect

namespace {

/// The single verdict of each Expect record of @p text, run as `stepwise run` does.
test::ExpectationOutcome runText(const std::string& text) { return test::runExpectations(parseScene(text, "soft.scene")); }

std::vector<ConfigDiagnostic> problemsIn(const std::string& text) {
    try {
        parseScene(text, "soft.scene");
    } catch (const ConfigError& error) {
        return error.diagnostics();
    }
    return {};
}

std::string fixed(Real value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", double(value));
    return text;
}

}  // namespace

TEST_CASE("Expect on a soft ball without gravity: Volume and Pressure where the gas balances the springs, 1 %",
          "[soft][expect]") {
    // The balance of the [soft] test "Without gravity a soft ball settles ...": every node at s times
    // its distance from the centre, 3·nRT = k·(s − 1)·s·ΣL0², so V = s³·V0 and P = nRT / V.
    const Real k = 100, nRT = 40;
    SoftBodyMaking making;
    making.resolution = 2;
    making.radius = Real(0.5);
    making.stiffness = k;
    making.nRT = nRT;
    SoftBody mesh;
    buildSoftBody(making, mesh);
    Real sumL0 = 0;
    for (std::uint32_t i = 0; i < mesh.edgeSprings; ++i) sumL0 += mesh.springs[i].restLength * mesh.springs[i].restLength;
    const Real v0 = enclosedVolume(mesh.nodePositions, mesh.faces);
    const Real s = (1 + std::sqrt(1 + 12 * nRT / (k * sumL0))) / 2;
    const Real volume = s * s * s * v0;
    const Real pressure = nRT / volume;
    const std::string text =
        "World, TimeStep=1/60, Substeps=8, Gravity=(0, 0, 0), Duration=20\n"
        "SoftBody, Name=ball, Shape=Sphere, Radius=0.5, Resolution=2, Mass=1, Stiffness=100, Damping=0.1, Pressure=40\n"
        "Expect, Object=ball, Time=20, Pressure=" + fixed(pressure) + ", Tolerance=" + fixed(pressure / 100) + "\n" +
        "Expect, Object=ball, Time=20, Volume=" + fixed(volume) + ", Tolerance=" + fixed(volume / 100) + "\n" +
        // Nothing pushes it: its centre stays at the origin, and it never moves off
        "Expect, Object=ball, Until=20, Position=(0, 0, 0), Tolerance=1e-9\n"
        // A pressure a tenth too high must fail: the check can tell
        "Expect, Object=ball, Time=20, Pressure=" + fixed(pressure * Real(1.1)) + ", Tolerance=" + fixed(pressure / 100) + "\n";
    const test::ExpectationOutcome outcome = runText(text);
    REQUIRE(outcome.results.size() == 4);
    for (std::size_t i = 0; i < 4; ++i) {
        INFO(describe(outcome.expectations[i]) << " -> " << describeMeasurement(outcome.expectations[i], outcome.results[i]));
        CHECK(outcome.results[i].passed == (i < 3));
    }
    CHECK(outcome.results[0].value == Approx(pressure).epsilon(0.01));
}

TEST_CASE("Expect on a soft ball dropped on a floor: at rest after 3 s, its centre in a band, asleep", "[soft][expect][sleep]") {
    // Dropped with its lowest node 0.3 m up, it lands at 0.25 s and the dampers settle it. At rest its
    // centre is below the inflated radius (the ball sags under its weight) and well above half of it:
    // 0.3 m < y < 0.6 m.
    const std::string scene =
        "World, TimeStep=1/60, Substeps=8, Duration=5, Sleep=true\n"
        "CollisionPlane, Name=floor, Friction=0.8\n"
        "SoftBody, Name=ball, Shape=Sphere, Position=(0, 0.85, 0), Radius=0.5, Resolution=1, Mass=1, Stiffness=100, "
        "Damping=4, Pressure=40, Elasticity=0, Friction=0.8\n"
        "Expect, Object=ball, From=3, Until=5, AtRest=true\n"
        "Expect, Object=ball, From=3, Until=5, PositionY=0.45, Tolerance=0.15\n"
        "Expect, Object=ball, Until=5, NotThroughPlane=floor\n"
        "Expect, Object=ball, Time=5, Asleep=true\n"
        "Expect, Object=ball, Apex=1, PositionY=0.85, Compare=AtMost\n"
        // Falling, it is not at rest: AtRest=false holds at 0.2 s (v = g·0.2 s = 2 m/s)
        "Expect, Object=ball, Time=0.2, AtRest=false\n"
        "Expect, Object=ball, Time=0.2, VelocityY=" + fixed(-kStandardGravity * Real(0.2)) + ", Tolerance=0.01\n";
    const test::ExpectationOutcome outcome = runText(scene);
    REQUIRE(outcome.results.size() == 7);
    for (std::size_t i = 0; i < outcome.results.size(); ++i) {
        INFO(describe(outcome.expectations[i]) << " -> " << describeMeasurement(outcome.expectations[i], outcome.results[i]));
        CHECK(outcome.results[i].passed);
    }
}

TEST_CASE("Expect EnergyChange of a soft ball matches its energy summed independently", "[soft][expect]") {
    // Free flight, no dampers: springs, gas and gravity are conservative (pressure_forces.cpp), and
    // symplectic Euler keeps the energy within its O(h) breathing error. The monitor's value is
    // checked against the energy summed here from the nodes: ½mv² − m·g·x + ½k(l − L0)² − nRT·ln V.
    const std::string text =
        "World, TimeStep=1/120, Substeps=8, Duration=1\n"
        "SoftBody, Name=ball, Shape=Sphere, Position=(0, 5, 0), Velocity=(1, 2, 0), Radius=0.5, Resolution=1, "
        "Mass=1, Stiffness=100, Damping=0, Pressure=40\n"
        "Expect, Object=ball, Time=1, EnergyChange=0, Tolerance=0.01\n";
    const Scene scene = parseScene(text, "soft.scene");
    const auto energy = [&](const SoftBody& b) {
        Real e = 0;
        for (std::size_t i = 0; i < b.nodeCount(); ++i) {
            const Real m = 1 / b.nodeInverseMasses[i];
            e += Real(0.5) * m * glm::dot(b.nodeVelocities[i], b.nodeVelocities[i]) -
                 m * glm::dot(scene.settings.gravity, b.nodePositions[i]);
        }
        for (const SoftSpring& sp : b.springs) {
            const Real stretch = glm::length(b.nodePositions[sp.b] - b.nodePositions[sp.a]) - sp.restLength;
            e += Real(0.5) * sp.stiffness * stretch * stretch;
        }
        return e - b.nRT * std::log(enclosedVolume(b.nodePositions, b.faces));
    };
    const Real e0 = energy(scene.softBodies[0]);
    World world{Scene(scene)};
    for (int i = 0; i < 120; ++i) world.step();
    const Real expected = (energy(world.softBodies()[0]) - e0) / std::abs(e0);

    const test::ExpectationOutcome outcome = test::runExpectations(scene);
    REQUIRE(outcome.results.size() == 1);
    INFO(describeMeasurement(outcome.expectations[0], outcome.results[0]));
    CHECK(outcome.results[0].passed);
    CHECK(outcome.results[0].value == Approx(expected).margin(1e-12));
}

TEST_CASE("Expect records about a soft body refuse a rigid-only quantity, and a rigid body Volume and Pressure",
          "[soft][expect][config]") {
    struct Case {
        const char* line;
        int column;
        const char* field;
        const char* words;
    };
    const Case cases[] = {
        // column 29 is "TiltDeg=1"
        {"Expect, Object=ball, Time=1, TiltDeg=1, Tolerance=1", 30, "TiltDeg", "a quantity a SoftBody has"},
        {"Expect, Object=ball, Time=1, AngularSpeed=0, Tolerance=1", 30, "AngularSpeed", "no single rotation"},
        {"Expect, Object=box, Time=1, Volume=1, Tolerance=1", 29, "Volume", "a quantity a DynamicObject has"},
        {"Expect, Object=box, Time=1, Pressure=1, Tolerance=1", 29, "Pressure", "are a SoftBody's"},
        {"Expect, Object=bal, Time=1, Volume=1, Tolerance=1", 16, "Object", "did you mean 'ball'?"},
        {"Expect, Object=floor, Time=1, Volume=1, Tolerance=1", 16, "Object", "the name of a DynamicObject or SoftBody"},
        {"Expect, Object=ball, Time=1, Pressure=-1, Tolerance=1", 39, "Pressure", "a number >= 0"},
        {"Expect, Object=ball, Time=1, Volume=1", 1, "Tolerance", "a Tolerance for Volume"},
    };
    for (const Case& c : cases) {
        const std::string text = std::string("DynamicObject, Name=box, Shape=Box\nCollisionPlane, Name=floor\n"
                                             "SoftBody, Name=ball, Position=(0, 3, 0), Stiffness=50\n") + c.line + "\n";
        INFO(c.line);
        const std::vector<ConfigDiagnostic> problems = problemsIn(text);
        for (const ConfigDiagnostic& problem : problems) INFO(problem.message());
        REQUIRE(problems.size() == 1);
        CHECK(problems[0].line == 4);
        CHECK(problems[0].column == c.column);
        CHECK(problems[0].field == c.field);
        CHECK_THAT(problems[0].message(), Contains(c.words));
    }
    // And the good ones load
    CHECK(problemsIn("SoftBody, Name=ball, Stiffness=50\nExpect, Object=ball, Time=1, Volume=0.5, Tolerance=0.1\n"
                     "Expect, Object=BALL, Time=1, Speed=0, Tolerance=0.1\n")
              .empty());
}
