// The thread pool (src/core/thread_pool.cpp) and the threaded narrowphase:
// the same scene must give bit-identical contacts and trajectories with 1, 2
// or 4 threads.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstring>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "config/scene_generator.hpp"
#include "config/scene_loader.hpp"
#include "core/thread_pool.hpp"
#include "dynamics/contact_solver.hpp"
#include "fast/fast_path_counts.hpp"
#include "fast/parallel_records.hpp"
#include "objects/inertia.hpp"
#include "test_support.hpp"

using namespace stepwise;
using namespace stepwise::test;

namespace {

const std::string kSourceDir = STEPWISE_SOURCE_DIR;

/// Steps @p scene with @p threads and returns every body's final state, in order.
std::vector<DynamicObject> runWith(Scene scene, int threads, int steps, std::size_t* mostPairs = nullptr) {
    scene.settings.threads = threads;
    World world(std::move(scene));
    REQUIRE(world.threadCount() == static_cast<unsigned>(threads));
    for (int step = 0; step < steps; ++step) {
        world.step();
        if (mostPairs) *mostPairs = std::max(*mostPairs, world.candidatePairs().size());
    }
    return world.dynamics();
}

/// Every number of the state, compared with == (bit-identical, not approximately equal).
void requireIdentical(const std::vector<DynamicObject>& a, const std::vector<DynamicObject>& b) {
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        INFO("body " << a[i].name);
        REQUIRE(a[i].position == b[i].position);
        REQUIRE(a[i].velocity == b[i].velocity);
        REQUIRE(a[i].orientation == b[i].orientation);
        REQUIRE(a[i].angularMomentum == b[i].angularMomentum);
        REQUIRE(a[i].angularVelocity == b[i].angularVelocity);
    }
}

}  // namespace

TEST_CASE("The thread pool runs every chunk exactly once, job after job", "[threads]") {
    const unsigned threads = GENERATE(1u, 2u, 4u);
    ThreadPool pool(threads);
    REQUIRE(pool.threadCount() == threads);
    constexpr std::size_t kChunks = 1000;
    std::vector<std::atomic<int>> runs(kChunks);
    for (int job = 0; job < 50; ++job) {
        auto chunk = [&](std::size_t i) { runs[i].fetch_add(1, std::memory_order_relaxed); };
        pool.run(kChunks, chunk);
    }
    for (std::size_t i = 0; i < kChunks; ++i) REQUIRE(runs[i].load() == 50);
}

TEST_CASE("The thread pool hands over jobs in quick succession and after its workers fall asleep", "[threads]") {
    // Thousands of tiny jobs back to back meet the workers spinning; a pause longer than
    // kSpinBeforeSleep finds them asleep. Either way each chunk runs once per job, and what a
    // chunk wrote is visible when run() returns (the plain, non-atomic writes are read back).
    const unsigned threads = GENERATE(2u, 4u);
    ThreadPool pool(threads);
    constexpr std::size_t kChunks = 8;
    std::vector<long> written(kChunks, 0);
    long expected = 0;
    for (int job = 0; job < 5000; ++job) {
        auto chunk = [&](std::size_t i) { written[i] += job; };
        pool.run(kChunks, chunk);
        expected += job;
        if (job % 1000 == 999) std::this_thread::sleep_for(kSpinBeforeSleep * 5);  // let the workers sleep
    }
    for (std::size_t i = 0; i < kChunks; ++i) REQUIRE(written[i] == expected);
}

