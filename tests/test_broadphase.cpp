// The broadphases: each one against brute force on seeded random scenes,
// the tree's invariants, Auto's choice, whole trajectories that do not
// depend on the broadphase, and the broadphase tracker. Tag: [broadphase].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "collision/broadphase_tracker.hpp"
#include "collision/narrowphase.hpp"
#include "test_support.hpp"

using namespace stepwise;

namespace {

constexpr BroadphaseKind kFastBroadphases[] = {BroadphaseKind::SweepAndPrune, BroadphaseKind::AabbTree,
                                               BroadphaseKind::Grid, BroadphaseKind::Octree};

/// A scene's bodies in vectors the test can move, with the BodySet view the broadphases take.
struct Bodies {
    std::vector<DynamicObject> dynamics;
    std::vector<KinematicsObject> kinematics;
    std::vector<CollisionPlane> planes;
    BodySet view() { return {dynamics, kinematics, planes}; }
};

Quat randomOrientation(std::mt19937& random) {
    std::normal_distribution<Real> gauss;
    const Quat q(gauss(random), gauss(random), gauss(random), gauss(random));
    return glm::normalize(q);
}

/// @p count dynamic spheres and boxes of sizes from 0.1 m to 1 m scattered in
/// a cube sized so that each touches a few others, some kinematic bodies
/// (one of them a 30 m slab, oversize for the grid) and two planes.
Bodies randomBodies(std::uint32_t seed, std::size_t count) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<Real> unit(0, 1);
    const Real side = Real(0.9) * std::cbrt(Real(count));
    const auto place = [&] { return Vec3(unit(random), unit(random), unit(random)) * side; };
    Bodies b;
    for (std::size_t i = 0; i < count; ++i) {
        if (i % 3 == 2) {
            DynamicObject box = test::dynamicBox("box" + std::to_string(i), place(),
                                                 Vec3(0.1 + 0.9 * unit(random), 0.1 + 0.9 * unit(random), 0.2), 1, 0.5);
            box.orientation = randomOrientation(random);
            b.dynamics.push_back(box);
        } else {
            b.dynamics.push_back(test::sphere("ball" + std::to_string(i), place(), Vec3(0), 0.05 + 0.45 * unit(random)));
        }
    }
    b.kinematics.push_back(test::kinematicBox("slab", Vec3(side / 2, 0, side / 2), Vec3(30, 0.5, 30)));
    b.kinematics.push_back(test::kinematicBox("paddle", place(), Vec3(1, 0.3, 0.6)));
    KinematicsObject ball = test::kinematicBox("roller", place(), Vec3(0.8));
    ball.shape = Shape::Sphere;
    ball.radius = 0.4;
    b.kinematics.push_back(ball);
    b.planes.push_back(test::ground("floor"));
    CollisionPlane slope = test::ground("slope");
    slope.position = Vec3(side, 0, 0);
    slope.normal = glm::normalize(Vec3(-1, 1, 0));
    b.planes.push_back(slope);
    return b;
}

/// Moves every body: most by a little (as in a step), a few far (thrown
/// across the scene), and turns the boxes.
void shake(Bodies& b, std::mt19937& random, Real side) {
    std::uniform_real_distribution<Real> unit(0, 1);
    std::uniform_real_distribution<Real> nudge(-0.05, 0.05);
    for (DynamicObject& body : b.dynamics) {
        if (unit(random) < 0.05) {
            body.position = Vec3(unit(random), unit(random), unit(random)) * side;
        } else {
            body.position += Vec3(nudge(random), nudge(random), nudge(random));
        }
        if (body.shape == Shape::Box) {
            const Vec3 axis = glm::normalize(Vec3(unit(random), unit(random), unit(random)) + Vec3(0.1));
            body.orientation = glm::normalize(glm::angleAxis(Real(0.2), axis) * body.orientation);
        }
    }
    for (std::size_t k = 1; k < b.kinematics.size(); ++k) b.kinematics[k].position += Vec3(nudge(random), 0, nudge(random));
}

/// The boxes of the bodies the structures hold: the dynamic ones (the kinematic ones are in the static tree).
std::vector<Aabb> proxyBoxes(Bodies& b) {
    std::vector<Aabb> boxes;
    for (const DynamicObject& body : b.dynamics) boxes.push_back(broadphaseBounds(body));
    return boxes;
}

/// Every broadphase, keeping its state from call to call, must return
/// exactly brute force's pairs in brute force's order.
void requireAllAgree(Bodies& b, std::vector<Broadphase>& broadphases, const std::string& what) {
    std::vector<Aabb> scratch;
    std::vector<CandidatePair> reference;
    findPairsBruteForce(b.view(), scratch, reference);
    for (std::size_t k = 0; k < broadphases.size(); ++k) {
        std::vector<CandidatePair> pairs;
        broadphases[k].findPairs(kFastBroadphases[k], b.view(), pairs);
        INFO(what << ", " << toString(kFastBroadphases[k]) << ": " << pairs.size() << " pairs, brute force "
                  << reference.size());
        REQUIRE(pairs.size() == reference.size());
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            INFO("pair " << i);
            REQUIRE(pairs[i].a == reference[i].a);
            REQUIRE(pairs[i].b.kind == reference[i].b.kind);
            REQUIRE(pairs[i].b.index == reference[i].b.index);
        }
    }
}

}  // namespace

