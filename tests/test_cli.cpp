// The stepwise program as a user meets it: commands, options, exit codes,
// CSV output and error messages. Tag: [cli].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "command_runner.hpp"
#include "skip.hpp"
#include "config/scene_loader.hpp"

using Catch::Matchers::Contains;

namespace {

using Result = stepwise::test::CommandResult;

using stepwise::test::runStepwise;
using stepwise::test::TempFile;

std::vector<std::string> lines(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::vector<std::string> all;
    for (std::string line; std::getline(in, line);) all.push_back(line);
    return all;
}

const std::string kSourceDir = STEPWISE_SOURCE_DIR;

}  // namespace

TEST_CASE("With no arguments stepwise prints its usage", "[cli]") {
    const Result r = runStepwise("");
    CHECK(r.exitCode == 0);
    CHECK_THAT(r.output, Contains("Usage:") && Contains("stepwise run") && Contains("stepwise check"));
}

TEST_CASE("stepwise view --help prints the view command's usage and the window's controls", "[cli][viewer]") {
    // Whether or not the viewer was built into this program: --help opens no window.
    for (const char* flag : {"--help", "-h"}) {
        const Result r = runStepwise(std::string("view ") + flag);
        INFO(flag << ": " << r.output);
        CHECK(r.exitCode == 0);
        CHECK_THAT(r.output, Contains("stepwise view [FILE]") && Contains("--screenshot PATH"));
        CHECK_THAT(r.output, Contains("In the window:") && Contains("Space   pause / resume") && Contains("Esc, Q  quit"));
    }
}

TEST_CASE("Unknown commands and options are errors with exit code 2", "[cli]") {
    CHECK(runStepwise("fly").exitCode == 2);
    const Result r = runStepwise("run --speed 3");
    CHECK(r.exitCode == 2);
    CHECK_THAT(r.output, Contains("unknown option '--speed'"));
    CHECK(runStepwise("run --steps").exitCode == 2);          // missing value
    CHECK(runStepwise("run --steps ten").exitCode == 2);      // not a number
    CHECK(runStepwise("run --every 0").exitCode == 2);        // must be > 0
    CHECK(runStepwise("run --duration 1 --steps 5").exitCode == 2);
    CHECK(runStepwise("check").exitCode == 2);
}

TEST_CASE("run with no file runs the default scene and prints a summary", "[cli]") {
    const Result r = runStepwise("run --steps 30");
    CHECK(r.exitCode == 0);
    CHECK_THAT(r.output, Contains("default.scene") && Contains("Simulated") && Contains("Energy") &&
                             Contains("momentum") && Contains("integrate") && Contains("narrowphase"));
}

TEST_CASE("check validates a scene and describes it", "[cli]") {
    const Result good = runStepwise("check '" + kSourceDir + "/config/lesson03_bounce.scene'");
    CHECK(good.exitCode == 0);
    CHECK_THAT(good.output, Contains("ball") && Contains("floor") && Contains("valid"));

    TempFile bad("bad.scene", "World, TimeStep=0\nDynamicObject, Name=a, Mass=-2\n");
    const Result r = runStepwise("check " + bad.quoted());
    CHECK(r.exitCode == 2);
    // file:line:column for each problem, and nothing half-loaded
    CHECK_THAT(r.output, Contains("bad.scene:1:") && Contains("TimeStep") && Contains("bad.scene:2:") &&
                             Contains("Mass") && Contains("nothing was loaded"));
}

TEST_CASE("check lists a scene's materials, its pairs and its combine rules", "[cli][materials]") {
    const Result r = runStepwise("check '" + kSourceDir + "/config/lesson07_materials.scene'");
    CHECK(r.exitCode == 0);
    CHECK_THAT(r.output, Contains("3 material(s), 1 pair(s); contacts combine friction by GeometricMean") &&
                             Contains("mass 137.5 kg") &&  // rubber: 1100 kg/m^3 x 0.125 m^3
                             Contains("Material         ice              density 917 kg/m^3") &&
                             Contains("MaterialPair     ice / wood       friction 0.15, elasticity -"));
    // A scene without materials says nothing about them.
    const Result classic = runStepwise("check '" + kSourceDir + "/config/lesson03_bounce.scene'");
    CHECK_THAT(classic.output, !Contains("material"));
}

