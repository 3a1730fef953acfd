// Expect records: what the loader makes of them, what the monitor measures
// (against closed-form motion), and how `stepwise run` and `stepwise grade`
// report them. Tag: [expect] (the command tests also [cli]).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "config/scene_loader.hpp"
#include "expectation_runner.hpp"
#include "test_support.hpp"

using namespace stepwise;
using Catch::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// Round-off allowance for quantities the integrators reproduce exactly (Verlet under constant g).
constexpr Real kRoundOff = 1e-9;

/// The single expectation of a one-Expect scene, and its verdict.
struct Single {
    Expectation expectation;
    ExpectationResult result;
};

Single runSingle(const std::string& text) {
    const test::ExpectationOutcome outcome = test::runExpectations(parseScene(text, "test.scene"));
    REQUIRE(outcome.results.size() == 1);
    INFO(describe(outcome.expectations[0]) << " -> " << describeMeasurement(outcome.expectations[0], outcome.results[0]));
    return {outcome.expectations[0], outcome.results[0]};
}

std::vector<ConfigDiagnostic> problemsIn(const std::string& text) {
    try {
        (void)parseScene(text, "test.scene");
    } catch (const ConfigError& error) {
        return error.diagnostics();
    }
    FAIL("the scene loaded, but it should have been rejected:\n" << text);
    return {};
}

/// A scratch folder below the system's temporary folder, removed at scope exit.
struct TempFolder {
    std::filesystem::path path;
    explicit TempFolder(const std::string& name)
        : path(std::filesystem::temp_directory_path() / ("stepwise-test-" + name)) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempFolder() { std::filesystem::remove_all(path); }
    void write(const std::string& file, const std::string& text) const {
        std::filesystem::create_directories((path / file).parent_path());
        std::ofstream(path / file) << text;
    }
    std::string quoted() const { return "'" + path.string() + "'"; }
};

using stepwise::test::runStepwise;

}  // namespace

// ------------------------------------------------------------------ loading

TEST_CASE("An Expect record loads into an Expectation", "[expect][config]") {
    const Scene scene = parseScene(
        "CollisionPlane, Name=Floor\n"
        "Expect, Object=BALL, Apex=3, PositionY=0.6, Tolerance=0.02\n"
        "Expect, Object=ball, From=1, Until=2, AtRest=no, Tolerance=0.05\n"
        "Expect, Until=4, EnergyChange=0.1, Compare=AtMost\n"
        "Expect, Object=ball, Time=2, Velocity=(1, 2, 3), Tolerance=0.5\n"
        "Expect, Object=ball, NotThroughPlane=floor\n"
        "DynamicObject, Name=Ball\n",  // declared after the records that name it
        "test.scene");
    REQUIRE(scene.expectations.size() == 5);
    const Expectation& apex = scene.expectations[0];
    CHECK(apex.line == 2);
    CHECK(apex.object == "Ball");  // the body's own spelling
    CHECK(apex.quantity == ExpectQuantity::Position);
    CHECK(apex.component == 1);
    CHECK(apex.when == ExpectWhen::Apex);
    CHECK(apex.apex == 3);
    CHECK(apex.target == Approx(0.6));
    CHECK(apex.tolerance == Approx(0.02));
    CHECK(apex.compare == ExpectCompare::Within);

    const Expectation& moving = scene.expectations[1];
    CHECK(moving.quantity == ExpectQuantity::AtRest);
    CHECK_FALSE(moving.flag);
    CHECK(moving.when == ExpectWhen::Throughout);
    CHECK(moving.from == Approx(1));
    CHECK(moving.until == Approx(2));

    const Expectation& energy = scene.expectations[2];
    CHECK(energy.object.empty());
    CHECK(energy.compare == ExpectCompare::AtMost);
    CHECK(energy.from == 0);
    CHECK(energy.until == Approx(4));

    const Expectation& velocity = scene.expectations[3];
    CHECK(velocity.when == ExpectWhen::Instant);
    CHECK(velocity.component == -1);
    CHECK(velocity.targetVector == Vec3(1, 2, 3));

    const Expectation& plane = scene.expectations[4];
    CHECK(plane.plane == "Floor");
    CHECK(plane.tolerance == 0);
    // AtRest without a Tolerance gets the documented default.
    CHECK(parseScene("DynamicObject, Name=b\nExpect, Object=b, AtRest=true\n", "t.scene").expectations[0].tolerance ==
          kDefaultRestSpeed);
}

