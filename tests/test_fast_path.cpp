// The fast path (src/fast/): the plain path's numbers, bit for bit, by another road.
// Tags: [fast], [solver], [lanes].
//
// Contacts with stored rows (boxes, kinematic bodies) have lanes of their own
// (box_contact_lanes.hpp): the same claims are checked for them below, on a
// heap of boxes with balls and a kinematic slab, and on whole scenes.
//
// Claims, from the smallest piece to the whole step:
// - the waves make the lanes independent and keep each body's order (no wave
//   holds two contacts of one dynamic body, each body meets its contacts in
//   their order, every round contact is solved exactly once);
// - so a pass in lanes is the plain scalar pass of solve_contacts.cpp, one
//   contact at a time in its order: the same velocities and impulses;
// - and a whole World on the fast path, on the objects (balls with boxes,
//   joints, another integrator) or on the packed records (a rain of balls),
//   ends every step where the same World on the plain path does.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include "collision/broadphase.hpp"
#include "collision/narrowphase.hpp"
#include "config/scene_loader.hpp"
#include "dynamics/contact_solver.hpp"
#include "dynamics/softness.hpp"
#include "fast/box_contact_lanes.hpp"
#include "fast/fast_path.hpp"
#include "fast/fast_workspace.hpp"
#include "fast/packed_substeps.hpp"
#include "fast/round_contact_lanes.hpp"
#include "objects/inertia.hpp"
#include "test_support.hpp"
#include "world/world.hpp"

using namespace stepwise;

namespace {

/// A heap of balls of two sizes and masses, pressed into each other and into
/// the ground and two walls, moving and spinning at random: many round contacts.
struct BallHeap {
    std::vector<DynamicObject> dynamics;
    std::vector<KinematicsObject> kinematics;
    std::vector<CollisionPlane> planes;
    std::vector<Contact> contacts;

    BallHeap() {
        std::mt19937 random(7);
        std::uniform_real_distribution<double> jitter(-0.04, 0.04);
        std::uniform_real_distribution<double> speed(-1.5, 1.5);
        for (int layer = 0; layer < 4; ++layer) {
            for (int row = 0; row < 5; ++row) {
                for (int column = 0; column < 5; ++column) {
                    // Centres 0.95 m apart: neighbours overlap by about 5 cm (radius 0.5 m)
                    const Vec3 centre(0.45 + 0.95 * column + jitter(random), 0.47 + 0.93 * layer + jitter(random),
                                      0.45 + 0.95 * row + jitter(random));
                    DynamicObject ball = test::sphere("b" + std::to_string(dynamics.size()), centre,
                                                      Vec3(speed(random), speed(random), speed(random)));
                    if ((row + column + layer) % 3 == 0) ball.setMass(3);  // a heavier ball now and then
                    ball.angularVelocity = Vec3(speed(random), speed(random), speed(random));
                    ball.friction = 0.6;
                    dynamics.push_back(ball);
                }
            }
        }
        planes.push_back(test::ground());
        CollisionPlane wallX;
        wallX.normal = Vec3(1, 0, 0);
        CollisionPlane wallZ;
        wallZ.normal = Vec3(0, 0, 1);
        planes.push_back(wallX);
        planes.push_back(wallZ);
        for (DynamicObject& body : dynamics) initialiseMassProperties(body);

        contacts = test::contactsOf({dynamics, kinematics, planes});
    }
    BodySet bodies() { return {dynamics, kinematics, planes}; }
};

ContactSolverSettings substepSettings() {
    ContactSolverSettings settings;
    settings.substep = Real(1) / 960;
    settings.inverseSubstep = Real(960);
    settings.softness = makeSoftness(240, 1, settings.substep);
    return settings;
}

}  // namespace

TEST_CASE("Waves: no wave holds two contacts of one dynamic body, each body meets its contacts in order", "[fast][solver][lanes]") {
    BallHeap heap;
    SolverWorkspace workspace;
    prepareContacts(heap.bodies(), heap.contacts, {}, Real(1) / 60, false, workspace);
    REQUIRE(workspace.contacts.size() > 100);  // a heap, not a handful
    FastWorkspace fast;
    batchRoundContacts(workspace, fast);

    std::vector<int> solved(workspace.contacts.size(), 0);
    std::vector<std::uint32_t> waveRecords;                                  // the dynamic records of the current wave
    std::vector<std::int64_t> lastContact(workspace.bodies.size(), -1);      // per record: its last contact's place in the pass
    std::vector<std::int64_t> position(workspace.contacts.size(), -1);       // each contact's place in the pass order
    for (std::size_t k = 0; k < workspace.roundContacts.size(); ++k) position[workspace.roundContacts[k]] = std::int64_t(k);
    for (std::size_t n = 0; n < fast.roundBatches.size(); ++n) {
        const RoundBatch& batch = fast.roundBatches[n];
        if (n > 0) CHECK(batch.wave >= fast.roundBatches[n - 1].wave);  // wave by wave
        if (n == 0 || batch.wave != fast.roundBatches[n - 1].wave) {
            std::sort(waveRecords.begin(), waveRecords.end());
            CHECK(std::adjacent_find(waveRecords.begin(), waveRecords.end()) == waveRecords.end());
            waveRecords.clear();
        }
        for (int lane = 0; lane < kLanes; ++lane) {
            if (batch.contact[lane] == kEmptyLane) {
                CHECK(batch.bodyA[lane] == kStaticSolverBody);  // an empty lane moves nothing
                CHECK(batch.bodyB[lane] == kStaticSolverBody);
                continue;
            }
            const std::uint32_t index = batch.contact[lane];
            const SolverContact& c = workspace.contacts[index];
            CHECK(c.rows == kRoundContact);
            CHECK(batch.bodyA[lane] == c.bodyA);
            CHECK(batch.bodyB[lane] == c.bodyB);
            ++solved[index];
            for (const std::uint32_t record : {c.bodyA, c.bodyB}) {
                if (record == kStaticSolverBody) continue;
                waveRecords.push_back(record);
                INFO("contact " << index << ", record " << record);
                CHECK(lastContact[record] < position[index]);  // the body's contacts in the pass's order
                lastContact[record] = position[index];
            }
        }
    }
    std::sort(waveRecords.begin(), waveRecords.end());
    CHECK(std::adjacent_find(waveRecords.begin(), waveRecords.end()) == waveRecords.end());
    for (const std::uint32_t index : workspace.otherContacts) ++solved[index];
    for (std::size_t i = 0; i < solved.size(); ++i) {
        INFO("contact " << i);
        CHECK(solved[i] == 1);
    }
    CHECK(workspace.otherContacts.empty());  // balls and planes only: every contact is round
    CHECK(workspace.roundContacts.size() == workspace.contacts.size());
    // Wide waves: the lanes are mostly full (each wave's last batch may not be).
    const std::size_t waves = fast.roundBatches.back().wave + 1;
    CHECK(fast.roundBatches.size() * kLanes < workspace.contacts.size() + waves * kLanes);
    CHECK(waves * 8 < workspace.contacts.size());
}

