/// @file trace.cpp
/// @brief `stepwise trace FILE [...]`: what each stage of each step took in and produced (src/io/trace_writer.hpp).
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "app/cli.hpp"
#include "core/errors.hpp"
#include "io/trace_writer.hpp"

namespace stepwise::cli {

int traceCommand(const std::vector<std::string>& args) {
    if (args.empty() || (!args[0].empty() && args[0][0] == '-')) {
        throw UsageError("'trace' needs a scene file first: stepwise trace FILE [--steps N] [--from STEP] "
                         "[--stage NAME] [--object NAME] [--substeps all] [--digits D]");
    }
    TraceOptions options;
    try {
        options = parseTraceOptions(std::vector<std::string>(args.begin() + 1, args.end()));
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    std::unique_ptr<Scene> scene = loadOrReport(args[0]);
    if (!scene) return kExitUsageError;
    try {
        checkTraceObjects(options, *scene);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    try {
        writeTrace(*scene, options, std::cout);
    } catch (const SimulationError& error) {
        std::cout.flush();
        std::fprintf(stderr, "stepwise: simulation failed: %s\n", error.what());
        return kExitSimulationError;
    }
    return kExitOk;
}

}  // namespace stepwise::cli
