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
#include "forces/conveyor.hpp"
#include "forces/random_force.hpp"
#include "test_support.hpp"
#include "trace_values.hpp"

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

// Conveyor belts (src/forces/conveyor.hpp): no force, a moving surface for friction. Against
// Coulomb's law: a body set down at rest on a belt of speed u is pushed by friction μ·m·g until
// its contact point moves with the belt. Tolerances: speeds within 1 % of u, times within 2 steps.
namespace {

/// A belt over the floor y = 0: a Conveyor region 40 m along x, 4 m across z, 2 m high, moving at @p u.
Region belt(Vec3 u) {
    Region region;
    region.name = "belt";
    region.shape = RegionShape::Box;
    region.position = Vec3(0, 1, 0);
    region.halfExtents = Vec3(20, 1, 2);
    region.effect = RegionEffect::Conveyor;
    region.velocity = u;
    return region;
}

constexpr Real kBeltStep = Real(1) / 60;  // the steps of emptyScene(), s

}  // namespace

TEST_CASE("A box set down on a belt slides at mu g until it moves with the belt, at t = u / (mu g)",
          "[forces][regions][conveyor]") {
    const SolverKind solver = GENERATE(SolverKind::SequentialImpulse, SolverKind::Impulse);
    INFO("Solver=" << toString(solver));
    const Real mu = 0.4, u = 2, h = kBeltStep;  // the floor's Friction is 1: the pair's μ is the box's
    Scene scene = emptyScene();
    scene.settings.solver = solver;
    scene.planes.push_back(test::ground());
    scene.dynamics.push_back(test::dynamicBox("crate", Vec3(0, 0.25, 0), Vec3(0.5), 1, mu));
    scene.dynamics.push_back(test::dynamicBox("beside", Vec3(0, 0.25, 5), Vec3(0.5), 1, mu));  // off the belt
    World still(scene);  // the same scene without the belt
    scene.regions.push_back(belt(Vec3(u, 0, 0)));
    World world(std::move(scene));
    REQUIRE(world.plan().conveyors.runs);
    const Real arrival = u / (mu * kG);  // 0.51 s: 30.6 steps
    Real reached = -1;
    for (int n = 1; n <= 120; ++n) {
        world.step();
        still.step();
        const Real t = world.time();
        const DynamicObject& crate = world.dynamics()[0];
        INFO("t = " << t);
        if (reached < 0 && crate.velocity.x >= Real(0.99) * u) reached = t;
        if (t < arrival - 2 * h) REQUIRE(crate.velocity.x == Approx(mu * kG * t).margin(0.01 * u));
        if (t > arrival + 2 * h) REQUIRE(crate.velocity.x == Approx(u).margin(0.01 * u));
        REQUIRE(std::abs(crate.velocity.z) < 0.01 * u);  // carried along the belt, not across it
        REQUIRE(std::abs(crate.velocity.y) < 0.01 * u);  // nor lifted or pressed down
        // Off the belt, a box settles on the floor as in a world without one, to 1e-9 (not to the bit: a
        // box sliding elsewhere, belt or no belt, changes the rounding of a resting one)
        REQUIRE(glm::length(world.dynamics()[1].position - still.dynamics()[1].position) < Real(1e-9));
        REQUIRE(glm::length(world.dynamics()[1].velocity - still.dynamics()[1].velocity) < Real(1e-9));
    }
    // v reaches 0.99·u at 0.99·t*: the first step at or after that
    CHECK(std::abs(reached - Real(0.99) * arrival) <= 2 * h);
}