TEST_CASE("run --csv writes the header, the initial state and every K-th step", "[cli]") {
    TempFile csv("trajectory.csv");
    const std::string scene = "'" + kSourceDir + "/config/lesson03_collisions.scene'";
    const Result r = runStepwise("run " + scene + " --steps 12 --every 4 --csv " + csv.quoted());
    REQUIRE(r.exitCode == 0);
    const std::vector<std::string> rows = lines(csv.path);
    REQUIRE(!rows.empty());
    CHECK(rows[0] == "time,name,px,py,pz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz");
    // 5 dynamic + 1 kinematic objects, sampled at steps 0, 4, 8, 12.
    CHECK(rows.size() == 1 + 6 * 4);
    CHECK_THAT(rows[1], Catch::Matchers::StartsWith("0,left,-2,"));
    // The last row is the kinematic wall at t = 12/120 s, at x = 1 m/s * t = 0.1 m.
    std::istringstream last(rows.back());
    std::string time, name, px;
    std::getline(last, time, ',');
    std::getline(last, name, ',');
    std::getline(last, px, ',');
    CHECK(name == "wall");
    CHECK(std::abs(std::stod(time) - 0.1) < 1e-12);
    CHECK(std::abs(std::stod(px) - 0.1) < 1e-12);
}

TEST_CASE("CSV output is identical run after run", "[cli]") {
    TempFile first("first.csv"), second("second.csv");
    const std::string scene = "'" + kSourceDir + "/config/default.scene'";
    REQUIRE(runStepwise("run " + scene + " --duration 3 --csv " + first.quoted()).exitCode == 0);
    REQUIRE(runStepwise("run " + scene + " --duration 3 --csv " + second.quoted()).exitCode == 0);
    CHECK(lines(first.path) == lines(second.path));
}

TEST_CASE("A non-finite state ends the run with exit code 1 naming object, stage and step", "[cli]") {
    TempFile scene("runaway.scene",
                   "World, Gravity=(0,0,0)\n"
                   "DynamicObject, Name=rocket, Acceleration=(0, 1e308, 0)\n");
    const Result r = runStepwise("run " + scene.quoted() + " --duration 10");
    CHECK(r.exitCode == 1);
    CHECK_THAT(r.output, Contains("rocket") && Contains("integrate") && Contains("step") && Contains("non-finite"));
}

TEST_CASE("Every shipped scene runs for one simulated second, and a self-checking one passes its Expect records", "[cli]") {
    // A scene with Expect records runs for its own Duration, which reaches every moment they name
    // (cut to one second it would end with them "not reached", exit code 3); the others for 1 s.
    for (const auto& entry : std::filesystem::directory_iterator(kSourceDir + "/config")) {
        if (entry.path().extension() != ".scene") continue;
        INFO(entry.path().string());
        const bool selfChecking = !stepwise::loadSceneFile(entry.path().string()).expectations.empty();
        const Result r = runStepwise("run '" + entry.path().string() + "'" + (selfChecking ? "" : " --duration 1"));
        INFO(r.output);
        CHECK(r.exitCode == 0);
    }
}

TEST_CASE("stepwise check warns about a spring past its stability limit, and still loads it", "[cli][spring]") {
    // stress_spring_past.scene: h·ω = 126.5/60 = 2.11 > 2; stress_spring_edge.scene: 1.90, inside.
    const Result past = runStepwise("check '" + kSourceDir + "/config/stress_spring_past.scene'");
    CHECK(past.exitCode == 0);
    CHECK_THAT(past.output, Contains("warning: Spring 'stiff'") && Contains("h*w = ") && Contains("> 2") &&
                                Contains("use TimeStep < 0.01581 s"));
    const Result edge = runStepwise("check '" + kSourceDir + "/config/stress_spring_edge.scene'");
    CHECK(edge.exitCode == 0);
    CHECK_THAT(edge.output, !Contains("warning"));
}

