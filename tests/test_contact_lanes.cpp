// The round contacts solved four at a time (src/dynamics/round_contact_lanes.hpp).
// Tags: [solver], [lanes].
//
// Two claims: the waves make the lanes independent and keep each body's order
// (no wave holds two contacts of one dynamic body, each body meets its contacts
// in their order, every contact is solved exactly once), and so a pass in lanes
// is the plain scalar pass of contact_solver.cpp, one contact at a time in the
// contacts' order: the same velocities and impulses.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "collision/broadphase.hpp"
#include "collision/narrowphase.hpp"
#include "dynamics/contact_solver.hpp"
#include "objects/inertia.hpp"
#include "dynamics/round_contact_lanes.hpp"
#include "dynamics/softness.hpp"
#include "test_support.hpp"

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

        const BodySet bodies{dynamics, kinematics, planes};
        std::vector<CandidatePair> pairs;
        Broadphase().findPairs(BroadphaseKind::BruteForce, bodies, pairs);
        ThreadPool pool(1);
        NarrowphaseWorkspace workspace;
        findContacts(bodies, pairs, contacts, false, kSpeculativeDistance, pool, workspace);
    }
    BodySet bodies() { return {dynamics, kinematics, planes}; }
};

ContactSolverSettings substepSettings() {
    ContactSolverSettings settings;
    settings.substep = Real(1) / 960;
    settings.softness = makeSoftness(240, 1, settings.substep);
    return settings;
}

}  // namespace

TEST_CASE("Waves: no wave holds two contacts of one dynamic body, each body meets its contacts in order", "[solver][lanes]") {
    BallHeap heap;
    SolverWorkspace workspace;
    prepareContacts(heap.bodies(), heap.contacts, {}, Real(1) / 60, false, workspace);
    REQUIRE(workspace.contacts.size() > 100);  // a heap, not a handful

    std::vector<int> solved(workspace.contacts.size(), 0);
    std::vector<std::uint32_t> waveRecords;                                  // the dynamic records of the current wave
    std::vector<std::int64_t> lastContact(workspace.bodies.size(), -1);      // per record: its last contact solved so far
    for (std::size_t n = 0; n < workspace.roundBatches.size(); ++n) {
        const RoundBatch& batch = workspace.roundBatches[n];
        if (n > 0) CHECK(batch.wave >= workspace.roundBatches[n - 1].wave);  // wave by wave
        if (n == 0 || batch.wave != workspace.roundBatches[n - 1].wave) {
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
                CHECK(lastContact[record] < std::int64_t(index));  // the body's contacts in their order
                lastContact[record] = index;
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
    // Wide waves: the lanes are mostly full (each wave's last batch may not be).
    const std::size_t waves = workspace.roundBatches.back().wave + 1;
    CHECK(workspace.roundBatches.size() * kLanes < workspace.contacts.size() + waves * kLanes);
    CHECK(waves * 8 < workspace.contacts.size());
}

TEST_CASE("A pass in lanes is the scalar pass, four contacts at a time", "[solver][lanes]") {
    // The same contacts, solved once by the lanes and once one at a time by the scalar pass in
    // the contacts' own order (every contact listed in otherContacts, no batches): warm start, a
    // solve and a relax pass must leave the same velocities and impulses. Each lane rounds as a
    // scalar does and each body meets its contacts in the same order, so they agree to the last
    // bit in a build that does not target fused multiply-add (the default): whichever copy of the
    // lanes this processor runs (AVX-512, AVX2 or SSE2; round_contact_lanes.cpp is built with
    // -ffp-contract=off so that none fuses). A build for a processor with FMA (-march=native)
    // may fuse the scalar pass and not the lanes; it gets a tolerance of a billionth of the values.
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
    batchRoundContacts(lanes);
    REQUIRE(lanes.roundBatches.size() > 20);

    SolverWorkspace scalar = lanes;
    scalar.roundBatches.clear();
    scalar.otherContacts.clear();
    for (std::uint32_t i = 0; i < scalar.contacts.size(); ++i) scalar.otherContacts.push_back(i);

    for (SolverWorkspace* w : {&lanes, &scalar}) {
        recordPoses(heap.bodies(), *w);
        copyVelocitiesIn(*w);
        warmStartContacts(*w, true);
        solveContacts(*w, settings, true);
        solveContacts(*w, settings, false);
    }
    syncRoundContacts(lanes);

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

TEST_CASE("A relax pass leaves a ball contact's friction as the solve pass left it, unless told to solve it too", "[solver][lanes][friction]") {
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
    SolverWorkspace w;
    prepareContacts(heap.bodies(), heap.contacts, {}, Real(1) / 60, false, w);
    recordPoses(heap.bodies(), w);
    copyVelocitiesIn(w);
    solveContacts(w, settings, true);
    syncRoundContacts(w);
    const std::vector<SolverContact> afterSolve = w.contacts;
    solveContacts(w, settings, false);
    syncRoundContacts(w);

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

TEST_CASE("The solver's footprint counts what a pass reads: the body records and the batches", "[solver][lanes]") {
    CHECK(solverFootprint(SolverWorkspace{}).allBytes == 0);  // nothing prepared, nothing held

    BallHeap heap;
    SolverWorkspace workspace;
    prepareContacts(heap.bodies(), heap.contacts, {}, Real(1) / 60, false, workspace);
    recordPoses(heap.bodies(), workspace);
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
    const std::size_t batches = workspace.roundBatches.size();
    CHECK(batches * kLanes >= contacts);

    const SolverFootprint footprint = solverFootprint(workspace);
    CHECK(footprint.passBytes == records * (sizeof(SolverBody) + sizeof(SolverCentre)) + batches * sizeof(RoundBatch));
    // Everything else is on top: at least each contact's record and start
    CHECK(footprint.allBytes >= footprint.passBytes + contacts * (sizeof(SolverContact) + sizeof(ContactStart)));
}
