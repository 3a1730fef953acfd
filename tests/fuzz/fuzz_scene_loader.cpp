// libFuzzer target: the scene loader, and the World that takes what the loader accepts.
//
// What counts as a bug is checkSceneText() in fuzz_oracles.hpp: anything but a ConfigError out
// of the loader, any exception out of the World for a scene the loader accepted, anything but a
// SimulationError out of the first few steps. AddressSanitizer and UndefinedBehaviorSanitizer
// add every memory error and undefined operation. Run it (the `fuzz` preset, README "Fuzzing"):
//   build/fuzz/tests/fuzz/fuzz_scene_loader -max_total_time=600 build/fuzz/corpus/scenes build/fuzz/seeds/scenes
// An input it stops on goes into tests/fuzz/regressions/scenes/ once fixed.
#include <cstdio>
#include <cstdlib>

#include "fuzz_oracles.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        stepwise::fuzz::checkSceneText(std::string_view(reinterpret_cast<const char*>(data), size));
    } catch (const stepwise::fuzz::FuzzFailure& failure) {
        std::fprintf(stderr, "fuzz_scene_loader: %s\n", failure.what());
        std::abort();  // libFuzzer keeps the input
    }
    return 0;
}