TEST_CASE("The thread pool never lets a late worker run a chunk of the next, larger job", "[threads]") {
    // A worker that finished the last chunk of a job may still be in its claim loop when run()
    // returns and the next job is published. Were it to read the new job's chunk count against
    // the old job's ticket, it could claim chunk c of the new job under the old ticket (c = the
    // old job's chunk count, within the new one's): that chunk would run twice, or run() would
    // return before it ended. So the jobs here grow and shrink (2 to 9 chunks), back to back,
    // twenty thousand of them, and after each run() every chunk must have run exactly once.
    const unsigned threads = GENERATE(2u, 4u);
    ThreadPool pool(threads);
    constexpr std::size_t kMostChunks = 9;
    std::array<std::atomic<int>, kMostChunks> runs{};
    constexpr int kJobs = 20000;
    int wellRun = 0;  // jobs whose chunks each ran once
    for (int job = 0; job < kJobs; ++job) {
        const std::size_t chunks = 2 + static_cast<std::size_t>(job % 8);
        for (std::atomic<int>& r : runs) r.store(0, std::memory_order_relaxed);
        auto chunk = [&](std::size_t i) { runs[i].fetch_add(1, std::memory_order_relaxed); };
        pool.run(chunks, chunk);
        for (std::size_t i = 0; i < kMostChunks; ++i) {
            const int expected = i < chunks ? 1 : 0;
            if (runs[i].load() != expected) {
                INFO("job " << job << " of " << chunks << " chunks, " << threads << " threads: chunk " << i);
                REQUIRE(runs[i].load() == expected);
            }
        }
        ++wellRun;
    }
    REQUIRE(wellRun == kJobs);
}

TEST_CASE("Threads=0 means one thread per hardware thread", "[threads]") {
    Scene scene = emptyScene();
    scene.settings.threads = kAutoThreads;
    World world(std::move(scene));
    CHECK(world.threadCount() == autoThreadCount());
    CHECK(world.threadCount() >= 1);
}

TEST_CASE("The threaded narrowphase gives the one-thread contact list, bit for bit", "[threads]") {
    // 800 falling spheres after 30 steps, landing in a heap: about 6000 candidate pairs, twelve chunks.
    GeneratorOptions options;
    options.scene = GeneratedScene::SphereRain;
    options.count = 800;
    Scene scene = parseScene(generateSceneText(options), "sphere-rain");
    scene.settings.threads = 1;
    World world(std::move(scene));
    for (int step = 0; step < 30; ++step) world.step();
    const std::vector<CandidatePair>& pairs = world.candidatePairs();
    REQUIRE(pairs.size() > 4 * kPairsPerChunk);  // several chunks, or the test proves nothing

    std::vector<Contact> serial;
    const BodySet bodies{world.dynamics(), world.kinematics(), world.planes()};
    findContacts(bodies, pairs, serial);
    for (unsigned threads : {1u, 2u, 4u}) {
        INFO(threads << " threads");
        ThreadPool pool(threads);
        NarrowphaseWorkspace workspace;
        std::vector<Contact> threaded;
        for (int repeat = 0; repeat < 3; ++repeat) {  // reused workspace, as from step to step
            findContacts(bodies, pairs, threaded, false, 0, pool, workspace);
            REQUIRE(threaded.size() == serial.size());
            for (std::size_t i = 0; i < serial.size(); ++i) {
                REQUIRE(threaded[i].a == serial[i].a);
                REQUIRE(threaded[i].b.kind == serial[i].b.kind);
                REQUIRE(threaded[i].b.index == serial[i].b.index);
                REQUIRE(threaded[i].normal == serial[i].normal);
                REQUIRE(threaded[i].point == serial[i].point);
                REQUIRE(threaded[i].depth == serial[i].depth);
                REQUIRE(threaded[i].featureId == serial[i].featureId);
            }
        }
    }
}

TEST_CASE("A sphere pile runs bit-identically with 1, 2 and 4 threads", "[threads]") {
    // 800 spheres falling into a heap for 45 steps: thousands of pairs, and fast
    // spheres stopped by continuous collision as they land (both stages in play).
    GeneratorOptions options;
    options.scene = GeneratedScene::SphereRain;
    options.count = 800;
    const Scene scene = parseScene(generateSceneText(options), "sphere-rain");
    std::size_t mostPairs = 0;
    const std::vector<DynamicObject> one = runWith(scene, 1, 45, &mostPairs);
    REQUIRE(mostPairs > 4 * kPairsPerChunk);  // the threaded path really ran
    requireIdentical(one, runWith(scene, 2, 45));
    requireIdentical(one, runWith(scene, 4, 45));
}

