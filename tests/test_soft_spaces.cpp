/// @file test_soft_spaces.cpp
/// @brief Soft bodies in scenes with `Space` records (src/world/spaces.hpp): each space steps its own
/// soft bodies, exactly as a scene of its own would (bit for bit: spaces share nothing), and
/// `stepwise run`, `--csv`, `--csv-nodes`, `stepwise trace` and the viewer's layout name and see
/// them. Tags: [soft][spaces].
#include <catch2/catch.hpp>

#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "command_runner.hpp"
#include "config/scene_loader.hpp"
#include "io/trace_writer.hpp"
#include "test_support.hpp"
#include "viewer/space_layout.hpp"
#include "world/spaces.hpp"

using namespace stepwise;

namespace {

/// The same soft ball over a floor on the Earth and on Mars, in two spaces.
const char* kEarthAndMars =
    "World, TimeStep=1/60, Substeps=8, Integrator=SymplecticEuler, Duration=1\n"
    "Space, Name=earth, Gravity=(0, -9.81, 0)\n"
    "Space, Name=mars, Gravity=(0, -3.71, 0), Integrator=Verlet\n"
    "CollisionPlane, Name=floor_e, Space=earth, Friction=0.8\n"
    "CollisionPlane, Name=floor_m, Space=mars, Friction=0.8\n"
    "SoftBody, Name=ball_e, Space=earth, Position=(0, 1, 0), Radius=0.5, Resolution=2, Stiffness=60, Damping=0.05, "
    "Pressure=60\n"
    "SoftBody, Name=ball_m, Space=mars, Position=(0, 1, 0), Radius=0.5, Resolution=2, Stiffness=60, Damping=0.05, "
    "Pressure=60\n";

/// Each space of kEarthAndMars as a scene of its own.
const char* kEarthAlone =
    "World, TimeStep=1/60, Substeps=8, Integrator=SymplecticEuler, Duration=1, Gravity=(0, -9.81, 0)\n"
    "CollisionPlane, Name=floor_e, Friction=0.8\n"
    "SoftBody, Name=ball_e, Position=(0, 1, 0), Radius=0.5, Resolution=2, Stiffness=60, Damping=0.05, Pressure=60\n";
const char* kMarsAlone =
    "World, TimeStep=1/60, Substeps=8, Integrator=Verlet, Duration=1, Gravity=(0, -3.71, 0)\n"
    "CollisionPlane, Name=floor_m, Friction=0.8\n"
    "SoftBody, Name=ball_m, Position=(0, 1, 0), Radius=0.5, Resolution=2, Stiffness=60, Damping=0.05, Pressure=60\n";

void requireSameNodes(const SoftBody& a, const SoftBody& b) {
    REQUIRE(a.nodeCount() == b.nodeCount());
    for (std::size_t i = 0; i < a.nodeCount(); ++i) {
        INFO("node " << i);
        REQUIRE(a.nodePositions[i] == b.nodePositions[i]);
        REQUIRE(a.nodeVelocities[i] == b.nodeVelocities[i]);
    }
    CHECK(a.volume == b.volume);
    CHECK(a.pressure == b.pressure);
}

std::string fileText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

TEST_CASE("The loader puts a SoftBody in the space it names, and refuses a space it does not know", "[soft][spaces][config]") {
    const Scene scene = parseScene(kEarthAndMars, "soft_spaces.scene");
    REQUIRE(scene.softBodies.size() == 2);
    REQUIRE(scene.softBodySpace.size() == 2);
    CHECK(scene.softBodySpace[0] == 1);  // 1 + the index of its Space record
    CHECK(scene.softBodySpace[1] == 2);
    const auto split = splitIntoSpaces(scene);
    REQUIRE(split.size() == 2);  // nothing in the default space: left out
    REQUIRE(split[0].second.softBodies.size() == 1);
    CHECK(split[0].second.softBodies[0].name == "ball_e");
    CHECK(split[1].second.softBodies[0].name == "ball_m");
    // A space holding nothing but a soft body is still a space
    CHECK(splitIntoSpaces(parseScene("Space, Name=s\nSoftBody, Name=b, Space=s, Stiffness=10\n", "only.scene")).size() == 1);
    test::checkRefused("Space, Name=earth\nSoftBody, Name=b, Space=eartj, Stiffness=10\n", "did you mean 'earth'?");
    test::checkRefused("SoftBody, Name=b, Space=nowhere, Stiffness=10\n", "the Name of a Space record");
}

TEST_CASE("A soft ball in each of two spaces computes, bit for bit, what it computes alone", "[soft][spaces]") {
    Spaces spaces(parseScene(kEarthAndMars, "soft_spaces.scene"));
    REQUIRE(spaces.all().size() == 2);
    World earth(parseScene(kEarthAlone, "earth.scene"));
    World mars(parseScene(kMarsAlone, "mars.scene"));
    const Real tick = spaces.finestTick();
    for (int i = 0; i < 60; ++i) spaces.advance(tick);  // 1 s: the fall, the landing, a bounce
    while (earth.stepCount() < 60) earth.step();
    while (mars.stepCount() < 60) mars.step();
    REQUIRE(spaces.all()[0].world.stepCount() == 60);
    REQUIRE(spaces.all()[1].world.stepCount() == 60);
    requireSameNodes(spaces.all()[0].world.softBodies()[0], earth.softBodies()[0]);
    requireSameNodes(spaces.all()[1].world.softBodies()[0], mars.softBodies()[0]);
    // And each space kept its own gravity and integrator: after 0.25 s of free fall (the Earth's
    // ball lands from 0.5 m at t = √(2h/g) = 0.32 s) the centre of mass, which the internal forces
    // do not move, has fallen ½·g·t² under Verlet (exact for a constant force) and
    // ½·g·h_s²·N(N+1) = ½·g·t²·(1 + 1/N) in N substeps of symplectic Euler.
    Spaces early(parseScene(kEarthAndMars, "soft_spaces.scene"));
    for (int i = 0; i < 15; ++i) early.advance(tick);
    const Real t = Real(0.25);
    const Real substeps = 15 * 8;
    CHECK(1 - early.all()[0].world.softBodies()[0].position.y ==
          Approx(Real(0.5) * Real(9.81) * t * t * (1 + 1 / substeps)).epsilon(1e-9));
    CHECK(1 - early.all()[1].world.softBodies()[0].position.y == Approx(Real(0.5) * Real(3.71) * t * t).epsilon(1e-9));
}

TEST_CASE("stepwise run names each space and lists its soft bodies, in the CSV and the node CSV too", "[soft][spaces][cli]") {
    const test::TempFile scene("soft_spaces.scene", kEarthAndMars);
    const test::TempFile csv("soft_spaces.csv");
    const test::TempFile nodes("soft_spaces_nodes.csv");
    const test::CommandResult r =
        test::runStepwise("run " + scene.quoted() + " --steps 6 --csv " + csv.quoted() + " --csv-nodes " + nodes.quoted());
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    CHECK(r.output.find("earth") != std::string::npos);
    CHECK(r.output.find("1 soft body") != std::string::npos);
    CHECK(r.output.find("=== Space mars") != std::string::npos);
    const std::size_t marsAt = r.output.find("=== Space mars");
    CHECK(r.output.find("ball_m", marsAt) != std::string::npos);  // its soft body's row, under its space
    CHECK(r.output.find("Soft bodies (", marsAt) != std::string::npos);
    const std::string rows = fileText(csv.path);
    CHECK(rows.rfind("time,space,name,px,py,pz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz,volume,pressure\n", 0) == 0);
    CHECK(rows.find(",mars,ball_m,") != std::string::npos);
    CHECK(rows.find(",earth,ball_e,") != std::string::npos);
    const std::string nodeRows = fileText(nodes.path);
    CHECK(nodeRows.rfind("time,space,body,node,px,py,pz,vx,vy,vz\n", 0) == 0);
    CHECK(nodeRows.find(",mars,ball_m,161,") != std::string::npos);  // 162 nodes, numbered from 0
}

TEST_CASE("stepwise trace of a scene with spaces traces each space's soft bodies under its name", "[soft][spaces][trace]") {
    TraceOptions options;
    options.steps = 2;
    options.stages = {Stage::SoftBodies};
    options.objects = {"ball_m"};
    std::ostringstream out;
    REQUIRE(writeTrace(parseScene(kEarthAndMars, "soft_spaces.scene"), options, out));
    const std::string text = out.str();
    INFO(text);
    const std::size_t earth = text.find("=== Space earth");
    const std::size_t mars = text.find("=== Space mars");
    REQUIRE(earth != std::string::npos);
    REQUIRE(mars != std::string::npos);
    CHECK(earth < mars);
    CHECK(text.find("ball_m", mars) != std::string::npos);
    CHECK(text.find("ball_e") == std::string::npos);  // --object ball_m: the Earth's ball is left out
}

TEST_CASE("The viewer's layout gives a space of soft bodies the room of their nodes", "[soft][spaces][viewer]") {
    // A soft ball of radius 0.5 m at x = 3 alone in its space: its swept box is the box of its
    // nodes' spheres (a space with no body seen would get a 1 m cube about its origin instead).
    Spaces spaces(parseScene("Space, Name=a\nSpace, Name=b\n"
                             "DynamicObject, Name=rigid, Space=a, Radius=0.5\n"
                             "SoftBody, Name=ball, Space=b, Position=(3, 0, 0), Radius=0.5, Stiffness=60, Pressure=10\n",
                             "layout.scene"));
    viewer::SpaceLayout layout;
    layout.reset(2);
    layout.grow(0, spaces.all()[0].world);
    layout.grow(1, spaces.all()[1].world);
    const SoftBody& ball = spaces.all()[1].world.softBodies()[0];
    Aabb nodes{ball.nodePositions[0], ball.nodePositions[0]};
    for (const Vec3& x : ball.nodePositions) nodes = {glm::min(nodes.min, x), glm::max(nodes.max, x)};
    const Aabb box = layout.bounds(1);
    CHECK(box.min.x == Approx(nodes.min.x - ball.nodeRadius).margin(1e-12));
    CHECK(box.max.x == Approx(nodes.max.x + ball.nodeRadius).margin(1e-12));
    CHECK(box.min.y == Approx(nodes.min.y - ball.nodeRadius).margin(1e-12));
    CHECK(box.min.x > 2.4);  // about the ball at x = 3, not the origin
}

TEST_CASE("The stability warning reads the step of the soft body's own space", "[soft][spaces][config]") {
    // Stiffness=1000 on 162 nodes: ω = √(12k·162) = 1394 rad/s, so h_s·ω = 2.9 at 8 substeps of
    // 1/60 s (past 2) and 0.73 at 32. The World record's step is the unstable one; the space's is not.
    const Scene calm = parseScene("World, TimeStep=1/60, Substeps=8\nSpace, Name=fine, Substeps=32\n"
                                  "SoftBody, Name=stiff, Space=fine, Stiffness=1000\n",
                                  "s.scene");
    CHECK(calm.warnings.empty());
    const Scene coarse = parseScene("World, TimeStep=1/60, Substeps=32\nSpace, Name=coarse, Substeps=8\n"
                                    "SoftBody, Name=stiff, Space=coarse, Stiffness=1000\n",
                                    "s.scene");
    REQUIRE(coarse.warnings.size() == 1);
    CHECK_THAT(coarse.warnings[0], Catch::Matchers::Contains("s.scene:3: warning: SoftBody 'stiff'"));
}