TEST_CASE("Each rule of the Expect record is reported at its line and column", "[expect][config]") {
    struct Case {
        const char* line;  // the second line of the file; the first declares ball and floor
        int column;
        const char* field;
        const char* words;  // part of the message
    };
    const Case cases[] = {
        // no quantity: reported at the record name
        {"Expect, Object=ball, Time=1", 1, "Expect", "one quantity to check"},
        // two components are two quantities: column 43 is "PositionY=1"
        {"Expect, Object=ball, Time=1, PositionX=1, PositionY=1, Tolerance=1", 43, "PositionY",
         "one quantity per Expect record"},
        // Time and a window: column 30 is "From=1"
        {"Expect, Object=ball, Time=1, From=1, Speed=1, Tolerance=1", 30, "From", "one timing per Expect record"},
        {"Expect, Object=ball, From=2, Until=1, Speed=1, Tolerance=1", 36, "Until", "a time not before From"},
        {"Expect, Object=ball, Apex=1.5, Speed=1, Tolerance=1", 27, "Apex", "a whole number"},
        {"Expect, Object=ball, Apex=0, Speed=1, Tolerance=1", 27, "Apex", "a number > 0"},
        {"Expect, Object=ball, Speed=1", 1, "Tolerance", "a Tolerance for Speed"},
        {"Expect, Object=ball, Position=(1, 2, 3)", 1, "Tolerance", "a Tolerance for Position"},
        // a problem with a value is reported at the value (Tolerance=1: its '1')
        {"Expect, Object=ball, Speed=1, Compare=AtMost, Tolerance=1", 57, "Tolerance", "no Tolerance for Speed"},
        {"Expect, Object=ball, Asleep=true, Tolerance=1", 45, "Tolerance", "no Tolerance for Asleep"},
        {"Expect, Object=ball, AtRest=true, Compare=AtMost", 43, "Compare", "no Compare for AtRest"},
        {"Expect, Object=ball, Position=(1, 2, 3), Compare=AtLeast, Tolerance=1", 50, "Compare", "no Compare"},
        {"Expect, Speed=1, Tolerance=1", 1, "Object", "the name of the DynamicObject or SoftBody to check"},
        {"Expect, Object=floor, Speed=1, Tolerance=1", 16, "Object", "the name of a DynamicObject"},
        {"Expect, Object=ball, NotThroughPlane=ball", 38, "NotThroughPlane", "the name of a CollisionPlane"},
        {"Expect, Object=ball, TiltDeg=-1, Tolerance=1", 30, "TiltDeg", "a number >= 0"},
        {"Expect, Object=ball, Speed=1, Tolerance=1, Compare=Equal", 52, "Compare", "one of Within, AtLeast, AtMost"},
        {"Expect, Object=ball, Speed=1, Tolerance=1, Mass=2", 44, "Expect", "one of its fields"},
    };
    for (const Case& c : cases) {
        const std::string text = std::string("DynamicObject, Name=ball\nCollisionPlane, Name=floor\n") + c.line + "\n";
        INFO(c.line);
        const std::vector<ConfigDiagnostic> problems = problemsIn(text);
        for (const ConfigDiagnostic& problem : problems) INFO(problem.message());
        REQUIRE(problems.size() == 1);
        CHECK(problems[0].line == 3);
        CHECK(problems[0].column == c.column);
        CHECK(problems[0].field == c.field);
        CHECK_THAT(problems[0].message(), Contains(c.words));
    }
}

// ------------------------------------------------------------------ measuring

