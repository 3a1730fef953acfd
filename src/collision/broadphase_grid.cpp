/// @file broadphase_grid.cpp
/// @brief Stage 4, uniform grid: cells sized from the bodies, a hash table filled by counting sort.
#include "collision/broadphase_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace stepwise {

namespace {

/// Large primes of the spatial hash of Teschner et al. (2003): each
/// coordinate is scrambled by one, and the three are combined by XOR.
constexpr std::uint64_t kHashPrimeX = 73856093u;
constexpr std::uint64_t kHashPrimeY = 19349663u;
constexpr std::uint64_t kHashPrimeZ = 83492791u;
/// 2⁶⁴/φ: multiplying by it and keeping the top bits spreads nearby keys
/// over the whole table (Knuth's multiplicative "Fibonacci" hashing, TAOCP §6.4).
constexpr std::uint64_t kFibonacciMultiplier = 0x9E3779B97F4A7C15ull;

std::int32_t cellIndex(Real coordinate, Real cellSize) {
    const Real index = std::floor(coordinate / cellSize);
    return static_cast<std::int32_t>(std::clamp(index, -kGridMaxCellIndex, kGridMaxCellIndex));
}

}  // namespace

UniformGrid::Cell UniformGrid::cellOf(const Vec3& point) const {
    return {cellIndex(point.x, cellSize_), cellIndex(point.y, cellSize_), cellIndex(point.z, cellSize_)};
}

std::size_t UniformGrid::bucketOf(const Cell& cell) const {
    const std::uint64_t key = (static_cast<std::uint64_t>(cell.x) * kHashPrimeX) ^
                              (static_cast<std::uint64_t>(cell.y) * kHashPrimeY) ^
                              (static_cast<std::uint64_t>(cell.z) * kHashPrimeZ);
    return static_cast<std::size_t>((key * kFibonacciMultiplier) >> (64 - bucketBits_));
}

void UniformGrid::chooseCellSize(const ProxySet& proxies) {
    // The median size, not the mean: one huge body (a floor box) must not
    // make the cells huge for everyone else; it becomes oversize instead.
    sizes_.resize(proxies.size());
    for (std::uint32_t p = 0; p < proxies.size(); ++p) sizes_[p] = proxies.boxes[p].longestSide();
    const auto middle = sizes_.begin() + static_cast<std::ptrdiff_t>(sizes_.size() / 2);
    std::nth_element(sizes_.begin(), middle, sizes_.end());
    oversizeLimit_ = kGridOversizeRatio * *middle;
    // The cells must hold the largest listed body (every box is grown by
    // kSpeculativeDistance, so this is > 0).
    cellSize_ = 0;
    for (const Real size : sizes_) {
        if (size <= oversizeLimit_) cellSize_ = std::max(cellSize_, size);
    }
}

void UniformGrid::findOverlaps(const ProxySet& proxies, std::vector<ProxyPair>& pairs, BroadphaseCounters& counters) {
    const std::uint32_t n = proxies.size();
    oversize_.clear();
    if (n == 0) return;
    chooseCellSize(proxies);

    // Each proxy's cell; the oversize ones are set aside.
    cells_.resize(n);
    isOversize_.assign(n, 0);
    for (std::uint32_t p = 0; p < n; ++p) {
        cells_[p] = cellOf(proxies.boxes[p].min);
        if (proxies.boxes[p].longestSide() > oversizeLimit_) {
            isOversize_[p] = 1;
            oversize_.push_back(p);
        }
    }

    // Counting sort of the listed proxies into buckets.
    const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(kGridBucketsPerBody * n, 2));
    bucketBits_ = std::countr_zero(buckets);
    bucketStart_.assign(buckets + 1, 0);
    for (std::uint32_t p = 0; p < n; ++p) {
        if (!isOversize_[p]) ++bucketStart_[bucketOf(cells_[p]) + 1];
    }
    for (std::size_t b = 0; b < buckets; ++b) bucketStart_[b + 1] += bucketStart_[b];
    entries_.resize(n - oversize_.size());
    // Place each entry at its bucket's next free slot; bucketStart_[b] walks
    // to the bucket's end, i.e. to where bucket b + 1 starts...
    for (std::uint32_t p = 0; p < n; ++p) {
        if (!isOversize_[p]) entries_[bucketStart_[bucketOf(cells_[p])]++] = {proxies.boxes[p], cells_[p], p};
    }
    // ...so shifting the starts up by one restores them.
    for (std::size_t b = buckets; b > 0; --b) bucketStart_[b] = bucketStart_[b - 1];
    bucketStart_[0] = 0;

    // Each dynamic body looks for partners with a higher index (kinematic
    // bodies have the highest, and never look themselves) in the cells where
    // their lowest corner can be.
    for (std::uint32_t a = 0; a < proxies.dynamicCount; ++a) {
        if (isOversize_[a]) continue;
        const Aabb& box = proxies.boxes[a];
        const Cell low = cellOf(box.min - Vec3(cellSize_));
        const Cell high = cellOf(box.max);
        for (std::int32_t x = low.x; x <= high.x; ++x) {
            for (std::int32_t y = low.y; y <= high.y; ++y) {
                for (std::int32_t z = low.z; z <= high.z; ++z) {
                    const Cell cell{x, y, z};
                    const std::size_t bucket = bucketOf(cell);
                    for (std::uint32_t e = bucketStart_[bucket]; e < bucketStart_[bucket + 1]; ++e) {
                        const Entry& entry = entries_[e];
                        if (entry.proxy <= a || !(entry.cell == cell)) continue;
                        ++counters.pairTests;
                        if (box.overlaps(entry.box)) pairs.push_back({a, entry.proxy});
                    }
                }
            }
        }
    }

    // Oversize bodies against every other body; two oversize ones only once.
    for (const std::uint32_t big : oversize_) {
        for (std::uint32_t q = 0; q < n; ++q) {
            if (q == big || (isOversize_[q] && q < big)) continue;
            if (proxies.isKinematic(big) && proxies.isKinematic(q)) continue;
            ++counters.pairTests;
            if (proxies.boxes[big].overlaps(proxies.boxes[q])) pairs.push_back(orderedPair(big, q));
        }
    }
}

}  // namespace stepwise
