// Per-island substeps (src/dynamics/substep_rule.hpp, `World, SubstepsPerIsland=true`).
// Tags: [substeps].
//
// Claims:
// - each of the rule's inputs (stack height, mass ratio, relative speed, stiffness) raises the count,
//   and free flight under an integrator exact for a uniform field needs one substep;
// - in a scene of a tall stack and a lone ball the stack gets the full count, the ball fewer;
// - an island given the full count computes, bit for bit, what the fixed count computes;
// - `SubstepsPerIsland=false` forces the fixed count;
// - a joint keeps its island at the full count, computing the fixed count's numbers bit for bit,
//   while the islands beside it get their own;
// - a ball alone in free flight with velocity Verlet, run at one substep, still falls
//   exactly as x₀ + v₀t + ½gt².
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "config/scene_loader.hpp"
#include "dynamics/substep_rule.hpp"
#include "test_support.hpp"
#include "world/world.hpp"

using namespace stepwise;

namespace {

constexpr Real kH = Real(1) / 60;
constexpr int kCap = 16;
constexpr int kTowerHeight = 12;  // > kCap/2 boxes: its height term asks for the full count
constexpr Real kBoxEdge = 1;

/// The rule's inputs at the defaults, but with contacts soft enough (15 Hz) that one substep keeps
/// them at their frequency: the stiffness term then asks for 1 and the other terms show alone.
SubstepRuleInputs softInputs() { return {kCap, 1, kH, IntegratorKind::SymplecticEuler, 15}; }

/// The stiffness term at the defaults: 60 Hz needs ⌈4·h·60 Hz⌉ = 4 substeps at 1/60 s.
constexpr int kStiffCount = 4;

/// A tower of kTowerHeight unit boxes on the ground at x = 0 and a ball at rest on it at x = 20 m.
Scene towerAndBall(bool perIsland) {
    Scene scene = test::emptyScene();
    scene.settings.substepsPerIsland = perIsland;
    scene.settings.sleeping = false;  // keep both islands awake: every step runs the rule
    scene.planes.push_back(test::ground());
    for (int k = 0; k < kTowerHeight; ++k) {
        scene.dynamics.push_back(test::dynamicBox("box" + std::to_string(k), Vec3(0, kBoxEdge * (Real(k) + Real(0.5)), 0),
                                                  Vec3(kBoxEdge), 1, 0.6));
    }
    scene.dynamics.push_back(test::sphere("ball", Vec3(20, 0.5, 0)));
    return scene;
}

/// The first @p count bodies of @p perIsland and @p fixed are where each other are and move alike, bit for bit.
void requireSameMotion(const World& perIsland, const World& fixed, std::size_t count, int step) {
    for (std::size_t i = 0; i < count; ++i) {
        const DynamicObject& a = perIsland.dynamics()[i];
        const DynamicObject& b = fixed.dynamics()[i];
        INFO(a.name << " at step " << step);
        REQUIRE(a.position == b.position);
        REQUIRE(a.velocity == b.velocity);
        REQUIRE(a.orientation == b.orientation);
        REQUIRE(a.angularMomentum == b.angularMomentum);
    }
}

const IslandSubsteps& islandHolding(const World& world, std::uint32_t body) {
    for (const IslandSubsteps& island : world.islandSubsteps()) {
        if (island.firstBody == body) return island;
    }
    FAIL("no island starts at body " << body);
    return world.islandSubsteps().front();
}

}  // namespace

TEST_CASE("Each input of the substep rule raises an island's count", "[substeps]") {
    const SubstepRuleInputs in = softInputs();
    SubstepReason reason{};
    // One body resting on the floor, equal masses, at rest: the least count
    CHECK(islandSubstepCount(1, 1, 0, 0.5, true, true, in, reason) == kMinIslandSubsteps);
    CHECK(reason == SubstepReason::Minimum);
    // Height: ⌈H/P⌉ rounded up to a power of two; with two passes half as many
    CHECK(islandSubstepCount(3, 1, 0, 0.5, true, true, in, reason) == 4);
    CHECK(reason == SubstepReason::Height);
    CHECK(islandSubstepCount(40, 1, 0, 0.5, true, true, in, reason) == kCap);
    CHECK(reason == SubstepReason::Cap);
    SubstepRuleInputs twoPasses = in;
    twoPasses.passes = 2;
    CHECK(islandSubstepCount(8, 1, 0, 0.5, true, true, twoPasses, reason) == 4);
    // Mass ratio: ⌈2r⌉, so 2:1 → 4, 100:1 → the cap
    CHECK(islandSubstepCount(1, 2, 0, 0.5, true, true, in, reason) == 4);
    CHECK(reason == SubstepReason::MassRatio);
    CHECK(islandSubstepCount(1, 100, 0, 0.5, true, true, in, reason) == kCap);
    // Speed: ⌈v·h/(0.1·s)⌉; at s = 0.5 m, h = 1/60 s, 3 m/s moves 0.1·s a step: 1; 9 m/s: 3 → 4
    CHECK(islandSubstepCount(1, 1, 2.9, 0.5, true, true, in, reason) == 1);
    CHECK(islandSubstepCount(1, 1, 9, 0.5, true, true, in, reason) == 4);
    CHECK(reason == SubstepReason::Speed);
    // Free flight: exact under Verlet or without acceleration, else the full count
    CHECK(islandSubstepCount(1, 1, 0, 0.5, false, true, in, reason) == kCap);
    CHECK(reason == SubstepReason::FreeFlight);
    CHECK(islandSubstepCount(1, 1, 0, 0.5, false, false, in, reason) == 1);
    SubstepRuleInputs verlet = in;
    verlet.integrator = IntegratorKind::Verlet;
    CHECK(islandSubstepCount(1, 1, 0, 0.5, false, true, verlet, reason) == 1);
}