TEST_CASE("Brute force keeps every pair the narrowphase finds touching", "[broadphase]") {
    // The reference itself, checked against the exact tests: every pair of
    // bodies that the narrowphase finds in contact must be a candidate.
    for (std::uint32_t seed = 1; seed <= 5; ++seed) {
        Bodies b = randomBodies(seed, 150);
        std::vector<Aabb> scratch;
        std::vector<CandidatePair> pairs;
        findPairsBruteForce(b.view(), scratch, pairs);
        const auto isCandidate = [&](std::uint32_t a, BodyRef other) {
            return std::any_of(pairs.begin(), pairs.end(), [&](const CandidatePair& p) {
                return p.a == a && p.b.kind == other.kind && p.b.index == other.index;
            });
        };
        std::size_t touching = 0;
        for (std::uint32_t a = 0; a < b.dynamics.size(); ++a) {
            std::vector<BodyRef> others;
            for (std::uint32_t j = a + 1; j < b.dynamics.size(); ++j) others.push_back({BodyKind::Dynamic, j});
            for (std::uint32_t k = 0; k < b.kinematics.size(); ++k) others.push_back({BodyKind::Kinematic, k});
            for (std::uint32_t p = 0; p < b.planes.size(); ++p) others.push_back({BodyKind::Plane, p});
            for (const BodyRef& other : others) {
                if (!pairTouches(b.view(), {a, other})) continue;
                ++touching;
                INFO("seed " << seed << ": " << b.dynamics[a].name << " and " << bodyName(b.view(), other));
                CHECK(isCandidate(a, other));
            }
        }
        CHECK(touching > 20);  // the scene is dense enough for the check to mean something
    }
}

TEST_CASE("Every broadphase returns brute force's pairs, in its order, step after step", "[broadphase]") {
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        const std::size_t count = 60 + 150 * seed;
        Bodies b = randomBodies(seed, count);
        std::vector<Broadphase> broadphases(std::size(kFastBroadphases));
        std::mt19937 random(seed + 100);
        const Real side = Real(0.9) * std::cbrt(Real(count));
        for (int step = 0; step < 30; ++step) {
            requireAllAgree(b, broadphases, "seed " + std::to_string(seed) + ", step " + std::to_string(step));
            CHECK(broadphases[2].grid().dense());  // bodies packed in a cube: one slot per cell
            const std::vector<Aabb> boxes = proxyBoxes(b);
            CHECK(broadphases[1].tree().isConsistent({boxes, static_cast<std::uint32_t>(b.dynamics.size())}));
            CHECK(broadphases[3].octree().isConsistent({boxes, static_cast<std::uint32_t>(b.dynamics.size())}));
            shake(b, random, side);
        }
        // Bodies leave the scene: every structure must notice and start again.
        b.dynamics.resize(b.dynamics.size() / 2);
        requireAllAgree(b, broadphases, "seed " + std::to_string(seed) + ", half the bodies removed");
    }
}

TEST_CASE("The broadphases agree on degenerate scenes", "[broadphase]") {
    std::vector<Broadphase> broadphases(std::size(kFastBroadphases));
    Bodies b;
    SECTION("no bodies at all") { requireAllAgree(b, broadphases, "empty"); }
    SECTION("only kinematic bodies: they never pair with each other") {
        b.kinematics.push_back(test::kinematicBox("k0", Vec3(0), Vec3(1)));
        b.kinematics.push_back(test::kinematicBox("k1", Vec3(0.5, 0, 0), Vec3(1)));
        requireAllAgree(b, broadphases, "kinematic only");
        std::vector<CandidatePair> pairs;
        broadphases[0].findPairs(BroadphaseKind::SweepAndPrune, b.view(), pairs);
        CHECK(pairs.empty());
    }
    SECTION("every body at the same point") {
        for (int i = 0; i < 40; ++i) b.dynamics.push_back(test::sphere("s" + std::to_string(i), Vec3(1, 2, 3)));
        requireAllAgree(b, broadphases, "coincident");
        std::vector<CandidatePair> pairs;
        broadphases[2].findPairs(BroadphaseKind::Grid, b.view(), pairs);
        CHECK(pairs.size() == 40 * 39 / 2);  // every pair overlaps
    }
    SECTION("a tower: every sweep interval along x overlaps") {
        for (int i = 0; i < 60; ++i) b.dynamics.push_back(test::sphere("s" + std::to_string(i), Vec3(0, 0.9 * i, 0)));
        requireAllAgree(b, broadphases, "tower");
        std::vector<CandidatePair> pairs;
        broadphases[0].findPairs(BroadphaseKind::SweepAndPrune, b.view(), pairs);
        CHECK(pairs.size() == 59);  // neighbours only: 0.9 m apart, 1 m across (+2 cm of speculative margin)
        CHECK(broadphases[0].sweepAndPrune().axis() == 1);  // the tower spreads along y
    }
    SECTION("bodies touching exactly, face to face") {
        // Boxes 1 m wide, 1 m apart: their grown boxes overlap by 2·kSpeculativeDistance.
        for (int i = 0; i < 30; ++i) {
            b.dynamics.push_back(test::dynamicBox("b" + std::to_string(i), Vec3(i, 0.5, 0), Vec3(1), 1, 0.5));
        }
        b.planes.push_back(test::ground());
        requireAllAgree(b, broadphases, "a row of touching boxes");
    }
    SECTION("one body far away from the rest") {
        for (int i = 0; i < 30; ++i) b.dynamics.push_back(test::sphere("s" + std::to_string(i), Vec3(i * 0.5, 0, 0)));
        b.dynamics.push_back(test::sphere("far", Vec3(1e12, -1e12, 1e12)));
        requireAllAgree(b, broadphases, "far away");
        // A grid over the box around all 31 would need ~10³⁶ cells: the grid hashes them instead.
        CHECK_FALSE(broadphases[2].grid().dense());
    }
}