TEST_CASE("A pass in lanes is the scalar pass, four contacts at a time", "[fast][solver][lanes]") {
    // The same contacts, solved once by the lanes and once one at a time by the plain scalar pass
    // (solveContacts(), solve_contacts.cpp): warm start, a solve and a relax pass must leave the same
    // velocities and impulses. Each lane rounds as a scalar does and each body meets its contacts in
    // the same order, so they agree to the last bit: the engine is built with -ffp-contract=off, so
    // that no copy of the lanes (AVX-512, AVX2 or SSE2) and no scalar line fuses a·b + c. A build for
    // a processor with FMA whose own flags fuse anyway gets a tolerance of a billionth of the values.
    BallHeap heap;
    ContactSolverSettings settings = substepSettings();
    // Both kinds of relax pass: the normal rows only (the default), and with friction.
    settings.relaxBallFriction = GENERATE(false, true);
    INFO("relaxBallFriction " << settings.relaxBallFriction);
    SolverWorkspace lanes;
    prepareContacts(heap.bodies(), heap.contacts, {}, Real(1) / 60, false, lanes);
    // Something to warm start from: the impulses a previous step might have left.
    for (SolverContact& c : lanes.contacts) {
        c.normalImpulse = Real(0.01) * c.normalMass;
        c.tangentImpulse[0] = Real(0.002) * c.normalMass;
    }
    SolverWorkspace scalar = lanes;
    FastWorkspace fast;
    batchRoundContacts(lanes, fast);
    REQUIRE(fast.roundBatches.size() > 20);

    recordPoses(heap.bodies(), lanes);
    recordCentres(lanes, fast);
    copyVelocitiesIn(lanes);
    warmStartRoundContacts(lanes, fast);
    solveRoundContacts(lanes, fast, settings, true);
    solveRoundContacts(lanes, fast, settings, false);
    syncRoundContacts(fast, lanes);

    recordPoses(heap.bodies(), scalar);
    copyVelocitiesIn(scalar);
    warmStartContacts(scalar, true);
    solveContacts(scalar, settings, true);
    solveContacts(scalar, settings, false);

#if defined(__FMA__)
    const auto same = [](Real x, Real y) { return x == Approx(y).epsilon(1e-9).margin(1e-12); };
#else
    const auto same = [](Real x, Real y) { return x == y; };
#endif
    int pushing = 0;
    for (std::size_t i = 0; i < lanes.contacts.size(); ++i) {
        INFO("contact " << i);
        CHECK(same(lanes.contacts[i].normalImpulse, scalar.contacts[i].normalImpulse));
        CHECK(same(lanes.contacts[i].maxNormalImpulse, scalar.contacts[i].maxNormalImpulse));
        for (int k = 0; k < 2; ++k) CHECK(same(lanes.contacts[i].tangentImpulse[k], scalar.contacts[i].tangentImpulse[k]));
        if (lanes.contacts[i].normalImpulse > 0) ++pushing;
    }
    CHECK(pushing > 50);  // the passes did work: there is something to compare
    for (std::size_t r = 0; r < lanes.bodies.size(); ++r) {
        INFO("record " << r);
        for (int k = 0; k < 3; ++k) {
            CHECK(same(lanes.bodies[r].velocity[k], scalar.bodies[r].velocity[k]));
            CHECK(same(lanes.bodies[r].angularVelocity[k], scalar.bodies[r].angularVelocity[k]));
        }
    }
    // The static record stays at rest whatever the empty lanes and plane contacts wrote into it.
    CHECK(lanes.bodies[kStaticSolverBody].velocity == Vec3(0));
    CHECK(lanes.bodies[kStaticSolverBody].angularVelocity == Vec3(0));
}

TEST_CASE("A relax pass leaves a ball contact's friction as the solve pass left it, unless told to solve it too", "[fast][solver][lanes][friction]") {
    // The relax pass is there to take back the push-out speed, which the normal rows carry;
    // a round contact's friction rows are not coupled to its own normal row (K_nt = 0: the normal
    // impulse passes through the centres), so by default the relax solves the normal rows only
    // (contact_solver.hpp, "Friction in the relax"). Were the template argument or the setting
    // not wired through, one of the two checks below fails.
    BallHeap heap;
    ContactSolverSettings settings = substepSettings();
    const bool relaxBallFriction = GENERATE(false, true);
    settings.relaxBallFriction = relaxBallFriction;
    INFO("relaxBallFriction " << relaxBallFriction);
    // On both roads: the plain pass, and the lanes.
    const bool inLanes = GENERATE(false, true);
    INFO((inLanes ? "in lanes" : "plain"));
    SolverWorkspace w;
    FastWorkspace fast;
    prepareContacts(heap.bodies(), heap.contacts, {}, Real(1) / 60, false, w);
    recordPoses(heap.bodies(), w);
    copyVelocitiesIn(w);
    auto pass = [&](bool useBias) {
        if (inLanes) {
            solveRoundContacts(w, fast, settings, useBias);
            syncRoundContacts(fast, w);
        } else {
            solveContacts(w, settings, useBias);
        }
    };
    if (inLanes) {
        batchRoundContacts(w, fast);
        recordCentres(w, fast);
    }
    pass(true);
    const std::vector<SolverContact> afterSolve = w.contacts;
    pass(false);

    int normalsChanged = 0;
    int frictionChanged = 0;
    for (std::size_t i = 0; i < w.contacts.size(); ++i) {
        if (w.contacts[i].normalImpulse != afterSolve[i].normalImpulse) ++normalsChanged;
        for (int k = 0; k < 2; ++k) {
            if (w.contacts[i].tangentImpulse[k] != afterSolve[i].tangentImpulse[k]) ++frictionChanged;
        }
    }
    CHECK(normalsChanged > 50);  // the relax pass ran, and took back push-out
    if (relaxBallFriction) CHECK(frictionChanged > 50);
    else CHECK(frictionChanged == 0);
}

