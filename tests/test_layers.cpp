// The folders of src/ are layers: a folder includes only folders below it (docs/architecture.md, "Layers").
// Tag: [layers].
//
// The order is read from the table in docs/architecture.md, so the page and the code cannot
// disagree: a new folder, or an include that runs up a layer or sideways between two folders of
// one layer, fails here with the file, the line and the two layers.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::filesystem::path kRoot = STEPWISE_SOURCE_DIR;

/// Folder → layer, from the rows "| N | `core/` … |" of docs/architecture.md's layer table.
std::map<std::string, int> layersFromArchitecturePage() {
    std::ifstream page(kRoot / "docs" / "architecture.md");
    REQUIRE(page);
    std::map<std::string, int> layers;
    const std::regex row(R"re(^\| *(\d+) *\| *((?:`[a-z_]+/`[ ,]*)+)\|)re");
    const std::regex folder("`([a-z_]+)/`");
    std::string line;
    while (std::getline(page, line)) {
        std::smatch match;
        if (!std::regex_search(line, match, row)) continue;
        const int layer = std::stoi(match[1]);
        const std::string folders = match[2];
        for (auto it = std::sregex_iterator(folders.begin(), folders.end(), folder); it != std::sregex_iterator(); ++it) {
            layers[(*it)[1]] = layer;
        }
    }
    return layers;
}

struct Include {
    std::string file;    ///< Below src/, e.g. "world/world.cpp".
    int line = 0;        ///< 1-based.
    std::string target;  ///< As written, e.g. "fast/fast_path.hpp".
};

/// Every `#include "folder/…"` line of every file below src/.
std::vector<Include> includesOfSource() {
    std::vector<Include> includes;
    const std::regex quoted(R"re(^\s*#\s*include\s*"([^"]+)")re");
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kRoot / "src")) {
        if (!entry.is_regular_file()) continue;
        std::ifstream file(entry.path());
        std::string text;
        int number = 0;
        while (std::getline(file, text)) {
            ++number;
            std::smatch match;
            if (std::regex_search(text, match, quoted)) {
                includes.push_back({std::filesystem::relative(entry.path(), kRoot / "src").generic_string(), number,
                                    match[1]});
            }
        }
    }
    return includes;
}

std::string folderOf(const std::string& path) { return path.substr(0, path.find('/')); }

}  // namespace

TEST_CASE("No folder of src/ includes a folder above it or beside it", "[layers]") {
    const std::map<std::string, int> layers = layersFromArchitecturePage();
    REQUIRE(layers.size() >= 10);  // the table was found and read: core, objects, … app
    REQUIRE(layers.count("core") == 1);
    REQUIRE(layers.at("core") == 0);

    // Every folder of src/ has a layer.
    for (const auto& entry : std::filesystem::directory_iterator(kRoot / "src")) {
        if (!entry.is_directory()) continue;
        const std::string name = entry.path().filename().string();
        INFO("src/" << name << "/ has no row in the layer table of docs/architecture.md");
        CHECK(layers.count(name) == 1);
    }

    const std::vector<Include> includes = includesOfSource();
    REQUIRE(includes.size() > 300);  // the whole tree was read
    int crossing = 0;
    for (const Include& include : includes) {
        if (include.target.find('/') == std::string::npos) continue;  // a file beside it: its own folder
        const std::string from = folderOf(include.file);
        const std::string to = folderOf(include.target);
        if (from == to) continue;
        ++crossing;
        REQUIRE(layers.count(from) == 1);
        INFO("src/" << include.file << ":" << include.line << " includes \"" << include.target << "\": " << from
                    << "/ is layer " << layers.at(from) << ", " << to << "/ is layer "
                    << (layers.count(to) ? std::to_string(layers.at(to)) : std::string("not in the table")));
        CHECK(layers.count(to) == 1);
        if (layers.count(to) == 1) CHECK(layers.at(to) < layers.at(from));
    }
    CHECK(crossing > 100);  // the layers do talk to each other: the check above was not empty
}

TEST_CASE("The layer test catches an include that runs up", "[layers]") {
    // The rule above, applied to a made-up include: world/ (layer 6 or so) into app/ (the top).
    const std::map<std::string, int> layers = layersFromArchitecturePage();
    REQUIRE(layers.count("world") == 1);
    REQUIRE(layers.count("app") == 1);
    CHECK_FALSE(layers.at("app") < layers.at("world"));  // "world/x.cpp includes app/cli.hpp" would fail
    CHECK(layers.at("core") < layers.at("world"));        // "world/x.cpp includes core/types.hpp" passes
}
