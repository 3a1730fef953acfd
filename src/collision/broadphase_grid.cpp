/// @file broadphase_grid.cpp
/// @brief Stage 4, uniform grid: cells sized from the bodies, a hash table filled by counting sort,
/// and the pairs kept from step to step while the bodies stay inside their fat boxes.
#include "collision/broadphase_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "core/insertion_sort.hpp"

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

/// Compares the boxes of proxies @p p and @p q, and keeps the pair if they overlap;
/// two kinematic bodies are never compared (neither can be pushed).
void testPair(const ProxySet& proxies, std::uint32_t p, std::uint32_t q, std::vector<ProxyPair>& pairs,
              BroadphaseCounters& counters) {
    if (proxies.isKinematic(p) && proxies.isKinematic(q)) return;
    ++counters.pairTests;
    if (proxies.boxes[p].overlaps(proxies.boxes[q])) pairs.push_back(orderedPair(p, q));
}

/// Pair @p x comes before pair @p y: by lower proxy, then higher.
bool comesBefore(const ProxyPair& x, const ProxyPair& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); }

/// Sorts @p pairs by lower proxy, then higher, into @p sorted, in O(pairs + proxies): a counting
/// sort by the lower proxy, then each proxy's few partners by insertion (core/insertion_sort.hpp).
void sortByProxies(const std::vector<ProxyPair>& pairs, std::uint32_t proxyCount, std::vector<std::uint32_t>& start,
                   std::vector<ProxyPair>& sorted) {
    start.assign(proxyCount + 1, 0);
    for (const ProxyPair& pair : pairs) ++start[pair.a + 1];
    for (std::uint32_t p = 0; p < proxyCount; ++p) start[p + 1] += start[p];
    sorted.resize(pairs.size());
    for (const ProxyPair& pair : pairs) sorted[start[pair.a]++] = pair;
    // Placing moved each start to its run's end, the next run's start.
    std::uint32_t first = 0;
    for (std::uint32_t p = 0; p < proxyCount; ++p) {
        insertionSort(std::span<ProxyPair>(sorted.data() + first, start[p] - first), comesBefore);
        first = start[p];
    }
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
    if (n == 0) {
        kept_.clear();
        keeping_ = false;
        movedCount_ = 0;
        refoundAll_ = true;
        return;
    }
    // Which proxies left the fat box they were filed under?
    const bool canKeep = keeping_ && fat_.size() == n && keptDynamicCount_ == proxies.dynamicCount;
    movedCount_ = 0;
    if (canKeep) {
        moved_.assign(n, 0);
        for (std::uint32_t p = 0; p < n; ++p) {
            if (!fat_[p].contains(proxies.boxes[p])) {
                moved_[p] = 1;
                ++movedCount_;
            }
        }
    }
    const auto fatten = [&](std::uint32_t p) {
        const Aabb& box = proxies.boxes[p];
        const Vec3 margin(kGridFatMarginFraction * box.longestSide());
        fat_[p] = {box.min - margin, box.max + margin};
    };
    fat_.resize(n);
    const ProxySet fat{fat_, proxies.dynamicCount};
    refoundAll_ = !canKeep || movedCount_ * kGridRefindAllShare > n;
    if (refoundAll_) {
        for (std::uint32_t p = 0; p < n; ++p) fatten(p);
        fileProxies(fat);
        findAllFatPairs(fat, counters);
        movedCount_ = n;
    } else if (movedCount_ > 0) {
        for (std::uint32_t p = 0; p < n; ++p) {
            if (moved_[p]) fatten(p);
        }
        fileProxies(fat);
        // The 27 cells around a body hold all its partners only in the dense grid without oversize bodies
        refoundAll_ = !dense_ || !oversize_.empty();
        if (refoundAll_) {
            findAllFatPairs(fat, counters);
        } else {
            findFatPairsOfMoved(fat, counters);
        }
    }
    keeping_ = true;
    keptDynamicCount_ = proxies.dynamicCount;

    // The kept pairs whose exact boxes overlap: those the search on the exact boxes would find.
    for (const ProxyPair& pair : kept_) {
        ++counters.pairTests;
        if (proxies.boxes[pair.a].overlaps(proxies.boxes[pair.b])) pairs.push_back(pair);
    }
}

void UniformGrid::fileProxies(const ProxySet& proxies) {
    const std::uint32_t n = proxies.size();
    oversize_.clear();
    chooseCellSize(proxies);
    isOversize_.assign(n, 0);
    for (std::uint32_t p = 0; p < n; ++p) {
        if (proxies.boxes[p].longestSide() > oversizeLimit_) {
            isOversize_[p] = 1;
            oversize_.push_back(p);
        }
    }
    dense_ = fitDenseGrid(proxies);
    if (dense_) fillDenseCells(proxies);
}