TEST_CASE("A ball on a belt rolls up to 2u/7, its lowest point moving with the belt", "[forces][regions][conveyor]") {
    // The friction impulse J that brings the contact point to the belt's speed (v + ω·r = u, ω about z)
    // gives Δv = J/m and Δ(ω·r) = 5J/(2m) (I = 2/5·m·r²): v = 2u/7. Sliding until then, the point's
    // speed grows at μg + 5μg/2 = 7μg/2, so it arrives at t = 2u/(7μg).
    const SolverKind solver = GENERATE(SolverKind::SequentialImpulse, SolverKind::Impulse);
    INFO("Solver=" << toString(solver));
    const Real mu = 0.2, u = 3, r = 0.25, h = kBeltStep;
    Scene scene = emptyScene();
    scene.settings.solver = solver;
    scene.planes.push_back(test::ground());
    scene.dynamics.push_back(sphere("ball", Vec3(0, r, 0), Vec3(0), r, 2, 0, mu));
    scene.regions.push_back(belt(Vec3(u, 0, 0)));
    World world(std::move(scene));
    const Real arrival = 2 * u / (7 * mu * kG);  // 0.437 s: 26.2 steps
    const Real rolling = 2 * u / 7;
    Real reached = -1;
    for (int n = 1; n <= 90; ++n) {
        world.step();
        const DynamicObject& ball = world.dynamics()[0];
        if (reached < 0 && ball.velocity.x >= Real(0.99) * rolling) reached = world.time();
    }
    const DynamicObject& ball = world.dynamics()[0];
    CHECK(ball.velocity.x == Approx(rolling).epsilon(0.01));
    CHECK(ball.velocity.x + ball.angularVelocity.z * r == Approx(u).epsilon(0.01));  // the lowest point's speed
    CHECK(std::abs(reached - Real(0.99) * arrival) <= 2 * h);
}

TEST_CASE("A belt's velocity counts in the contact's plane only: its part along the normal is dropped",
          "[forces][regions][conveyor]") {
    // Over a floor of normal (0, 1, 0), u = (2, 1, 0) and (2, 0, 0) have the same tangential part,
    // v_s = u − (u·n)·n, to the bit: the same run, not a box lifted by the belt.
    const auto run = [](Vec3 u) {
        Scene scene = emptyScene();
        scene.planes.push_back(test::ground());
        scene.dynamics.push_back(test::dynamicBox("crate", Vec3(0, 0.25, 0), Vec3(0.5), 1, 0.5));
        scene.dynamics.push_back(sphere("ball", Vec3(2, 0.2, 0), Vec3(0), 0.2, 1, 0, 0.5));
        scene.regions.push_back(belt(u));
        return World(std::move(scene));
    };
    World tilted = run(Vec3(2, 1, 0));
    World flat = run(Vec3(2, 0, 0));
    for (int n = 0; n < 60; ++n) {
        tilted.step();
        flat.step();
        test::requireSameState(tilted, flat);
    }
    CHECK(flat.dynamics()[0].velocity.x == Approx(2).epsilon(0.01));
    CHECK(conveyorSurfaceVelocity(Vec3(2, 1, 0), Vec3(0, -1, 0)) == Vec3(2, 0, 0));
}

TEST_CASE("Dynamic-dynamic contacts keep their own friction: a crate on a pallet rides at u, not 2u",
          "[forces][regions][conveyor]") {
    // Both centres are inside the belt, but only the pallet's contact with the floor takes the belt's
    // speed: the crate is carried by the pallet's friction (μ = 0.4·0.4 between the two) up to u.
    // Were the belt applied between them too, the crate would end at 2u.
    const Real u = 1.5;
    Scene scene = emptyScene();
    scene.planes.push_back(test::ground());
    scene.dynamics.push_back(test::dynamicBox("pallet", Vec3(0, 0.25, 0), Vec3(1.2, 0.5, 1.2), 10, 0.4));
    scene.dynamics.push_back(test::dynamicBox("crate", Vec3(0, 0.75, 0), Vec3(0.5), 1, 0.4));
    scene.regions.push_back(belt(Vec3(u, 0, 0)));
    World world(std::move(scene));
    for (int n = 0; n < 180; ++n) world.step();  // the crate arrives after u/(0.16 g) = 0.96 s
    CHECK(world.dynamics()[0].velocity.x == Approx(u).epsilon(0.01));
    CHECK(world.dynamics()[1].velocity.x == Approx(u).epsilon(0.01));
}