TEST_CASE("The grid finds brute force's pairs whether it stores its cells densely or hashed", "[broadphase]") {
    // The random scenes are packed, so the grid stores them densely; a second copy of
    // each scene gets a few bodies a kilometre away (a box around all of them would need
    // millions of cells per body), so it is hashed. Both must give brute force's pairs.
    for (std::uint32_t seed = 11; seed <= 12; ++seed) {
        Bodies packed = randomBodies(seed, 400);
        // Boulders among the pebbles, two of them overlapping: oversize bodies that find their
        // partners in the cells their boxes cover, and each other.
        const Real middle = Real(0.45) * std::cbrt(Real(400));
        for (int i = 0; i < 4; ++i) {
            packed.dynamics.push_back(test::sphere("boulder" + std::to_string(i), Vec3(middle + (i % 2) * 2, middle - i, middle), Vec3(0), 1.5));
        }
        Bodies spread = packed;
        for (int i = 0; i < 3; ++i) {
            spread.dynamics.push_back(test::sphere("far" + std::to_string(i), Vec3(1000 + i * 0.8, 500, -1000)));
        }
        std::vector<Broadphase> forPacked(std::size(kFastBroadphases));
        std::vector<Broadphase> forSpread(std::size(kFastBroadphases));
        std::mt19937 random(seed);
        const Real side = Real(0.9) * std::cbrt(Real(400));
        for (int step = 0; step < 10; ++step) {
            requireAllAgree(packed, forPacked, "packed, seed " + std::to_string(seed) + ", step " + std::to_string(step));
            CHECK(forPacked[2].grid().dense());
            CHECK(forPacked[2].grid().oversizeCount() >= 4);  // the boulders (the slab is in the static tree)
            requireAllAgree(spread, forSpread, "spread, seed " + std::to_string(seed) + ", step " + std::to_string(step));
            CHECK_FALSE(forSpread[2].grid().dense());
            shake(packed, random, side);
            std::copy(packed.dynamics.begin(), packed.dynamics.end(), spread.dynamics.begin());
            spread.kinematics = packed.kinematics;
        }
    }
}

TEST_CASE("The grid keeps its pairs while bodies stay in their fat boxes, and finds the movers' pairs again", "[broadphase]") {
    // A settling pile: balls of similar sizes packed in a cube (a dense grid, none oversize)
    // and a kinematic ball rolling through them. Every body creeps by a millimetre or two a
    // step, which its fat box absorbs; on some steps a few jump 20–40 cm, out of theirs.
    // Each step the grid must still return brute force's pairs exactly, whether it kept
    // them all, found the movers' pairs again, or found every pair again.
    std::mt19937 random(5);
    std::uniform_real_distribution<Real> unit(0, 1);
    const std::size_t count = 400;
    const Real side = Real(0.9) * std::cbrt(Real(count));
    Bodies b;
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 centre = Vec3(unit(random), unit(random), unit(random)) * side;
        b.dynamics.push_back(test::sphere("ball" + std::to_string(i), centre, Vec3(0), Real(0.4) + Real(0.1) * unit(random)));
    }
    KinematicsObject roller = test::kinematicBox("roller", Vec3(side / 2), Vec3(0.9));
    roller.shape = Shape::Sphere;
    roller.radius = 0.45;
    b.kinematics.push_back(roller);
    b.planes.push_back(test::ground("floor"));

    std::vector<Broadphase> broadphases(std::size(kFastBroadphases));
    std::uniform_real_distribution<Real> creep(-0.002, 0.002);
    int keptAll = 0, foundMovers = 0, foundAll = 0;
    for (int step = 0; step < 60; ++step) {
        requireAllAgree(b, broadphases, "step " + std::to_string(step));
        const UniformGrid& grid = broadphases[2].grid();
        REQUIRE(grid.dense());
        REQUIRE(grid.oversizeCount() == 0);
        if (grid.refoundAll()) ++foundAll;
        else if (grid.movedCount() == 0) ++keptAll;
        else ++foundMovers;
        for (DynamicObject& body : b.dynamics) body.position += Vec3(creep(random), creep(random), creep(random));
        if (step % 3 == 1) {
            for (int jump = 0; jump < 6; ++jump) {
                DynamicObject& body = b.dynamics[static_cast<std::size_t>(unit(random) * Real(count - 1))];
                const Vec3 direction = glm::normalize(Vec3(unit(random), unit(random), unit(random)) - Vec3(0.5));
                body.position += (Real(0.2) + Real(0.2) * unit(random)) * direction;
            }
            b.kinematics[0].position.x += Real(0.15);
        }
    }
    CHECK(foundAll >= 1);       // the first step at least
    CHECK(keptAll >= 10);       // the creeping steps
    CHECK(foundMovers >= 10);   // the steps after the jumps
}

TEST_CASE("The grid sizes its cells from the bodies and sets oversize bodies aside", "[broadphase]") {
    Bodies b = randomBodies(7, 300);
    std::vector<CandidatePair> pairs;
    Broadphase broadphase;
    broadphase.findPairs(BroadphaseKind::Grid, b.view(), pairs);
    const std::vector<Aabb> boxes = proxyBoxes(b);
    // The grid files each body under its fat box: grown by kGridFatMarginFraction of its
    // longest side on every side, so 1 + 2·kGridFatMarginFraction times as long.
    std::vector<Real> sizes;
    for (const Aabb& box : boxes) sizes.push_back((1 + 2 * kGridFatMarginFraction) * box.longestSide());
    std::vector<Real> sorted = sizes;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const Real limit = kGridOversizeRatio * sorted[sorted.size() / 2];
    Real largestListed = 0;
    std::size_t oversize = 0;
    for (const Real size : sizes) {
        if (size > limit) ++oversize;
        else largestListed = std::max(largestListed, size);
    }
    CHECK(broadphase.grid().cellSize() == Approx(largestListed).epsilon(1e-12));
    CHECK(broadphase.grid().oversizeCount() == oversize);
}