void UniformGrid::findAllFatPairs(const ProxySet& fat, BroadphaseCounters& counters) {
    found_.clear();
    if (dense_) {
        findOverlapsDense(fat, found_, counters);
        findOversizeOverlapsDense(fat, found_, counters);
    } else {
        findOverlapsHashed(fat, found_, counters);
        // Oversize bodies against every listed body: the hashed grid has no cell ranges to walk.
        for (const std::uint32_t big : oversize_) {
            for (std::uint32_t q = 0; q < fat.size(); ++q) {
                if (!isOversize_[q]) testPair(fat, big, q, found_, counters);
            }
        }
    }
    // The oversize bodies among themselves, each pair once.
    for (std::size_t i = 0; i < oversize_.size(); ++i) {
        for (std::size_t j = i + 1; j < oversize_.size(); ++j) testPair(fat, oversize_[i], oversize_[j], found_, counters);
    }
    sortByProxies(found_, fat.size(), pairStart_, kept_);
}

void UniformGrid::findFatPairsOfMoved(const ProxySet& fat, BroadphaseCounters& counters) {
    found_.clear();
    for (std::uint32_t e = 0; e < entries_.size(); ++e) {
        const Entry& entry = entries_[e];
        if (!moved_[entry.proxy]) continue;
        const bool kinematic = fat.isKinematic(entry.proxy);
        const std::int32_t zLow = std::max(entry.cell.z - 1, 0);
        const std::int32_t zHigh = std::min(entry.cell.z + 1, columns_[2] - 1);
        for (std::int32_t x = std::max(entry.cell.x - 1, 0); x <= std::min(entry.cell.x + 1, columns_[0] - 1); ++x) {
            for (std::int32_t y = std::max(entry.cell.y - 1, 0); y <= std::min(entry.cell.y + 1, columns_[1] - 1); ++y) {
                for (std::uint32_t f = bucketStart_[slotOf(x, y, zLow)]; f < bucketStart_[slotOf(x, y, zHigh) + 1]; ++f) {
                    const Entry& other = entries_[f];
                    if (f == e || (kinematic && fat.isKinematic(other.proxy))) continue;
                    if (moved_[other.proxy] && other.proxy < entry.proxy) continue;  // found from the other side
                    ++counters.pairTests;
                    if (entry.box.overlaps(other.box)) found_.push_back(orderedPair(entry.proxy, other.proxy));
                }
            }
        }
    }
    sortByProxies(found_, fat.size(), pairStart_, merged_);
    found_.swap(merged_);
    // The kept pairs of proxies that stayed, with the new ones merged in, in order: no pair is in both.
    merged_.clear();
    auto next = found_.begin();
    for (const ProxyPair& pair : kept_) {
        if (moved_[pair.a] || moved_[pair.b]) continue;
        for (; next != found_.end() && comesBefore(*next, pair); ++next) merged_.push_back(*next);
        merged_.push_back(pair);
    }
    merged_.insert(merged_.end(), next, found_.end());
    kept_.swap(merged_);
}

bool UniformGrid::fitDenseGrid(const ProxySet& proxies) {
    // The box around the listed bodies' lowest corners, in cells.
    Vec3 low(std::numeric_limits<Real>::max());
    Vec3 high(std::numeric_limits<Real>::lowest());
    std::size_t listed = 0;
    for (std::uint32_t p = 0; p < proxies.size(); ++p) {
        if (isOversize_[p]) continue;
        low = glm::min(low, proxies.boxes[p].min);
        high = glm::max(high, proxies.boxes[p].min);
        ++listed;
    }
    if (listed == 0) return false;
    const Vec3 spans = glm::floor((high - low) / cellSize_) + Real(1);  // cells along each axis (in Real: no overflow)
    if (spans.x * spans.y * spans.z > kGridDenseCellsPerBody * Real(listed)) return false;
    origin_ = low;
    for (int axis = 0; axis < 3; ++axis) columns_[axis] = static_cast<std::int32_t>(spans[axis]);
    return true;
}

std::uint32_t UniformGrid::slotOf(std::int32_t x, std::int32_t y, std::int32_t z) const {
    return static_cast<std::uint32_t>((x * columns_[1] + y) * columns_[2] + z);
}