TEST_CASE("The solver's footprint counts what a pass reads: the body records and the batches", "[fast][solver][lanes]") {
    CHECK(solverFootprint(SolverWorkspace{}).allBytes == 0);  // nothing prepared, nothing held
    CHECK(fastFootprint(SolverWorkspace{}, FastWorkspace{}).allBytes == 0);

    BallHeap heap;
    SolverWorkspace workspace;
    prepareContacts(heap.bodies(), heap.contacts, {}, Real(1) / 60, false, workspace);
    recordPoses(heap.bodies(), workspace);
    FastWorkspace fast;
    batchRoundContacts(workspace, fast);
    recordCentres(workspace, fast);
    // Counted from the contacts themselves: a record per dynamic body in a contact, and record 0
    std::vector<bool> inContact(heap.dynamics.size(), false);
    for (const Contact& contact : heap.contacts) {
        inContact[contact.a] = true;
        if (contact.b.kind == BodyKind::Dynamic) inContact[contact.b.index] = true;
    }
    const std::size_t records = 1 + std::size_t(std::count(inContact.begin(), inContact.end(), true));
    const std::size_t contacts = heap.contacts.size();
    REQUIRE(workspace.bodies.size() == records);
    // Every contact is round here: all of them in batches of four, a wave's last batch perhaps not full
    const std::size_t batches = fast.roundBatches.size();
    CHECK(batches * kLanes >= contacts);

    // The plain pass reads the records, every contact, and the poses (no rows: all round)
    const SolverFootprint plain = solverFootprint(workspace);
    CHECK(plain.passBytes == records * sizeof(SolverBody) + contacts * (sizeof(SolverContact) + sizeof(std::uint32_t)) +
                                 workspace.poses.size() * sizeof(Pose));
    // The lanes read the records, their centres and the batches
    const SolverFootprint lanes = fastFootprint(workspace, fast);
    CHECK(lanes.passBytes == records * (sizeof(SolverBody) + sizeof(SolverCentre)) + batches * sizeof(RoundBatch));
    // A substep walks the passes' arrays and, between the passes, each record's summed turn
    // (nothing has sized the substep-start velocities yet; these steps took no packed substeps)
    CHECK(plain.substepBytes == plain.passBytes + records * sizeof(SpinSum) + workspace.substepStart.size() * sizeof(BodyVelocity));
    CHECK(lanes.substepBytes == lanes.passBytes + records * sizeof(SpinSum) + workspace.substepStart.size() * sizeof(BodyVelocity));
    // Everything else is on top: at least each contact's record and start
    CHECK(plain.allBytes >= plain.passBytes + contacts * sizeof(ContactStart));
    CHECK(lanes.allBytes >= lanes.passBytes + contacts * (sizeof(SolverContact) + sizeof(ContactStart)));
}

namespace {

/// Steps @p scene twice, once with FastPath=false and once with true, and requires every body's
/// state to be the same, bit for bit, after every step; returns the fast World's counts.
FastPathCounts requireSameOnBothRoads(Scene scene, int steps) {
    scene.settings.fastPath = false;
    World plain(scene);
    scene.settings.fastPath = true;
    World fast(scene);
    REQUIRE_FALSE(plain.plan().fastPath.runs);
    REQUIRE(fast.plan().fastPath.runs);
    for (int step = 0; step < steps; ++step) {
        plain.step();
        fast.step();
        test::requireSameState(fast, plain);
    }
    CHECK(plain.fastPathCounts().steps == 0);
    return fast.fastPathCounts();
}

Scene sceneFrom(const std::string& text) { return parseScene(text, "fast-path test"); }

}  // namespace

TEST_CASE("A rain of balls on the packed substeps ends every step where the plain path does", "[fast][lanes]") {
    // Rough, bouncing, spinning balls dropped into a box of planes: every step's contacts hold
    // balls only, so the fast path runs its substeps on the packed records.
    std::string text = "World, Duration=2, Sleep=false\n"
                       "CollisionPlane, Name=floor, Position=(0,0,0), Normal=(0,1,0)\n"
                       "CollisionPlane, Name=west, Position=(-1.5,0,0), Normal=(1,0,0)\n"
                       "CollisionPlane, Name=east, Position=(1.5,0,0), Normal=(-1,0,0)\n"
                       "CollisionPlane, Name=south, Position=(0,0,-1.5), Normal=(0,0,1)\n"
                       "CollisionPlane, Name=north, Position=(0,0,1.5), Normal=(0,0,-1)\n";
    for (int i = 0; i < 48; ++i) {
        const double x = -1.1 + 0.45 * (i % 6), z = -1.0 + 0.5 * ((i / 6) % 4), y = 0.4 + 0.45 * (i / 24) + 0.05 * (i % 3);
        text += "DynamicObject, Name=b" + std::to_string(i) + ", Shape=Sphere, Radius=0.2, Mass=" +
                std::to_string(1 + i % 3) + ", Position=(" + std::to_string(x) + "," + std::to_string(y) + "," +
                std::to_string(z) + "), Velocity=(" + std::to_string(0.3 * (i % 5) - 0.6) + ",0," +
                std::to_string(0.2 * (i % 4) - 0.3) + "), AngularVelocity=(0," + std::to_string(i % 7) +
                ",0), Elasticity=0.6, Friction=0.5\n";
    }
    const FastPathCounts counts = requireSameOnBothRoads(sceneFrom(text), 90);
    INFO(counts.packedSteps << " of " << counts.steps << " steps on the packed records");
    CHECK(counts.steps == 90);
    CHECK(counts.packedSteps > 60);  // the comparison covers the packed substeps, not only the road on the objects
}

