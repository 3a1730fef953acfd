// Regions and their effects (src/forces/region.hpp): each effect against its physics.
//
// Drag and wind against the closed forms of v' = g − (c/m)·v; buoyancy against Archimedes'
// principle (the floating depth, the sphere's cubic, the sign of the metacentric height); the
// submerged volumes against geometry; RandomForce for repeatability; Kill for the step a body
// goes. The tolerances are the (0.5 % on speeds, 1 mm on floating depths) unless said.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "config/scene_loader.hpp"
#include "forces/buoyancy.hpp"
#include "forces/random_force.hpp"
#include "test_support.hpp"

using namespace stepwise;
using stepwise::test::emptyScene;
using stepwise::test::sphere;

namespace {

constexpr Real kG = kStandardGravity;

/// Everything below y = top: a fluid filling the world up to a level.
Region below(const std::string& name, RegionEffect effect, Real top = 0) {
    Region region;
    region.name = name;
    region.shape = RegionShape::HalfSpace;
    region.position = Vec3(0, top, 0);
    region.normal = Vec3(0, 1, 0);
    region.effect = effect;
    return region;
}

/// A box body of the given full edges and density.
DynamicObject boxOfDensity(const std::string& name, Vec3 position, Vec3 size, Real density) {
    return test::dynamicBox(name, position, size, density * size.x * size.y * size.z, 0.5);
}

/// The angle between a body's y axis and the world's y axis, degrees.
Real tiltDegrees(const DynamicObject& body) {
    const Vec3 up = body.orientation * Vec3(0, 1, 0);
    return std::acos(std::clamp(std::abs(up.y), Real(-1), Real(1))) * 180 / std::numbers::pi_v<Real>;
}

}  // namespace

TEST_CASE("Linear drag: v(t) = v_t (1 - exp(-c t / m)) and the terminal speed m g / c", "[forces][regions]") {
    const Real m = 2, c = 4;  // time constant m/c = 0.5 s
    Scene scene = emptyScene();
    scene.dynamics.push_back(sphere("ball", Vec3(0, 0, 0), Vec3(0), 0.1, m));
    Region air = below("air", RegionEffect::Drag, 1e6);
    air.coefficient = c;
    scene.regions.push_back(air);
    World world(std::move(scene));
    const Real terminal = m * kG / c;
    for (int n = 1; n <= 240; ++n) {
        world.step();
        const Real t = world.time();
        const Real expected = terminal * (1 - std::exp(-c * t / m));
        INFO("t = " << t);
        REQUIRE(-world.dynamics()[0].velocity.y == Approx(expected).margin(0.005 * terminal));
    }
    CHECK(-world.dynamics()[0].velocity.y == Approx(terminal).epsilon(0.005));  // 8 time constants
}

TEST_CASE("Quadratic drag: the terminal speed is sqrt(m g / c)", "[forces][regions]") {
    const Real m = 1, c = 0.2;  // v_t = 7.0 m/s, reached within a few v_t/g = 0.7 s
    Scene scene = emptyScene();
    scene.dynamics.push_back(sphere("ball", Vec3(0), Vec3(0), 0.1, m));
    Region air = below("air", RegionEffect::Drag, 1e6);
    air.law = DragLaw::Quadratic;
    air.coefficient = c;
    scene.regions.push_back(air);
    World world(std::move(scene));
    for (int n = 0; n < 600; ++n) world.step();
    CHECK(-world.dynamics()[0].velocity.y == Approx(std::sqrt(m * kG / c)).epsilon(0.005));
}

TEST_CASE("Wind with linear drag carries a free ball to the wind's speed", "[forces][regions]") {
    const Real m = 1, c = 2;
    const Vec3 w(3, 0, -1);
    Scene scene = emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60, Vec3(0));
    scene.dynamics.push_back(sphere("leaf", Vec3(0), Vec3(0), 0.1, m));
    Region wind;
    wind.name = "gale";
    wind.shape = RegionShape::Box;
    wind.halfExtents = Vec3(1e4);
    wind.effect = RegionEffect::Wind;
    wind.velocity = w;
    wind.coefficient = c;
    scene.regions.push_back(wind);
    World world(std::move(scene));
    for (int n = 1; n <= 300; ++n) {
        world.step();
        const Vec3 expected = w * (1 - std::exp(-c * world.time() / m));
        REQUIRE(glm::length(world.dynamics()[0].velocity - expected) <= 0.005 * glm::length(w));
    }
    CHECK(glm::length(world.dynamics()[0].velocity - w) <= 0.005 * glm::length(w));
}