TEST_CASE("The tree keeps resting bodies where they are and stays shallow", "[broadphase]") {
    Bodies b = randomBodies(3, 500);
    Broadphase broadphase;
    std::vector<CandidatePair> pairs;
    broadphase.findPairs(BroadphaseKind::AabbTree, b.view(), pairs);
    // Moving every body by less than its fat margin (a tenth of its size) moves no leaf.
    for (int step = 0; step < 5; ++step) {
        for (DynamicObject& body : b.dynamics) body.position += Vec3(1e-4);
        broadphase.findPairs(BroadphaseKind::AabbTree, b.view(), pairs);
        CHECK(broadphase.counters().reinsertions == 0);
    }
    // Moving one body far moves exactly its leaf.
    b.dynamics[17].position += Vec3(3, 0, 0);
    broadphase.findPairs(BroadphaseKind::AabbTree, b.view(), pairs);
    CHECK(broadphase.counters().reinsertions == 1);
    // A balanced binary tree over n leaves has height ⌈log₂ n⌉; the rotations
    // keep this one within twice that (503 leaves: log₂ = 9).
    const int leaves = static_cast<int>(b.dynamics.size());
    CHECK(broadphase.tree().height() <= 2 * static_cast<int>(std::ceil(std::log2(leaves))));
    const std::vector<Aabb> boxes = proxyBoxes(b);
    CHECK(broadphase.tree().isConsistent({boxes, static_cast<std::uint32_t>(b.dynamics.size())}));
}

TEST_CASE("Sweep and prune sorts along the axis of greatest spread", "[broadphase]") {
    Bodies b;
    for (int i = 0; i < 50; ++i) b.dynamics.push_back(test::sphere("s" + std::to_string(i), Vec3(0.1 * (i % 3), 0, 2 * i)));
    Broadphase broadphase;
    std::vector<CandidatePair> pairs;
    broadphase.findPairs(BroadphaseKind::SweepAndPrune, b.view(), pairs);
    CHECK(broadphase.sweepAndPrune().axis() == 2);
    // Spheres 2 m apart along z, 1 m across: the sweep meets no interval overlap at all.
    CHECK(broadphase.counters().pairTests == 0);
    CHECK(pairs.empty());
}

TEST_CASE("Auto picks brute force for a few bodies, then by count and sizes", "[broadphase]") {
    Bodies b;
    for (int i = 0; i < 10; ++i) b.dynamics.push_back(test::sphere("s" + std::to_string(i), Vec3(i, 0, 0)));
    BroadphaseChoice choice = chooseBroadphase(b.view());
    CHECK(choice.kind == BroadphaseKind::BruteForce);
    CHECK_THAT(choice.reason, Catch::Matchers::Contains("10 dynamic bodies"));

    for (int i = 10; i < 500; ++i) b.dynamics.push_back(test::sphere("s" + std::to_string(i), Vec3(i, 0, 0), Vec3(0), 0.4 + 0.0002 * i));
    choice = chooseBroadphase(b.view());
    CHECK(choice.kind == BroadphaseKind::SweepAndPrune);

    Bodies many;  // a lattice of 2 197 falling balls, 2 m apart
    for (int i = 0; i < 13 * 13 * 13; ++i) {
        many.dynamics.push_back(test::sphere("m" + std::to_string(i), Real(2) * Vec3(i % 13, i / 169, (i / 13) % 13), Vec3(0, -3, 0)));
    }
    CHECK(chooseBroadphase(many.view()).kind == BroadphaseKind::Grid);

    // Kinematic bodies, however large, are in the static tree: they do not count.
    Bodies level = b;
    for (std::size_t i = 0; i <= kAutoGridMaxOversize; ++i) {
        level.kinematics.push_back(test::kinematicBox("slab" + std::to_string(i), Vec3(0, -10, 10 * Real(i)), Vec3(8)));
    }
    CHECK(chooseBroadphase(level.view()).kind == BroadphaseKind::SweepAndPrune);

    for (std::size_t i = 0; i <= kAutoGridMaxOversize; ++i) {
        b.dynamics.push_back(test::dynamicBox("rock" + std::to_string(i), Vec3(0, -10, 10 * Real(i)), Vec3(8), 1, 0.5));
    }
    choice = chooseBroadphase(b.view());
    CHECK(choice.kind == BroadphaseKind::AabbTree);
    CHECK_THAT(choice.reason, Catch::Matchers::Contains("9 larger"));

    // A wall of bricks at rest is bodies of one size like any other: resting earns no
    // rule of its own (the grid and sweep and prune cost no more than the tree there).
    Bodies wall;
    for (int i = 0; i < 150; ++i) {
        wall.dynamics.push_back(test::dynamicBox("brick" + std::to_string(i), Vec3(i % 15, 0.5 + i / 15, 0), Vec3(1), 1, 0.5));
    }
    wall.planes.push_back(test::ground());
    const BroadphaseChoice built = chooseBroadphase(wall.view());
    CHECK(built.kind == BroadphaseKind::SweepAndPrune);
    CHECK_THAT(built.reason, Catch::Matchers::Contains("150 bodies of similar size"));
    // 512 of them (kAutoSweepBelow): the grid.
    for (int i = 150; i < 512; ++i) {
        wall.dynamics.push_back(test::dynamicBox("brick" + std::to_string(i), Vec3(i % 15, 0.5 + i / 15, 0), Vec3(1), 1, 0.5));
    }
    CHECK(chooseBroadphase(wall.view()).kind == BroadphaseKind::Grid);

    // The World resolves Auto on its first step and keeps the reason. (Under
    // SequentialImpulse its bounds also hold each body's sweep, |v|·h + ½|a|·h²,
    // so the sizes it quotes are a little larger than the bodies at rest.)
    Scene scene = test::emptyScene();
    scene.dynamics = b.dynamics;
    scene.kinematics = b.kinematics;
    World world(scene);
    world.step();
    CHECK(world.broadphase().lastKind() == BroadphaseKind::AabbTree);
    CHECK_THAT(world.broadphase().autoChoice().reason, Catch::Matchers::Contains("509 bodies of mixed sizes"));
}

