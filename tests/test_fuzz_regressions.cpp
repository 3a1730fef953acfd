// Replays, through the fuzz targets' own oracles (tests/fuzz/fuzz_oracles.hpp), the inputs that
// once crashed, hung or were misread: those found by the hostile-input campaign of issue 34 and
// any the fuzzers find later. Every input in tests/fuzz/regressions/ is one the program must
// refuse with a message (a ConfigError for a scene, a UsageError for a command line). A fixed
// fuzzer finding goes there, named after what it does, with the fix.
// The shipped scenes and the fuzzers' seeds are replayed too: the oracles must accept them.
// Tags: [fuzz].
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "fuzz/fuzz_oracles.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kFuzz = fs::path(STEPWISE_SOURCE_DIR) / "tests" / "fuzz";

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("Every scene in tests/fuzz/regressions/scenes is refused by the loader", "[fuzz]") {
    int replayed = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(kFuzz / "regressions" / "scenes")) {
        INFO(entry.path().filename().string());
        bool refused = false;
        REQUIRE_NOTHROW(refused = stepwise::fuzz::checkSceneText(readBytes(entry.path())));
        CHECK(refused);
        ++replayed;
    }
    CHECK(replayed >= 9);
}

TEST_CASE("Every command line in tests/fuzz/regressions/cli is refused by its parser", "[fuzz]") {
    int replayed = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(kFuzz / "regressions" / "cli")) {
        INFO(entry.path().filename().string());
        bool refused = false;
        REQUIRE_NOTHROW(refused = stepwise::fuzz::checkCommandLine(stepwise::fuzz::commandLineOf(readBytes(entry.path()))));
        CHECK(refused);
        ++replayed;
    }
    CHECK(replayed >= 5);
}

TEST_CASE("The fuzzers' seeds pass their oracles: command lines parse, and the shipped scenes load", "[fuzz]") {
    // A seed the oracle refuses would start the fuzzer from nothing useful; one it calls a
    // failure would stop it at once.
    int lines = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(kFuzz / "seeds" / "cli")) {
        INFO(entry.path().filename().string());
        bool refused = true;
        REQUIRE_NOTHROW(refused = stepwise::fuzz::checkCommandLine(stepwise::fuzz::commandLineOf(readBytes(entry.path()))));
        CHECK_FALSE(refused);
        ++lines;
    }
    CHECK(lines >= 10);  // every command but check (which has no options) and view twice
    int scenes = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(STEPWISE_SOURCE_DIR) / "config")) {
        if (entry.path().extension() != ".scene") continue;
        INFO(entry.path().filename().string());
        const std::string text = readBytes(entry.path());
        // The oracle reads no file (its input's outcome must depend on its bytes alone), so it
        // refuses a scene that names an OBJ model; such a scene is no seed.
        if (text.find("File=") != std::string::npos) continue;
        bool refused = true;
        REQUIRE_NOTHROW(refused = stepwise::fuzz::checkSceneText(text));
        CHECK_FALSE(refused);
        ++scenes;
    }
    CHECK(scenes >= 30);
}