TEST_CASE("The packed kick reads one free flight for all balls only when all have the same bits", "[fast][lanes]") {
    const auto pack = [](BallHeap& heap) {
        for (DynamicObject& ball : heap.dynamics) ball.acceleration = Vec3(0, -9.81, 0);  // what apply-forces leaves
        SolverWorkspace workspace;
        prepareContacts(heap.bodies(), heap.contacts, {}, Real(1) / 60, false, workspace);
        FastWorkspace fast;
        REQUIRE(packRecords(workspace, fast));
        return fast.sharedFlight;
    };
    BallHeap gravity;
    CHECK(pack(gravity));
    // One ball's torque of −0 instead of +0: equal numbers, other bits (v + h·(−0) is not always v + h·(+0))
    BallHeap negativeZero;
    negativeZero.dynamics[7].torque = Vec3(-0.0, 0, 0);
    CHECK_FALSE(pack(negativeZero));

    // A rain in which some balls have their own acceleration: each ball kicked by its own a, as on the plain path
    std::string text = "World, Duration=1, Sleep=false\n"
                       "CollisionPlane, Name=floor, Position=(0,0,0), Normal=(0,1,0)\n"
                       "CollisionPlane, Name=west, Position=(-1.5,0,0), Normal=(1,0,0)\n"
                       "CollisionPlane, Name=east, Position=(1.5,0,0), Normal=(-1,0,0)\n";
    for (int i = 0; i < 24; ++i) {
        const double x = -1.1 + 0.45 * (i % 6), y = 0.3 + 0.45 * (i / 6);
        text += "DynamicObject, Name=b" + std::to_string(i) + ", Shape=Sphere, Radius=0.2, Position=(" + std::to_string(x) +
                "," + std::to_string(y) + ",0), AngularVelocity=(0," + std::to_string(i % 5) + ",0)" +
                (i % 4 == 0 ? ", Acceleration=(0.5,0,-0.25)" : "") + ", Friction=0.5\n";
    }
    const FastPathCounts counts = requireSameOnBothRoads(sceneFrom(text), 60);
    CHECK(counts.packedSteps > 30);
}

TEST_CASE("Balls among boxes, on a joint and under Verlet take the fast path on the objects, with the plain numbers", "[fast][lanes]") {
    const std::string ground = "CollisionPlane, Name=floor, Position=(0,0,0), Normal=(0,1,0)\n";
    SECTION("balls and boxes in one pile: round contacts in lanes, box contacts one at a time") {
        std::string text = "World, Duration=2, Sleep=false\n" + ground;
        for (int i = 0; i < 12; ++i) {
            const std::string at = "(" + std::to_string(-0.9 + 0.35 * (i % 6)) + "," + std::to_string(0.3 + 0.4 * (i / 6)) +
                                   "," + std::to_string(0.05 * (i % 2)) + ")";
            text += i % 3 == 0 ? "DynamicObject, Name=box" + std::to_string(i) +
                                     ", Shape=Box, Scale=(0.3,0.3,0.3), Mass=2, Friction=0.6, Position=" + at + "\n"
                               : "DynamicObject, Name=ball" + std::to_string(i) +
                                     ", Shape=Sphere, Radius=0.16, Mass=1, Friction=0.6, Elasticity=0.3, Position=" + at + "\n";
        }
        const FastPathCounts counts = requireSameOnBothRoads(sceneFrom(text), 90);
        CHECK(counts.steps == 90);
        CHECK(counts.packedSteps < counts.steps);  // the boxes' contacts keep those steps on the objects
    }
    SECTION("a ball on a rope swinging into another: joints between the contact passes") {
        const std::string text = "World, Duration=2, Sleep=false\n" + ground +
                                 "DynamicObject, Name=bob, Shape=Sphere, Radius=0.2, Mass=1, Position=(-1,2,0)\n"
                                 "DynamicObject, Name=target, Shape=Sphere, Radius=0.2, Mass=1, Position=(0.05,1.0,0)\n"
                                 "DistanceJoint, Name=rod, BodyA=bob, AnchorA=(-1,2,0), AnchorB=(0,2,0)\n";
        const FastPathCounts counts = requireSameOnBothRoads(sceneFrom(text), 120);
        CHECK(counts.steps == 120);
        CHECK(counts.packedSteps == 0);  // joint passes work on the objects
    }
    SECTION("balls under velocity Verlet and explicit Euler") {
        const std::string integrator = GENERATE(std::string("Verlet"), std::string("Euler"));
        INFO(integrator);
        std::string text = "World, Duration=2, Integrator=" + integrator + "\n" + ground;
        for (int i = 0; i < 6; ++i) {
            text += "DynamicObject, Name=b" + std::to_string(i) + ", Shape=Sphere, Radius=0.2, Mass=1, Friction=0.4, Position=(" +
                    std::to_string(0.3 * i) + "," + std::to_string(0.25 + 0.45 * i) + ",0)\n";
        }
        const FastPathCounts counts = requireSameOnBothRoads(sceneFrom(text), 90);
        CHECK(counts.packedSteps == 0);  // the packed substeps carry symplectic Euler only
    }
}

namespace {

/// A heap of boxes, tilted, pressed into each other and into the ground, with a ball now and then
/// and a kinematic slab sliding into one side: contacts with stored rows of every kind (box–box,
/// box–plane, box–ball, box–kinematic, ball–kinematic) among round ones.
struct BoxHeap {
    std::vector<DynamicObject> dynamics;
    std::vector<KinematicsObject> kinematics;
    std::vector<CollisionPlane> planes;
    std::vector<Contact> contacts;