TEST_CASE("A scene's trajectory is bit for bit the same whichever broadphase runs", "[broadphase]") {
    // 120 bodies, spheres and boxes, dropped on a floor with a kinematic paddle
    // sweeping through them: many contacts, warm starting, resting piles.
    std::mt19937 random(11);
    std::uniform_real_distribution<Real> unit(0, 1);
    Scene scene = test::emptyScene();
    for (int i = 0; i < 120; ++i) {
        const Vec3 position(4 * unit(random), 0.3 + 3 * unit(random), 4 * unit(random));
        if (i % 2 == 0) {
            scene.dynamics.push_back(test::sphere("s" + std::to_string(i), position, Vec3(0), 0.15 + 0.1 * unit(random)));
        } else {
            DynamicObject box = test::dynamicBox("b" + std::to_string(i), position, Vec3(0.3, 0.2, 0.25), 1, 0.5);
            box.orientation = randomOrientation(random);
            scene.dynamics.push_back(box);
        }
    }
    scene.kinematics.push_back(test::kinematicBox("paddle", Vec3(-1, 0.3, 2), Vec3(0.2, 0.6, 4), Vec3(1, 0, 0)));
    scene.planes.push_back(test::ground());

    const auto trajectory = [&](BroadphaseKind kind) {
        Scene copy = scene;
        copy.settings.broadphase = kind;
        World world(copy);
        std::vector<Real> states;
        std::size_t contacts = 0;
        for (int step = 0; step < 150; ++step) {
            world.step();
            contacts += world.contacts().size();
            for (const DynamicObject& body : world.dynamics()) {
                for (int i = 0; i < 3; ++i) {
                    states.push_back(body.position[i]);
                    states.push_back(body.velocity[i]);
                    states.push_back(body.angularMomentum[i]);
                }
                states.push_back(body.orientation.w);
            }
        }
        CHECK(world.broadphase().lastKind() == kind);
        CHECK(contacts > 1000);
        return states;
    };
    const std::vector<Real> reference = trajectory(BroadphaseKind::BruteForce);
    for (const BroadphaseKind kind : kFastBroadphases) {
        INFO(toString(kind));
        const std::vector<Real> states = trajectory(kind);
        REQUIRE(states.size() == reference.size());
        // Exact equality, not a tolerance: the same pairs in the same order make the same arithmetic.
        CHECK(std::equal(states.begin(), states.end(), reference.begin()));
    }
}

TEST_CASE("The tracker finds no difference on random falling scenes and counts brute force's tests", "[broadphase]") {
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<Real> unit(0, 1);
        Scene scene = test::emptyScene();
        const std::size_t n = 100 * seed;
        for (std::size_t i = 0; i < n; ++i) {
            scene.dynamics.push_back(test::sphere("s" + std::to_string(i),
                                                  Vec3(3 * unit(random), 0.2 + 2 * unit(random), 3 * unit(random)),
                                                  Vec3(0), 0.1 + 0.05 * unit(random)));
        }
        scene.kinematics.push_back(test::kinematicBox("block", Vec3(1.5, 0.2, 1.5), Vec3(0.5)));
        scene.planes.push_back(test::ground());
        World world(scene);
        BroadphaseTracker tracker;
        const int steps = 60;
        for (int i = 0; i < steps; ++i) {
            world.step();
            tracker.observe({world.dynamics(), world.kinematics(), world.planes()}, world.stepCount(), i % 2 == 0);
        }
        INFO("seed " << seed);
        CHECK(tracker.agrees());
        CHECK(tracker.differences().empty());
        CHECK(tracker.steps() == steps);
        CHECK(tracker.checkedSteps() == steps / 2);
        const TrackedBroadphase& brute = tracker.results().front();
        REQUIRE(brute.kind == BroadphaseKind::BruteForce);
        CHECK(brute.steps == steps / 2);
        // n(n−1)/2 dynamic pairs, n·1 kinematic, n·1 plane, each checked step.
        CHECK(brute.pairTests == (n * (n - 1) / 2 + n + n) * brute.steps);
        CHECK(tracker.results().size() == 5);
        for (const TrackedBroadphase& t : tracker.results()) {
            INFO(toString(t.kind));
            CHECK(t.contactPairs > 0);
            CHECK(t.pairTests <= brute.pairTests * t.steps / brute.steps);  // never more work than brute force
        }
        const std::vector<TrackedBroadphase> ranked = tracker.ranked();
        for (std::size_t i = 1; i < ranked.size(); ++i) CHECK(ranked[i - 1].secondsPerStep() <= ranked[i].secondsPerStep());
    }
}