TEST_CASE("Time samples the step nearest the moment: Verlet free fall is exact", "[expect]") {
    // Verlet's update is the constant-acceleration formula, so y(t) = y0 + v0 t − ½ g t² at every step.
    const Real y0 = 10, v0 = 4, t = 1.5;
    const Real expected = y0 + v0 * t - Real(0.5) * kStandardGravity * t * t;
    const Single s = runSingle("World, Integrator=Verlet, TimeStep=1/10, Duration=2\n"
                               "DynamicObject, Name=ball, Position=(0, 10, 0), Velocity=(0, 4, 0)\n"
                               "Expect, Object=ball, Time=1.52, PositionY=" + std::to_string(expected) +
                               ", Tolerance=1e-6\n");
    CHECK(s.result.passed);
    CHECK_THAT(s.result.time, WithinAbs(1.5, kRoundOff));  // 1.52 is nearest to step 15 of 0.1 s
    CHECK_THAT(s.result.value, WithinAbs(expected, kRoundOff));

    const Single missed = runSingle("World, Integrator=Verlet, TimeStep=1/10, Duration=2\n"
                                    "DynamicObject, Name=ball, Position=(0, 10, 0), Velocity=(0, 4, 0)\n"
                                    "Expect, Object=ball, Time=1.5, PositionY=7, Tolerance=0.1\n");
    CHECK_FALSE(missed.result.passed);
    CHECK(missed.result.measured);
    CHECK_THAT(missed.result.value, WithinAbs(expected, kRoundOff));
}

TEST_CASE("Apex finds the top of a throw within g h^2 / 8", "[expect]") {
    // Thrown up at v0 from y = 0: the top is v0²/(2g) at t = v0/g. The sample is the higher
    // of the two steps around the turn, at most half a step from the top: ½·g·(h/2)² = g·h²/8 below it.
    const Real v0 = 5, h = Real(1) / 60;
    const Real top = v0 * v0 / (2 * kStandardGravity);
    const Single s = runSingle("World, Integrator=Verlet, TimeStep=1/60, Duration=2\n"
                               "DynamicObject, Name=ball, Velocity=(0, 5, 0)\n"
                               "Expect, Object=ball, Apex=1, PositionY=" + std::to_string(top) + ", Tolerance=0.01\n");
    CHECK(s.result.passed);
    CHECK(s.result.value <= top + kRoundOff);
    CHECK(s.result.value >= top - kStandardGravity * h * h / 8 - kRoundOff);
    CHECK(std::abs(s.result.time - v0 / kStandardGravity) <= h / 2 + kRoundOff);

    const Single second = runSingle("World, Integrator=Verlet, TimeStep=1/60, Duration=2\n"
                                    "DynamicObject, Name=ball, Velocity=(0, 5, 0)\n"
                                    "Expect, Object=ball, Apex=2, PositionY=1, Tolerance=1\n");
    CHECK_FALSE(second.result.passed);
    CHECK_FALSE(second.result.measured);
    CHECK_THAT(second.result.reason, Contains("only 1 apex(es)"));
}

TEST_CASE("Apex counts bounces: the n-th apex of a ball of elasticity e is e^(2n) of the drop", "[expect]") {
    // Each impact returns e·v, so each rise reaches e² of the height before it (lecture 3).
    const Real e = 0.8, drop = 1, radius = 0.1;
    for (int n = 1; n <= 3; ++n) {
        const Real apex = radius + std::pow(e, 2 * n) * drop;
        const Single s = runSingle("World, Integrator=Verlet, TimeStep=1/60, Duration=5\n"
                                   "CollisionPlane, Name=floor\n"
                                   "DynamicObject, Name=ball, Position=(0, 1.1, 0), Radius=0.1, Elasticity=0.8\n"
                                   "Expect, Object=ball, Apex=" + std::to_string(n) + ", PositionY=" +
                                   std::to_string(apex) + ", Tolerance=0.005\n");
        INFO("apex " << n << ": expected " << apex << " m, measured " << s.result.value << " m");
        CHECK(s.result.passed);
    }
}

