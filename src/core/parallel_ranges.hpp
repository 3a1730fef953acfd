/// @file parallel_ranges.hpp
/// @brief Work on items that are each their own, cut into ranges and handed to the pool's threads.
///
/// A stage whose items change from their own numbers only (a body's free
/// flight, a contact's preparation) may run its items in any order, or at the
/// same time on several cores, and every item gets the same bits as on one
/// thread. So [begin, end) is cut into ranges, two per thread (so that a
/// thread the machine slows down is helped by the others), and each range is
/// one chunk of a ThreadPool job. What must be gathered from the items (a sum,
/// a list) is kept per range and joined in range order afterwards: then it too
/// is what one thread gives, whatever thread ran which range (thread_pool.hpp).
///
/// A hand-over costs a few microseconds, so a stage names the fewest items
/// worth cutting (its `minimum`); below that, or with one thread, the calling
/// thread runs the whole of [begin, end) as a single range.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include "core/thread_pool.hpp"
#include "core/types.hpp"

namespace stepwise {

/// Ranges at most: two per thread of the largest pool this is meant for (what is gathered is kept per range).
inline constexpr std::size_t kMaxRanges = 16;

/// Bodies below which free flight on the objects stays on one thread: a box's flight (its torque-free
/// turn in five sub-rotations) costs some 150 ns, so 512 boxes are some 80 µs against a hand-over of a few.
inline constexpr std::size_t kParallelBodies = 512;

/// @brief How [begin, end) is cut: `count` ranges of `size` items, range i from begin + i·size (the
/// last ones shorter, or empty).
struct RangeSplit {
    std::size_t begin = 0;  ///< The first item.
    std::size_t end = 0;    ///< One past the last item.
    std::size_t count = 1;  ///< How many ranges.
    std::size_t size = 0;   ///< Items a range, a multiple of the alignment asked for.
    /// @brief The first item of range @p i (`end` for an empty range).
    std::size_t first(std::size_t i) const { return std::min(end, begin + i * size); }
    /// @brief One past the last item of range @p i.
    std::size_t last(std::size_t i) const { return std::min(end, first(i) + size); }
};

/// @brief Cuts [@p begin, @p end) for @p pool: one range on the calling thread when there is no pool,
/// one thread or fewer than @p minimum items; otherwise two ranges a thread (at most kMaxRanges), each
/// starting at @p begin plus a multiple of @p alignment.
inline RangeSplit splitRanges(const ThreadPool* pool, std::size_t begin, std::size_t end, std::size_t minimum,
                              std::size_t alignment = 1) {
    const std::size_t items = end > begin ? end - begin : 0;
    const std::size_t threads = pool == nullptr ? 1 : pool->threadCount();
    if (threads == 1 || items < minimum) return {begin, begin + items, 1, items};
    const std::size_t ranges = std::min(kMaxRanges, 2 * threads);
    // ⌈items/ranges⌉ rounded up to the alignment: the ranges cover every item
    const std::size_t size = ((items + ranges - 1) / ranges + alignment - 1) / alignment * alignment;
    return {begin, end, ranges, size};
}

/// @brief Calls `stage(i, first, last)` for every range i of @p split, on @p pool's threads when it has
/// more than one range (a single range runs on the calling thread; then @p pool may be null).
template <class Stage>
void runRanges(ThreadPool* pool, const RangeSplit& split, Stage&& stage) {
    if (split.count == 1) {
        stage(std::size_t(0), split.begin, split.end);
        return;
    }
    auto range = [&](std::size_t i) { stage(i, split.first(i), split.last(i)); };
    pool->run(split.count, range);
}

/// @brief Calls `stage(first, last)` over [@p begin, @p end) in ranges starting at @p begin plus a multiple
/// of @p alignment, on @p pool's threads when there are at least @p minimum items, and returns the sum of
/// what the calls return (the finite probes), added in range order.
template <class Stage>
Real forRanges(ThreadPool& pool, std::size_t begin, std::size_t end, std::size_t minimum, std::size_t alignment,
               Stage&& stage) {
    const RangeSplit split = splitRanges(&pool, begin, end, minimum, alignment);
    if (split.count == 1) return stage(split.begin, split.end);
    std::array<Real, kMaxRanges> probes{};
    runRanges(&pool, split, [&](std::size_t i, std::size_t first, std::size_t last) {
        if (first < last) probes[i] = stage(first, last);
    });
    Real probe = 0;
    for (std::size_t i = 0; i < split.count; ++i) probe += probes[i];
    return probe;
}

/// @brief Calls `stage(first, last)` over the dynamic bodies [0, @p bodies) in ranges, on @p pool's threads
/// when there are at least kParallelBodies, and returns the sum of the calls' finite probes.
template <class Stage>
Real forBodyRanges(ThreadPool& pool, std::size_t bodies, Stage&& stage) {
    return forRanges(pool, 0, bodies, kParallelBodies, 1, stage);
}

}  // namespace stepwise
