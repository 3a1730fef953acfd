/// @file parallel_records.hpp
/// @brief The per-body stages of the fast path split between threads: each record is its own work.
///
/// The kick and the drift of the packed substeps (packed_substeps.hpp) change
/// each solver record from its own numbers only: no record reads another. So
/// the records can be cut into ranges and the ranges handed to the World's
/// threads, and every record gets the same bits as on one thread. What must
/// be gathered, the finite probes, is summed per range and then in range order.
///
/// A range starts at record 1 + 8k, where the one-thread loop starts a group of
/// eight too (driftPackedRecords()), and a scene of fewer records than
/// kParallelRecords runs on the calling thread alone.
///
/// Free flight on the objects (the substeps of a scene with boxes) is the same
/// kind of work: each body moves by its own velocity and momentum alone, so
/// forBodyRanges() cuts the dynamic bodies into ranges in the same way.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include "core/thread_pool.hpp"
#include "core/types.hpp"

namespace stepwise {

/// Records below which the per-record stages stay on one thread: a kick or a drift costs a few
/// nanoseconds a record, so some 4000 records are tens of microseconds, against a hand-over of a few.
inline constexpr std::size_t kParallelRecords = 4096;

/// Ranges at most: two per thread of the largest pool this is meant for (probes are kept per range).
inline constexpr std::size_t kMaxRecordRanges = 16;

/// Range starts are 1 + a multiple of this: the drift's group of two times four lanes.
inline constexpr std::size_t kRecordRangeAlignment = 8;

/// Bodies below which free flight on the objects stays on one thread: a box's flight (its torque-free
/// turn in five sub-rotations) costs some 150 ns, so 512 boxes are some 80 µs against a hand-over of a few.
inline constexpr std::size_t kParallelBodies = 512;

/// @brief Calls `stage(first, end)` over [@p begin, @p end) in ranges starting at @p begin plus a multiple
/// of @p alignment, on @p pool's threads when there are at least @p minimum items, and returns the sum of
/// what the calls return (the finite probes), added in range order.
template <class Stage>
Real forRanges(ThreadPool& pool, std::size_t begin, std::size_t end, std::size_t minimum, std::size_t alignment,
               Stage&& stage) {
    const std::size_t threads = pool.threadCount();
    const std::size_t items = end > begin ? end - begin : 0;
    if (threads == 1 || items < minimum) return stage(begin, end);
    const std::size_t ranges = std::min(kMaxRecordRanges, 2 * threads);
    // ⌈items/ranges⌉ rounded up to the alignment: the ranges cover every item
    const std::size_t perRange = ((items + ranges - 1) / ranges + alignment - 1) / alignment * alignment;
    std::array<Real, kMaxRecordRanges> probes{};
    auto range = [&](std::size_t i) {
        const std::size_t first = begin + i * perRange;
        if (first >= end) return;
        probes[i] = stage(first, std::min(end, first + perRange));
    };
    pool.run(ranges, range);
    Real probe = 0;
    for (std::size_t i = 0; i < ranges; ++i) probe += probes[i];
    return probe;
}

/// @brief Calls `stage(first, end)` over the records [1, @p records) in ranges, on @p pool's threads when
/// there are enough records, and returns the sum of what the calls return (the finite probes), added
/// in range order.
template <class Stage>
Real forRecordRanges(ThreadPool& pool, std::size_t records, Stage&& stage) {
    return forRanges(pool, 1, records, kParallelRecords, kRecordRangeAlignment, stage);
}

/// @brief Calls `stage(first, end)` over the dynamic bodies [0, @p bodies) in ranges, on @p pool's threads
/// when there are at least kParallelBodies, and returns the sum of the calls' finite probes.
template <class Stage>
Real forBodyRanges(ThreadPool& pool, std::size_t bodies, Stage&& stage) {
    return forRanges(pool, 0, bodies, kParallelBodies, kRecordRangeAlignment, stage);
}

}  // namespace stepwise