TEST_CASE("EnergyChange under explicit Euler grows as g h t / (2 y0) in free fall", "[expect]") {
    // Explicit Euler keeps v exact and lets y lag by ½·g·h·t, so E = ½mv² + mgy gains
    // m·g·(½·g·h·t); from rest at height y0, E0 = m·g·y0, so ΔE/E0 = g·h·t / (2·y0).
    const Real y0 = 10, h = Real(1) / 60, t = 1;
    const Real expected = kStandardGravity * h * t / (2 * y0);
    const std::string scene = "World, Integrator=Euler, TimeStep=1/60, Duration=1, Solver=Impulse\n"
                              "DynamicObject, Name=ball, Position=(0, 10, 0), Mass=3\n";
    const Single one = runSingle(scene + "Expect, Object=ball, Time=1, EnergyChange=" + std::to_string(expected) +
                                 ", Tolerance=1e-6\n");
    CHECK(one.result.passed);
    CHECK_THAT(one.result.value, WithinRel(double(expected), 1e-9));
    // The whole scene's energy, checked through the run: the worst step is the last.
    const Single all = runSingle(scene + "Expect, Until=1, EnergyChange=0, Tolerance=0.005\n");
    CHECK_FALSE(all.result.passed);
    CHECK_THAT(all.result.value, WithinRel(double(expected), 1e-9));
    CHECK_THAT(all.result.time, WithinAbs(1, kRoundOff));
}

TEST_CASE("AtRest: a sliding box is moving until friction stops it at v0 / (mu g)", "[expect]") {
    // Kinetic friction decelerates it at μ·g: from 2 m/s with μ = 0.5 it stops at 0.408 s.
    const std::string scene = "World, Integrator=SymplecticEuler, TimeStep=1/120, Duration=1\n"
                              "CollisionPlane, Name=floor\n"
                              "DynamicObject, Name=box, Shape=Box, Position=(0, 0.5, 0), Velocity=(2, 0, 0), "
                              "Elasticity=0, Friction=0.5\n";
    const Real stop = 2 / (0.5 * kStandardGravity);
    const Single sliding = runSingle(scene + "Expect, Object=box, Until=0.35, AtRest=false\n");
    CHECK(sliding.result.passed);
    const Single stopped = runSingle(scene + "Expect, Object=box, From=0.5, Until=1, AtRest=true\n");
    CHECK(stopped.result.passed);
    const Single early = runSingle(scene + "Expect, Object=box, Until=1, AtRest=true\n");
    CHECK_FALSE(early.result.passed);
    CHECK_THAT(early.result.value, WithinAbs(2, 1e-9));  // the worst moment is the launch
    CHECK(stop > 0.35);
    CHECK(stop < 0.5);
}

TEST_CASE("TiltDeg is the angle of the body's y axis from up", "[expect]") {
    // A cube spun about z at π/4 rad/s with no gravity and no torque has turned 45° after 1 s
    // (its inertia is isotropic, so ω stays constant and the rotation is exact).
    const Single s = runSingle("World, Gravity=(0, 0, 0), Duration=1\n"
                               "DynamicObject, Name=cube, Shape=Box, AngularVelocity=(0, 0, 0.7853981633974483)\n"
                               "Expect, Object=cube, Time=1, TiltDeg=45, Tolerance=1e-6\n");
    CHECK(s.result.passed);
    // Turning about the vertical does not tilt; a 30 degree Rotation about x does.
    CHECK(runSingle("World, Gravity=(0, 0, 0), Duration=1\n"
                    "DynamicObject, Name=box, Shape=Box, Rotation=(0, 40, 0), AngularVelocity=(0, 2, 0)\n"
                    "Expect, Object=box, Until=1, TiltDeg=1e-6, Compare=AtMost\n")
              .result.passed);
    CHECK(runSingle("World, Gravity=(0, 0, 0), Duration=1\n"
                    "DynamicObject, Name=box, Shape=Box, Rotation=(30, 0, 0)\n"
                    "Expect, Object=box, Time=0.5, TiltDeg=30, Tolerance=1e-9\n")
              .result.passed);
}

TEST_CASE("NotThroughPlane measures the centre's signed distance, and fails behind the plane", "[expect]") {
    // Free flight towards the floor: the closest the centre comes in the first 0.5 s is y(0.5).
    const Real closest = 5 - Real(0.5) * kStandardGravity * Real(0.25);
    const Single s = runSingle("World, Integrator=Verlet, TimeStep=1/100, Duration=0.5\n"
                               "CollisionPlane, Name=floor\n"
                               "DynamicObject, Name=ball, Position=(0, 5, 0)\n"
                               "Expect, Object=ball, Until=0.5, NotThroughPlane=floor\n");
    CHECK(s.result.passed);
    CHECK_THAT(s.result.value, WithinAbs(closest, kRoundOff));

    // Tunnelling cannot happen against a plane (its whole back is solid), so put the body
    // behind it by hand between two observations, as a fast body in a thin wall would be.
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60, Vec3(0));
    scene.planes.push_back(test::ground("floor"));
    scene.dynamics.push_back(test::sphere("ball", Vec3(0, 5, 0)));
    Expectation e;
    e.object = "ball";
    e.quantity = ExpectQuantity::NotThroughPlane;
    e.plane = "floor";
    World world(scene);
    ExpectationMonitor monitor(world, {e});
    monitor.observe(world);
    world.dynamics()[0].position.y = -0.25;
    monitor.observe(world);
    const ExpectationResult r = monitor.results(world)[0];
    CHECK_FALSE(r.passed);
    CHECK_THAT(r.value, WithinAbs(-0.25, kRoundOff));
}