TEST_CASE("A Gravity region replaces the World's gravity inside it", "[forces][regions]") {
    Scene scene = emptyScene();
    scene.dynamics.push_back(sphere("inside", Vec3(0), Vec3(0), 0.1));
    scene.dynamics.push_back(sphere("outside", Vec3(100, 0, 0), Vec3(0), 0.1));
    Region moon;
    moon.name = "moon";
    moon.shape = RegionShape::Sphere;
    moon.radius = 50;
    moon.effect = RegionEffect::Gravity;
    moon.gravity = Vec3(0, -1.62, 0);
    scene.regions.push_back(moon);
    World world(std::move(scene));
    for (int n = 0; n < 60; ++n) world.step();
    // v = g·t exactly under symplectic Euler with a constant acceleration
    CHECK(world.dynamics()[0].velocity.y == Approx(-1.62 * world.time()).epsilon(1e-9));
    CHECK(world.dynamics()[1].velocity.y == Approx(-kG * world.time()).epsilon(1e-9));
}

TEST_CASE("Submerged volumes of spheres and boxes match geometry", "[forces][regions][buoyancy]") {
    const FluidSurface water{Vec3(0), Vec3(0, 1, 0)};
    const Real r = 0.5;
    const Real ball = 4 * std::numbers::pi_v<Real> * r * r * r / 3;
    SECTION("a sphere: dry, half, full, and the cap's centroid") {
        CHECK(submergedSphere(Vec3(0, 2, 0), r, water).volume == 0);
        const SubmergedPart half = submergedSphere(Vec3(0), r, water);
        CHECK(half.volume == Approx(ball / 2).epsilon(1e-12));
        CHECK(half.centroid.y == Approx(-3 * r / 8).epsilon(1e-12));  // a hemisphere's centroid
        CHECK(submergedSphere(Vec3(0, -2, 0), r, water).volume == Approx(ball).epsilon(1e-12));
    }
    SECTION("an upright box: base area times depth, centroid halfway down the wet part") {
        const SubmergedPart part = submergedBox(Vec3(0, 0.1, 0), Quat(1, 0, 0, 0), Vec3(1, 0.5, 0.25), water);
        const Real depth = 0.5 - 0.1;  // the bottom face is at y = −0.4
        CHECK(part.volume == Approx(2 * 0.5 * depth).epsilon(1e-12));
        CHECK(part.centroid.y == Approx(-depth / 2).epsilon(1e-12));
        CHECK(part.centroid.x == Approx(0).margin(1e-12));
    }
    SECTION("any orientation: the parts below and above the plane make the whole box") {
        std::mt19937 rng(7);
        std::uniform_real_distribution<Real> u(-1, 1);
        const FluidSurface air{Vec3(0), Vec3(0, -1, 0)};  // the same plane, the other side
        for (int k = 0; k < 200; ++k) {
            const Quat q = glm::normalize(Quat(u(rng), u(rng), u(rng), u(rng)));
            const Vec3 centre(u(rng), 0.6 * u(rng), u(rng));
            const Vec3 half(0.5, 0.3, 0.2);
            const SubmergedPart wet = submergedBox(centre, q, half, water);
            const SubmergedPart dry = submergedBox(centre, q, half, air);
            const Real whole = 8 * half.x * half.y * half.z;
            REQUIRE(wet.volume + dry.volume == Approx(whole).epsilon(1e-12));
            // The two centroids, weighted, give the box's centre (the moments add up)
            const Vec3 centroid = (wet.volume * wet.centroid + dry.volume * dry.centroid) / whole;
            REQUIRE(glm::length(centroid - centre) < 1e-12);
        }
    }
    SECTION("a cube turned 45 degrees about z, cut through its centre: half the volume, a triangle prism") {
        const Quat q = glm::angleAxis(std::numbers::pi_v<Real> / 4, Vec3(0, 0, 1));
        const SubmergedPart part = submergedBox(Vec3(0), q, Vec3(0.5), water);
        CHECK(part.volume == Approx(0.5).epsilon(1e-12));
        // The wet part is a prism on a right triangle of depth √2/2: its centroid is a third of the way down
        CHECK(part.centroid.y == Approx(-std::sqrt(Real(2)) / 2 / 3).epsilon(1e-12));
    }
}

