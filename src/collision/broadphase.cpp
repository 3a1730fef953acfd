/// @file broadphase.cpp
/// @brief Stage 4 dispatcher: run the chosen broadphase, then put its pairs in the one canonical order.
///
/// Every broadphase but brute force works in three parts:
///
/// 1. the bounding boxes of all dynamic and kinematic bodies (the proxies),
///    computed once here, exactly as brute force computes them;
/// 2. the structure (sweep and prune, tree, grid or octree) finds the overlapping
///    pairs of proxies, in whatever order it meets them. Each structure only
///    *proposes* pairs; the final word is always the same exact test on the
///    same boxes as brute force (Aabb::overlaps), so the pair *set* is the same;
/// 3. here, the pairs are put in brute force's order, and the kinematic and
///    plane pairs are added: each dynamic body asks the static tree for the
///    kinematic bodies its box overlaps (StaticTree, broadphase_static.hpp),
///    and tests each plane.
///
/// The kinematic bodies are kept out of the structure of part 2: they never
/// pair with each other, and at rest they never move, so the structure holds
/// only bodies that can move, and a level of static boxes is queried as
/// planes are, never re-inserted.
///
/// The order matters because the impulse stage visits contacts in order, and
/// Gauss–Seidel results depend on it: the same pairs in another order would
/// give a (slightly) different trajectory. With the canonical order, the
/// trajectory is bit for bit the same whichever broadphase runs.
#include "collision/broadphase.hpp"

#include <algorithm>
#include <cstdio>

namespace stepwise {

BroadphaseChoice chooseBroadphase(const BodySet& bodies) {
    char text[256];
    const std::size_t dynamicCount = bodies.dynamics.size();
    if (dynamicCount < kAutoBruteForceBelow) {
        std::snprintf(text, sizeof text,
                      "%zu dynamic bodies, fewer than %zu: testing every pair costs less than keeping a structure",
                      dynamicCount, kAutoBruteForceBelow);
        return {BroadphaseKind::BruteForce, text};
    }
    // How different are the sizes? The grid's cells are sized from the median body. Only the
    // dynamic bodies count: the kinematic ones (a floor, walls) are in the static tree, not in the grid.
    std::vector<Real> sizes;
    sizes.reserve(dynamicCount);
    for (const DynamicObject& body : bodies.dynamics) sizes.push_back(broadphaseBounds(body).longestSide());
    const auto middle = sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2);
    std::nth_element(sizes.begin(), middle, sizes.end());
    const Real median = *middle;
    const auto oversize = static_cast<std::size_t>(
        std::count_if(sizes.begin(), sizes.end(), [&](Real size) { return size > kGridOversizeRatio * median; }));
    if (oversize <= kAutoGridMaxOversize && dynamicCount < kAutoSweepBelow) {
        std::snprintf(text, sizeof text,
                      "%zu bodies of similar size (%zu larger than %.3g x the median %.3g m), fewer than %zu: "
                      "sorting along one axis and sweeping is the fastest at this count",
                      sizes.size(), oversize, double(kGridOversizeRatio), double(median), kAutoSweepBelow);
        return {BroadphaseKind::SweepAndPrune, text};
    }
    if (oversize <= kAutoGridMaxOversize) {
        std::snprintf(text, sizeof text,
                      "%zu bodies of similar size (%zu larger than %.3g x the median %.3g m): a grid sized from "
                      "them costs the same per body at any count",
                      sizes.size(), oversize, double(kGridOversizeRatio), double(median));
        return {BroadphaseKind::Grid, text};
    }
    std::snprintf(text, sizeof text,
                  "%zu bodies of mixed sizes (%zu larger than %.3g x the median %.3g m, more than %zu): a grid "
                  "would test each of those against all, the AABB tree adapts to any sizes",
                  sizes.size(), oversize, double(kGridOversizeRatio), double(median), kAutoGridMaxOversize);
    return {BroadphaseKind::AabbTree, text};
}