TEST_CASE("A tall stack gets the full count, a lone ball beside it fewer", "[substeps]") {
    World world(towerAndBall(true));
    REQUIRE(world.plan().islandSubsteps.runs);
    world.step();
    REQUIRE(world.islandSubsteps().size() == 2);
    const IslandSubsteps& tower = islandHolding(world, 0);
    CHECK(tower.bodies == kTowerHeight);
    CHECK(tower.height == kTowerHeight);  // every box is one layer higher
    CHECK(tower.count == kCap);
    const IslandSubsteps& ball = islandHolding(world, kTowerHeight);
    CHECK(ball.bodies == 1);
    CHECK(ball.height == 1);
    CHECK(ball.count == kStiffCount);  // at rest on the ground: only the stiffness term asks for more than 1
    CHECK(ball.reason == SubstepReason::Stiffness);
}

TEST_CASE("An island given the full count computes what the fixed count computes, bit for bit", "[substeps]") {
    World perIsland(towerAndBall(true));
    World fixed(towerAndBall(false));
    constexpr int kSteps = 120;  // two seconds: the tower settles, the ball stays a separate island
    for (int step = 0; step < kSteps; ++step) {
        perIsland.step();
        fixed.step();
        REQUIRE(islandHolding(perIsland, 0).count == kCap);
        requireSameMotion(perIsland, fixed, kTowerHeight, step + 1);
    }
    CHECK(fixed.islandSubsteps().empty());  // SubstepsPerIsland=false: the rule never ran
}

TEST_CASE("SubstepsPerIsland=false forces the fixed count", "[substeps]") {
    SECTION("the field, read from a scene") {
        const Scene scene = parseScene("World, Substeps=8, SubstepsPerIsland=true\n", "test");
        CHECK(scene.settings.substepsPerIsland);
        CHECK(scene.settings.substeps == 8);
        CHECK_FALSE(parseScene("World, Substeps=8\n", "test").settings.substepsPerIsland);
    }
    SECTION("off: every island runs Substeps") {
        World world(towerAndBall(false));
        CHECK_FALSE(world.plan().islandSubsteps.runs);
        world.step();
        CHECK(world.islandSubsteps().empty());
    }
}

namespace {

/// Three islands: a pendulum swinging from the world (a joint, no contact), a dumbbell of two balls
/// joined by a rod lying on the ground (a joint and contacts), and a ball at rest on the ground.
/// The bodies are listed so that each island's first body is the one named: bob, left, ball.
/// @p sleeping sets Sleep (the file's World record says false).
Scene jointedScene(bool perIsland, bool sleeping = false) {
    Scene scene = parseScene(
        "World, Sleep=false\n"
        "CollisionPlane, 0, 0, 0, 0, 1, 0\n"
        "DynamicObject, Name=bob, Shape=Sphere, Radius=0.1, Mass=1, Position=(-9, 5, 0)\n"
        "DistanceJoint, Name=pendulum, BodyA=bob, AnchorA=(-9, 5, 0), AnchorB=(-10, 6, 0)\n"
        "DynamicObject, Name=left, Shape=Sphere, Radius=0.5, Mass=1, Position=(0, 0.5, 0)\n"
        "DynamicObject, Name=right, Shape=Sphere, Radius=0.5, Mass=3, Position=(2, 0.5, 0)\n"
        "DistanceJoint, Name=rod, BodyA=left, BodyB=right, AnchorA=(0, 0.5, 0), AnchorB=(2, 0.5, 0)\n"
        "DynamicObject, Name=ball, Shape=Sphere, Radius=0.5, Position=(20, 0.5, 0)\n",
        "test");
    scene.settings.substepsPerIsland = perIsland;
    scene.settings.sleeping = sleeping;
    return scene;
}

}  // namespace

