// Spaces (src/world/spaces.hpp): simulations side by side that never touch, on one clock.
//
// A space must compute exactly what its scene computes alone (bit for bit: spaces share nothing),
// take the steps its time step and TimeScale give on the shared clock, and stop while paused.
#include <catch2/catch.hpp>

#include "config/scene_loader.hpp"
#include "world/spaces.hpp"
#include "test_support.hpp"

using namespace stepwise;

namespace {

const char* kTwoSpaces =
    "World, Gravity=(0, -9.81, 0), TimeStep=1/60, Duration=2\n"
    "Space, Name=impulse, Solver=Impulse\n"
    "Space, Name=soft, Solver=SequentialImpulse, TimeStep=1/240\n"
    "CollisionPlane, Name=floor_i, Space=impulse\n"
    "CollisionPlane, Name=floor_s, Space=soft\n"
    "DynamicObject, Name=box_i, Space=impulse, Shape=Box, Position=(0, 0.6, 0), Rotation=(10, 0, 20), Elasticity=0.2\n"
    "DynamicObject, Name=box_s, Space=soft, Shape=Box, Position=(0, 0.6, 0), Rotation=(10, 0, 20), Elasticity=0.2\n"
    "DynamicObject, Name=ball_s, Space=soft, Position=(3, 2, 0), Elasticity=0.8\n";

/// The same bodies as one space of kTwoSpaces, in a scene of their own.
const char* kSoftAlone =
    "World, Gravity=(0, -9.81, 0), TimeStep=1/240, Duration=2, Solver=SequentialImpulse\n"
    "CollisionPlane, Name=floor_s\n"
    "DynamicObject, Name=box_s, Shape=Box, Position=(0, 0.6, 0), Rotation=(10, 0, 20), Elasticity=0.2\n"
    "DynamicObject, Name=ball_s, Position=(3, 2, 0), Elasticity=0.8\n";

const char* kImpulseAlone =
    "World, Gravity=(0, -9.81, 0), TimeStep=1/60, Duration=2, Solver=Impulse\n"
    "CollisionPlane, Name=floor_i\n"
    "DynamicObject, Name=box_i, Shape=Box, Position=(0, 0.6, 0), Rotation=(10, 0, 20), Elasticity=0.2\n";

}  // namespace

TEST_CASE("Each space computes, bit for bit, what its scene computes alone", "[spaces]") {
    Spaces spaces(parseScene(kTwoSpaces, "spaces.scene"));
    REQUIRE(spaces.all().size() == 2);  // the default space holds nothing: left out
    CHECK(spaces.all()[0].name == "impulse");
    CHECK(spaces.all()[1].name == "soft");
    World impulse(parseScene(kImpulseAlone, "impulse.scene"));
    World soft(parseScene(kSoftAlone, "soft.scene"));
    const Real tick = spaces.finestTick();
    CHECK(tick == Approx(1.0 / 240));
    for (int i = 0; i < 480; ++i) spaces.advance(tick);  // 2 s on the clock
    while (impulse.stepCount() < 120) impulse.step();
    while (soft.stepCount() < 480) soft.step();
    CHECK(spaces.all()[0].world.stepCount() == 120);
    CHECK(spaces.all()[1].world.stepCount() == 480);
    test::requireSameState(spaces.all()[0].world, impulse);
    test::requireSameState(spaces.all()[1].world, soft);
}

TEST_CASE("TimeScale sets a space's pace on the shared clock, and a paused space waits", "[spaces]") {
    Spaces spaces(parseScene("World, TimeStep=1/60\n"
                             "Space, Name=slow, TimeScale=0.5\n"
                             "Space, Name=fast, TimeScale=2\n"
                             "Space, Name=frozen, Paused=true\n"
                             "DynamicObject, Name=a, Space=slow\n"
                             "DynamicObject, Name=b, Space=fast\n"
                             "DynamicObject, Name=c, Space=frozen\n"
                             "DynamicObject, Name=d\n",
                             "pace.scene"));
    REQUIRE(spaces.all().size() == 4);  // the default space holds d
    CHECK(spaces.all()[0].name == kDefaultSpaceName);
    const Real tick = spaces.finestTick();
    CHECK(tick == Approx(1.0 / 120));  // h / TimeScale of the fast space
    for (int i = 0; i < 120; ++i) spaces.advance(tick);  // 1 s on the clock
    CHECK(spaces.all()[0].world.stepCount() == 60);
    CHECK(spaces.all()[1].world.stepCount() == 30);
    CHECK(spaces.all()[2].world.stepCount() == 120);
    CHECK(spaces.all()[3].world.stepCount() == 0);
    spaces.togglePause(3);  // resumed: it goes on from where it stopped, no jump
    spaces.togglePause(1);  // the slow one stops
    for (int i = 0; i < 120; ++i) spaces.advance(tick);
    CHECK(spaces.all()[3].world.stepCount() == 60);
    CHECK(spaces.all()[1].world.stepCount() == 30);
    // Free fall in the fast space: 2 simulated seconds of v = −g·t
    CHECK(spaces.all()[2].world.dynamics()[0].velocity.y == Approx(-kStandardGravity * 4).epsilon(1e-9));
}

TEST_CASE("A scene without Space records is one simulation, as before", "[spaces]") {
    const Scene scene = parseScene("DynamicObject, Name=a\n", "one.scene");
    CHECK(scene.spaces.empty());
    CHECK(scene.dynamicSpace.empty());
    CHECK(splitIntoSpaces(scene).size() == 1);
}

TEST_CASE("Space records are checked: names, Duration, and no spring or joint across spaces", "[spaces][config]") {
    const auto refused = test::checkRefused;
    refused("Space, Name=verlet\nDynamicObject, Name=a, Space=verlt\n", "did you mean 'verlet'?");
    refused("DynamicObject, Name=a, Space=nowhere\n", "the Name of a Space record");
    refused("Space, Name=s, Duration=3\n", "no Duration on a Space");
    refused("Space, Integrator=Verlet\n", "a Name field");
    refused("Space, Name=s\nDynamicObject, Name=a, Space=s\nDynamicObject, Name=b\n"
            "Spring, BodyA=a, BodyB=b, Stiffness=10\n",
            "two bodies of one space");
    refused("Space, Name=s\nDynamicObject, Name=a, Space=s\nDynamicObject, Name=b, Position=(1, 0, 0)\n"
            "BallJoint, BodyA=a, BodyB=b, Anchor=(0.5, 0, 0)\n",
            "two bodies of one space");
    // A Space inherits the World record's fields, wherever the World record is
    const Scene scene = parseScene("Space, Name=s, Integrator=Verlet\nWorld, TimeStep=1/30, Substeps=4\n", "order.scene");
    REQUIRE(scene.spaces.size() == 1);
    CHECK(scene.spaces[0].settings.integrator == IntegratorKind::Verlet);
    CHECK(scene.spaces[0].settings.timeStep == Approx(1.0 / 30));
    CHECK(scene.spaces[0].settings.substeps == 4);
}
