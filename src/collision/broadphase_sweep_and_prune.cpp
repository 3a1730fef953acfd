/// @file broadphase_sweep_and_prune.cpp
/// @brief Stage 4, sweep and prune: sort the boxes along one axis, then sweep for overlapping intervals.
#include "collision/broadphase_sweep_and_prune.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/insertion_sort.hpp"

namespace stepwise {

void SweepAndPrune::chooseAxis(const ProxySet& proxies) {
    // Variance of the box centres along each axis, σ² = E[c²] − E[c]².
    Vec3 sum(0), sumOfSquares(0);
    for (const Aabb& box : proxies.boxes) {
        const Vec3 c = box.centre();
        sum += c;
        sumOfSquares += c * c;
    }
    const Real n = Real(proxies.size());
    const Vec3 mean = sum / n;
    const Vec3 variance = sumOfSquares / n - mean * mean;

    int best = 0;
    for (int i = 1; i < 3; ++i) {
        if (variance[i] > variance[best]) best = i;
    }
    if (axis_ < 0 || variance[best] > kAxisSwitchRatio * variance[axis_]) axis_ = best;
}

void SweepAndPrune::findOverlaps(const ProxySet& proxies, std::vector<ProxyPair>& pairs, BroadphaseCounters& counters) {
    const std::uint32_t n = proxies.size();
    if (n == 0) {
        sorted_.clear();  // nothing for query() to find
        return;
    }
    const int previousAxis = axis_;
    chooseAxis(proxies);
    const int axis = axis_;
    const auto byMin = [axis](const Entry& p, const Entry& q) { return p.box.min[axis] < q.box.min[axis]; };

    if (sorted_.size() != n || axis != previousAxis) {
        // Nothing to be coherent with: sort from scratch (std::sort sorts in place, no allocation).
        sorted_.resize(n);
        for (std::uint32_t i = 0; i < n; ++i) sorted_[i] = {proxies.boxes[i], i};
        std::sort(sorted_.begin(), sorted_.end(), byMin);
    } else {
        // Refresh the boxes in last step's order, then insertion sort: each
        // entry moves left past the entries it has overtaken, usually none.
        for (Entry& entry : sorted_) entry.box = proxies.boxes[entry.proxy];
        insertionSort(std::span<Entry>(sorted_), byMin);
    }

    widest_ = 0;
    for (const Entry& entry : sorted_) widest_ = std::max(widest_, entry.box.max[axis] - entry.box.min[axis]);

    // The sweep: i's partners are the entries after it that start before i ends.
    // Along the sweep axis such a partner overlaps i already (it starts after i
    // starts, sorted by min, and before i ends), so only the two other axes are
    // tested: four comparisons combined with & (no early exit, whose branches the
    // processor could not predict), and the count kept in a register.
    const int u = (axis + 1) % 3;
    const int w = (axis + 2) % 3;
    std::uint64_t tests = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const Entry& first = sorted_[i];
        const Aabb& a = first.box;
        const Real end = a.max[axis];
        const bool firstKinematic = proxies.isKinematic(first.proxy);
        for (std::uint32_t j = i + 1; j < n && sorted_[j].box.min[axis] <= end; ++j) {
            const Entry& second = sorted_[j];
            if (firstKinematic && proxies.isKinematic(second.proxy)) continue;  // neither can be pushed
            ++tests;
            const Aabb& b = second.box;
            // The four comparisons as 0 or 1, and'ed: all four made, one branch instead of four.
            const int overlaps = int(a.min[u] <= b.max[u]) & int(b.min[u] <= a.max[u]) & int(a.min[w] <= b.max[w]) &
                                 int(b.min[w] <= a.max[w]);
            if (overlaps != 0) pairs.push_back(orderedPair(first.proxy, second.proxy));
        }
    }
    counters.pairTests += tests;
}

void SweepAndPrune::query(const Aabb& box, std::vector<std::uint32_t>& hits, BroadphaseCounters& counters) const {
    if (sorted_.empty()) return;
    const int axis = axis_;
    // A min below box.min − widest_ leaves that box's max short of box.min. The widths were
    // rounded when they were measured, so the bound is lowered by a few units of rounding:
    // one more candidate costs a box test, a lost one a wrong answer.
    const Real slack = 4 * std::numeric_limits<Real>::epsilon() * (std::abs(box.min[axis]) + widest_);
    const Real lowest = box.min[axis] - widest_ - slack;
    const auto first = std::partition_point(sorted_.begin(), sorted_.end(),
                                            [&](const Entry& entry) { return entry.box.min[axis] < lowest; });
    for (auto entry = first; entry != sorted_.end() && entry->box.min[axis] <= box.max[axis]; ++entry) {
        ++counters.pairTests;
        if (entry->box.overlaps(box)) hits.push_back(entry->proxy);
    }
}

}  // namespace stepwise