TEST_CASE("A joint keeps its own island at the full count, and the islands beside it get theirs", "[substeps][joints]") {
    World world(jointedScene(true));
    REQUIRE(world.plan().islandSubsteps.runs);
    world.step();
    REQUIRE(world.islandSubsteps().size() == 3);
    const IslandSubsteps& pendulum = islandHolding(world, 0);
    CHECK(pendulum.bodies == 1);
    CHECK(pendulum.joints == 1);
    CHECK(pendulum.count == kCap);
    CHECK(pendulum.reason == SubstepReason::Joint);
    const IslandSubsteps& dumbbell = islandHolding(world, 1);  // joined by the rod, not by a contact
    CHECK(dumbbell.bodies == 2);
    CHECK(dumbbell.joints == 1);
    CHECK(dumbbell.massRatio == 1);  // the rule's mass ratio is across contacts; the rod's 3:1 is not one
    CHECK(dumbbell.count == kCap);
    CHECK(dumbbell.reason == SubstepReason::Joint);
    const IslandSubsteps& ball = islandHolding(world, 3);
    CHECK(ball.joints == 0);
    CHECK(ball.count == kStiffCount);
    CHECK(ball.reason == SubstepReason::Stiffness);
}

TEST_CASE("An island a joint holds computes what the fixed count computes, bit for bit", "[substeps][joints]") {
    // With Sleep=true the dumbbell, at rest from the start, falls asleep with its joint; the pendulum
    // swings on, and its island (now of one joint among two, the other asleep) keeps the full count.
    const bool sleeping = GENERATE(false, true);
    INFO((sleeping ? "Sleep=true" : "Sleep=false"));
    World perIsland(jointedScene(true, sleeping));
    World fixed(jointedScene(false, sleeping));
    constexpr int kSteps = 120;  // two seconds: most of a swing of the pendulum (period 2.4 s)
    constexpr std::size_t kJointed = 3;  // bob, left, right
    Real lowest = perIsland.dynamics()[0].position.y;
    for (int step = 0; step < kSteps; ++step) {
        perIsland.step();
        fixed.step();
        lowest = std::min(lowest, perIsland.dynamics()[0].position.y);
        REQUIRE(islandHolding(perIsland, 3).count < kCap);  // the ball's island ran fewer substeps all along
        requireSameMotion(perIsland, fixed, kJointed, step + 1);
    }
    // And it swung: its rod of √2 m, released 45° from the vertical, passes through its lowest point,
    // √2 m below the pivot (a step of 1/60 s there, at 2.85 m/s, samples it within 1 mm)
    CHECK(lowest == Approx(6 - std::sqrt(Real(2))).margin(0.005));
    CHECK(fixed.islandSubsteps().empty());
    CHECK(perIsland.dynamics()[1].asleep == sleeping);  // the dumbbell slept, or never could
    CHECK_FALSE(perIsland.dynamics()[0].asleep);       // the pendulum never stops
}

TEST_CASE("A ball in free flight under Verlet runs one substep and falls exactly", "[substeps]") {
    Scene scene = test::emptyScene(IntegratorKind::Verlet);
    scene.settings.substepsPerIsland = true;
    scene.planes.push_back(test::ground());  // far below: contacts are possible, none is found
    const Vec3 x0(0, 1000, 0);
    const Vec3 v0(3, 4, -2);
    scene.dynamics.push_back(test::sphere("ball", x0, v0));
    World world(scene);
    constexpr int kSteps = 60;
    for (int step = 0; step < kSteps; ++step) {
        world.step();
        REQUIRE(world.islandSubsteps().size() == 1);
        REQUIRE(world.islandSubsteps()[0].count == 1);
        REQUIRE(world.islandSubsteps()[0].reason == SubstepReason::Minimum);
    }
    const Real t = kSteps * kH;
    const Vec3 g = scene.settings.gravity;
    const Vec3 expected = x0 + v0 * t + Real(0.5) * g * t * t;
    // Verlet is exact for a constant acceleration; what is left is rounding, 60 steps of
    // additions to a 1000 m coordinate: a few ulps of 1000 m (1e-13 m each), so 1e-10 m.
    const Vec3 error = world.dynamics()[0].position - expected;
    CHECK(glm::length(error) < 1e-10);
    CHECK(glm::length(world.dynamics()[0].velocity - (v0 + g * t)) < 1e-10);
}
