/// @file parallel_waves.cpp
/// @brief The round contacts' waves solved on the pool's threads (parallel_waves.hpp says why it is exact).
#include "fast/parallel_waves.hpp"

#include <algorithm>

#include "fast/round_contact_lanes.hpp"

namespace stepwise {

void solveRoundContactsOnThreads(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings,
                                 bool useBias, ThreadPool& pool) {
    const std::size_t threads = pool.threadCount();
    const std::vector<std::uint32_t>& waveBatches = fast.waveBatches;  // per wave its first batch, then the count
    if (threads == 1 || waveBatches.size() < 2) {
        solveRoundContacts(solver, fast, settings, useBias);
        return;
    }
    // Walk the waves; a run of small waves goes to the calling thread in one call, in order.
    std::size_t serialFrom = 0;  // the first batch not yet solved
    for (std::size_t wave = 0; wave + 1 < waveBatches.size(); ++wave) {
        const std::size_t first = waveBatches[wave];
        const std::size_t end = waveBatches[wave + 1];
        const std::size_t batches = end - first;
        if (batches < kParallelWaveBatches) continue;
        if (serialFrom < first) solveRoundContactRange(solver, fast, settings, useBias, serialFrom, first);
        // Pieces of about equal size, two per thread so that a thread slowed by the machine is
        // helped by the others; each piece at least kMinBatchesPerPiece batches.
        const std::size_t pieces = std::max<std::size_t>(1, std::min(2 * threads, batches / kMinBatchesPerPiece));
        const std::size_t size = (batches + pieces - 1) / pieces;
        auto piece = [&](std::size_t i) {
            const std::size_t from = first + i * size;
            if (from >= end) return;  // the last pieces of a rounded-up size may be empty
            solveRoundContactRange(solver, fast, settings, useBias, from, std::min(end, from + size));
        };
        pool.run(pieces, piece);
        fast.counts.splitWaves += 1;
        serialFrom = end;
    }
    const std::size_t count = fast.roundBatches.size();
    if (serialFrom < count) solveRoundContactRange(solver, fast, settings, useBias, serialFrom, count);
}

}  // namespace stepwise
