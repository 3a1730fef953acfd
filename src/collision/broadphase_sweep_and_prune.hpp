/// @file broadphase_sweep_and_prune.hpp
/// @brief Broadphase by sorting the boxes along one axis and sweeping (sort and sweep).
#pragma once

#include <vector>

#include "collision/broadphase_proxies.hpp"

namespace stepwise {

/// @brief Sweep and prune along the axis of greatest spread (Ericson, RTCD §7.5.2; Baraff 1992 §5.1).
///
/// Project every box onto one axis as the interval [min, max]. Two boxes can
/// only overlap if their intervals do, so with the boxes sorted by min, the
/// partners of box i are the boxes j after it whose min is ≤ max_i: the sweep
/// walks forward from i and stops at the first j that starts beyond i's end.
/// Each step:
///
/// 1. pick the axis along which the box centres are most spread out (largest
///    variance σ² = E[c²] − E[c]²), so as few intervals as possible overlap;
///    keep the current axis unless another is kAxisSwitchRatio times better;
/// 2. re-sort by min. Bodies move little in one step, so last step's order
///    is almost right and an insertion sort costs O(n + swaps): this *time
///    coherence* is what makes sweep and prune fast. A new axis, or a new
///    body count, sorts from scratch (O(n log n));
/// 3. sweep, testing the full box of every pair whose intervals overlap.
///
/// Cost: O(n + k) per step for n bodies and k interval overlaps, when bodies
/// are spread along the axis; it degrades towards O(n²) when they are stacked
/// across it (a tall tower sorted along x: every interval overlaps).
class SweepAndPrune {
public:
    /// @brief Appends every overlapping pair of proxies (not kinematic–kinematic) to @p pairs, in sweep order.
    void findOverlaps(const ProxySet& proxies, std::vector<ProxyPair>& pairs, BroadphaseCounters& counters);

    /// @brief The axis sorted along in the last call: 0 = x, 1 = y, 2 = z (−1 before the first call).
    int axis() const { return axis_; }

    /// @brief Appends to @p hits every proxy of the last call whose box overlaps @p box, in sort order.
    ///
    /// The sorted axis answers it: a proxy can overlap only if its min lies in
    /// [box.min − w, box.max] along the axis, w the widest proxy along it (its
    /// max is at most min + w), so a binary search finds the first candidate
    /// and the walk stops at the first min beyond box.max: O(log n + m) for m
    /// candidates, as many as a sweep interval of that length crosses.
    void query(const Aabb& box, std::vector<std::uint32_t>& hits, BroadphaseCounters& counters) const;

private:
    /// One box in sort order. The whole box is copied here so the sweep
    /// reads one contiguous array instead of jumping around the proxies.
    struct Entry {
        Aabb box;                  ///< The proxy's box this step.
        std::uint32_t proxy = 0;   ///< Which proxy.
    };

    void chooseAxis(const ProxySet& proxies);

    std::vector<Entry> sorted_;  ///< Every proxy, sorted by box.min[axis_].
    int axis_ = -1;              ///< Sort axis, or −1 before the first call.
    Real widest_ = 0;            ///< Widest box along the sort axis in the last call, m (for query()).
};

/// A new sort axis must spread the centres this many times more (in variance)
/// than the current one before the sweep switches: without the margin, two
/// nearly equal axes would swap every step and each swap costs a full sort.
inline constexpr Real kAxisSwitchRatio = Real(1.5);

}  // namespace stepwise