TEST_CASE("The tracker reports a missed touching pair as an error, with its step and pair", "[broadphase]") {
    Bodies b;
    b.dynamics.push_back(test::sphere("left", Vec3(0, 0.5, 0)));
    b.dynamics.push_back(test::sphere("right", Vec3(0.9, 0.5, 0)));  // 0.1 m overlap
    b.dynamics.push_back(test::sphere("near", Vec3(1.905, 0.5, 0)));  // 5 mm gap to right: boxes overlap, no touch
    b.planes.push_back(test::ground());
    std::vector<Aabb> scratch;
    std::vector<CandidatePair> reference;
    findPairsBruteForce(b.view(), scratch, reference);
    REQUIRE(reference.size() == 5);  // left–right, left–floor, right–near, right–floor, near–floor

    TrackedBroadphase totals;
    totals.kind = BroadphaseKind::Grid;
    std::vector<BroadphaseDifference> kept;
    SECTION("a missed touching pair is an error") {
        std::vector<CandidatePair> candidate = reference;
        candidate.erase(candidate.begin());  // left–right
        compareWithReference(b.view(), reference, candidate, 42, totals, kept);
        CHECK(totals.missedContacts == 1);
        CHECK(totals.otherDifferences == 0);
        REQUIRE(kept.size() == 1);
        CHECK(kept[0].step == 42);
        CHECK(kept[0].missing);
        CHECK(kept[0].touching);
        CHECK(kept[0].pair.a == 0);
        CHECK(kept[0].pair.b.index == 1);
    }
    SECTION("a missed pair that does not touch is a difference, not an error") {
        std::vector<CandidatePair> candidate = reference;
        candidate.erase(candidate.begin() + 2);  // right–near
        compareWithReference(b.view(), reference, candidate, 7, totals, kept);
        CHECK(totals.missedContacts == 0);
        CHECK(totals.otherDifferences == 1);
        REQUIRE(kept.size() == 1);
        CHECK_FALSE(kept[0].touching);
    }
    SECTION("an extra pair and a wrong order are differences") {
        std::vector<CandidatePair> candidate = reference;
        std::swap(candidate[0], candidate[1]);
        candidate.push_back({0, {BodyKind::Dynamic, 2}});
        compareWithReference(b.view(), reference, candidate, 3, totals, kept);
        CHECK(totals.missedContacts == 0);
        CHECK(totals.otherDifferences == 2);
        REQUIRE(kept.size() == 2);
        CHECK(kept[0].orderOnly);
        CHECK_FALSE(kept[1].missing);
        CHECK(kept[1].pair.b.index == 2);
    }
}

TEST_CASE("Static boxes live in their own tree: built once, queried like planes, rebuilt when one moves", "[broadphase]") {
    // A room of static boxes (floor, four walls, and 40 pillars of mixed sizes) with balls
    // among them: every broadphase must still return brute force's pairs in its order,
    // while the kinematic bodies stay out of the structures and the static tree is built once.
    std::mt19937 random(21);
    std::uniform_real_distribution<Real> unit(0, 1);
    const Real side = 12;
    Bodies b;
    b.kinematics.push_back(test::kinematicBox("floor", Vec3(side / 2, -0.5, side / 2), Vec3(side + 2, 1, side + 2)));
    b.kinematics.push_back(test::kinematicBox("west", Vec3(-0.5, 3, side / 2), Vec3(1, 6, side + 2)));
    b.kinematics.push_back(test::kinematicBox("east", Vec3(side + 0.5, 3, side / 2), Vec3(1, 6, side + 2)));
    b.kinematics.push_back(test::kinematicBox("south", Vec3(side / 2, 3, -0.5), Vec3(side, 6, 1)));
    b.kinematics.push_back(test::kinematicBox("north", Vec3(side / 2, 3, side + 0.5), Vec3(side, 6, 1)));
    for (int i = 0; i < 40; ++i) {
        const Vec3 size(0.2 + 2 * unit(random), 0.5 + 3 * unit(random), 0.2 + 2 * unit(random));
        b.kinematics.push_back(test::kinematicBox("pillar" + std::to_string(i),
                                                  Vec3(unit(random) * side, size.y / 2, unit(random) * side), size));
    }
    for (int i = 0; i < 600; ++i) {
        b.dynamics.push_back(test::sphere("ball" + std::to_string(i),
                                          Vec3(unit(random) * side, unit(random) * 5, unit(random) * side), Vec3(0),
                                          Real(0.2) + Real(0.2) * unit(random)));
    }
    b.planes.push_back(test::ground());

    std::vector<Broadphase> broadphases(std::size(kFastBroadphases));
    std::uniform_real_distribution<Real> nudge(-0.05, 0.05);
    for (int step = 0; step < 20; ++step) {
        requireAllAgree(b, broadphases, "step " + std::to_string(step));
        for (const Broadphase& broadphase : broadphases) {
            CHECK(broadphase.staticTree().size() == b.kinematics.size());
            CHECK(broadphase.staticTree().builds() == 1);  // nothing static moved: never rebuilt
            CHECK(broadphase.staticTree().isConsistent());
        }
        // The grid sees the balls only: the floor and walls, 14 m long, are not oversize bodies of its.
        CHECK(broadphases[2].grid().oversizeCount() == 0);
        for (DynamicObject& body : b.dynamics) body.position += Vec3(nudge(random), nudge(random), nudge(random));
    }
    // One pillar slides: the next call rebuilds the tree, once, and the pairs still agree.
    b.kinematics[7].position.x += Real(0.7);
    requireAllAgree(b, broadphases, "after a pillar moved");
    for (const Broadphase& broadphase : broadphases) {
        CHECK(broadphase.staticTree().builds() == 2);
        CHECK(broadphase.staticTree().isConsistent());
    }
    // A pillar removed: the tree is rebuilt for the new count.
    b.kinematics.pop_back();
    requireAllAgree(b, broadphases, "after a pillar was removed");
    CHECK(broadphases[0].staticTree().size() == b.kinematics.size());
}

