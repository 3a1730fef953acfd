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

double parseNumber(const std::string& option, const std::string& text, double lowest, const char* expected) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value) || value < lowest) {
        throw UsageError(option + " expects " + expected + ", found '" + text + "'");
    }
    return value;
}

std::uint64_t parseCount(const std::string& option, const std::string& text) {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value == 0) {
        throw UsageError(option + " expects a whole number > 0, found '" + text + "'");
    }
    return value;
}

/// "x,y,z" → a vector.
Vec3 parseVector(const std::string& option, const std::string& text) {
    Vec3 v(0);
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = text.find(',', start);
        if ((i < 2) == (comma == std::string::npos)) {
            throw UsageError(option + " expects three numbers x,y,z such as 0,1.5,-2; found '" + text + "'");
        }
        const std::string part = text.substr(start, i < 2 ? comma - start : std::string::npos);
        v[i] = Real(parseNumber(option, part, -std::numeric_limits<double>::infinity(), "three numbers x,y,z"));
        start = comma + 1;
    }
    return v;
}

/// Walks an argument list: options with one value each, and positional words.
template <class OnOption, class OnWord>
void parseArguments(const std::vector<std::string>& args, const char* command, OnOption&& onOption, OnWord&& onWord) {
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.size() > 1 && arg[0] == '-' && arg[1] == '-') {
            if (i + 1 >= args.size()) throw UsageError(arg + " needs a value");
            if (!onOption(arg, args[i + 1])) throw UsageError("unknown option '" + arg + "' for '" + command + "'");
            ++i;
        } else {
            onWord(arg);
        }
    }
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

int raycastCommand(const std::vector<std::string>& args) {
    std::string scenePath;
    std::optional<Vec3> from, direction;
    double maxDistance = std::numeric_limits<double>::infinity();
    double at = 0;
    parseArguments(
        args, "raycast",
        [&](const std::string& option, const std::string& value) {
            if (option == "--from") from = parseVector(option, value);
            else if (option == "--dir") direction = parseVector(option, value);
            else if (option == "--max") maxDistance = parseNumber(option, value, 0, "a distance >= 0 in metres");
            else if (option == "--at") at = parseNumber(option, value, 0, "a time >= 0 in seconds");
            else return false;
            return true;
        },
        [&](const std::string& word) {
            if (!scenePath.empty()) throw UsageError("'raycast' takes one scene file, got '" + scenePath + "' and '" + word + "'");
            scenePath = word;
        });
    if (scenePath.empty() || !from || !direction) throw UsageError("'raycast' needs a scene file, --from x,y,z and --dir x,y,z");
    if (glm::length(*direction) <= 0) throw UsageError("--dir must not be the zero vector");

    std::unique_ptr<Scene> scene = loadOrReport(scenePath);
    if (!scene) return kExitUsageError;
    World world(std::move(*scene));
    const auto steps = static_cast<std::uint64_t>(std::llround(at / double(world.settings().timeStep)));
    try {
        for (std::uint64_t i = 0; i < steps; ++i) world.step();
    } catch (const SimulationError& error) {
        std::fprintf(stderr, "stepwise: simulation failed: %s\n", error.what());
        return kExitSimulationError;
    }

    const Vec3 unit = glm::normalize(*direction);
    std::printf("Ray from %s along %s", vec(*from).c_str(), vec(unit).c_str());
    if (std::isfinite(maxDistance)) std::printf(", up to %.6g m", maxDistance);
    std::printf(", at t = %.6g s\n", double(world.time()));
    const std::optional<RayHit> hit = world.raycast(*from, unit, Real(maxDistance));
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

int generateCommand(const std::vector<std::string>& args) {
    GeneratorOptions options;
    std::optional<GeneratedScene> scene;
    std::string outPath;
    bool countGiven = false;
    parseArguments(
        args, "generate",
        [&](const std::string& option, const std::string& value) {
            if (option == "--count") {
                options.count = parseCount(option, value);
                countGiven = true;
            } else if (option == "--seed") {
                options.seed = parseCount(option, value);
            } else if (option == "--out") {
                outPath = value;
            } else if (option == "--broadphase") {
                const auto found = std::find_if(config::kBroadphaseChoices.begin(), config::kBroadphaseChoices.end(),
                                                [&](const auto& choice) { return config::equalsIgnoreCase(choice.word, value); });
                if (found == config::kBroadphaseChoices.end()) {
                    throw UsageError("--broadphase expects Auto, BruteForce, SweepAndPrune, AabbTree or Grid, found '" +
                                     value + "'");
                }
                options.broadphase = found->value;
            } else {
                return false;
            }
            return true;
        },
        [&](const std::string& word) {
            if (scene) throw UsageError("'generate' makes one scene at a time, got a second: '" + word + "'");
            scene = generatedSceneNamed(word);
            if (!scene) throw UsageError("unknown scene '" + word + "' (scenes: sphere-rain, box-pile, pyramids)");
        });
    if (!scene || !countGiven || outPath.empty()) {
        throw UsageError("'generate' needs a scene (sphere-rain, box-pile, pyramids), --count N and --out FILE");
    }
    options.scene = *scene;

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

int benchCommand(const std::vector<std::string>& args) {
    if (args.empty() || args[0] != "broadphase") {
        throw UsageError("'bench' needs what to measure: 'stepwise bench broadphase FILE'");
    }
    std::string scenePath;
    std::optional<double> duration;
    std::optional<std::uint64_t> steps;
    std::uint64_t checkEvery = 1;
    parseArguments(
        std::vector<std::string>(args.begin() + 1, args.end()), "bench broadphase",
        [&](const std::string& option, const std::string& value) {
            if (option == "--steps") steps = parseCount(option, value);
            else if (option == "--duration") duration = parseNumber(option, value, 0, "a number of seconds > 0");
            else if (option == "--check-every") checkEvery = parseCount(option, value);
            else return false;
            return true;
        },
        [&](const std::string& word) {
            if (!scenePath.empty()) throw UsageError("'bench broadphase' takes one scene file");
            scenePath = word;
        });
    if (scenePath.empty()) throw UsageError("'bench broadphase' needs a scene file");
    if (duration && steps) throw UsageError("give --duration or --steps, not both");
    if (duration && *duration <= 0) throw UsageError("--duration expects a number of seconds > 0");

    std::unique_ptr<Scene> scene = loadOrReport(scenePath);
    if (!scene) return kExitUsageError;
    World world(std::move(*scene));
    const double h = double(world.settings().timeStep);
    const std::uint64_t stepCount =
        steps.value_or(static_cast<std::uint64_t>(std::llround(duration.value_or(double(world.settings().duration)) / h)));

    const BroadphaseChoice choice = chooseBroadphase(bodiesOf(world));
    std::printf("Scene %s: %llu steps of %.6g s\n", scenePath.c_str(), static_cast<unsigned long long>(stepCount), h);
    std::printf("  Auto would choose %s: %s\n", toString(choice.kind), choice.reason.c_str());

    BroadphaseTracker tracker;
    int exitCode = kExitOk;
    try {
        for (std::uint64_t i = 0; i < stepCount; ++i) {
            world.step();
            tracker.observe(bodiesOf(world), world.stepCount(), world.stepCount() % checkEvery == 0);
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