TEST_CASE("The 210-box pyramid runs bit-identically with 1, 2 and 4 threads", "[threads]") {
    const Scene scene = loadSceneFile(kSourceDir + "/config/lesson08_pyramid.scene");
    std::size_t mostPairs = 0;
    const std::vector<DynamicObject> one = runWith(scene, 1, 30, &mostPairs);
    REQUIRE(mostPairs > kPairsPerChunk);
    requireIdentical(one, runWith(scene, 2, 30));
    requireIdentical(one, runWith(scene, 4, 30));
}

TEST_CASE("The fast path's contact passes run bit-identically with 1, 2 and 4 threads", "[threads][fast]") {
    // 1200 balls heaped for 60 steps: waves of hundreds of contacts, which the threads split
    // between them (parallel_waves.hpp). Each piece of a wave touches bodies no other piece
    // touches, so the velocities, and the whole trajectory, must be one thread's to the bit.
    GeneratorOptions options;
    options.scene = GeneratedScene::SphereRain;
    options.count = 1200;
    Scene scene = parseScene(generateSceneText(options), "sphere-rain");
    scene.settings.fastPath = true;  // the debug build's default is the plain path
    const auto run = [&](int threads, std::uint64_t* splitWaves) {
        Scene copy = scene;
        copy.settings.threads = threads;
        World world(std::move(copy));
        for (int step = 0; step < 60; ++step) world.step();
        *splitWaves = world.fastPathCounts().splitWaves;
        REQUIRE(world.fastPathCounts().steps > 0);
        return world.dynamics();
    };
    std::uint64_t split = 0;
    const std::vector<DynamicObject> one = run(1, &split);
    REQUIRE(split == 0);  // one thread never splits a wave
    for (const int threads : {2, 4}) {
        INFO(threads << " threads");
        requireIdentical(one, run(threads, &split));
        REQUIRE(split > 0);  // the split really ran
    }
}

TEST_CASE("The per-record stages cover every record once, in ranges that start where the drift groups", "[threads][fast]") {
    // forRecordRanges() hands out [1, records): each record exactly once, every range starting
    // at 1 + 8k (the drift's groups of eight), and the probes summed from every range.
    const unsigned threads = GENERATE(1u, 2u, 4u);
    ThreadPool pool(threads);
    // 4098 records: 4097 to share out, one more than four ranges of 1024 hold
    for (const std::size_t records :
         {std::size_t(10), kParallelRecords - 1, kParallelRecords, std::size_t(4098), std::size_t(10007)}) {
        INFO(records << " records, " << threads << " threads");
        std::vector<int> visits(records, 0);
        std::atomic<int> badStarts{0};
        const Real sum = forRecordRanges(pool, records, [&](std::size_t first, std::size_t end) {
            if ((first - 1) % kRecordRangeAlignment != 0) badStarts.fetch_add(1);
            for (std::size_t i = first; i < end; ++i) visits[i] += 1;
            return Real(end - first);  // a probe that counts the records it saw
        });
        REQUIRE(visits[0] == 0);  // record 0 is the static one: never visited
        for (std::size_t i = 1; i < records; ++i) REQUIRE(visits[i] == 1);
        REQUIRE(badStarts.load() == 0);
        REQUIRE(sum == Real(records - 1));
    }
}

TEST_CASE("Free flight on the objects covers every body once, in ranges", "[threads][fast]") {
    // forBodyRanges() hands out [0, bodies): each body exactly once, the probes summed.
    const unsigned threads = GENERATE(1u, 2u, 4u);
    ThreadPool pool(threads);
    for (const std::size_t bodies : {std::size_t(3), kParallelBodies - 1, kParallelBodies, std::size_t(1025), std::size_t(5003)}) {
        INFO(bodies << " bodies, " << threads << " threads");
        std::vector<int> visits(bodies, 0);
        const Real sum = forBodyRanges(pool, bodies, [&](std::size_t first, std::size_t end) {
            for (std::size_t i = first; i < end; ++i) visits[i] += 1;
            return Real(end - first);
        });
        for (std::size_t i = 0; i < bodies; ++i) REQUIRE(visits[i] == 1);
        REQUIRE(sum == Real(bodies));
    }
}

