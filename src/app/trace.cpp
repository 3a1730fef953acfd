/// @file trace.cpp
/// @brief `stepwise trace FILE [...]`: what each stage of each step took in and produced (src/io/trace_writer.hpp).
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "app/cli.hpp"
#include "app/interrupt.hpp"
#include "core/errors.hpp"
#include "io/trace_writer.hpp"

namespace stepwise::cli {

int traceCommand(const TraceCommandOptions& options) {
    std::unique_ptr<Scene> scene = loadOrReport(options.scenePath);
    if (!scene) return kExitUsageError;
    try {
        checkTraceObjects(options.trace, *scene);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    // Ctrl-C, kill or the time budget: stop between two steps, with every line whole.
    const InterruptGuard interrupts;
    const Deadline deadline(options.maxSeconds);
    bool finished = true;
    try {
        finished = writeTrace(*scene, options.trace, std::cout,
                              [&] { return InterruptGuard::signalReceived() != 0 || deadline.passed(); });
    } catch (const SimulationError& error) {
        std::cout.flush();
        std::fprintf(stderr, "stepwise: simulation failed: %s\n", error.what());
        return kExitSimulationError;
    }
    std::cout.flush();
    if (finished) return kExitOk;
    if (const int signal = InterruptGuard::signalReceived(); signal != 0) {
        std::fprintf(stderr, "stepwise: trace stopped by signal %d\n", signal);
        return exitCodeForSignal(signal);
    }
    std::fprintf(stderr, "stepwise: trace stopped: --max-seconds %g of wall-clock time ran out\n", deadline.seconds());
    return kExitSimulationError;
}

}  // namespace stepwise::cli
