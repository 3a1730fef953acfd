// The debugger set-up of the lectures: .vscode/launch.json has one entry per
// scene the course map of lectures/README.md names (lecture 9's reference and
// stress scenes included), each sourcing a breakpoint file in
// lectures/gdb/breakpoints/ whose functions exist in the engine, and one entry
// per step-through session, lectures/gdb/NN-*.gdb, on the session's own command
// line; scripts/debug.sh starts gdb the same way; and the sessions stop at lines
// named by their code (break-at FILE "TEXT", lectures/gdb/stepwise.py), each of
// which is on exactly one line. Tag: [lectures].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "command_runner.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = STEPWISE_SOURCE_DIR;

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The scene files of config/ whose names start with @p prefix.
std::vector<std::string> scenesStartingWith(const std::string& prefix) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(kRoot / "config")) {
        const std::string stem = entry.path().stem().string();
        if (entry.path().extension() == ".scene" && stem.rfind(prefix, 0) == 0) names.push_back(stem);
    }
    std::sort(names.begin(), names.end());
    return names;
}

/// Every scene the course map of lectures/README.md names (its "scene(s)" column), by file stem.
/// A name with a `*` (`config/reference_*.scene`) stands for every scene file it matches.
std::vector<std::string> courseMapScenes() {
    std::ifstream in(kRoot / "lectures" / "README.md");
    const std::regex row(R"(^\| \d+a? \| [^|]+ \| ([^|]+) \|)");
    const std::regex named(R"(`config/([A-Za-z0-9_*]+)\.scene`)");
    std::vector<std::string> scenes;
    for (std::string line; std::getline(in, line);) {
        std::smatch cells;
        if (!std::regex_search(line, cells, row)) continue;
        const std::string column = cells[1];
        for (auto it = std::sregex_iterator(column.begin(), column.end(), named); it != std::sregex_iterator(); ++it) {
            const std::string name = (*it)[1];
            const std::size_t star = name.find('*');
            std::vector<std::string> matches;
            if (star == std::string::npos) {
                matches.push_back(name);
            } else {
                for (const std::string& stem : scenesStartingWith(name.substr(0, star))) {
                    const std::string suffix = name.substr(star + 1);
                    if (stem.size() >= suffix.size() && stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0)
                        matches.push_back(stem);
                }
                INFO("lectures/README.md names config/" << name << ".scene");
                CHECK(!matches.empty());  // a pattern that matches no file names nothing
            }
            for (const std::string& stem : matches) {
                if (std::find(scenes.begin(), scenes.end(), stem) == scenes.end()) scenes.push_back(stem);
            }
        }
    }
    return scenes;
}

/// The configurations of .vscode/launch.json, each as its text from its "name" to the next one's.
std::vector<std::string> launchEntries() {
    const std::string launch = readText(kRoot / ".vscode" / "launch.json");
    std::vector<std::string> entries;
    const std::string key = "\"name\": \"";
    for (std::size_t at = launch.find(key); at != std::string::npos;) {
        const std::size_t next = launch.find(key, at + 1);
        entries.push_back(launch.substr(at, next == std::string::npos ? std::string::npos : next - at));
        at = next;
    }
    return entries;
}

/// The entry of launch.json that contains @p text, or "" (and how many do, in @p count).
std::string entryWith(const std::vector<std::string>& entries, const std::string& text, int& count) {
    std::string found;
    count = 0;
    for (const std::string& entry : entries) {
        if (entry.find(text) == std::string::npos) continue;
        found = entry;
        ++count;
    }
    return found;
}

/// A session's header line "#   LABEL:  TEXT" (LABEL "interactive", "scene copy", …): TEXT, or "".
std::string headerLine(const fs::path& session, const std::string& label) {
    std::ifstream in(session);
    const std::string start = "#   " + label + ":";
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(start, 0) != 0) continue;
        const std::size_t text = line.find_first_not_of(' ', start.size());
        return text == std::string::npos ? "" : line.substr(text);
    }
    return "";
}

/// The command line after `--args build/debug/stepwise ` in a session's "interactive:" line.
std::string sessionArguments(const fs::path& session) {
    const std::string interactive = headerLine(session, "interactive");
    const std::string program = "--args build/debug/stepwise ";
    const std::size_t at = interactive.find(program);
    return at == std::string::npos ? "" : interactive.substr(at + program.size());
}

/// What a JSON string holds for @p text: backslashes and quotes escaped.
std::string jsonEscaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\\' || c == '"') out += '\\';
        out += c;
    }
    return out;
}