    BoxHeap() {
        std::mt19937 random(11);
        std::uniform_real_distribution<double> jitter(-0.03, 0.03);
        std::uniform_real_distribution<double> speed(-1.0, 1.0);
        std::uniform_real_distribution<double> tilt(-0.15, 0.15);
        for (int layer = 0; layer < 3; ++layer) {
            for (int row = 0; row < 4; ++row) {
                for (int column = 0; column < 4; ++column) {
                    // Edges 0.5 m, centres 0.48 m apart: neighbours overlap by about 2 cm
                    const Vec3 centre(0.25 + 0.48 * column + jitter(random), 0.24 + 0.48 * layer + jitter(random),
                                      0.25 + 0.48 * row + jitter(random));
                    const std::string name = "b" + std::to_string(dynamics.size());
                    DynamicObject body = (row + column + layer) % 3 == 0
                                             ? test::sphere(name, centre, Vec3(0), Real(0.25))
                                             : test::dynamicBox(name, centre, Vec3(0.5), 1 + (row + layer) % 3, Real(0.6));
                    body.friction = 0.6;
                    body.velocity = Vec3(speed(random), speed(random), speed(random));
                    body.angularVelocity = Vec3(speed(random), speed(random), speed(random));
                    body.orientation = glm::normalize(Quat(1, tilt(random), tilt(random), tilt(random)));
                    dynamics.push_back(body);
                }
            }
        }
        planes.push_back(test::ground());
        // A slab along x = −0.2 moving into the heap, overlapping its first column a little
        kinematics.push_back(test::kinematicBox("slab", Vec3(-0.2, 0.7, 0.9), Vec3(0.44, 1.4, 2.0), Vec3(0.5, 0, 0.2)));
        for (DynamicObject& body : dynamics) initialiseMassProperties(body);

        contacts = test::contactsOf({dynamics, kinematics, planes});
    }
    BodySet bodies() { return {dynamics, kinematics, planes}; }
};

/// Whether the batches @p batches (RoundBatch or BoxBatch) hold each contact of @p list once, wave by
/// wave, with no two contacts of one dynamic body in a wave and each body's contacts in their order.
template <class Batch>
void requireWavesKeepOrder(const std::vector<Batch>& batches, const std::vector<std::uint32_t>& list,
                           const SolverWorkspace& workspace) {
    std::vector<int> solved(workspace.contacts.size(), 0);
    std::vector<std::uint32_t> waveRecords;                              // the dynamic records of the current wave
    std::vector<std::int64_t> lastContact(workspace.bodies.size(), -1);  // per record: its last contact so far
    std::vector<std::int64_t> position(workspace.contacts.size(), -1);   // each contact's place in the list
    for (std::size_t k = 0; k < list.size(); ++k) position[list[k]] = std::int64_t(k);
    auto closeWave = [&] {
        std::sort(waveRecords.begin(), waveRecords.end());
        CHECK(std::adjacent_find(waveRecords.begin(), waveRecords.end()) == waveRecords.end());
        waveRecords.clear();
    };
    for (std::size_t n = 0; n < batches.size(); ++n) {
        const Batch& batch = batches[n];
        if (n > 0) CHECK(batch.wave >= batches[n - 1].wave);  // wave by wave
        if (n > 0 && batch.wave != batches[n - 1].wave) closeWave();
        for (int lane = 0; lane < kLanes; ++lane) {
            if (batch.contact[lane] == kEmptyLane) {
                CHECK(batch.bodyA[lane] == kStaticSolverBody);  // an empty lane moves nothing
                CHECK(batch.bodyB[lane] == kStaticSolverBody);
                continue;
            }
            const std::uint32_t index = batch.contact[lane];
            const SolverContact& c = workspace.contacts[index];
            REQUIRE(position[index] >= 0);  // a contact of this list
            CHECK(batch.bodyA[lane] == c.bodyA);
            CHECK(batch.bodyB[lane] == c.bodyB);
            ++solved[index];
            for (const std::uint32_t record : {c.bodyA, c.bodyB}) {
                if (record == kStaticSolverBody) continue;
                waveRecords.push_back(record);
                INFO("contact " << index << ", record " << record);
                CHECK(lastContact[record] < position[index]);  // the body's contacts in their order
                lastContact[record] = position[index];
            }
        }
    }
    closeWave();
    for (const std::uint32_t index : list) {
        INFO("contact " << index);
        CHECK(solved[index] == 1);
    }
}

}  // namespace

TEST_CASE("Box waves: no wave holds two contacts of one dynamic body, each body meets its contacts in order", "[fast][solver][lanes]") {
    BoxHeap heap;
    SolverWorkspace workspace;
    prepareContacts(heap.bodies(), heap.contacts, {}, Real(1) / 60, false, workspace);
    REQUIRE(workspace.otherContacts.size() > 100);  // a heap of boxes, not a handful
    REQUIRE(workspace.roundContacts.size() > 5);     // and some balls among them
    FastWorkspace fast;
    batchRoundContacts(workspace, fast);
    batchBoxContacts(workspace, fast);
    for (const std::uint32_t index : workspace.otherContacts) CHECK(workspace.contacts[index].rows != kRoundContact);
    requireWavesKeepOrder(fast.roundBatches, workspace.roundContacts, workspace);
    requireWavesKeepOrder(fast.boxBatches, workspace.otherContacts, workspace);
    // Every kind of B: a dynamic body, the static record (the ground), and the slab's surface speed
    bool kinematic = false;
    for (const std::uint32_t index : workspace.otherContacts) {
        const ContactRows& rows = workspace.rows[workspace.contacts[index].rows];
        kinematic = kinematic || rows.tangentSurfaceSpeed[0] != 0 || rows.tangentSurfaceSpeed[1] != 0;
    }
    CHECK(kinematic);
}

