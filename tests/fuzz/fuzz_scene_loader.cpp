// libFuzzer target: the scene loader, and the World that takes what the loader accepts.
//
// What counts as a bug (libFuzzer stops and keeps the input):
// - anything but a ConfigError out of parseScene(): the loader must refuse bad text with a
//   diagnostic, never crash, hang or throw something else;
// - any exception out of World(scene) for a scene the loader accepted: the loader checks all
//   the World checks ("One validation for loader and engine", issue #34);
// - anything but a SimulationError out of the first few steps.
// AddressSanitizer and UndefinedBehaviorSanitizer add every memory error and undefined
// operation. Run it (the `fuzz` preset, README "Fuzzing"):
//   build/fuzz/tests/fuzz/fuzz_scene_loader -max_total_time=600 build/fuzz/corpus/scenes tests/fuzz/seeds/scenes
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "config/scene_loader.hpp"
#include "core/errors.hpp"
#include "world/world.hpp"

namespace {

/// Steps worth taking on a fuzzed scene: a few, and only while a step stays cheap, so that
/// libFuzzer spends its time on inputs, not on simulating a thousand bodies.
bool cheapEnoughToStep(const stepwise::Scene& scene) {
    const std::size_t bodies = scene.dynamics.size() + scene.kinematics.size();
    const auto& s = scene.settings;
    return bodies <= 64 && s.substeps * (s.velocityIterations + s.relaxIterations) <= 256 && s.impulseIterations <= 64;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace stepwise;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Scene scene;
    try {
        scene = parseScene(text, "fuzz.scene");
    } catch (const ConfigError&) {
        return 0;  // refused, with a diagnostic: what a bad file should get
    }
    const bool step = cheapEnoughToStep(scene);
    // A pool of threads per input costs more than the input: one thread computes the same bits
    // (tests "[threads]"). A count past the documented range is left for the World to meet.
    if (scene.settings.threads >= 0 && scene.settings.threads <= 256) scene.settings.threads = 1;
    World world(std::move(scene));  // must not throw: the loader accepted it
    if (!step) return 0;
    try {
        for (int i = 0; i < 3; ++i) world.step();
    } catch (const SimulationError&) {
        // a non-finite state, named: a clean report
    }
    return 0;
}