TEST_CASE("The static tree is balanced and its query finds exactly the overlapping boxes, in index order", "[broadphase]") {
    std::mt19937 random(4);
    std::uniform_real_distribution<Real> unit(0, 1);
    for (const std::uint32_t count : {0u, 1u, 4u, 5u, 17u, 300u}) {
        std::vector<Aabb> boxes;
        for (std::uint32_t k = 0; k < count; ++k) {
            const Vec3 low(unit(random) * 20, unit(random) * 20, unit(random) * 20);
            boxes.push_back({low, low + Vec3(unit(random), unit(random), unit(random)) * Real(4)});
        }
        StaticTree tree;
        CHECK(tree.update(boxes));
        CHECK_FALSE(tree.update(boxes));  // the same boxes: not rebuilt
        CHECK(tree.isConsistent());
        std::vector<std::uint32_t> hits;
        BroadphaseCounters counters;
        for (int q = 0; q < 200; ++q) {
            const Vec3 low(unit(random) * 22 - 1, unit(random) * 22 - 1, unit(random) * 22 - 1);
            const Aabb box{low, low + Vec3(unit(random), unit(random), unit(random)) * Real(3)};
            hits.clear();
            tree.query(box, hits, counters);
            std::vector<std::uint32_t> expected;
            for (std::uint32_t k = 0; k < count; ++k) {
                if (box.overlaps(boxes[k])) expected.push_back(k);
            }
            INFO(count << " boxes, query " << q);
            REQUIRE(hits == expected);
        }
        if (count == 300) {
            // A balanced tree over 300 boxes in leaves of at most kStaticLeafSize: a query of a small
            // box visits a few branches of ⌈log₂(300/4)⌉ = 7 levels, not all 300 boxes.
            CHECK(counters.pairTests < 200 * 300 / 4);
        }
    }
}

TEST_CASE("The octree files each body at the depth its size fixes, in the cell of its centre", "[broadphase][octree]") {
    // Sizes from 2 cm to 3 m: pebbles, the random scene's bodies and boulders, spread over
    // seven powers of two, so the bodies sit on several levels.
    Bodies b = randomBodies(21, 400);
    const Real middle = Real(0.45) * std::cbrt(Real(400));
    for (int i = 0; i < 4; ++i) {
        b.dynamics.push_back(test::sphere("boulder" + std::to_string(i), Vec3(middle + 2 * i, middle, middle), Vec3(0), 1.5));
    }
    for (int i = 0; i < 20; ++i) {
        b.dynamics.push_back(test::sphere("pebble" + std::to_string(i), Vec3(0.3 * i, middle, 1), Vec3(0), 0.001));
    }
    Broadphase broadphase;
    std::vector<CandidatePair> pairs;
    broadphase.findPairs(BroadphaseKind::Octree, b.view(), pairs);
    const LooseOctree& octree = broadphase.octree();
    const std::vector<Aabb> boxes = proxyBoxes(b);
    REQUIRE(octree.isConsistent({boxes, static_cast<std::uint32_t>(boxes.size())}));

    // The root cube is kOctreeRootPadding times the longest side of the box around all bodies.
    Aabb around = boxes.front();
    for (const Aabb& box : boxes) around = merged(around, box);
    const Real width = octree.rootSide();
    CHECK(width == Approx(kOctreeRootPadding * around.longestSide()).epsilon(1e-12));
    // Ulrich's rule, d = ⌊log₂(W / s)⌋: the deepest level whose cells (side W/2^d) are as large as the body.
    std::set<int> levels;
    for (std::uint32_t p = 0; p < boxes.size(); ++p) {
        const Real size = boxes[p].longestSide();
        const int expected = std::min(kOctreeMaxDepth, static_cast<int>(std::floor(std::log2(width / size))));
        INFO(b.dynamics[p].name << ", size " << size << " m");
        CHECK(octree.levelOf(p) == expected);
        levels.insert(octree.levelOf(p));
    }
    CHECK(levels.size() >= 5);
    CHECK(octree.depth() == *levels.rbegin());
}

TEST_CASE("The octree moves a body only when it leaves its node's loose box", "[broadphase][octree]") {
    Bodies b = randomBodies(22, 300);
    Broadphase broadphase;
    std::vector<CandidatePair> pairs;
    broadphase.findPairs(BroadphaseKind::Octree, b.view(), pairs);
    const std::size_t nodes = broadphase.octree().nodeCount();
    // A body may move a quarter of its cell's side, at least s/2, past its cell before it leaves
    // the loose box: 0.1 mm moves nobody.
    for (int step = 0; step < 5; ++step) {
        for (DynamicObject& body : b.dynamics) body.position += Vec3(1e-4);
        broadphase.findPairs(BroadphaseKind::Octree, b.view(), pairs);
        CHECK(broadphase.counters().reinsertions == 0);
        CHECK(broadphase.octree().nodeCount() == nodes);
    }
    // Three times its cell's side away (a cell is shorter than twice the body), towards the
    // middle of the scene (so inside the root cube), it must move.
    const Real cell = broadphase.octree().rootSide() / Real(1 << broadphase.octree().levelOf(17));
    const Real middle = Real(0.45) * std::cbrt(Real(300));
    b.dynamics[17].position.x += b.dynamics[17].position.x < middle ? 3 * cell : -3 * cell;
    broadphase.findPairs(BroadphaseKind::Octree, b.view(), pairs);
    CHECK(broadphase.counters().reinsertions == 1);
    const std::vector<Aabb> boxes = proxyBoxes(b);
    CHECK(broadphase.octree().isConsistent({boxes, static_cast<std::uint32_t>(boxes.size())}));
    CHECK(broadphase.octree().fits() == 1);
}