namespace {

/// A pond: water below y = 0 with enough drag to let a floating body settle.
Region pond(Real linearDrag, Real angularDrag) {
    Region water = below("pond", RegionEffect::Buoyancy);
    water.density = 1000;
    water.coefficient = linearDrag;
    water.angularCoefficient = angularDrag;
    return water;
}

}  // namespace

TEST_CASE("A box of half the water's density floats with half its height under water", "[forces][regions][buoyancy]") {
    const Vec3 size(2, 0.5, 2);  // flat: W > √1.5·H, so it floats upright
    Scene scene = emptyScene();
    scene.dynamics.push_back(boxOfDensity("raft", Vec3(0, 1, 0), size, 500));
    scene.regions.push_back(pond(2000, 500));
    World world(std::move(scene));
    for (int n = 0; n < 60 * 20; ++n) world.step();
    const DynamicObject& raft = world.dynamics()[0];
    // Half of H = 0.5 m under water: the bottom at −0.25, the centre at the surface
    CHECK(raft.position.y == Approx(0).margin(1e-3));
    CHECK(std::abs(raft.velocity.y) < 1e-3);
}

TEST_CASE("A ball of a quarter of the water's density floats where the cap holds a quarter of its volume",
          "[forces][regions][buoyancy]") {
    // V_cap(d) = π·d²·(3r − d)/3 = ¼·(4/3)·π·r³  ⇔  x³ − 3x² + 1 = 0 with x = d/r; the root in (0, 1), by bisection
    Real lo = 0, hi = 1;
    for (int k = 0; k < 100; ++k) {
        const Real mid = (lo + hi) / 2;
        (mid * mid * mid - 3 * mid * mid + 1 > 0 ? lo : hi) = mid;
    }
    const Real r = 0.5;
    const Real depth = lo * r;  // 0.3264 m
    const Real mass = 250 * 4 * std::numbers::pi_v<Real> * r * r * r / 3;
    Scene scene = emptyScene();
    scene.dynamics.push_back(sphere("buoy", Vec3(0, 1, 0), Vec3(0), r, mass));
    scene.regions.push_back(pond(400, 0));
    World world(std::move(scene));
    for (int n = 0; n < 60 * 20; ++n) world.step();
    CHECK(world.dynamics()[0].position.y == Approx(r - depth).margin(1e-3));
}

TEST_CASE("Archimedes' torque rights a box with GM > 0 and capsizes one with GM < 0", "[forces][regions][buoyancy]") {
    // GM = BM − BG = W²/(12·d) − (H − d)/2 for a box of width W, height H floating at depth d = H·ρ/ρ_f
    const auto metacentricHeight = [](Real width, Real height, Real density) {
        const Real d = height * density / 1000;
        return width * width / (12 * d) - (height - d) / 2;
    };
    // A box of density 500 kg/m³ and @p size dropped at the surface tilted @p degrees about z,
    // settled for 20 s in a pond of @p linearDrag and @p angularDrag: its tilt at the end, degrees.
    const auto tiltAfterSettling = [](Vec3 size, Real degrees, Real linearDrag, Real angularDrag) {
        Scene scene = emptyScene();
        DynamicObject box = boxOfDensity("box", Vec3(0, 0, 0), size, 500);
        box.orientation = glm::angleAxis(degrees * std::numbers::pi_v<Real> / 180, Vec3(0, 0, 1));
        scene.dynamics.push_back(box);
        scene.regions.push_back(pond(linearDrag, angularDrag));
        World world(std::move(scene));
        for (int n = 0; n < 60 * 20; ++n) world.step();
        return tiltDegrees(world.dynamics()[0]);
    };
    SECTION("a flat raft, tilted 15 degrees, rights itself") {
        const Vec3 size(2, 0.5, 2);
        REQUIRE(metacentricHeight(size.x, size.y, 500) > 0);
        CHECK(tiltAfterSettling(size, 15, 2000, 500) < 1);
    }
    SECTION("a tall post with its centre of mass high, tilted 5 degrees, capsizes") {
        const Vec3 size(0.5, 2, 0.5);
        REQUIRE(metacentricHeight(size.x, size.y, 500) < 0);
        CHECK(tiltAfterSettling(size, 5, 500, 50) > 60);  // it ends lying down, its long axis near the surface
    }
}

