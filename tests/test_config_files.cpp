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
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "config/field_values.hpp"
#include "config/scene_loader.hpp"
#include "config/scene_records.hpp"
#include "core/limits.hpp"
#include "expectation_runner.hpp"

using namespace stepwise;
using namespace stepwise::config;
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
/// The ```scene examples load as if they were a scene in config/, so that a `File=models/….obj`
/// in one reads the model shipped in config/models/ (a File= is relative to its scene's folder).
const std::string kExampleInConfig = STEPWISE_SOURCE_DIR "/config/example.scene";
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
                const Scene scene = parseScene(block.body, kExampleInConfig);
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

namespace {

/// The lines of @p markdown from the heading that names @p record (e.g. "## DynamicObject {#...}",
/// "### DistanceJoint and Rope {#...}") to the next heading of the same or a higher level.
std::vector<std::string> sectionOf(const std::string& markdown, std::string_view record) {
    std::vector<std::string> section;
    std::istringstream lines(markdown);
    std::string line;
    std::size_t level = 0;
    const std::regex names("^(#{2,3}) .*\\b" + std::string(record) + "\\b.*\\{#");
    while (std::getline(lines, line)) {
        const std::size_t hashes = line.find_first_not_of('#');
        const bool heading = hashes != std::string::npos && hashes >= 1 && line[hashes] == ' ';
        if (level == 0) {
            std::smatch match;
            if (std::regex_search(line, match, names)) level = match[1].length();
        } else if (heading && hashes <= level) {
            break;
        } else {
            section.push_back(line);
        }
    }
    return section;
}

/// The cells of a Markdown table row "| a | b |", trimmed.
std::vector<std::string> cellsOf(const std::string& row) {
    std::vector<std::string> cells;
    std::string cell;
    for (std::size_t i = 1; i < row.size(); ++i) {
        if (row[i] == '|') {
            cells.push_back(trimmed(cell));
            cell.clear();
        } else {
            cell += row[i];
        }
    }
    return cells;
}

/// What the *Valid* cell of a field of range @p range must say, taken from the words the loader's
/// diagnostics use (describe()), so that both come from the constants of src/core/limits.hpp.
std::string documentedRange(Range range) {
    switch (range) {
        case Range::Positive: return "> 0";
        case Range::NonNegative: return "≥ 0";
        case Range::UnitInterval: return "0–1";
        default: break;
    }
    const std::string words = describe(range);  // "a size from 1e-6 to 1e6 m", "a length of at least 1e-6 m"
    std::smatch match;
    if (std::regex_search(words, match, std::regex("from (\\S+ to \\S+)"))) return match[1];
    if (std::regex_search(words, match, std::regex("at least (\\S+)"))) return "≥ " + match[1].str();
    FAIL("no documented form for the range described as '" << words << "'");
    return {};
}

}  // namespace

TEST_CASE("The Valid column of docs/config-format.md gives every field's range as the loader checks it",
          "[config]") {
    const std::string markdown = readText(STEPWISE_SOURCE_DIR "/docs/config-format.md");
    std::size_t checked = 0;
    for (const RecordSpec& record : allRecords()) {
        const std::vector<std::string> section = sectionOf(markdown, record.name);
        for (const FieldSpec& field : record.fields) {
            const bool numeric = field.kind == FieldKind::Number || field.kind == FieldKind::Vector || field.kind == FieldKind::Color;
            if (field.range == Range::Any || !numeric) continue;
            // A Space takes every World field: those rows are the World section's
            if (record.kind == RecordKind::Space && findField(*findRecord("World"), field.name)) continue;
            INFO(record.name << "." << field.name << ": expected '" << documentedRange(field.range) << "'");
            // Find the field's row: the table's header names the Valid column.
            int validColumn = -1;
            std::string validCell;
            bool found = false;
            for (const std::string& line : section) {
                if (line.rfind('|', 0) != 0) continue;
                const std::vector<std::string> cells = cellsOf(line);
                for (std::size_t c = 0; c < cells.size(); ++c) {
                    if (cells[c] == "Valid") validColumn = int(c);
                }
                const std::string name = "`" + std::string(field.name) + "`";
                for (const std::string& cell : cells) {
                    if (cell.rfind(name, 0) == 0 && validColumn >= 0 && validColumn < int(cells.size())) {
                        validCell = cells[validColumn];
                        found = true;
                    }
                }
                if (found) break;
            }
            if (!found) {
                // Expect and MayChange list their fields in prose; the rest must have a table row.
                if (record.kind == RecordKind::Expect || record.kind == RecordKind::MayChange) continue;
                FAIL_CHECK("no table row in the record's section");
                continue;
            }
            INFO("Valid cell: '" << validCell << "'");
            // A count checked as whole elsewhere (Expect's Apex) may say "whole number ≥ 1" for "> 0".
            const bool wholeCount = field.range == Range::Positive && validCell == "whole number ≥ 1";
            CHECK((validCell.find(documentedRange(field.range)) != std::string::npos || wholeCount));
            ++checked;
        }
    }
    // Mass, Radius, Scale, Elasticity, Friction, the World's counts and rates, springs, joints...
    CHECK(checked >= 40);
}

TEST_CASE("The mass ratio the docs quote is the solver's kMaxMassRatio", "[config][solver]") {
    // Prose wraps lines anywhere: compare with runs of white space made one space.
    const auto flattened = [](const std::string& text) {
        return std::regex_replace(text, std::regex("\\s+"), " ");
    };
    const std::string ratio = std::to_string(static_cast<long long>(kMaxMassRatio));
    const std::string reference = flattened(readText(STEPWISE_SOURCE_DIR "/docs/config-format.md"));
    CHECK_THAT(reference, Catch::Matchers::Contains("one more than " + ratio + " times heavier than the other"));
    const std::string lecture = flattened(readText(STEPWISE_SOURCE_DIR "/lectures/08-constraint-solver.md"));
    CHECK_THAT(lecture, Catch::Matchers::Contains("at " + ratio + ":1 both overlaps stay under 1 cm"));
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
