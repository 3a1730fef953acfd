// No allocation in a running broadphase: every global operator new is
// counted while the broadphases run on a scene that moves back and forth.
// Tag: [broadphase]. Not under AddressSanitizer, which must keep its own
// operator new to track memory.
#include <catch2/catch.hpp>

#if !defined(__SANITIZE_ADDRESS__)

#include <atomic>
#include <cstdlib>
#include <new>

#include "allocation_counter.hpp"
#include "collision/broadphase.hpp"
#include "test_support.hpp"

// The one replacement of operator new in the test program; tests/allocation_counter.hpp shares its counters.
namespace stepwise::test {
std::atomic<bool> gCounting{false};
std::atomic<std::size_t> gAllocations{0};
}  // namespace stepwise::test
using stepwise::test::gAllocations;
using stepwise::test::gCounting;

void* operator new(std::size_t size) {
    if (gCounting.load(std::memory_order_relaxed)) gAllocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace stepwise;

TEST_CASE("A broadphase allocates nothing once its arrays have grown", "[broadphase]") {
    // Two configurations far apart: switching between them makes the tree
    // reinsert every leaf, the sweep re-sort, the grid rebuild. After one
    // round trip every array has its largest size; later ones must not allocate.
    std::vector<DynamicObject> first, second;
    for (int i = 0; i < 400; ++i) {
        const Real x = Real(0.7) * Real(i % 20), z = Real(0.7) * Real(i / 20);
        first.push_back(test::sphere("s" + std::to_string(i), Vec3(x, 0.5, z), Vec3(0), 0.4));
        second.push_back(test::sphere("s" + std::to_string(i), Vec3(z, 3.5, x), Vec3(0), 0.4));
    }
    std::vector<DynamicObject> bodies = first;
    std::vector<KinematicsObject> kinematics{test::kinematicBox("paddle", Vec3(3, 1, 3), Vec3(2, 0.5, 2))};
    std::vector<CollisionPlane> planes{test::ground()};
    const BodySet view{bodies, kinematics, planes};

    for (const BroadphaseKind kind : {BroadphaseKind::BruteForce, BroadphaseKind::SweepAndPrune,
                                      BroadphaseKind::AabbTree, BroadphaseKind::Grid, BroadphaseKind::Octree}) {
        INFO(toString(kind));
        Broadphase broadphase;
        std::vector<CandidatePair> pairs;
        for (int round = 0; round < 2; ++round) {  // warm up: arrays grow here
            bodies = first;
            broadphase.findPairs(kind, view, pairs);
            bodies = second;
            broadphase.findPairs(kind, view, pairs);
        }
        gAllocations = 0;
        for (int round = 0; round < 5; ++round) {
            std::copy(first.begin(), first.end(), bodies.begin());  // copies into existing strings: no allocation
            gCounting = true;
            broadphase.findPairs(kind, view, pairs);
            gCounting = false;
            std::copy(second.begin(), second.end(), bodies.begin());
            gCounting = true;
            broadphase.findPairs(kind, view, pairs);
            gCounting = false;
        }
        CHECK(gAllocations == 0);
        CHECK(!pairs.empty());

        // Region queries through the structure, into an array that has grown to the answer's size.
        std::vector<std::uint32_t> inside;
        inside.reserve(bodies.size());
        const Aabb regions[] = {{Vec3(2, 0, 2), Vec3(5, 1, 5)}, {Vec3(-1e9), Vec3(1e9)}, {Vec3(50), Vec3(60)}};
        gAllocations = 0;
        gCounting = true;
        for (const Aabb& region : regions) broadphase.dynamicBodiesOverlapping(region, inside);
        gCounting = false;
        CHECK(gAllocations == 0);
        CHECK(inside.empty());  // the last region is far from every body
    }
}

#endif