TEST_CASE("RandomForce repeats bit for bit with its seed, differs with another, and stays within Strength",
          "[forces][regions]") {
    const auto run = [](std::uint64_t seed) {
        Scene scene = emptyScene();
        for (int i = 0; i < 5; ++i) scene.dynamics.push_back(sphere("b" + std::to_string(i), Vec3(2 * i, 0, 0), Vec3(0), 0.2));
        Region shaker = below("shaker", RegionEffect::RandomForce, 1e6);
        shaker.strength = 3;
        shaker.seed = seed;
        scene.regions.push_back(shaker);
        World world(std::move(scene));
        for (int n = 0; n < 120; ++n) world.step();
        std::vector<Vec3> positions;
        for (const DynamicObject& body : world.dynamics()) positions.push_back(body.position);
        return positions;
    };
    CHECK(run(42) == run(42));
    CHECK(run(42) != run(43));
    for (std::uint64_t step = 0; step < 1000; ++step) REQUIRE(glm::length(randomForce(9, step, 3, 3)) <= 3);
}

TEST_CASE("A body falling into a Kill region is removed at the step it enters", "[forces][regions]") {
    const Real h = Real(1) / 60;
    Scene scene = emptyScene();
    scene.dynamics.push_back(sphere("faller", Vec3(0), Vec3(0), 0.1));
    scene.dynamics.push_back(sphere("stayer", Vec3(5, 0, 0), Vec3(0), 0.1));
    scene.dynamics.back().constantAcceleration = Vec3(0, kG, 0);  // hovers
    Spring spring;  // joins the two: it must go with the faller
    spring.name = "tether";
    spring.bodyA = 1;
    spring.bodyB = 0;
    spring.stiffness = 0;
    spring.restLength = 5;
    scene.springs.push_back(spring);
    scene.regions.push_back(below("abyss", RegionEffect::Kill, -5));
    // Symplectic Euler with 16 substeps of h_s under g: after k substeps y_k = −g·h_s²·k(k+1)/2.
    // The faller goes in the step whose last substep first takes y to −5 or below.
    const Real hs = h / Real(scene.settings.substeps);
    int k = 0;
    while (-kG * hs * hs * k * (k + 1) / 2 > -5) ++k;
    const int enteringStep = (k + scene.settings.substeps - 1) / scene.settings.substeps;
    World world(std::move(scene));
    for (int n = 1; n < enteringStep; ++n) world.step();
    REQUIRE(world.dynamics().size() == 2);
    world.step();
    REQUIRE(world.dynamics().size() == 1);
    CHECK(world.dynamics()[0].name == "stayer");
    CHECK(world.springs().empty());
    REQUIRE(world.removedBodies().size() == 1);
    CHECK(world.removedBodies()[0].name == "faller");
    CHECK(world.removedBodies()[0].region == "abyss");
    CHECK(world.removedBodies()[0].time == Approx(enteringStep * h));
    for (int n = 0; n < 10; ++n) world.step();  // the world goes on without it
    CHECK(world.dynamics()[0].position.y == Approx(0).margin(1e-9));
}

