// The debugger set-up of the lectures: .vscode/launch.json has one entry per
// lecture scene, each sourcing a breakpoint file in lectures/gdb/breakpoints/
// whose functions exist in the engine. Tag: [lectures].
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = STEPWISE_SOURCE_DIR;

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Every lecture scene: config/lessonNN_*.scene.
std::vector<std::string> lectureScenes() {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(kRoot / "config")) {
        const std::string stem = entry.path().stem().string();
        if (entry.path().extension() == ".scene" && stem.rfind("lesson", 0) == 0) names.push_back(stem);
    }
    std::sort(names.begin(), names.end());
    return names;
}

/// All engine sources, concatenated: where a breakpoint's function must be defined.
std::string engineSources() {
    std::string all;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kRoot / "src")) {
        if (entry.path().extension() == ".cpp") all += readText(entry.path());
    }
    return all;
}

}  // namespace

TEST_CASE("launch.json has one entry per lecture scene, with breakpoints that exist", "[lectures]") {
    const std::string launch = readText(kRoot / ".vscode" / "launch.json");
    const std::string sources = engineSources();
    const std::vector<std::string> scenes = lectureScenes();
    REQUIRE(scenes.size() >= 10);
    for (const std::string& scene : scenes) {
        INFO("config/" << scene << ".scene");
        CHECK(launch.find("\"config/" + scene + ".scene\"") != std::string::npos);
        const std::string breakpoints = "lectures/gdb/breakpoints/" + scene + ".gdb";
        CHECK(launch.find("source ${workspaceFolder}/" + breakpoints) != std::string::npos);
        REQUIRE(fs::exists(kRoot / breakpoints));

        // Each "break [scope::]function" names a function the engine defines.
        const std::string text = readText(kRoot / breakpoints);
        const std::regex breakLine(R"(^break\s+(?:[\w:() ]*::)?(\w+)\s*$)", std::regex::multiline);
        int count = 0;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), breakLine); it != std::sregex_iterator(); ++it) {
            const std::string function = (*it)[1];
            INFO("break " << function);
            CHECK(std::regex_search(sources, std::regex("\\b" + function + "\\s*\\([^;]*\\)\\s*(const\\s*)?\\{")));
            ++count;
        }
        CHECK(count >= 1);
    }
}