TEST_CASE("A belt on a kinematic body adds to the body's own surface velocity", "[forces][regions][conveyor]") {
    // A still slab under a belt moves its surface at u; one that itself moves at w at u + w.
    const SolverKind solver = GENERATE(SolverKind::SequentialImpulse, SolverKind::Impulse);
    INFO("Solver=" << toString(solver));
    const Vec3 u(2, 0, 0);
    const Vec3 w(0, 0, 1);
    Scene scene = emptyScene();
    scene.kinematics.push_back(test::kinematicBox("still", Vec3(0, -0.25, 0), Vec3(10, 0.5, 10)));
    scene.kinematics.push_back(test::kinematicBox("moving", Vec3(20, -0.25, 0), Vec3(10, 0.5, 10), w));
    scene.dynamics.push_back(test::dynamicBox("on_still", Vec3(0, 0.25, 0), Vec3(0.5), 1, 0.5));
    scene.dynamics.push_back(test::dynamicBox("on_moving", Vec3(20, 0.25, 0), Vec3(0.5), 1, 0.5));
    Region region = belt(u);
    region.position = Vec3(10, 1, 0);
    region.halfExtents = Vec3(20, 1, 10);
    scene.regions.push_back(region);
    World world(std::move(scene));
    for (int n = 0; n < 90; ++n) world.step();  // both arrive within |u + w|/(μ g) = 0.46 s
    CHECK(glm::length(world.dynamics()[0].velocity - u) <= 0.01 * glm::length(u));
    CHECK(glm::length(world.dynamics()[1].velocity - (u + w)) <= 0.01 * glm::length(u + w));
}

TEST_CASE("A Conveyor region is planned apart: it pushes nothing, so forces stay once a step",
          "[forces][regions][conveyor][plan]") {
    Scene scene = emptyScene();
    scene.planes.push_back(test::ground());
    scene.dynamics.push_back(sphere("ball", Vec3(0, 0.5, 0)));
    const StepPlan without = World(scene).plan();
    CHECK_FALSE(without.conveyors.runs);
    scene.regions.push_back(belt(Vec3(1, 0, 0)));
    const StepPlan with = World(scene).plan();
    CHECK(with.conveyors.runs);
    CHECK(with.regions.runs);              // the regions find their bodies: the belt needs to know who is on it
    CHECK_FALSE(with.substepForces.runs);  // but it adds no force, so none is worked out again in the substeps
    CHECK_THAT(describeStepPlan(with), Catch::Contains("conveyors") && Catch::Contains("src/forces/conveyor.cpp"));
}

TEST_CASE("Conveyor records load, and one without a Velocity or with a field it does not use is refused",
          "[forces][regions][conveyor][config]") {
    const Scene scene = parseScene("World, Gravity=(0, -9.81, 0)\n"
                                   "Region, Name=belt, Shape=Box, Scale=(8, 1, 2), Effect=Conveyor, Velocity=(2, 0, 0)\n",
                                   "belt.scene");
    REQUIRE(scene.regions.size() == 1);
    CHECK(scene.regions[0].effect == RegionEffect::Conveyor);
    CHECK(scene.regions[0].velocity == Vec3(2, 0, 0));
    const auto refused = test::checkRefused;
    refused("Region, Name=r, Effect=Conveyor\n", "a Velocity field (every Effect=Conveyor region needs one)");
    refused("Region, Name=r, Effect=Conveyor, Velocity=(1, 0, 0), Coefficient=1\n", "no Coefficient on an Effect=Conveyor region");
    refused("Region, Name=r, Effect=Conveyor, Velocity=(1, 0, 0), Strength=1\n", "no Strength on an Effect=Conveyor region");
    refused("Region, Name=r, Effect=Conveyer, Velocity=(1, 0, 0)\n", "Conveyor");
}

TEST_CASE("The trace shows the belt a contact's friction aims for, its normal part dropped", "[forces][regions][conveyor][trace]") {
    Scene scene = emptyScene();
    scene.planes.push_back(test::ground());
    scene.dynamics.push_back(test::dynamicBox("crate", Vec3(0, 0.25, 0), Vec3(0.5), 1, 0.5));
    scene.dynamics.push_back(test::dynamicBox("beside", Vec3(0, 0.25, 5), Vec3(0.5), 1, 0.5));  // off the belt
    scene.regions.push_back(belt(Vec3(1.5, 0.7, -0.5)));
    const std::string trace = test::traceOf(scene, {"--steps", "1", "--stage", "prepare-constraints", "--digits", "6"});
    INFO(trace);
    const std::string onBelt = test::traceLine(trace, "step 1 prepare-constraints crate|ground");
    REQUIRE(!onBelt.empty());
    CHECK(test::traceValue(onBelt, "v_s") == std::vector<double>{1.5, 0, -0.5});  // v_s = u − (u·n)·n, n = ∓y
    const std::string offBelt = test::traceLine(trace, "step 1 prepare-constraints beside|ground");
    REQUIRE(!offBelt.empty());
    CHECK(offBelt.find("belt") == std::string::npos);
}