TEST_CASE("A moment the run never reaches fails as not reached", "[expect]") {
    const std::string scene = "World, Duration=1\nDynamicObject, Name=ball\n";
    const Single late = runSingle(scene + "Expect, Object=ball, Time=2, Speed=0, Compare=AtLeast\n");
    CHECK_FALSE(late.result.passed);
    CHECK_THAT(late.result.reason, Contains("not reached"));
    // A window that held as far as the run went is still not a pass.
    const Single window = runSingle(scene + "Expect, Object=ball, Until=3, Speed=100, Compare=AtMost\n");
    CHECK_FALSE(window.result.passed);
    CHECK(window.result.measured);
    CHECK_THAT(window.result.reason, Contains("not reached"));
}

TEST_CASE("Asleep reads the body's sleep, and unknown names fail at the monitor", "[expect][sleep]") {
    // A ball resting on the floor is still from the start: asleep after the
    // time to sleep (0.5 s), never in the air.
    const std::string resting = "World, Duration=2\nCollisionPlane, 0, 0, 0, 0, 1, 0\n"
                                "DynamicObject, Name=ball, Position=(0, 0.5, 0), Radius=0.5\n";
    CHECK(runSingle(resting + "Expect, Object=ball, Time=2, Asleep=true\n").result.passed);
    CHECK_FALSE(runSingle(resting + "Expect, Object=ball, Time=0.2, Asleep=true\n").result.passed);
    const Single off = runSingle("World, Sleep=false\n" + resting.substr(resting.find('\n') + 1) +
                                 "Expect, Object=ball, Time=1, Asleep=true\n");
    CHECK_FALSE(off.result.passed);
    CHECK_THAT(off.result.reason, Contains("Sleep=false"));

    // Expectations from another file (stepwise grade --expect) may name a body this scene lacks.
    Scene scene = test::emptyScene();
    scene.dynamics.push_back(test::sphere("ball", Vec3(0)));
    Expectation e;
    e.object = "bal";
    e.quantity = ExpectQuantity::Speed;
    World world(scene);
    ExpectationMonitor monitor(world, {e});
    monitor.observe(world);
    const ExpectationResult r = monitor.results(world)[0];
    CHECK_FALSE(r.passed);
    CHECK_THAT(r.reason, Contains("no DynamicObject or SoftBody named 'bal'"));
}

TEST_CASE("Watching a scene does not change its trajectory", "[expect]") {
    const std::string text = "World, Integrator=Verlet, TimeStep=1/60, Duration=3\n"
                             "CollisionPlane, Name=floor\n"
                             "DynamicObject, Name=ball, Position=(0, 2, 0), Velocity=(1, 0, 0), Elasticity=0.7\n"
                             "DynamicObject, Name=box, Shape=Box, Position=(3, 1, 0), Rotation=(10, 0, 20)\n";
    const std::string expects = "Expect, Object=ball, Apex=1, PositionY=0, Compare=AtLeast\n"
                                "Expect, Object=box, Until=3, AtRest=true\n"
                                "Expect, Until=3, EnergyChange=0, Tolerance=1\n";
    World plain(parseScene(text, "plain.scene"));
    const Scene watched = parseScene(text + expects, "watched.scene");
    World observed(watched);
    ExpectationMonitor monitor(observed, watched.expectations);
    monitor.observe(observed);
    for (int i = 0; i < 180; ++i) {
        plain.step();
        observed.step();
        monitor.observe(observed);
    }
    for (std::size_t i = 0; i < plain.dynamics().size(); ++i) {
        CHECK(plain.dynamics()[i].position == observed.dynamics()[i].position);  // bit for bit
        CHECK(plain.dynamics()[i].velocity == observed.dynamics()[i].velocity);
        CHECK(plain.dynamics()[i].orientation == observed.dynamics()[i].orientation);
    }
}