void Broadphase::findPairs(BroadphaseKind kind, const BodySet& bodies, std::vector<CandidatePair>& pairs) {
    if (kind == BroadphaseKind::Auto) {
        if (!autoChosen_) {
            autoChoice_ = chooseBroadphase(bodies);  // once per World: the first step decides
            autoChosen_ = true;
        }
        kind = autoChoice_.kind;
    }
    lastKind_ = kind;
    counters_ = {};

    const auto dynamicCount = static_cast<std::uint32_t>(bodies.dynamics.size());
    lastDynamicCount_ = dynamicCount;
    if (kind == BroadphaseKind::BruteForce) {
        findPairsBruteForce(bodies, boxes_, pairs);
        const std::uint64_t n = dynamicCount;
        counters_.pairTests = n * (n - (n > 0 ? 1 : 0)) / 2 + n * bodies.kinematics.size() + n * bodies.planes.size();
        return;
    }

    // The structure holds the dynamic bodies only; the kinematic ones are in the static tree,
    // rebuilt only in a step where one of them moved (StaticTree::update()).
    boxes_.resize(bodies.dynamics.size());
    for (std::size_t i = 0; i < bodies.dynamics.size(); ++i) boxes_[i] = broadphaseBounds(bodies.dynamics[i]);
    staticBoxes_.resize(bodies.kinematics.size());
    for (std::size_t k = 0; k < bodies.kinematics.size(); ++k) staticBoxes_[k] = broadphaseBounds(bodies.kinematics[k]);
    staticTree_.update(staticBoxes_);
    const ProxySet proxies{boxes_, dynamicCount};
    rawPairs_.clear();
    switch (kind) {
        case BroadphaseKind::SweepAndPrune: sweepAndPrune_.findOverlaps(proxies, rawPairs_, counters_); break;
        case BroadphaseKind::AabbTree: tree_.findOverlaps(proxies, rawPairs_, counters_); break;
        case BroadphaseKind::Grid: grid_.findOverlaps(proxies, rawPairs_, counters_); break;
        case BroadphaseKind::Octree: octree_.findOverlaps(proxies, rawPairs_, counters_); break;
        case BroadphaseKind::Auto:
        case BroadphaseKind::BruteForce: break;  // handled above
    }
    sortIntoCanonicalOrder(bodies, pairs);
}

void Broadphase::dynamicBodiesOverlapping(const Aabb& box, std::vector<std::uint32_t>& out) const {
    out.clear();
    const std::uint32_t n = lastDynamicCount_;
    if (n == 0) return;  // also before the first call: nothing was filed
    const std::span<const Aabb> boxes(boxes_.data(), n);  // brute force keeps the kinematic boxes after them
    BroadphaseCounters counters;  // a query's work is not the step's: counters_ stays the last findPairs()'
    switch (lastKind_) {
        case BroadphaseKind::Auto:  // never stored: findPairs() resolves it
        case BroadphaseKind::BruteForce:
            for (std::uint32_t i = 0; i < n; ++i) {
                if (boxes[i].overlaps(box)) out.push_back(i);
            }
            return;  // found in index order
        case BroadphaseKind::SweepAndPrune: sweepAndPrune_.query(box, out, counters); break;
        case BroadphaseKind::AabbTree: tree_.query(box, boxes, out, counters); break;
        case BroadphaseKind::Grid: grid_.query(box, boxes, out, counters); break;
        case BroadphaseKind::Octree: octree_.query(box, boxes, out, counters); break;
    }
    std::sort(out.begin(), out.end());  // in place: no allocation
}

void Broadphase::sortIntoCanonicalOrder(const BodySet& bodies, std::vector<CandidatePair>& pairs) {
    const auto dynamicCount = static_cast<std::uint32_t>(bodies.dynamics.size());

    // Counting sort by body A, O(n + pairs): count each body's partners, take
    // running sums as the start of each body's run, then place the partners.
    pairStart_.assign(dynamicCount + 1, 0);
    for (const ProxyPair& pair : rawPairs_) ++pairStart_[pair.a + 1];
    for (std::uint32_t a = 0; a < dynamicCount; ++a) pairStart_[a + 1] += pairStart_[a];
    partners_.resize(rawPairs_.size());
    for (const ProxyPair& pair : rawPairs_) partners_[pairStart_[pair.a]++] = pair.b;
    // Placing moved each start to the end of its run, which is the next run's start.
    for (std::uint32_t a = dynamicCount; a > 0; --a) pairStart_[a] = pairStart_[a - 1];
    pairStart_[0] = 0;

    // Brute force's order for each A: dynamic partners by index, then kinematic
    // ones by index (the static tree's answer, which comes sorted), then the planes.
    pairs.clear();
    for (std::uint32_t a = 0; a < dynamicCount; ++a) {
        const auto first = partners_.begin() + pairStart_[a];
        const auto last = partners_.begin() + pairStart_[a + 1];
        std::sort(first, last);  // a body has a few partners: this is cheap, and sorts in place
        for (auto b = first; b != last; ++b) pairs.push_back({a, {BodyKind::Dynamic, *b}});
        staticHits_.clear();
        staticTree_.query(boxes_[a], staticHits_, counters_);
        for (const std::uint32_t k : staticHits_) pairs.push_back({a, {BodyKind::Kinematic, k}});
        for (std::uint32_t p = 0; p < bodies.planes.size(); ++p) {
            ++counters_.pairTests;
            if (aabbTouchesPlane(boxes_[a], bodies.planes[p])) pairs.push_back({a, {BodyKind::Plane, p}});
        }
    }
}

}  // namespace stepwise