TEST_CASE("run says which broadphase ran, and why when the scene leaves it to Auto", "[cli][broadphase]") {
    const Result automatic = runStepwise("run --steps 3");
    CHECK_THAT(automatic.output, Contains("Broadphase BruteForce (Auto:") && Contains("fewer than"));
    TempFile scene("grid.scene", "World, Broadphase=Grid\nDynamicObject\nCollisionPlane\n");
    const Result chosen = runStepwise("run " + scene.quoted() + " --steps 3");
    CHECK(chosen.exitCode == 0);
    CHECK_THAT(chosen.output, Contains("Broadphase Grid (set by the scene)"));
}

TEST_CASE("run says why no broadphase ran when the step plan skipped it", "[cli][broadphase]") {
    // One ball on a spring and nothing to hit: the plan skips the broadphase on every step, so
    // Auto never chose one, and the summary must not say it did (nor that no step ran).
    const Result single = runStepwise("run '" + kSourceDir + "/config/stress_spring_past.scene' --duration 1");
    CHECK(single.exitCode == 0);
    CHECK_THAT(single.output, Contains("Simulated 1 s in 60 steps") &&
                                  Contains("Broadphase none ran (skipped: a single body and nothing to hit") &&
                                  !Contains("no step ran") && !Contains("Auto:"));
    TempFile scene("lone-grid.scene", "World, Broadphase=Grid, Gravity=(0, 0, 0)\nDynamicObject\n");
    const Result set = runStepwise("run " + scene.quoted() + " --steps 3");
    CHECK(set.exitCode == 0);
    CHECK_THAT(set.output, Contains("Broadphase none ran (skipped:") && !Contains("set by the scene"));
}

TEST_CASE("raycast prints the first body along the ray", "[cli][raycast]") {
    // A ball of radius 0.5 at x = 3 above a floor: along +x at its height the
    // ray meets it at x = 2.5; straight down from (0, 2, 0) it meets the floor 2 m below.
    TempFile scene("ray.scene", "DynamicObject, Name=ball, Position=(3, 1, 0), Radius=0.5\n"
                                "CollisionPlane, Name=floor\nWorld, Gravity=(0, 0, 0)\n");
    const Result ball = runStepwise("raycast " + scene.quoted() + " --from 0,1,0 --dir 1,0,0");
    CHECK(ball.exitCode == 0);
    CHECK_THAT(ball.output, Contains("Hit ball (dynamic) at distance 2.5 m") && Contains("(-1.0000, 0.0000, 0.0000)"));
    const Result floor = runStepwise("raycast " + scene.quoted() + " --from 0,2,0 --dir 0,-3,0");
    CHECK_THAT(floor.output, Contains("Hit floor (plane) at distance 2 m"));
    const Result none = runStepwise("raycast " + scene.quoted() + " --from 0,2,0 --dir 0,-1,0 --max 1.5");
    CHECK(none.exitCode == 0);
    CHECK_THAT(none.output, Contains("No hit"));
    CHECK(runStepwise("raycast " + scene.quoted() + " --from 0,2 --dir 0,-1,0").exitCode == 2);
    CHECK(runStepwise("raycast " + scene.quoted() + " --from 0,2,0 --dir 0,0,0").exitCode == 2);
    CHECK(runStepwise("raycast " + scene.quoted() + " --from 0,2,0").exitCode == 2);
}

TEST_CASE("generate writes a scene that loads with the asked number of bodies", "[cli][broadphase]") {
    for (const std::string name : {"sphere-rain", "box-pile", "pyramids"}) {
        INFO(name);
        TempFile out(name + ".scene");
        const Result r = runStepwise("generate " + name + " --count 123 --seed 5 --out " + out.quoted());
        REQUIRE(r.exitCode == 0);
        const Result check = runStepwise("check " + out.quoted());
        CHECK(check.exitCode == 0);
        CHECK_THAT(check.output, Contains("123 dynamic"));
    }
    CHECK(runStepwise("generate sphere-rain --count 10").exitCode == 2);             // no --out
    CHECK(runStepwise("generate marbles --count 10 --out -").exitCode == 2);         // unknown scene
    CHECK(runStepwise("generate sphere-rain --count 0 --out -").exitCode == 2);      // no bodies
    // The same options give the same file.
    CHECK(runStepwise("generate box-pile --count 50 --out -").output ==
          runStepwise("generate box-pile --count 50 --out -").output);
}