TEST_CASE("A pass of box contacts in lanes is the scalar pass, four contacts at a time", "[fast][solver][lanes]") {
    // As for the round contacts above: warm start, a solve pass and a relax pass, on both roads, must
    // leave the same velocities and impulses, to the bit (a build whose own flags fuse a·b + c gets
    // a tolerance of a billionth). The plain pass solves the round contacts first, then the others;
    // the lanes do the same, round batches then box batches.
    BoxHeap heap;
    ContactSolverSettings settings = substepSettings();
    settings.accumulate = GENERATE(true, false);  // and Box2D-Lite's clamp of each increment
    INFO("accumulate " << settings.accumulate);
    SolverWorkspace lanes;
    prepareContacts(heap.bodies(), heap.contacts, {}, Real(1) / 60, false, lanes);
    // Something to warm start from: the impulses a previous step might have left, and a few points
    // that hold nothing at all (the plain pass skips their friction).
    for (std::size_t i = 0; i < lanes.contacts.size(); ++i) {
        SolverContact& c = lanes.contacts[i];
        if (i % 7 == 3) continue;
        c.normalImpulse = Real(0.01) * c.normalMass;
        c.tangentImpulse[0] = Real(0.002) * c.normalMass;
        c.tangentImpulse[1] = Real(-0.001) * c.normalMass;
    }
    SolverWorkspace scalar = lanes;
    FastWorkspace fast;
    batchRoundContacts(lanes, fast);
    batchBoxContacts(lanes, fast);
    REQUIRE(fast.boxBatches.size() > 20);

    recordPoses(heap.bodies(), lanes);
    recordCentres(lanes, fast);
    recordBoxSeparations(lanes, fast);
    copyVelocitiesIn(lanes);
    if (settings.accumulate) {
        warmStartRoundContacts(lanes, fast);
        warmStartBoxContacts(lanes, fast);
    } else {
        for (SolverContact& c : lanes.contacts) c.normalImpulse = c.tangentImpulse[0] = c.tangentImpulse[1] = 0;
        clearRoundContactImpulses(fast);
        clearBoxContactImpulses(fast);
    }
    for (const bool useBias : {true, false}) {
        solveRoundContacts(lanes, fast, settings, useBias);
        solveBoxContacts(lanes, fast, settings, useBias);
    }
    syncRoundContacts(fast, lanes);
    syncBoxContacts(fast, lanes);

    recordPoses(heap.bodies(), scalar);
    copyVelocitiesIn(scalar);
    warmStartContacts(scalar, settings.accumulate);
    solveContacts(scalar, settings, true);
    solveContacts(scalar, settings, false);

#if defined(__FMA__)
    const auto same = [](Real x, Real y) { return x == Approx(y).epsilon(1e-9).margin(1e-12); };
#else
    const auto same = [](Real x, Real y) { return x == y; };
#endif
    int pushing = 0;
    int sliding = 0;
    for (const std::uint32_t i : scalar.otherContacts) {
        INFO("contact " << i);
        CHECK(same(lanes.contacts[i].normalImpulse, scalar.contacts[i].normalImpulse));
        CHECK(same(lanes.contacts[i].maxNormalImpulse, scalar.contacts[i].maxNormalImpulse));
        for (int k = 0; k < 2; ++k) CHECK(same(lanes.contacts[i].tangentImpulse[k], scalar.contacts[i].tangentImpulse[k]));
        if (scalar.contacts[i].normalImpulse > 0) ++pushing;
        // On Coulomb's circle: the friction was clamped (the division's branch ran)
        const Real friction = std::hypot(scalar.contacts[i].tangentImpulse[0], scalar.contacts[i].tangentImpulse[1]);
        if (friction > 0 && friction == Approx(scalar.contacts[i].friction * scalar.contacts[i].normalImpulse)) ++sliding;
    }
    CHECK(pushing > 50);  // the passes did work: there is something to compare
    CHECK(sliding > 5);   // and both branches of the friction's clamp were taken
    for (std::size_t r = 0; r < lanes.bodies.size(); ++r) {
        INFO("record " << r);
        for (int k = 0; k < 3; ++k) {
            CHECK(same(lanes.bodies[r].velocity[k], scalar.bodies[r].velocity[k]));
            CHECK(same(lanes.bodies[r].angularVelocity[k], scalar.bodies[r].angularVelocity[k]));
        }
    }
    CHECK(lanes.bodies[kStaticSolverBody].velocity == Vec3(0));
    CHECK(lanes.bodies[kStaticSolverBody].angularVelocity == Vec3(0));
}

namespace {

/// Nine bodies in three rows over a 3 m deck at y = 0.5: boxes of 1 to 3 kg (μ = 0.7) and two
/// balls (μ = 0.5), each a little off the one below, so they land at different moments.
std::string boxesAndBallsOnADeck() {
    std::string text;
    for (int i = 0; i < 9; ++i) {
        const std::string at = "(" + std::to_string(-0.8 + 0.8 * (i % 3)) + "," + std::to_string(0.75 + 0.6 * (i / 3)) +
                               "," + std::to_string(-0.6 + 0.6 * (i % 3) + 0.05 * (i / 3)) + ")";
        text += i % 4 == 2 ? "DynamicObject, Name=ball" + std::to_string(i) +
                                 ", Shape=Sphere, Radius=0.2, Mass=1, Friction=0.5, Position=" + at + "\n"
                           : "DynamicObject, Name=box" + std::to_string(i) +
                                 ", Shape=Box, Scale=(0.5,0.5,0.5), Mass=" + std::to_string(1 + i % 3) +
                                 ", Friction=0.7, Position=" + at + "\n";
    }
    return text;
}

}  // namespace