// ------------------------------------------------------------------ the commands

TEST_CASE("run prints a pass/fail table and exits 3 when an expectation fails", "[expect][cli]") {
    TempFolder folder("run-expect");
    const std::string scene = "World, Integrator=Verlet, TimeStep=1/60, Duration=1\n"
                              "DynamicObject, Name=ball, Position=(0, 10, 0)\n"
                              "Expect, Object=ball, Time=1, PositionY=5.095, Tolerance=0.001\n";
    folder.write("pass.scene", scene);
    folder.write("fail.scene", scene + "Expect, Object=ball, Time=1, Speed=0, Tolerance=0.1\n");
    const auto pass = runStepwise("run '" + (folder.path / "pass.scene").string() + "'");
    CHECK(pass.exitCode == 0);
    CHECK_THAT(pass.output, Contains("Expectations: 1 of 1 passed") && Contains("PASS") &&
                                Contains("ball: PositionY = 5.095 +- 0.001 m at t = 1 s"));
    const auto fail = runStepwise("run '" + (folder.path / "fail.scene").string() + "'");
    CHECK(fail.exitCode == 3);
    // The speed after 1 s of free fall is g·1 s = 9.81 m/s.
    CHECK_THAT(fail.output, Contains("Expectations: 1 of 2 passed") && Contains("FAIL") && Contains("9.81 m/s"));
}

TEST_CASE("grade prints one row per file: PASS, FAIL, ERROR, and exits 3 unless all pass", "[expect][cli]") {
    TempFolder folder("grade");
    const std::string ball = "World, Integrator=Verlet, TimeStep=1/60, Duration=1\n"
                             "DynamicObject, Name=ball, Position=(0, 10, 0)\n";
    folder.write("alice.scene", ball + "Expect, Object=ball, Time=1, PositionY=5.095, Tolerance=0.001\n");
    folder.write("bob/answer.scene", ball + "Expect, Object=ball, Time=1, PositionY=6, Tolerance=0.001\n");
    folder.write("carol.scene", ball + "DynamicObject, Mass=-1\n");
    folder.write("dave.scene", ball);
    folder.write("notes.txt", "not a scene");
    const auto all = runStepwise("grade " + folder.quoted());
    CHECK(all.exitCode == 3);
    CHECK_THAT(all.output, Contains("Grading 4 file(s)") && Contains("alice.scene") && Contains("PASS") &&
                               Contains("bob/answer.scene") && Contains("FAIL") && Contains("0/1") &&
                               Contains("carol.scene") && Contains("ERROR") && Contains("Mass") &&
                               Contains("dave.scene") && Contains("no Expect records") &&
                               Contains("4 file(s): 1 passed, 1 failed, 2 could not be run"));
    CHECK_THAT(all.output, !Contains("notes.txt"));

    const auto one = runStepwise("grade " + folder.quoted() + " --scene-glob 'a*.scene'");
    CHECK(one.exitCode == 0);
    CHECK_THAT(one.output, Contains("1 file(s): 1 passed, 0 failed, 0 could not be run"));

    // The instructor's expectations instead of each file's own: dave now passes, bob too.
    folder.write("key/expect.scene", ball + "Expect, Object=ball, Time=1, Speed=9.81, Tolerance=1e-6\n");
    const auto keyed = runStepwise("grade " + folder.quoted() + " --scene-glob '[bd]*.scene' --expect '" +
                                   (folder.path / "key/expect.scene").string() + "'");
    CHECK(keyed.exitCode == 0);
    CHECK_THAT(keyed.output, Contains("2 file(s): 2 passed"));

    CHECK(runStepwise("grade").exitCode == 2);
    CHECK(runStepwise("grade '" + (folder.path / "missing").string() + "'").exitCode == 2);
    CHECK(runStepwise("grade " + folder.quoted() + " --scene-glob '*.none'").exitCode == 2);
}