/// All engine sources, concatenated: where a breakpoint's function must be defined.
std::string engineSources() {
    std::string all;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kRoot / "src")) {
        if (entry.path().extension() == ".cpp") all += readText(entry.path());
    }
    return all;
}

bool isWordCharacter(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

std::size_t skipSpaces(const std::string& text, std::size_t at) {
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at])) != 0) ++at;
    return at;
}

/// Whether SOURCES define FUNCTION: its name as a whole word, "(", and then, before the next ";",
/// a ")" followed by an optional "const" and "{". A call or a declaration reaches a ";" first.
/// This is the regex \bNAME\s*\([^;]*\)\s*(const\s*)?\{ scanned by hand: std::regex
/// backtracks through every "(" of every engine file for each name, which under the
/// sanitizers' -O0 made this test one of the slowest of the suite.
bool definesFunction(const std::string& sources, const std::string& function) {
    for (std::size_t at = sources.find(function); at != std::string::npos; at = sources.find(function, at + 1)) {
        const std::size_t end = at + function.size();
        if ((at > 0 && isWordCharacter(sources[at - 1])) || (end < sources.size() && isWordCharacter(sources[end]))) {
            continue;  // part of a longer name
        }
        const std::size_t open = skipSpaces(sources, end);
        if (open >= sources.size() || sources[open] != '(') continue;
        const std::size_t stop = std::min(sources.find(';', open), sources.size());
        for (std::size_t close = sources.find(')', open); close < stop; close = sources.find(')', close + 1)) {
            std::size_t next = skipSpaces(sources, close + 1);
            if (sources.compare(next, 5, "const") == 0) next = skipSpaces(sources, next + 5);
            if (next < sources.size() && sources[next] == '{') return true;
        }
    }
    return false;
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

TEST_CASE("The breakpoint check tells a definition from a call, a declaration or a longer name", "[lectures]") {
    CHECK(definesFunction("void World::step(Real dt) {", "step"));
    CHECK(definesFunction("Real energy(const World& w)\n    const\n{", "energy"));
    CHECK(definesFunction("bool fits(Vec3 a, std::pair<int, int> b) { return true; }", "fits"));
    CHECK_FALSE(definesFunction("step(dt); if (x) {", "step"));           // a call: ";" comes first
    CHECK_FALSE(definesFunction("void step(Real dt);\nint y() {", "step"));  // a declaration
    CHECK_FALSE(definesFunction("void substep(Real dt) {", "step"));       // a longer name
    CHECK_FALSE(definesFunction("void step_all(Real dt) {", "step"));
    CHECK_FALSE(definesFunction("", "step"));
}

TEST_CASE("launch.json has one entry per lecture scene, with breakpoints that exist", "[lectures]") {
    const std::vector<std::string> entries = launchEntries();
    const std::string sources = engineSources();
    const std::vector<std::string> scenes = courseMapScenes();
    // The course map names every lesson scene, and lecture 9's reference and stress scenes by pattern.
    for (const char* prefix : {"lesson", "reference_", "stress_"}) {
        for (const std::string& scene : scenesStartingWith(prefix)) {
            INFO("config/" << scene << ".scene is not in lectures/README.md's course map");
            CHECK(std::find(scenes.begin(), scenes.end(), scene) != scenes.end());
        }
    }
    REQUIRE(scenes.size() >= 30);
    for (const std::string& scene : scenes) {
        INFO("config/" << scene << ".scene");
        // One entry sources the scene's breakpoints and runs the scene (session entries may run it too).
        const std::string breakpoints = "lectures/gdb/breakpoints/" + scene + ".gdb";
        int sourcing = 0;
        const std::string entry = entryWith(entries, "\"source ${workspaceFolder}/" + breakpoints + "\"", sourcing);
        CHECK(sourcing == 1);
        CHECK(entry.find("\"config/" + scene + ".scene\"") != std::string::npos);
        CHECK(entry.find("\"preLaunchTask\": \"build debug\"") != std::string::npos);
        REQUIRE(fs::exists(kRoot / breakpoints));

        // Each "break [scope::]function" names a function the engine defines.
        const std::string text = readText(kRoot / breakpoints);
        const std::regex breakLine(R"(^break\s+(?:[\w:() ]*::)?(\w+)\s*$)", std::regex::multiline);
        int count = 0;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), breakLine); it != std::sregex_iterator(); ++it) {
            const std::string function = (*it)[1];
            INFO("break " << function);
            CHECK(definesFunction(sources, function));
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

TEST_CASE("launch.json has one entry per gdb session, on the session's command line", "[lectures]") {
    // A session entry hands gdb the program, the command line of the session's "interactive:"
    // header line and the repository's folder, then sources the session, which runs the program
    // itself (launchCompleteCommand None: VS Code does not start it a second time).
    const std::vector<std::string> entries = launchEntries();
    const std::string tasks = readText(kRoot / ".vscode" / "tasks.json");
    int sessions = 0;
    for (const fs::path& session : lectureSessions()) {
        const std::string name = session.stem().string();
        INFO("lectures/gdb/" << name << ".gdb");
        int count = 0;
        const std::string entry = entryWith(entries, "\"source ${workspaceFolder}/lectures/gdb/" + name + ".gdb\"", count);
        CHECK(count == 1);
        const std::string arguments = sessionArguments(session);
        REQUIRE(!arguments.empty());
        CHECK(entry.find("\"-exec-arguments " + jsonEscaped(arguments) + "\"") != std::string::npos);
        CHECK(entry.find("\"launchCompleteCommand\": \"None\"") != std::string::npos);
        // A session on a copy of a scene has the copy made first, by scripts/debug.sh --prepare.
        const std::string task = headerLine(session, "scene copy").empty() ? "build debug" : "prepare session " + name;
        CHECK(entry.find("\"preLaunchTask\": \"" + task + "\"") != std::string::npos);
        CHECK(tasks.find("\"label\": \"" + task + "\"") != std::string::npos);
        if (task != "build debug") {
            CHECK(tasks.find("\"command\": \"scripts/debug.sh --prepare lectures/gdb/" + name + ".gdb\"") != std::string::npos);
        }
        ++sessions;
    }
    CHECK(sessions >= 28);
}

TEST_CASE("scripts/debug.sh starts gdb on each lecture scene and each session as the lectures do", "[lectures]") {
    // --dry-run prints the commands without running them: configure, build, the scene copy, then gdb.
    const std::string script = "cd '" + kRoot.string() + "' && scripts/debug.sh ";
    const auto lastLines = [](const std::string& output, std::size_t n) {
        std::vector<std::string> lines;
        std::istringstream in(output);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        if (lines.size() > n) lines.erase(lines.begin(), lines.end() - static_cast<std::ptrdiff_t>(n));
        return lines;
    };
    for (const std::string& scene : courseMapScenes()) {
        INFO("config/" << scene << ".scene");
        const stepwise::test::CommandResult r = stepwise::test::shell(script + "--dry-run config/" + scene + ".scene");
        CHECK(r.exitCode == 0);
        CHECK(lastLines(r.output, 1).at(0) == "gdb -x lectures/gdb/breakpoints/" + scene +
                                                  ".gdb --args build/debug/stepwise run config/" + scene + ".scene");
    }
    for (const fs::path& session : lectureSessions()) {
        const std::string name = "lectures/gdb/" + session.filename().string();
        INFO(name);
        const stepwise::test::CommandResult r = stepwise::test::shell(script + "--dry-run " + name);
        const std::string copy = headerLine(session, "scene copy");
        std::istringstream arguments(sessionArguments(session));
        std::string run;
        std::string scene;
        arguments >> run >> scene;  // "run SCENE [OPTIONS]"
        if (copy.empty() && scene.rfind("/tmp/", 0) == 0 && !fs::exists(scene)) {
            // A copy the student makes in an exercise: without it the script stops and says where it comes from.
            CHECK(r.exitCode == 2);
            CHECK(r.output.find(headerLine(session, "your copy")) != std::string::npos);
            continue;
        }
        CHECK(r.exitCode == 0);
        const std::vector<std::string> lines = lastLines(r.output, 2);
        CHECK(lines.at(1) == "gdb -x " + name + " --args build/debug/stepwise " + sessionArguments(session));
        if (!copy.empty()) {
            CHECK(lines.at(0) == copy);
            CHECK(copy.find("> " + scene) != std::string::npos);  // the copy is the scene the session runs
        }
    }
    // Bad input: exit 2 and a message naming the cause.
    const stepwise::test::CommandResult none = stepwise::test::shell(script);
    CHECK(none.exitCode == 2);
    CHECK(none.output.find("usage: scripts/debug.sh") != std::string::npos);
    const stepwise::test::CommandResult missing = stepwise::test::shell(script + "config/no_such.scene");
    CHECK(missing.exitCode == 2);
    CHECK(missing.output.find("no scene file 'config/no_such.scene'") != std::string::npos);
    const stepwise::test::CommandResult other = stepwise::test::shell(script + "README.md");
    CHECK(other.exitCode == 2);
    CHECK(other.output.find("neither a scene") != std::string::npos);
}