TEST_CASE("Stacks of boxes and a kinematic platform take the fast path with the plain numbers", "[fast][lanes]") {
    SECTION("the pyramid of 210 boxes (lesson 8)") {
        Scene scene = loadSceneFile(std::string(STEPWISE_SOURCE_DIR) + "/config/lesson08_pyramid.scene");
        const FastPathCounts counts = requireSameOnBothRoads(scene, 20);
        CHECK(counts.steps == 20);
        CHECK(counts.packedSteps == 0);    // box contacts: the road on the objects
        CHECK(counts.boxLaneSteps == 20);  // wide waves: every step's box contacts in lanes
    }
    SECTION("the tower of 20 boxes (lesson 8), in colour order") {
        Scene scene = loadSceneFile(std::string(STEPWISE_SOURCE_DIR) + "/config/lesson08_tower.scene");
        const FastPathCounts counts = requireSameOnBothRoads(scene, 60);
        CHECK(counts.steps == 60);
        CHECK(counts.boxLaneSteps == 60);  // two colours of ten manifolds each: wide enough for lanes
    }
    SECTION("the tower of 20 boxes, in the order found") {
        Scene scene = loadSceneFile(std::string(STEPWISE_SOURCE_DIR) + "/config/lesson08_tower.scene");
        scene.settings.contactOrder = ContactOrder::Found;
        const FastPathCounts counts = requireSameOnBothRoads(scene, 60);
        CHECK(counts.steps == 60);
        CHECK(counts.boxLaneSteps == 0);  // a chain: waves too thin, its contacts one at a time
    }
    SECTION("boxes riding a moving, turning kinematic platform, balls among them") {
        std::string text = "World, Duration=2, Sleep=false\n"
                           "CollisionPlane, Name=floor, Position=(0,0,0), Normal=(0,1,0)\n"
                           "KinematicsObject, Name=deck, Shape=Box, Position=(0,0.25,0), Scale=(3,0.5,3), "
                           "Velocity=(0.4,0,0.1), AngularVelocity=(0,0.5,0)\n";
        text += boxesAndBallsOnADeck();
        const FastPathCounts counts = requireSameOnBothRoads(sceneFrom(text), 90);
        CHECK(counts.steps == 90);
        INFO(counts.boxLaneSteps << " steps with box lanes");
        CHECK(counts.boxLaneSteps > 0);
    }
}

TEST_CASE("How full the box lanes are: contacts per wave of the pyramid and the tower", "[fast][lanes]") {
    // Not a timing: how many contacts a wave holds, for the record (the figure the lanes' speed
    // rests on), at the scene's first contacts. A manifold's points share both bodies and fall in
    // successive waves; a tower is a chain of manifolds, each sharing a box with the next. In the
    // order found, the tower's waves are that chain, one contact each; in colour order its
    // manifolds take turns, every other one in the same colour, and the waves are the colours.
    const bool colours = GENERATE(true, false);
    INFO((colours ? "ContactOrder=Colours" : "ContactOrder=Found"));
    for (const char* name : {"lesson08_pyramid", "lesson08_tower"}) {
        Scene scene = loadSceneFile(std::string(STEPWISE_SOURCE_DIR) + "/config/" + name + ".scene");
        const BodySet bodies{scene.dynamics, scene.kinematics, scene.planes};
        for (DynamicObject& body : scene.dynamics) initialiseMassProperties(body);
        const std::vector<Contact> contacts = test::contactsOf(bodies);
        SolverWorkspace workspace;
        workspace.colourOrder = colours;
        prepareContacts(bodies, contacts, {}, scene.settings.timeStep, false, workspace);
        recordPoses(bodies, workspace);
        FastWorkspace fast;
        batchRoundContacts(workspace, fast);
        recordCentres(workspace, fast);
        batchBoxContacts(workspace, fast);
        const std::size_t count = workspace.otherContacts.size();
        std::printf("%s: a pass reads %zu bytes a contact on the plain path, %zu in lanes\n", name,
                    solverFootprint(workspace).passBytes / workspace.contacts.size(),
                    fastFootprint(workspace, fast).passBytes / workspace.contacts.size());
        const std::size_t waves = fast.waves;
        const std::size_t batches = fast.boxBatches.size();
        std::printf("%s: %zu contacts with stored rows in %zu waves, %.1f a wave; %zu batches, lanes %.0f %% full\n", name,
                    count, waves, double(count) / double(waves), batches,
                    batches == 0 ? 0.0 : 100.0 * double(count) / double(kLanes * batches));
        INFO(name);
        REQUIRE(count > 0);
        if (std::string(name) == "lesson08_pyramid") {
            CHECK(waves * 4 < count);  // the pyramid's waves are wide: in lanes
            requireWavesKeepOrder(fast.boxBatches, workspace.otherContacts, workspace);
        } else if (colours) {
            // A manifold's 4 points are in 4 colours (they share both boxes); the floor's and the
            // manifolds above alternate: 8 colours of 10 contacts, whatever the tower's height.
            CHECK(waves <= 8);
            CHECK(waves * 4 < count);
            requireWavesKeepOrder(fast.boxBatches, workspace.otherContacts, workspace);
        } else {
            CHECK(double(count) < kMinBoxContactsPerWave * double(waves));  // the tower's are thin: one at a time
            CHECK(batches == 0);
        }
    }
}

TEST_CASE("A rain of balls into a box of static boxes runs in the lanes and on the packed records, with the plain numbers", "[fast][lanes]") {
    // The same kind of rain as above, but the floor and the walls are kinematic boxes at rest:
    // they neither move nor turn, so a ball's contact with one is round, as a plane's is
    // (contact_solver.hpp, "Rows stored or computed"), and the steps run on the packed records.
    std::string text = "World, Duration=2, Sleep=false\n"
                       "KinematicsObject, Name=floor, Shape=Box, Position=(0,-0.5,0), Scale=(4,1,4)\n"
                       "KinematicsObject, Name=west, Shape=Box, Position=(-2,1.5,0), Scale=(1,3,4)\n"
                       "KinematicsObject, Name=east, Shape=Box, Position=(2,1.5,0), Scale=(1,3,4)\n"
                       "KinematicsObject, Name=south, Shape=Box, Position=(0,1.5,-2), Scale=(3,3,1)\n"
                       "KinematicsObject, Name=north, Shape=Box, Position=(0,1.5,2), Scale=(3,3,1)\n";
    for (int i = 0; i < 48; ++i) {
        const double x = -1.1 + 0.45 * (i % 6), z = -1.0 + 0.5 * ((i / 6) % 4), y = 0.4 + 0.45 * (i / 24) + 0.05 * (i % 3);
        text += "DynamicObject, Name=b" + std::to_string(i) + ", Shape=Sphere, Radius=0.2, Mass=" +
                std::to_string(1 + i % 3) + ", Position=(" + std::to_string(x) + "," + std::to_string(y) + "," +
                std::to_string(z) + "), Velocity=(" + std::to_string(0.3 * (i % 5) - 0.6) + ",0," +
                std::to_string(0.2 * (i % 4) - 0.3) + "), AngularVelocity=(0," + std::to_string(i % 7) +
                ",0), Elasticity=0.6, Friction=0.5\n";
    }
    SECTION("walls at rest: every contact round, the packed substeps") {
        const FastPathCounts counts = requireSameOnBothRoads(sceneFrom(text), 90);
        INFO(counts.packedSteps << " of " << counts.steps << " steps on the packed records");
        CHECK(counts.steps == 90);
        CHECK(counts.packedSteps == 90);  // no contact has stored rows: every step can be packed
    }
    SECTION("a paddle moving through the balls: its contacts keep stored rows, with its surface speed") {
        text += "KinematicsObject, Name=paddle, Shape=Box, Position=(-1.2,0.3,0), Scale=(0.1,0.6,2.5), Velocity=(0.8,0,0)\n";
        const FastPathCounts counts = requireSameOnBothRoads(sceneFrom(text), 90);
        CHECK(counts.steps == 90);
        CHECK(counts.packedSteps < counts.steps);  // the paddle's contacts keep those steps on the objects
    }
}

