// The debugger set-up of the lectures: .vscode/launch.json has one entry per
// lecture scene, each sourcing a breakpoint file in lectures/gdb/breakpoints/
// whose functions exist in the engine; and the step-through sessions in
// lectures/gdb/NN-*.gdb stop at lines named by their code (break-at FILE "TEXT",
// lectures/gdb/stepwise.py), each of which is on exactly one line. Tag: [lectures].
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

/// The files under src/ whose path ends with /NAME (what stepwise.py's find_file() matches).
std::vector<fs::path> sourcesNamed(const std::string& name) {
    std::vector<fs::path> found;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kRoot / "src")) {
        const std::string path = entry.path().generic_string();
        if (path.size() > name.size() && path.compare(path.size() - name.size() - 1, std::string::npos, "/" + name) == 0) {
            found.push_back(entry.path());
        }
    }
    return found;
}

/// How many lines of FILE contain TEXT (stepwise.py's find_line() needs exactly 1).
int linesContaining(const fs::path& file, const std::string& text) {
    std::ifstream in(file);
    int count = 0;
    for (std::string line; std::getline(in, line);) count += line.find(text) != std::string::npos ? 1 : 0;
    return count;
}

/// The step-through sessions: lectures/gdb/NN-*.gdb.
std::vector<fs::path> lectureSessions() {
    std::vector<fs::path> sessions;
    for (const fs::directory_entry& entry : fs::directory_iterator(kRoot / "lectures" / "gdb")) {
        if (entry.path().extension() == ".gdb") sessions.push_back(entry.path());
    }
    std::sort(sessions.begin(), sessions.end());
    return sessions;
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

TEST_CASE("lecture gdb sessions name their breakpoints by code, and each anchor is on exactly one line", "[lectures]") {
    const std::vector<fs::path> sessions = lectureSessions();
    REQUIRE(sessions.size() >= 20);
    // break-at / tbreak-at / until-at FILE "TEXT" [+N] [if COND]: the same grammar as stepwise.py's ANCHOR.
    const std::regex anchored(R"re(^\s*(?:t?break|until)-at\s+(\S+)\s+"((?:[^"\\]|\\.)*)"\s*(?:\+\d+)?\s*(?:if\s+.+)?$)re");
    // A line number that goes stale: break file.cpp:93, tbreak 187, until 187, advance world.cpp:97.
    const std::regex numbered(R"(^\s*(?:t?break|until|advance|b|tb)\s+(?:\S+:)?\d+\b.*$)");
    int anchors = 0;
    for (const fs::path& session : sessions) {
        std::ifstream in(session);
        bool sourced = false;
        int number = 0;
        for (std::string line; std::getline(in, line);) {
            ++number;
            INFO(session.filename().string() << ":" << number << ": " << line);
            CHECK_FALSE(std::regex_match(line, numbered));
            if (line.rfind("source lectures/gdb/stepwise.py", 0) == 0) sourced = true;
            if (line.find("-at ") == std::string::npos || line.rfind("#", 0) == 0) continue;
            std::smatch match;
            REQUIRE(std::regex_match(line, match, anchored));
            CHECK(sourced);  // the commands exist only after stepwise.py is sourced
            const std::vector<fs::path> files = sourcesNamed(match[1]);
            REQUIRE(files.size() == 1);
            std::string text = match[2];
            text = std::regex_replace(text, std::regex(R"(\\(["\\]))"), "$1");
            CHECK(linesContaining(files[0], text) == 1);
            ++anchors;
        }
    }
    CHECK(anchors >= 27);  // every stale break file:LINE of issue #8 became an anchor
}