void UniformGrid::fillDenseCells(const ProxySet& proxies) {
    const std::uint32_t n = proxies.size();
    // Each listed proxy's cell; the clamp only absorbs the rounding of (min − origin)/size at the far edge.
    cells_.resize(n);
    for (std::uint32_t p = 0; p < n; ++p) {
        if (isOversize_[p]) continue;
        const Vec3 offset = (proxies.boxes[p].min - origin_) / cellSize_;
        Cell& cell = cells_[p];
        cell.x = std::clamp(static_cast<std::int32_t>(offset.x), 0, columns_[0] - 1);
        cell.y = std::clamp(static_cast<std::int32_t>(offset.y), 0, columns_[1] - 1);
        cell.z = std::clamp(static_cast<std::int32_t>(offset.z), 0, columns_[2] - 1);
    }

    // Counting sort into the cells' slots, x-major.
    const std::uint32_t slots = static_cast<std::uint32_t>(columns_[0] * columns_[1] * columns_[2]);
    bucketStart_.assign(slots + 1, 0);
    for (std::uint32_t p = 0; p < n; ++p) {
        if (!isOversize_[p]) ++bucketStart_[slotOf(cells_[p].x, cells_[p].y, cells_[p].z) + 1];
    }
    for (std::uint32_t s = 0; s < slots; ++s) bucketStart_[s + 1] += bucketStart_[s];
    entries_.resize(n - oversize_.size());
    for (std::uint32_t p = 0; p < n; ++p) {
        if (isOversize_[p]) continue;
        const Cell& cell = cells_[p];
        entries_[bucketStart_[slotOf(cell.x, cell.y, cell.z)]++] = {proxies.boxes[p], cell, p};
    }
    // Placing moved each start to its slot's end, i.e. to where the next slot starts: shift them back.
    for (std::uint32_t s = slots; s > 0; --s) bucketStart_[s] = bucketStart_[s - 1];
    bucketStart_[0] = 0;
}

void UniformGrid::findOverlapsDense(const ProxySet& proxies, std::vector<ProxyPair>& pairs,
                                    BroadphaseCounters& counters) {
    // Tests entry e against the entries [first, last): all three axes (the run is not sorted along any).
    const auto testRun = [&](std::uint32_t e, std::uint32_t first, std::uint32_t last) {
        const Entry& entry = entries_[e];
        const bool kinematic = proxies.isKinematic(entry.proxy);
        for (std::uint32_t f = first; f < last; ++f) {
            const Entry& other = entries_[f];
            if (kinematic && proxies.isKinematic(other.proxy)) continue;  // neither can be pushed
            ++counters.pairTests;
            if (entry.box.overlaps(other.box)) pairs.push_back(orderedPair(entry.proxy, other.proxy));
        }
    };
    // The 13 neighbours ahead of a cell in x-major order, as (x, y) columns whose cells z − 1 … z + 1
    // are one run: (x, y + 1), and (x + 1, y − 1), (x + 1, y), (x + 1, y + 1). Its own column ahead of
    // it is the rest of its own cell and cell z + 1.
    constexpr std::int32_t kColumnsAhead[4][2] = {{0, 1}, {1, -1}, {1, 0}, {1, 1}};
    for (std::uint32_t e = 0; e < entries_.size(); ++e) {
        const Cell cell = entries_[e].cell;
        const std::int32_t zLow = std::max(cell.z - 1, 0);
        const std::int32_t zHigh = std::min(cell.z + 1, columns_[2] - 1);
        testRun(e, e + 1, bucketStart_[slotOf(cell.x, cell.y, zHigh) + 1]);
        for (const auto& step : kColumnsAhead) {
            const std::int32_t x = cell.x + step[0];
            const std::int32_t y = cell.y + step[1];
            if (x >= columns_[0] || y < 0 || y >= columns_[1]) continue;
            testRun(e, bucketStart_[slotOf(x, y, zLow)], bucketStart_[slotOf(x, y, zHigh) + 1]);
        }
    }
}

bool UniformGrid::cellRange(Real low, Real high, int axis, std::int32_t& first, std::int32_t& last) const {
    // The dense grid's cells along @p axis from the one of @p low to the one of @p high, clipped to the grid.
    // In Real, clamped to one cell beyond the grid on either side, before the cast: no overflow.
    const Real lowest = Real(-1);
    const Real highest = Real(columns_[axis]);
    first = static_cast<std::int32_t>(std::clamp(std::floor((low - origin_[axis]) / cellSize_), lowest, highest));
    last = static_cast<std::int32_t>(std::clamp(std::floor((high - origin_[axis]) / cellSize_), lowest, highest));
    first = std::max(first, 0);
    last = std::min(last, columns_[axis] - 1);
    return first <= last;
}

