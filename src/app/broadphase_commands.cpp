/// @file broadphase_commands.cpp
/// @brief `stepwise raycast`, `stepwise generate` and `stepwise bench broadphase`.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "app/cli.hpp"
#include "collision/broadphase_tracker.hpp"
#include "config/scene_generator.hpp"
#include "config/scene_loader.hpp"
#include "config/scene_records.hpp"
#include "config/spelling.hpp"
#include "core/errors.hpp"
#include "io/broadphase_table.hpp"
#include "io/output_file.hpp"
#include "world/world.hpp"

namespace stepwise::cli {

namespace {


std::string vec(const Vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.4f, %.4f, %.4f)", double(v.x), double(v.y), double(v.z));
    return text;
}

const char* describe(BodyKind kind) {
    switch (kind) {
        case BodyKind::Dynamic: return "dynamic";
        case BodyKind::Kinematic: return "kinematic";
        case BodyKind::Plane: break;
    }
    return "plane";
}

BodySet bodiesOf(World& world) { return {world.dynamics(), world.kinematics(), world.planes()}; }

}  // namespace

int raycastCommand(const RaycastOptions& options) {
    std::unique_ptr<Scene> scene = loadOrReport(options.scenePath);
    if (!scene) return kExitUsageError;
    World world(std::move(*scene));
    const auto steps = static_cast<std::uint64_t>(std::llround(options.at / double(world.settings().timeStep)));
    try {
        for (std::uint64_t i = 0; i < steps; ++i) world.step();
    } catch (const SimulationError& error) {
        std::fprintf(stderr, "stepwise: simulation failed: %s\n", error.what());
        return kExitSimulationError;
    }

    // parseDirection() has checked that the direction can be normalised: not zero, its length finite.
    const Vec3 unit = glm::normalize(options.direction);
    std::printf("Ray from %s along %s", vec(options.from).c_str(), vec(unit).c_str());
    if (std::isfinite(options.maxDistance)) std::printf(", up to %.6g m", options.maxDistance);
    std::printf(", at t = %.6g s\n", double(world.time()));
    const std::optional<RayHit> hit = world.raycast(options.from, unit, Real(options.maxDistance));
    if (!hit) {
        std::printf("No hit.\n");
        return kExitOk;
    }
    std::string name;
    switch (hit->body.kind) {
        case BodyKind::Dynamic: name = world.dynamics()[hit->body.index].name; break;
        case BodyKind::Kinematic: name = world.kinematics()[hit->body.index].name; break;
        case BodyKind::Plane: name = world.planes()[hit->body.index].name; break;
    }
    std::printf("Hit %s (%s) at distance %.6g m\n", name.c_str(), describe(hit->body.kind), double(hit->distance));
    std::printf("  point  %s m\n  normal %s\n", vec(hit->point).c_str(), vec(hit->normal).c_str());
    return kExitOk;
}

int generateCommand(const GenerateOptions& command) {
    const GeneratorOptions& options = command.generator;
    const std::string& outPath = command.outPath;
    const std::string text = generateSceneText(options);
    OutputFile out(outPath);  // "-": standard output
    if (!out.ok()) {
        std::fprintf(stderr, "stepwise: error: %s\n", out.error().c_str());
        return kExitUsageError;
    }
    std::fwrite(text.data(), 1, text.size(), out.file());
    if (const std::string error = out.close(); !error.empty()) {
        std::fprintf(stderr, "stepwise: error: %s\n", error.c_str());
        return kExitSimulationError;
    }
    if (outPath != "-") {
        std::printf("Wrote %s, %zu bodies, seed %llu, to %s\n", toString(options.scene), options.count,
                    static_cast<unsigned long long>(options.seed), outPath.c_str());
    }
    return kExitOk;
}

int benchCommand(const BenchOptions& options) {
    std::unique_ptr<Scene> scene = loadOrReport(options.scenePath);
    if (!scene) return kExitUsageError;
    World world(std::move(*scene));
    const double h = double(world.settings().timeStep);
    const std::uint64_t stepCount = options.steps.value_or(
        static_cast<std::uint64_t>(std::llround(options.duration.value_or(double(world.settings().duration)) / h)));

    const BroadphaseChoice choice = chooseBroadphase(bodiesOf(world));
    std::printf("Scene %s: %llu steps of %.6g s\n", options.scenePath.c_str(), static_cast<unsigned long long>(stepCount), h);
    std::printf("  Auto would choose %s: %s\n", toString(choice.kind), choice.reason.c_str());

    BroadphaseTracker tracker;
    int exitCode = kExitOk;
    try {
        for (std::uint64_t i = 0; i < stepCount; ++i) {
            world.step();
            tracker.observe(bodiesOf(world), world.stepCount(), world.stepCount() % options.checkEvery == 0);
        }
    } catch (const SimulationError& error) {
        std::fprintf(stderr, "stepwise: simulation failed: %s\n", error.what());
        exitCode = kExitSimulationError;
    }
    writeBroadphaseTable(stdout, tracker, bodiesOf(world));
    if (!tracker.agrees()) {
        std::fprintf(stderr, "stepwise: a broadphase differs from brute force (see the steps and pairs above)\n");
        exitCode = kExitSimulationError;
    }
    return exitCode;
}

}  // namespace stepwise::cli