TEST_CASE("The octree keeps bodies that left its cube in the root, and fits a new cube when many did", "[broadphase][octree]") {
    Bodies b = randomBodies(23, 200);
    std::vector<Broadphase> broadphases(std::size(kFastBroadphases));
    requireAllAgree(b, broadphases, "start");
    const LooseOctree& octree = broadphases[3].octree();
    REQUIRE(octree.fits() == 1);
    // Two bodies flung a kilometre away, 5 cm apart (their boxes overlap): in the root, found by its queries.
    b.dynamics[5].position = Vec3(1000, 0, 0);
    b.dynamics[9].position = Vec3(1000.05, 0, 0);
    requireAllAgree(b, broadphases, "two far away");
    CHECK(octree.levelOf(5) == 0);
    CHECK(octree.levelOf(9) == 0);
    CHECK(octree.fits() == 1);
    // More than one in kOctreeRefitShare outside: a new cube around everyone.
    for (std::size_t i = 0; i < b.dynamics.size(); i += 4) b.dynamics[i].position += Vec3(0, 5000, 0);
    requireAllAgree(b, broadphases, "a quarter far away");
    CHECK(octree.fits() == 2);
    CHECK(octree.rootSide() > 2 * 5000);
    const std::vector<Aabb> boxes = proxyBoxes(b);
    CHECK(octree.isConsistent({boxes, static_cast<std::uint32_t>(boxes.size())}));
}

TEST_CASE("Region queries through each broadphase find exactly the dynamic bodies a box overlaps", "[broadphase][regions]") {
    // For every broadphase, on scenes of mixed sizes (packed, so the grid is dense, and with a few
    // bodies a kilometre away, so it is hashed), after each of several steps: boxes of every size
    // inside the scene, far outside every structure's bounds, huge ones holding everything, points,
    // and boxes in gaps that hold nothing. The answer must be a loop over the boxes, filtered.
    constexpr BroadphaseKind kinds[] = {BroadphaseKind::BruteForce, BroadphaseKind::SweepAndPrune,
                                        BroadphaseKind::AabbTree, BroadphaseKind::Grid, BroadphaseKind::Octree};
    int empty = 0, some = 0, all = 0;
    for (std::uint32_t seed = 31; seed <= 32; ++seed) {
        Bodies packed = randomBodies(seed, 300);
        const Real side = Real(0.9) * std::cbrt(Real(300));
        for (int i = 0; i < 4; ++i) {
            packed.dynamics.push_back(test::sphere("boulder" + std::to_string(i), Vec3(side / 2 + i, side / 2 - i, side / 2), Vec3(0), 1.5));
        }
        Bodies spread = packed;
        for (int i = 0; i < 3; ++i) spread.dynamics.push_back(test::sphere("far" + std::to_string(i), Vec3(1000 + i * 0.8, 500, -1000)));
        for (Bodies* bodies : {&packed, &spread}) {
            std::vector<Broadphase> broadphases(std::size(kinds));
            std::mt19937 random(seed);
            std::uniform_real_distribution<Real> unit(0, 1);
            std::vector<std::uint32_t> found, expected;
            for (int step = 0; step < 6; ++step) {
                std::vector<CandidatePair> pairs;
                for (std::size_t k = 0; k < std::size(kinds); ++k) broadphases[k].findPairs(kinds[k], bodies->view(), pairs);
                if (bodies == &packed) CHECK(broadphases[3].grid().dense());
                else CHECK_FALSE(broadphases[3].grid().dense());
                const std::vector<Aabb> boxes = proxyBoxes(*bodies);
                std::vector<Aabb> queries;
                for (int q = 0; q < 40; ++q) {  // inside the scene, from 1 cm to the scene's size
                    const Vec3 corner = Vec3(unit(random), unit(random), unit(random)) * side;
                    const Real extent = Real(0.01) * std::pow(Real(100) * side, unit(random));
                    queries.push_back({corner, corner + extent * Vec3(unit(random), unit(random), unit(random))});
                }
                queries.push_back({Vec3(-1e4), Vec3(-1e4 + 5)});                 // outside everything
                queries.push_back({Vec3(1e6, -1e6, 1e6), Vec3(2e6, -5e5, 3e6)});  // beyond the far bodies
                queries.push_back({Vec3(-1e9), Vec3(1e9)});                     // everything
                queries.push_back({Vec3(side / 2), Vec3(side / 2)});             // a point
                queries.push_back({boxes[7].max + Vec3(1e-3), boxes[7].max + Vec3(1e-3)});  // just off a corner
                queries.push_back({Vec3(side / 2, -40, side / 2), Vec3(side / 2 + 1, -30, side / 2 + 1)});  // below the scene
                for (const Aabb& query : queries) {
                    expected.clear();
                    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
                        if (boxes[i].overlaps(query)) expected.push_back(i);
                    }
                    if (expected.empty()) ++empty;
                    else if (expected.size() == boxes.size()) ++all;
                    else ++some;
                    for (std::size_t k = 0; k < std::size(kinds); ++k) {
                        found.assign(3, 12345);  // cleared first
                        broadphases[k].dynamicBodiesOverlapping(query, found);
                        INFO("seed " << seed << (bodies == &packed ? ", packed" : ", spread") << ", step " << step
                                     << ", " << toString(kinds[k]) << ", query " << query.min.x << " " << query.min.y
                                     << " " << query.min.z << " to " << query.max.x << " " << query.max.y << " "
                                     << query.max.z);
                        REQUIRE(broadphases[k].lastKind() == kinds[k]);
                        CHECK(found == expected);
                    }
                }
                shake(*bodies, random, side);
                if (bodies == &spread) {  // the far bodies stay far, so the grid stays hashed
                    for (int i = 0; i < 3; ++i) spread.dynamics[spread.dynamics.size() - 3 + i].position = Vec3(1000 + i * 0.8, 500, -1000);
                }
            }
        }
    }
    CHECK(empty >= 50);
    CHECK(some >= 500);
    CHECK(all >= 20);
    // Before any step nothing was filed: no body overlaps anything.
    Broadphase fresh;
    std::vector<std::uint32_t> found{1, 2};
    fresh.dynamicBodiesOverlapping({Vec3(-1e9), Vec3(1e9)}, found);
    CHECK(found.empty());
}