template <class Visit>
bool UniformGrid::visitDenseCells(const Vec3& low, const Vec3& high, Visit&& visit) const {
    std::int32_t x0, x1, y0, y1, z0, z1;
    if (!cellRange(low.x, high.x, 0, x0, x1) || !cellRange(low.y, high.y, 1, y0, y1) ||
        !cellRange(low.z, high.z, 2, z0, z1)) {
        return false;  // beyond the listed proxies on some axis
    }
    // A column's cells (x, y, z0 … z1) are side by side in the dense layout: one run of entries.
    for (std::int32_t x = x0; x <= x1; ++x) {
        for (std::int32_t y = y0; y <= y1; ++y) {
            for (std::uint32_t e = bucketStart_[slotOf(x, y, z0)]; e < bucketStart_[slotOf(x, y, z1) + 1]; ++e) {
                visit(entries_[e]);
            }
        }
    }
    return true;
}

template <class Visit>
void UniformGrid::visitHashedCells(const Cell& low, const Cell& high, Visit&& visit) const {
    for (std::int32_t x = low.x; x <= high.x; ++x) {
        for (std::int32_t y = low.y; y <= high.y; ++y) {
            for (std::int32_t z = low.z; z <= high.z; ++z) {
                const Cell cell{x, y, z};
                const std::size_t bucket = bucketOf(cell);
                for (std::uint32_t e = bucketStart_[bucket]; e < bucketStart_[bucket + 1]; ++e) {
                    if (entries_[e].cell == cell) visit(entries_[e]);  // a bucket holds several cells
                }
            }
        }
    }
}

void UniformGrid::findOversizeOverlapsDense(const ProxySet& proxies, std::vector<ProxyPair>& pairs,
                                            BroadphaseCounters& counters) {
    // A listed body can touch an oversize box B only if its lowest corner lies between
    // B.min − cellSize and B.max: the cells of that range, column by column, hold all
    // its listed partners (a falling body's swept box, a boulder among pebbles: a few
    // dozen cells, not the n bodies of a test against everyone).
    for (const std::uint32_t big : oversize_) {
        const Aabb& box = proxies.boxes[big];
        visitDenseCells(box.min - Vec3(cellSize_), box.max,
                        [&](const Entry& entry) { testPair(proxies, big, entry.proxy, pairs, counters); });
    }
}

void UniformGrid::findOverlapsHashed(const ProxySet& proxies, std::vector<ProxyPair>& pairs,
                                     BroadphaseCounters& counters) {
    const std::uint32_t n = proxies.size();
    cells_.resize(n);
    for (std::uint32_t p = 0; p < n; ++p) cells_[p] = cellOf(proxies.boxes[p].min);

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
        visitHashedCells(cellOf(box.min - Vec3(cellSize_)), cellOf(box.max), [&](const Entry& entry) {
            if (entry.proxy <= a) return;
            ++counters.pairTests;
            if (box.overlaps(entry.box)) pairs.push_back({a, entry.proxy});
        });
    }
}

void UniformGrid::query(const Aabb& box, std::span<const Aabb> boxes, std::vector<std::uint32_t>& hits,
                        BroadphaseCounters& counters) const {
    if (!keeping_) return;  // no proxies in the last call
    const auto test = [&](const Entry& entry) {
        ++counters.pairTests;
        // The fat box first, read from the entry itself; the proxy's own box decides.
        if (entry.box.overlaps(box) && boxes[entry.proxy].overlaps(box)) hits.push_back(entry.proxy);
    };
    for (const std::uint32_t big : oversize_) {
        ++counters.pairTests;
        if (boxes[big].overlaps(box)) hits.push_back(big);
    }
    // The lowest corner to look from, box.min − cellSize, lowered by a few units of rounding
    // (the sizes the cell was fitted to were rounded when measured): an extra cell costs a
    // few box tests, a cell too few a wrong answer.
    const Vec3 slack = Real(4) * std::numeric_limits<Real>::epsilon() * (glm::abs(box.min) + Vec3(cellSize_));
    const Vec3 from = box.min - Vec3(cellSize_) - slack;
    if (dense_) {
        visitDenseCells(from, box.max, test);
        return;
    }
    const Cell low = cellOf(from);
    const Cell high = cellOf(box.max);
    const double cells = (double(high.x) - low.x + 1) * (double(high.y) - low.y + 1) * (double(high.z) - low.z + 1);
    if (cells > double(entries_.size())) {
        for (const Entry& entry : entries_) test(entry);  // fewer entries than cells: read them all
        return;
    }
    visitHashedCells(low, high, test);
}

}  // namespace stepwise
