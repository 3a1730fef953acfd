/// @file test_config_files.cpp
/// @brief Files on disk: loadSceneFile, every example in docs/config-format.md, every shipped scene.
///
/// The documentation's examples are tests: a ```scene block must load (and
/// its Expect records must pass), a
/// ```scene-error block must fail with exactly the message printed in the
/// ```text block that follows it. So the reference cannot drift from the code.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "config/scene_loader.hpp"
#include "expectation_runner.hpp"

using namespace stepwise;
namespace fs = std::filesystem;

namespace {

/// A fenced code block of a Markdown file.
struct FencedBlock {
    std::string tag;   ///< Info string after the opening fence, e.g. "scene".
    std::string body;  ///< Lines between the fences, each ending in '\n'.
    int line = 0;      ///< 1-based line of the opening fence.
};

constexpr std::string_view kFence = "```";
/// Source name the documented error messages are printed with.
const std::string kExampleSource = "example.scene";
/// The reference documents every record in positional and named form, plus
/// the World record: fewer blocks than this means the extraction broke.
constexpr std::size_t kMinimumSceneBlocks = 8;
constexpr std::size_t kMinimumErrorBlocks = 3;

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE(in.good());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string trimmed(std::string text) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!text.empty() && blank(text.back())) text.pop_back();
    std::size_t start = 0;
    while (start < text.size() && blank(text[start])) ++start;
    return text.substr(start);
}

std::vector<FencedBlock> fencedBlocks(const std::string& markdown) {
    std::vector<FencedBlock> blocks;
    std::istringstream lines(markdown);
    std::string line;
    int number = 0;
    bool inside = false;
    while (std::getline(lines, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.rfind(kFence, 0) == 0) {
            if (inside) {
                inside = false;
            } else {
                inside = true;
                blocks.push_back(FencedBlock{trimmed(line.substr(kFence.size())), "", number});
            }
        } else if (inside) {
            blocks.back().body += line + '\n';
        }
    }
    REQUIRE_FALSE(inside);  // an unterminated fence would swallow the rest of the document
    return blocks;
}

}  // namespace

TEST_CASE("loadSceneFile reads a file and records its path", "[config]") {
    const fs::path path = fs::temp_directory_path() / "stepwise_test_config_load.scene";
    {
        std::ofstream out(path, std::ios::binary);
        out << "World, TimeStep=1/120\r\nDynamicObject, Name=Ball, Position=(0, 2, 0)\r\nCollisionPlane\r\n";
    }
    const Scene scene = loadSceneFile(path.string());
    fs::remove(path);
    CHECK(scene.sourcePath == path.string());
    CHECK(scene.settings.timeStep == Approx(1.0 / 120));
    REQUIRE(scene.dynamics.size() == 1);
    CHECK(scene.dynamics[0].name == "Ball");
    CHECK(scene.planes.size() == 1);
}

TEST_CASE("loadSceneFile names the file in its diagnostics", "[config]") {
    const fs::path path = fs::temp_directory_path() / "stepwise_test_config_bad.scene";
    {
        std::ofstream out(path, std::ios::binary);
        out << "DynamicObject, Mass=-1\n";
    }
    try {
        (void)loadSceneFile(path.string());
        fs::remove(path);
        FAIL("should have thrown");
    } catch (const ConfigError& error) {
        fs::remove(path);
        CHECK_THAT(std::string(error.what()), Catch::StartsWith(path.string() + ":1:21: error: Mass:"));
    }
}

TEST_CASE("Every example in docs/config-format.md behaves as documented", "[config]") {
    const std::string markdown = readText(STEPWISE_SOURCE_DIR "/docs/config-format.md");
    const std::vector<FencedBlock> blocks = fencedBlocks(markdown);

    std::size_t scenes = 0;
    std::size_t errors = 0;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const FencedBlock& block = blocks[i];
        INFO("docs/config-format.md:" << block.line << " (```" << block.tag << ")\n" << block.body);
        if (block.tag == "scene") {
            ++scenes;
            try {
                const Scene scene = parseScene(block.body, kExampleSource);
                if (!scene.expectations.empty()) {
                    // An example of Expect records must show ones that hold.
                    const test::ExpectationOutcome outcome = test::runExpectations(scene);
                    for (std::size_t k = 0; k < outcome.results.size(); ++k) {
                        INFO(describe(outcome.expectations[k]) << " -> "
                                                                << describeMeasurement(outcome.expectations[k],
                                                                                       outcome.results[k]));
                        CHECK(outcome.results[k].passed);
                    }
                }
            } catch (const ConfigError& error) {
                FAIL("a ```scene example does not load:\n" << error.what());
            }
        } else if (block.tag == "scene-error") {
            ++errors;
            // The block after it must be the ```text block with the exact message.
            REQUIRE(i + 1 < blocks.size());
            REQUIRE(blocks[i + 1].tag == "text");
            const std::string documented = trimmed(blocks[i + 1].body);
            try {
                (void)parseScene(block.body, kExampleSource);
                FAIL("a ```scene-error example loads without error");
            } catch (const ConfigError& error) {
                CHECK(std::string(error.what()) == documented);
            }
        }
    }
    CHECK(scenes >= kMinimumSceneBlocks);
    CHECK(errors >= kMinimumErrorBlocks);
}

TEST_CASE("Every scene shipped in config/ loads", "[config]") {
    const fs::path folder = STEPWISE_SOURCE_DIR "/config";
    std::size_t loaded = 0;
    if (fs::is_directory(folder)) {
        for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
            if (!entry.is_regular_file() || entry.path().extension() != ".scene") continue;
            INFO(entry.path().string());
            try {
                (void)loadSceneFile(entry.path().string());
                ++loaded;
            } catch (const ConfigError& error) {
                FAIL("a shipped scene does not load:\n" << error.what());
            }
        }
    }
    if (loaded == 0) WARN("no .scene files in " << folder.string() << " yet: nothing to check");
    SUCCEED("loaded " << loaded << " scene files");
}