TEST_CASE("bench broadphase runs every broadphase on a scene and ranks them", "[cli][broadphase]") {
    TempFile scene("bench.scene");
    REQUIRE(runStepwise("generate sphere-rain --count 200 --out " + scene.quoted()).exitCode == 0);
    const Result r = runStepwise("bench broadphase " + scene.quoted() + " --steps 40 --check-every 4");
    CHECK(r.exitCode == 0);
    CHECK_THAT(r.output, Contains("BruteForce") && Contains("SweepAndPrune") && Contains("AabbTree") &&
                             Contains("Grid") && Contains("40 steps, 10 checked") && Contains("Auto would choose"));
    CHECK(runStepwise("bench broadphase").exitCode == 2);
    CHECK(runStepwise("bench narrowphase " + scene.quoted()).exitCode == 2);
}

namespace {

/// Every line of the CSV file at @p path has the 15 fields of the header: no row cut short.
std::size_t wholeRowsIn(const std::string& path) {
    std::ifstream file(path);
    std::string line;
    std::size_t rows = 0;
    while (std::getline(file, line)) {
        INFO("row " << rows << ": " << line);
        REQUIRE(std::count(line.begin(), line.end(), ',') == 14);
        ++rows;
    }
    return rows;
}

}  // namespace

TEST_CASE("run stopped by SIGINT or SIGTERM keeps its CSV whole, prints what ran, and exits 128 + the signal", "[cli]") {
    const std::string csv = (std::filesystem::temp_directory_path() / "stepwise-interrupted.csv").string();
    for (const auto& [signal, code] : {std::pair<std::string, int>{"INT", 130}, std::pair<std::string, int>{"TERM", 143}}) {
        INFO("SIG" << signal);
        std::filesystem::remove(csv);
        // A run far longer than the test: 1000 balls for 10^8 steps, stopped after half a second.
        const Result r = stepwise::test::shell(std::string("{ '") + STEPWISE_CLI_PATH +
                                               "' run config/bench_sphere_rain_1k.scene --steps 100000000 --csv '" + csv +
                                               "' > /dev/null & pid=$!; sleep 1; kill -" + signal +
                                               " $pid; wait $pid; echo \"exit $?\"; }");
        CHECK_THAT(r.output, Contains("stopped by signal") && Contains("exit " + std::to_string(code)));
        const std::size_t rows = wholeRowsIn(csv);
        CHECK(rows > 1001);  // the header, the start, and at least one step's 1000 balls, all whole
        CHECK((rows - 1) % 1000 == 0);
    }
    std::filesystem::remove(csv);
}

TEST_CASE("A write that fails is an error with the path and the reason, never a silent exit 0", "[cli]") {
    if (!std::filesystem::exists("/dev/full")) STEPWISE_SKIP("no /dev/full on this system (it is Linux's full device)");
    Result r = runStepwise("run config/lesson03_bounce.scene --csv /dev/full");
    CHECK(r.exitCode == 1);
    CHECK_THAT(r.output, Contains("cannot write '/dev/full': No space left on device"));
    CHECK_THAT(r.output, !Contains("Trajectory written"));
    r = runStepwise("generate sphere-rain --count 10 --out /dev/full");
    CHECK(r.exitCode == 1);
    CHECK_THAT(r.output, Contains("cannot write '/dev/full'"));
    for (const char* command : {"check config/default.scene", "run config/lesson03_bounce.scene",
                                "generate sphere-rain --count 10 --out -"}) {
        INFO(command);
        // Standard output into the full device, the messages (standard error) to the test
        r = stepwise::test::shell(std::string("{ '") + STEPWISE_CLI_PATH + "' " + command + " > /dev/full; }");
        CHECK(r.exitCode == 1);
        CHECK_THAT(r.output, Contains("cannot write standard output"));
    }
}
