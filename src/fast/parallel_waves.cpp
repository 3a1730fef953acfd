/// @file parallel_waves.cpp
/// @brief The waves of batched contacts solved on the pool's threads (parallel_waves.hpp says why it is exact).
#include "fast/parallel_waves.hpp"

#include <algorithm>
#include <vector>

#include "fast/box_contact_lanes.hpp"
#include "fast/round_contact_lanes.hpp"

namespace stepwise {

namespace {

/// One pass over @p batchCount batches in the waves @p waveBatches (per wave its first batch, then
/// the count): `solveRange(first, end)` on the calling thread for each run of small waves, and on
/// all of @p pool's threads, piece by piece, for each large wave. Returns how many waves it split.
template <class SolveRange>
std::uint64_t solveOnThreads(ThreadPool& pool, const std::vector<std::uint32_t>& waveBatches, std::size_t batchCount,
                             SolveRange&& solveRange) {
    const std::size_t threads = pool.threadCount();
    if (threads == 1 || waveBatches.size() < 2) {
        solveRange(std::size_t(0), batchCount);
        return 0;
    }
    std::uint64_t split = 0;
    std::size_t serialFrom = 0;  // the first batch not yet solved
    for (std::size_t wave = 0; wave + 1 < waveBatches.size(); ++wave) {
        const std::size_t first = waveBatches[wave];
        const std::size_t end = waveBatches[wave + 1];
        const std::size_t batches = end - first;
        if (batches < kParallelWaveBatches) continue;
        if (serialFrom < first) solveRange(serialFrom, first);
        // Pieces of about equal size, two per thread so that a thread slowed by the machine is
        // helped by the others; each piece at least kMinBatchesPerPiece batches.
        const std::size_t pieces = std::max<std::size_t>(1, std::min(2 * threads, batches / kMinBatchesPerPiece));
        const std::size_t size = (batches + pieces - 1) / pieces;
        auto piece = [&](std::size_t i) {
            const std::size_t from = first + i * size;
            if (from >= end) return;  // the last pieces of a rounded-up size may be empty
            solveRange(from, std::min(end, from + size));
        };
        pool.run(pieces, piece);
        ++split;
        serialFrom = end;
    }
    if (serialFrom < batchCount) solveRange(serialFrom, batchCount);
    return split;
}

}  // namespace

void solveRoundContactsOnThreads(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings,
                                 bool useBias, ThreadPool& pool) {
    fast.counts.splitWaves += solveOnThreads(pool, fast.waveBatches, fast.roundBatches.size(),
                                             [&](std::size_t first, std::size_t end) {
                                                 solveRoundContactRange(solver, fast, settings, useBias, first, end);
                                             });
}

void solveBoxContactsOnThreads(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings,
                               bool useBias, ThreadPool& pool) {
    fast.counts.splitWaves += solveOnThreads(pool, fast.boxWaveBatches, fast.boxBatches.size(),
                                             [&](std::size_t first, std::size_t end) {
                                                 solveBoxContactRange(solver, fast, settings, useBias, first, end);
                                             });
}

}  // namespace stepwise