TEST_CASE("A ball's contact with a kinematic body is round while the body is at rest, stored while it moves", "[fast][solver]") {
    // Two balls resting on two kinematic slabs, one at rest and one sliding along x at 0.5 m/s.
    Scene scene = test::emptyScene();
    scene.kinematics.push_back(test::kinematicBox("still", Vec3(0, -0.5, 0), Vec3(2, 1, 2)));
    scene.kinematics.push_back(test::kinematicBox("belt", Vec3(5, -0.5, 0), Vec3(2, 1, 2), Vec3(0.5, 0, 0)));
    scene.dynamics.push_back(test::sphere("on_still", Vec3(0, 0.5, 0)));
    scene.dynamics.push_back(test::sphere("on_belt", Vec3(5, 0.5, 0)));
    World world(scene);
    world.step();
    const std::vector<SolverContact>& contacts = world.solverContacts();
    const std::vector<ContactStart>& starts = world.solverContactStarts();
    REQUIRE(contacts.size() == 2);
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        INFO(world.kinematics()[starts[i].refB.index].name);
        REQUIRE(starts[i].refB.kind == BodyKind::Kinematic);
        const bool moving = starts[i].refB.index == 1;
        CHECK((contacts[i].rows == kRoundContact) == !moving);
        CHECK(contacts[i].bodyB == kStaticSolverBody);
        // rB is still the lever from the slab's centre (the trace shows it), 0.5 m above the centre.
        CHECK(starts[i].rB.y == Approx(0.5).margin(kSpeculativeDistance));
    }
    // The belt still drags its ball, through its surface speed. The friction impulse J that makes
    // the ball roll on the belt (its lowest point at the belt's speed u: v + ω r = u, ω about z)
    // gives Δv = J/m and Δ(ω r) = 5J/(2m) (I = 2/5 m r²), so from rest v ends at (2/7)·u: 0.143 m/s.
    // Within 1 %: once rolling, nothing but rounding changes it.
    for (int step = 0; step < 60; ++step) world.step();
    const DynamicObject& onBelt = world.dynamics()[1];
    CHECK(onBelt.velocity.x == Approx(Real(2) / 7 * Real(0.5)).epsilon(0.01));
    const DynamicObject& onStill = world.dynamics()[0];
    CHECK(std::abs(onStill.velocity.x) < Real(1e-9));  // nothing pushes it sideways: it stays put
}

TEST_CASE("Boxes and balls on a conveyor belt take the fast path with the plain numbers", "[fast][lanes][regions][conveyor]") {
    // A belt's contacts keep stored rows whose tangent surface speeds carry the belt (src/forces/conveyor.hpp):
    // the lanes read those numbers as the plain passes do, to the bit.
    SECTION("boxes and balls carried off the end of a belt over a still bed, onto the floor") {
        std::string text = "World, Duration=2, Sleep=false\n"
                           "CollisionPlane, Name=floor, Position=(0,0,0), Normal=(0,1,0)\n"
                           "KinematicsObject, Name=bed, Shape=Box, Position=(0,0.25,0), Scale=(3,0.5,3)\n"
                           "Region, Name=belt, Shape=Box, Position=(0,1.5,0), Scale=(3,2,3), Effect=Conveyor, "
                           "Velocity=(1.2,0.5,0.3)\n";
        text += boxesAndBallsOnADeck();
        const FastPathCounts counts = requireSameOnBothRoads(sceneFrom(text), 120);
        CHECK(counts.steps == 120);
        INFO(counts.boxLaneSteps << " steps with box lanes");
        CHECK(counts.boxLaneSteps > 0);
    }
    SECTION("a rain of balls, half of them onto a belt: its contacts keep the steps off the packed records") {
        std::string text = "World, Duration=2, Sleep=false\n"
                           "CollisionPlane, Name=floor, Position=(0,0,0), Normal=(0,1,0)\n"
                           "Region, Name=belt, Shape=Box, Position=(-1,1,0), Scale=(2,2,4), Effect=Conveyor, Velocity=(0,0,-0.8)\n";
        for (int i = 0; i < 24; ++i) {
            const double x = -1.8 + 0.6 * (i % 6), z = -0.9 + 0.6 * ((i / 6) % 4), y = 0.25 + 0.1 * (i % 3);
            text += "DynamicObject, Name=b" + std::to_string(i) + ", Shape=Sphere, Radius=0.2, Mass=" +
                    std::to_string(1 + i % 3) + ", Position=(" + std::to_string(x) + "," + std::to_string(y) + "," +
                    std::to_string(z) + "), Elasticity=0.3, Friction=0.6\n";
        }
        const FastPathCounts counts = requireSameOnBothRoads(sceneFrom(text), 90);
        CHECK(counts.steps == 90);
        CHECK(counts.packedSteps < counts.steps);  // a ball on the belt has stored rows: those steps run on the objects
    }
}