TEST_CASE("Boxes on a floor, their contacts in lanes, run bit-identically with 1, 2 and 4 threads", "[threads][fast]") {
    // 400 boxes, slightly turned, dropped on a floor: the k-th point of every box's manifold falls
    // in one wave (contact_waves.hpp), 400 contacts, wide enough to be split between threads.
    std::string text = "World, TimeStep=1/60, Sleep=false, FastPath=true\nCollisionPlane, 0, 0, 0, 0, 1, 0, Name=floor\n";
    for (int i = 0; i < 20; ++i) {
        for (int j = 0; j < 20; ++j) {
            text += "DynamicObject, Shape=Box, Name=b" + std::to_string(20 * i + j) + ", Position=(" +
                    std::to_string(1.5 * i) + ", " + std::to_string(0.52 + 0.01 * ((i * 7 + j * 3) % 5)) + ", " +
                    std::to_string(1.5 * j) + "), Rotation=(2, 3, 1), Scale=(1, 1, 1), Mass=1\n";
        }
    }
    const Scene scene = parseScene(text, "boxes-on-a-floor");
    const auto run = [&](int threads, std::uint64_t* splitWaves) {
        Scene copy = scene;
        copy.settings.threads = threads;
        World world(std::move(copy));
        for (int step = 0; step < 40; ++step) world.step();
        *splitWaves = world.fastPathCounts().splitWaves;
        REQUIRE(world.fastPathCounts().boxLaneSteps > 0);
        return world.dynamics();
    };
    std::uint64_t split = 0;
    const std::vector<DynamicObject> one = run(1, &split);
    for (const int threads : {2, 4}) {
        INFO(threads << " threads");
        requireIdentical(one, run(threads, &split));
        REQUIRE(split > 0);  // the split really ran
    }
}

TEST_CASE("Contacts prepared in ranges on 2 and 4 threads are the one-thread constraints, bit for bit", "[threads][solver]") {
    // The 1k box pile once it has landed: thousands of contacts, boxes (stored rows, turning
    // anchors) and their walls, warm-started from the step before. Each range keeps its rows and
    // anchors apart and they are joined in range order (prepareContacts()): every number and every
    // index into the side arrays must be the one-thread one.
    World world(loadSceneFile(std::string(STEPWISE_SOURCE_DIR) + "/config/bench_box_pile_1k.scene"));
    for (int step = 0; step < 150; ++step) world.step();
    std::vector<DynamicObject> dynamics = world.dynamics();
    const BodySet bodies{dynamics, world.kinematics(), world.planes()};
    const std::vector<Contact>& contacts = world.contacts();
    REQUIRE(contacts.size() >= 2 * kParallelPrepareContacts);  // enough for the ranges to run
    auto prepare = [&](unsigned threads) {
        ThreadPool pool(threads);
        SolverWorkspace w;
        // Last step's impulses, so that the warm-start lookups run too: each contact's key with an impulse
        for (const Contact& contact : contacts) {
            CachedImpulse entry;
            entry.key = keyOf(contact);
            entry.normalImpulse = Real(0.001) * Real(contact.featureId % 7 + 1);
            entry.frictionImpulse = Vec3(0.0002, 0, 0.0001);
            w.previousImpulses.push_back(entry);
        }
        std::sort(w.previousImpulses.begin(), w.previousImpulses.end(),
                  [](const CachedImpulse& x, const CachedImpulse& y) { return x.key < y.key; });
        prepareContacts(bodies, contacts, {}, Real(1) / 60, true, w, &pool);
        return w;
    };
    const SolverWorkspace one = prepare(1);
    REQUIRE(!one.rows.empty());
    REQUIRE(!one.turningAnchors.empty());
    for (const unsigned threads : {2u, 4u}) {
        INFO(threads << " threads");
        const SolverWorkspace many = prepare(threads);
        REQUIRE(many.contacts.size() == one.contacts.size());
        REQUIRE(std::memcmp(many.contacts.data(), one.contacts.data(), one.contacts.size() * sizeof(SolverContact)) == 0);
        REQUIRE(many.rows.size() == one.rows.size());
        REQUIRE(std::memcmp(many.rows.data(), one.rows.data(), one.rows.size() * sizeof(ContactRows)) == 0);
        REQUIRE(many.turningAnchors.size() == one.turningAnchors.size());
        REQUIRE(std::memcmp(many.turningAnchors.data(), one.turningAnchors.data(),
                            one.turningAnchors.size() * sizeof(TurningAnchors)) == 0);
        REQUIRE(many.roundContacts == one.roundContacts);
        REQUIRE(many.otherContacts == one.otherContacts);
        REQUIRE(many.bouncing == one.bouncing);
    }
}

