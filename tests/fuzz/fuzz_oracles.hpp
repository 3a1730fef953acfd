// What the fuzz targets count as handled, shared with the regression test that replays the
// inputs they (and the hostile-input campaign of issue 34) found: tests/test_fuzz_regressions.cpp.
//
// Each oracle returns whether the input was refused (true) or accepted (false) when it was
// handled as it should be, and throws FuzzFailure naming what went wrong otherwise. A fuzz target turns a FuzzFailure into an
// abort(), which libFuzzer reports as a crash and keeps the input; the regression test fails.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli.hpp"
#include "config/scene_loader.hpp"
#include "core/errors.hpp"
#include "core/limits.hpp"
#include "world/spaces.hpp"
#include "world/world.hpp"

namespace stepwise::fuzz {

/// @brief An input the program mishandled: the message says how.
class FuzzFailure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Steps worth taking on a fuzzed scene: a few, and only while a step stays cheap, so that
/// libFuzzer spends its time on inputs, not on simulating a thousand bodies.
inline bool cheapEnoughToStep(const Scene& scene) {
    const std::size_t bodies = scene.dynamics.size() + scene.kinematics.size();
    const auto cheap = [](const WorldSettings& s) {
        return s.substeps * (s.velocityIterations + s.relaxIterations) <= 256 && s.impulseIterations <= 64;
    };
    for (const SpaceDef& space : scene.spaces) {
        if (!cheap(space.settings)) return false;
    }
    return bodies <= 64 && cheap(scene.settings);
}

/// A scene file's text must either be refused with a ConfigError (a diagnostic), or load into a
/// Scene the World accepts ("One validation for loader and engine", issue #34), whose first steps
/// end cleanly or with a SimulationError that names the failure.
inline bool checkSceneText(std::string_view text) {
    Scene scene;
    try {
        // No File=: an input's outcome must depend on its bytes alone, and a path the fuzzer
        // invents must not make it read whatever file it names (SceneReadOptions).
        scene = parseScene(text, "fuzz.scene", SceneReadOptions{.readFiles = false});
    } catch (const ConfigError&) {
        return true;  // refused, with a diagnostic: what a bad file should get
    } catch (const std::exception& error) {
        throw FuzzFailure(std::string("the loader threw something other than a ConfigError: ") + error.what());
    }
    const bool step = cheapEnoughToStep(scene);
    // A pool of threads per input costs more than the input: one thread computes the same bits
    // (tests "[threads]"). The loader has checked the count against kMaxThreads.
    scene.settings.threads = 1;
    for (SpaceDef& space : scene.spaces) space.settings.threads = 1;
    try {
        // A scene with spaces is several Worlds on one clock (src/world/spaces.hpp)
        Spaces spaces(std::move(scene));
        if (!step) return false;
        try {
            for (Space& space : spaces.all()) {
                for (int i = 0; i < 3; ++i) space.world.step();
            }
        } catch (const SimulationError&) {
            // a non-finite state, named: a clean report
        }
    } catch (const std::exception& error) {
        throw FuzzFailure(std::string("a scene the loader accepted failed in the World: ") + error.what());
    }
    return false;
}

/// A command line's bytes: its arguments separated by NUL bytes, the first one the command.
inline std::vector<std::string> commandLineOf(std::string_view bytes) {
    std::vector<std::string> args(1);
    for (const char c : bytes) {
        if (c == '\0') args.emplace_back();
        else args.back() += c;
    }
    return args;
}

/// A command line must parse, or be refused with a UsageError (which main() prints with exit
/// code 2). Nothing is run: only parsed.
inline bool checkCommandLine(const std::vector<std::string>& args) {
    using namespace stepwise::cli;
    const std::string& command = args.front();
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    try {
        parseCommandOptions(command, rest, "default.scene");
    } catch (const UsageError&) {
        return true;  // refused with a message: what a bad command line should get
    } catch (const std::exception& error) {
        throw FuzzFailure("the '" + command + "' parser threw something other than a UsageError: " + error.what());
    }
    return false;
}

}  // namespace stepwise::fuzz
