// No allocation in a running World: every global operator new is counted
// during World::step() once a scene has warmed up (its arrays have grown to
// their largest size). Tag: [allocations]. Not under AddressSanitizer, which
// must keep its own operator new to track memory (allocation_counter.hpp).
#include <catch2/catch.hpp>

#if !defined(__SANITIZE_ADDRESS__)

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "allocation_counter.hpp"
#include "config/scene_loader.hpp"
#include "objects/triangle_mesh.hpp"
#include "test_support.hpp"

using namespace stepwise;

namespace {

/// Steps run before counting: the arrays grow while contacts appear and the
/// warm-start caches fill (two seconds at 60 steps per second).
constexpr int kWarmUpSteps = 120;
/// Steps counted.
constexpr int kCountedSteps = 60;

/// Allocations during kCountedSteps steps of @p scene after kWarmUpSteps, with @p stepPlan.
std::size_t allocationsPerRun(Scene scene, bool stepPlan) {
    scene.settings.stepPlan = stepPlan;
    World world(std::move(scene));
    // The first step does allocate (its arrays grow from empty): the counter must see that.
    test::gAllocations = 0;
    test::gCounting = true;
    world.step();
    test::gCounting = false;
    if (world.contacts().size() + world.candidatePairs().size() > 0) CHECK(test::gAllocations > 0);
    for (int i = 1; i < kWarmUpSteps; ++i) world.step();
    test::gAllocations = 0;
    for (int i = 0; i < kCountedSteps; ++i) {
        test::gCounting = true;
        world.step();
        test::gCounting = false;
    }
    return test::gAllocations;
}

Scene configScene(const std::string& file) { return loadSceneFile(std::string(STEPWISE_SOURCE_DIR) + "/config/" + file); }

}  // namespace

TEST_CASE("World::step allocates nothing in steady state", "[allocations]") {
    // Spheres and a paddle (sequential impulse); a box stack and a 20-box tower (sequential impulse);
    // joints (pendulum, chain bridge); boxes and spheres on the Impulse solver.
    const char* files[] = {"default.scene",        "lesson08_heavy_on_light.scene", "lesson08_tower.scene",
                           "lesson08_pendulum.scene", "lesson08_bridge.scene",      "lesson08_hinge_motor.scene",
                           "lesson03_collisions.scene", "lesson07_tipping.scene",   "lesson05_sat.scene",
                           // fast bodies every step: the continuous stage's candidate index (continuous_candidates.hpp)
                           "stress_fast_sphere_wall.scene", "stress_fast_box_wall.scene"};
    for (const char* file : files) {
        for (const bool stepPlan : {true, false}) {
            INFO(file << (stepPlan ? " with the plan" : " with StepPlan=Off"));
            CHECK(allocationsPerRun(configScene(file), stepPlan) == 0);
        }
    }
}

TEST_CASE("Regions allocate nothing per step", "[allocations][regions]") {
    // Drag, wind, buoyancy, a gravity region, random forces and Kill regions: their members are
    // found each step (World::findRegionMembers()) into lists that keep their capacity, and the
    // Kill test (World::removeKilledBodies()) allocates only when it removes a body. The wind
    // scene's ball reaches its Kill region after the counted steps; the pond's ball falls into
    // its abyss during the warm-up.
    for (const char* file : {"regions_pond.scene", "lesson13_boat.scene", "lesson13_capsize.scene",
                             "lesson13_terminal_speed.scene", "lesson13_wind.scene"}) {
        for (const bool stepPlan : {true, false}) {
            INFO(file << (stepPlan ? " with the plan" : " with StepPlan=Off"));
            CHECK(allocationsPerRun(configScene(file), stepPlan) == 0);
        }
    }
}

TEST_CASE("A box pyramid allocates nothing per step once it has settled", "[allocations]") {
    // The 210-box pyramid of lecture 8 (sequential impulse, the AABB tree chosen by Auto).
    CHECK(allocationsPerRun(configScene("lesson08_pyramid.scene"), true) == 0);
}

TEST_CASE("A soft ball in a triangle-mesh bowl allocates nothing per step", "[allocations][mesh][soft]") {
    // config/soft_on_mesh.scene: 162 nodes, each queried against the 512-triangle bowl every
    // substep (node_mesh_contacts.cpp: the hierarchy's fixed stack, meshContacts()' fixed arrays).
    for (const bool stepPlan : {true, false}) {
        INFO((stepPlan ? "with the plan" : "with StepPlan=Off"));
        CHECK(allocationsPerRun(configScene("soft_on_mesh.scene"), stepPlan) == 0);
    }
}

TEST_CASE("Bodies on a triangle mesh allocate nothing per step", "[allocations][mesh]") {
    // A 10 x 10 grid of 200 triangles: a ball rolling across it at 1 m/s (still on it after the
    // 3 s counted here) and a box that slides to rest on it. The hierarchy's query keeps its
    // nodes in a fixed stack and the pair test gathers its points in fixed arrays (mesh_query.hpp,
    // mesh_contacts.hpp). Sleep is off, so both are tested every step.
    std::vector<Vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    constexpr std::uint32_t n = 10;
    for (std::uint32_t i = 0; i <= n; ++i) {
        for (std::uint32_t k = 0; k <= n; ++k) vertices.emplace_back(Real(i), 0, Real(k));
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t k = 0; k < n; ++k) {
            const std::uint32_t a = i * (n + 1) + k;
            triangles.push_back({a, a + 1, a + n + 1});
            triangles.push_back({a + n + 1, a + 1, a + n + 2});
        }
    }
    Scene scene = test::emptyScene();
    scene.settings.sleeping = false;
    KinematicsObject floor;
    floor.name = "floor";
    floor.shape = Shape::Mesh;
    floor.mesh = std::make_shared<const TriangleMesh>(buildTriangleMesh(vertices, triangles));
    scene.kinematics.push_back(floor);
    DynamicObject ball = test::sphere("ball", Vec3(1, 0.25, 2), Vec3(1, 0, 0.3), 0.25, 1, 0, 0.5);
    ball.angularVelocity = glm::cross(Vec3(0, 1, 0), ball.velocity) / Real(0.25);
    scene.dynamics.push_back(ball);
    DynamicObject box = test::dynamicBox("box", Vec3(2, 0.25, 6), Vec3(0.5), 1, 0.3);
    box.velocity = Vec3(2, 0, 0);
    scene.dynamics.push_back(box);
    for (const bool stepPlan : {true, false}) {
        INFO((stepPlan ? "with the plan" : "with StepPlan=Off"));
        CHECK(allocationsPerRun(scene, stepPlan) == 0);
    }
}

#endif
