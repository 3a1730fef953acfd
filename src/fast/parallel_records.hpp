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

/// @brief Calls `stage(first, end)` over the records [1, @p records) in ranges, on @p pool's threads when
/// there are enough records, and returns the sum of what the calls return (the finite probes), added
/// in range order.
template <class Stage>
Real forRecordRanges(ThreadPool& pool, std::size_t records, Stage&& stage) {
    const std::size_t threads = pool.threadCount();
    if (threads == 1 || records < kParallelRecords) return stage(std::size_t(1), records);
    const std::size_t ranges = std::min(kMaxRecordRanges, 2 * threads);
    const std::size_t perRange = ((records - 1) / ranges + kRecordRangeAlignment - 1) / kRecordRangeAlignment *
                                 kRecordRangeAlignment;  // rounded up to the alignment
    std::array<Real, kMaxRecordRanges> probes{};
    auto range = [&](std::size_t i) {
        const std::size_t first = 1 + i * perRange;
        if (first >= records) return;
        probes[i] = stage(first, std::min(records, first + perRange));
    };
    pool.run(ranges, range);
    Real probe = 0;
    for (std::size_t i = 0; i < ranges; ++i) probe += probes[i];
    return probe;
}

}  // namespace stepwise