TEST_CASE("A region finds through the broadphase exactly the bodies a test of every body finds", "[forces][regions][broadphase]") {
    const BroadphaseKind kind =
        GENERATE(BroadphaseKind::BruteForce, BroadphaseKind::SweepAndPrune, BroadphaseKind::AabbTree, BroadphaseKind::Grid,
                 BroadphaseKind::Octree);
    std::mt19937 rng(11);
    std::uniform_real_distribution<Real> u(-20, 20);
    Scene scene = emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60, Vec3(0));
    scene.settings.broadphase = kind;
    for (int i = 0; i < 300; ++i) scene.dynamics.push_back(sphere("b" + std::to_string(i), Vec3(u(rng), u(rng), u(rng)), Vec3(0), 0.3));
    Region ball;
    ball.name = "ball";
    ball.shape = RegionShape::Sphere;
    ball.position = Vec3(3, -2, 1);
    ball.radius = 9;
    ball.effect = RegionEffect::Drag;
    ball.coefficient = 1;
    Region slab = below("slab", RegionEffect::Wind, -12);
    slab.coefficient = 1;
    Region box;
    box.name = "box";
    box.position = Vec3(-10, 5, 0);
    box.halfExtents = Vec3(6, 4, 15);
    box.effect = RegionEffect::Gravity;
    box.gravity = Vec3(1, 0, 0);
    scene.regions = {ball, slab, box};
    const std::vector<DynamicObject> start = scene.dynamics;
    World world(std::move(scene));
    world.step();
    INFO("Broadphase=" << toString(kind));
    for (std::size_t r = 0; r < world.regions().size(); ++r) {
        std::vector<std::uint32_t> expected;
        for (std::uint32_t i = 0; i < start.size(); ++i) {
            if (regionHolds(world.regions()[r], start[i])) expected.push_back(i);
        }
        const std::span<const std::uint32_t> found = world.regionMembers().of(r);
        CHECK(std::vector<std::uint32_t>(found.begin(), found.end()) == expected);
        CHECK(!expected.empty());
    }
}

TEST_CASE("Region records load, and a wrong one is refused with its line and column", "[forces][regions][config]") {
    const Scene scene = parseScene(
        "World, Gravity=(0, -9.81, 0)\n"
        "DynamicObject, Name=ball, Shape=Sphere, Position=(0, 1, 0)\n"
        "Region, Name=pond, Shape=HalfSpace, Position=(0, 0, 0), Effect=Buoyancy, Density=1000, Coefficient=5\n"
        "Region, Name=fan, Shape=Box, Position=(0, 3, 0), Scale=(2, 2, 2), Effect=Wind, Velocity=(4, 0, 0), Coefficient=1\n"
        "Region, Name=shake, Shape=Sphere, Radius=3, Effect=RandomForce, Strength=2, Seed=7\n",
        "regions.scene");
    REQUIRE(scene.regions.size() == 3);
    CHECK(scene.regions[0].effect == RegionEffect::Buoyancy);
    CHECK(scene.regions[0].density == 1000);
    CHECK(scene.regions[1].halfExtents == Vec3(1));
    CHECK(scene.regions[2].seed == 7);
    const auto refused = test::checkRefused;
    refused("Region, Name=r, Shape=Box\n", "an Effect field");
    refused("Region, Name=r, Effect=Drag, Coefficient=1, Density=1000\n", "no Density on an Effect=Drag region");
    refused("Region, Name=r, Effect=Wind, Coefficient=1\n", "a Velocity field");
    refused("Region, Name=r, Shape=Sphere, Effect=Buoyancy, Density=1000\n", "Box or HalfSpace for Effect=Buoyancy");
    refused("Region, Name=r, Effect=RandomForce, Strength=1, Seed=1.5\n", "a whole number");
    refused("Region, Name=r, Shape=HalfSpace, Scale=(1, 1, 1), Effect=Kill\n", "no Scale on a HalfSpace region");
    refused("DynamicObject, Name=pill, Shape=Capsule\nRegion, Name=r, Shape=HalfSpace, Effect=Buoyancy, Density=1000\n",
            "only spheres and boxes");
    refused("Region, Name=r, Effect=Drag, Law=Cubic, Coefficient=1\n", "Law");
}