TEST_CASE("Restitution's passes on 2 and 4 threads give the one-thread velocities, bit for bit", "[threads][restitution]") {
    // A block of 20 × 20 × 20 balls (e = 0.5), each overlapping its neighbours by 5 mm and moving
    // at a velocity of its own, in no gravity: every contact is an impact or a touch, none carries a
    // load, so all some 22800 take part in the compression (every one marked as having pushed, as the
    // substeps would). The balls sit in the array in a shuffled order, as a rain's come to lie, so
    // that the contacts found (pair by pair) fall in a few wide waves. With 1 thread the passes run in
    // the order found; with 2 and 4 they run wave by wave, each wide wave in ranges on the threads
    // (applyRestitution()). Every record's velocity must be the one-thread one, bit for bit.
    constexpr int kSide = 20;
    std::vector<int> site(kSide * kSide * kSide);
    for (std::size_t i = 0; i < site.size(); ++i) site[i] = static_cast<int>(i);
    std::mt19937 random(7);
    std::shuffle(site.begin(), site.end(), random);
    std::uniform_real_distribution<Real> speed(-2, 2);
    std::vector<DynamicObject> balls;
    for (const int s : site) {
        const Vec3 position = Real(0.995) * Vec3(s % kSide, (s / kSide) % kSide, s / (kSide * kSide));
        balls.push_back(sphere("b" + std::to_string(s), position, Vec3(speed(random), speed(random), speed(random))));
        initialiseMassProperties(balls.back());
    }
    const BodySet bodies{balls, {}, {}};
    const std::vector<Contact> contacts = contactsOf(bodies);
    REQUIRE(contacts.size() >= 3 * kParallelRestitution);
    auto bounce = [&](ThreadPool* pool, std::size_t* widestWave) {
        SolverWorkspace w;
        prepareContacts(bodies, contacts, {}, Real(1) / 60, false, w);
        for (SolverContact& c : w.contacts) c.maxNormalImpulse = Real(0.01);  // pushed in the substeps
        const std::vector<SolverBody> before = w.bodies;
        REQUIRE(applyRestitution(w, pool));
        REQUIRE(std::memcmp(before.data(), w.bodies.data(), before.size() * sizeof(SolverBody)) != 0);
        REQUIRE(w.pressed.size() >= kParallelRestitution);
        *widestWave = 0;
        const ContactWaveSchedule& waves = w.pressedWaves;
        for (std::uint32_t wave = 0; wave < waves.waves; ++wave)
            *widestWave = std::max<std::size_t>(*widestWave, waves.ends[wave] - (wave == 0 ? 0 : waves.ends[wave - 1]));
        return w;
    };
    std::size_t widest = 0;
    const SolverWorkspace alone = bounce(nullptr, &widest);
    for (const unsigned threads : {1u, 2u, 4u}) {
        INFO(threads << " threads");
        ThreadPool pool(threads);
        const SolverWorkspace many = bounce(&pool, &widest);
        if (threads > 1) REQUIRE(widest >= kParallelRestitutionWave);  // the ranges really ran
        REQUIRE(many.bodies.size() == alone.bodies.size());
        for (std::size_t i = 0; i < alone.bodies.size(); ++i) {
            INFO("record " << i);
            REQUIRE(many.bodies[i].velocity == alone.bodies[i].velocity);
            REQUIRE(many.bodies[i].angularVelocity == alone.bodies[i].angularVelocity);
        }
        for (std::size_t i = 0; i < alone.contacts.size(); ++i) {
            REQUIRE(many.contacts[i].normalImpulse == alone.contacts[i].normalImpulse);
            REQUIRE(many.starts[i].compression == alone.starts[i].compression);
        }
    }
}
