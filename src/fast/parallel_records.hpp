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
/// The cutting itself is forRanges() (core/parallel_ranges.hpp), which the plain
/// path's stages use too; free flight on the objects (the substeps of a scene
/// with boxes) goes through its forBodyRanges().
#pragma once

#include <cstddef>

#include "core/parallel_ranges.hpp"

namespace stepwise {

/// Records below which the per-record stages stay on one thread: a kick or a drift costs a few
/// nanoseconds a record, so some 4000 records are tens of microseconds, against a hand-over of a few.
inline constexpr std::size_t kParallelRecords = 4096;

/// Range starts are 1 + a multiple of this: the drift's group of two times four lanes.
inline constexpr std::size_t kRecordRangeAlignment = 8;

/// @brief Calls `stage(first, end)` over the records [1, @p records) in ranges, on @p pool's threads when
/// there are enough records, and returns the sum of what the calls return (the finite probes), added
/// in range order.
template <class Stage>
Real forRecordRanges(ThreadPool& pool, std::size_t records, Stage&& stage) {
    return forRanges(pool, 1, records, kParallelRecords, kRecordRangeAlignment, stage);
}

}  // namespace stepwise
