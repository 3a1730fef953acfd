// The ready assignments in lectures/assignments/: each starter scene fails its
// Expect records, each reference solution passes the same records and changes
// only what the starter's MayChange records allow, and `stepwise grade`
// refuses the wrong answers tried in lectures/instructors/tried-answers/ with
// a message that says what it measured or which line changed something else.
// Tag: [assignments].
//
// The expectations themselves come from closed-form physics (each README and
// solution derives its numbers); this test checks that the engine meets them
// for the solution and not for the starter or a wrong answer, so an
// assignment cannot silently become unsolvable, solved before the student
// starts, or solvable by an answer its statement calls wrong.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "assignment_files.hpp"
#include "command_runner.hpp"
#include "config/scene_changes.hpp"
#include "config/scene_loader.hpp"
#include "expectation_runner.hpp"

using namespace stepwise;
using namespace stepwise::test;
using Catch::Contains;

namespace {

/// The issue asks for at least five ready assignments.
constexpr std::size_t kMinimumAssignments = 5;
/// Each assignment is tried with at least this many wrong answers.
constexpr std::size_t kMinimumWrongAnswers = 2;
/// What a tried answer's header says the grade must be.
const std::string kGradeLine = "# Grade: ";
/// Set this variable to rewrite the answer table of lectures/instructors/README.md instead of checking it.
constexpr const char* kUpdateTable = "STEPWISE_UPDATE_ANSWER_TABLE";
const std::string kTableStart = "<!-- answer table:";
const std::string kTableEnd = "<!-- end of the answer table -->";

/// Every expectation in words, to compare the starter's with the solution's.
std::vector<std::string> described(const std::vector<Expectation>& expectations) {
    std::vector<std::string> words;
    for (const Expectation& e : expectations) words.push_back(describe(e));
    return words;
}

std::vector<std::string> described(const std::vector<MayChange>& allowed) {
    std::vector<std::string> words;
    for (const MayChange& m : allowed) words.push_back(describeAllowed(m));
    return words;
}

std::string report(const test::ExpectationOutcome& outcome) {
    std::string text;
    for (std::size_t i = 0; i < outcome.results.size(); ++i) {
        text += (outcome.results[i].passed ? "PASS " : "FAIL ") + describe(outcome.expectations[i]) + " -> " +
                describeMeasurement(outcome.expectations[i], outcome.results[i]) + "\n";
    }
    return text;
}

/// One row of `stepwise grade`'s table.
struct GradeRow {
    std::string result;  ///< PASS, FAIL or ERROR.
    std::string note;    ///< The first failure.
};

/// Runs `stepwise grade` and reads its table: file below the folder → row.
std::map<std::string, GradeRow> grade(const fs::path& folder, const std::string& glob, const fs::path& starter) {
    const CommandResult run = shell("'" + std::string(STEPWISE_CLI_PATH) + "' grade '" + folder.string() +
                                    "' --scene-glob '" + glob + "' --expect '" + starter.string() + "'");
    INFO(run.output);
    CHECK((run.exitCode == 0 || run.exitCode == 3));
    static const std::regex row(R"(^  (\S+)\s+(PASS|FAIL|ERROR)\s+\S+\s*(.*)$)");
    std::map<std::string, GradeRow> rows;
    std::istringstream lines(run.output);
    std::string line;
    while (std::getline(lines, line)) {
        std::smatch match;
        if (std::regex_match(line, match, row)) rows[match[1]] = {match[2], match[3]};
    }
    return rows;
}

/// The grade a tried answer's header asks for: "PASS", or "FAIL <first failure>".
std::string declaredGrade(const std::string& text) {
    const std::size_t at = text.find(kGradeLine);
    if (at == std::string::npos) return "";
    const std::size_t end = text.find('\n', at);
    return text.substr(at + kGradeLine.size(), end - at - kGradeLine.size());
}

/// "line 13:27: error: ball.PositionY: …" → "ball.PositionY: …": the change's own words.
std::string withoutLocation(const std::string& note) {
    static const std::regex location(R"(^line \d+:\d+: error: )");
    return std::regex_replace(note, location, "");
}

/// Does a FAIL note say what was measured (a value after "->"), or which line and column changed what?
bool saysWhy(const std::string& note) {
    static const std::regex measured(R"( -> (-?[0-9]|not reached))");
    static const std::regex changed(R"(^line \d+:\d+: error: \S+\.\S+: expected .*, found ')");
    return std::regex_search(note, measured) || std::regex_search(note, changed);
}

/// "ball.Elasticity 0.5 → 0.9" for each change of @p file against @p starter.
std::string changesInWords(const fs::path& starter, const fs::path& file, const std::vector<MayChange>& allowed) {
    std::string words;
    for (const SceneChange& c : compareWithStarter(readFile(starter), readFile(file), allowed)) {
        std::string one;
        if (c.field.empty()) {
            one = (c.line > 0 ? "adds " : "removes ") + c.record + " '" + c.object + "'";
        } else {
            one = (c.object.empty() ? "World" : c.object) + "." + c.field + " " +
                  (c.before.empty() ? "(left out)" : c.before) + " → " + (c.after.empty() ? "(left out)" : c.after);
        }
        if (!c.allowed) one = "**" + one + "**";
        words += (words.empty() ? "" : "; ") + one;
    }
    return words;
}

/// The answer table of lectures/instructors/README.md, as the files give it.
std::string answerTable() {
    std::string table =
        "| assignment | file | what it changes in the starter (**bold**: not allowed) | `stepwise grade --expect starter.scene` |\n"
        "|---|---|---|---|\n";
    for (const fs::path& folder : assignmentFolders()) {
        const std::string name = folder.filename().string();
        const fs::path starter = folder / "starter.scene";
        const std::vector<MayChange> allowed = loadSceneFile(starter.string()).mayChange;
        std::string first = name;
        const auto row = [&](const std::string& link, const fs::path& file, const std::string& verdict) {
            table += "| " + first + " | " + link + " | " + changesInWords(starter, file, allowed) + " | " + verdict + " |\n";
            first = "";
        };
        const fs::path solution = kSolutions / (name + ".scene");
        row("[solution](solutions/" + name + ".scene)", solution, "PASS");
        for (const fs::path& tried : filesBelow(kTriedAnswers / name)) {
            const std::string stem = tried.stem().string();
            std::string verdict = declaredGrade(readFile(tried));
            if (verdict.rfind("FAIL ", 0) == 0) verdict = "FAIL: " + verdict.substr(5);
            row("[" + stem + "](tried-answers/" + name + "/" + stem + ".scene)", tried, verdict);
        }
    }
    return table;
}

}  // namespace

TEST_CASE("Every assignment's starter fails, and its solution passes the same expectations changing only what MayChange allows",
          "[assignments]") {
    const std::vector<fs::path> folders = assignmentFolders();
    CHECK(folders.size() >= kMinimumAssignments);
    const bool answersHandedOut = fs::is_directory(kInstructors);
    if (!answersHandedOut) WARN("no lectures/instructors/ (a student copy): only the starters are checked");

    // The students' pages never point into the instructors' folder.
    CHECK_THAT(readFile(kAssignments / "README.md"), !Contains("instructors/"));

    for (const fs::path& folder : folders) {
        const std::string name = folder.filename().string();
        INFO("lectures/assignments/" << name);

        // The statement says what to edit and gives the exact command that checks it.
        const std::string readme = readFile(folder / "README.md");
        CHECK(readme.find("stepwise run lectures/assignments/" + name + "/starter.scene") != std::string::npos);
        CHECK_THAT(readme, !Contains("instructors/"));

        const Scene starter = loadSceneFile((folder / "starter.scene").string());
        REQUIRE_FALSE(starter.expectations.empty());
        // Without MayChange records grading could not refuse an answer that moves something else.
        REQUIRE_FALSE(starter.mayChange.empty());

        // A README that shows the table's lines shows the starter's own: "  PASS   20    ball: …".
        static const std::regex shownRow(R"(^  (PASS|FAIL)\s+(\d+)\s+(.+?)\s{2,}(.*)$)");
        std::istringstream lines(readme);
        std::string line;
        while (std::getline(lines, line)) {
            std::smatch match;
            if (!std::regex_match(line, match, shownRow)) continue;
            INFO("README line: " << line);
            const int shownLine = std::stoi(match[2]);
            const auto same = std::find_if(starter.expectations.begin(), starter.expectations.end(),
                                           [&](const Expectation& e) { return e.line == shownLine; });
            REQUIRE(same != starter.expectations.end());
            CHECK(describe(*same) == std::string(match[3]));
        }

        const test::ExpectationOutcome started = test::runExpectations(starter);
        INFO("starter:\n" << report(started));
        CHECK_FALSE(started.allPassed());

        if (!answersHandedOut) continue;
        const fs::path solutionPath = kSolutions / (name + ".scene");
        REQUIRE(fs::exists(solutionPath));
        const Scene solution = loadSceneFile(solutionPath.string());
        // Passing other expectations, or being allowed other changes, would prove nothing.
        CHECK(described(solution.expectations) == described(starter.expectations));
        CHECK(described(solution.mayChange) == described(starter.mayChange));
        const test::ExpectationOutcome solved = test::runExpectations(solution);
        INFO("solution:\n" << report(solved));
        CHECK(solved.allPassed());

        // The solution answers by the fields the assignment names, and by nothing else.
        const std::vector<SceneChange> changes =
            compareWithStarter(readFile(folder / "starter.scene"), readFile(solutionPath), starter.mayChange);
        CHECK_FALSE(changes.empty());
        for (const SceneChange& change : changes) {
            INFO(changeDiagnostic(change, solutionPath.string(), starter.mayChange).message());
            CHECK(change.allowed);
        }
    }
}

TEST_CASE("stepwise grade refuses every wrong answer tried, saying what it measured or what changed, and passes the right ones",
          "[assignments][cli]") {
    if (!fs::is_directory(kInstructors)) {
        WARN("no lectures/instructors/ (a student copy): no answers to try");
        return;
    }
    for (const fs::path& folder : assignmentFolders()) {
        const std::string name = folder.filename().string();
        const fs::path starter = folder / "starter.scene";
        INFO("lectures/assignments/" << name);

        // The untouched starter fails, saying what it measured.
        const auto started = grade(kAssignments, name + "/starter.scene", starter);
        REQUIRE(started.count(name + "/starter.scene") == 1);
        const GradeRow& starterRow = started.at(name + "/starter.scene");
        INFO("starter: " << starterRow.result << " " << starterRow.note);
        CHECK(starterRow.result == "FAIL");
        CHECK(saysWhy(starterRow.note));

        // The solution passes.
        const auto solved = grade(kSolutions, name + ".scene", starter);
        REQUIRE(solved.count(name + ".scene") == 1);
        INFO("solution: " << solved.at(name + ".scene").note);
        CHECK(solved.at(name + ".scene").result == "PASS");

        // Each tried answer gets the grade its header states; the wrong ones say why.
        const std::vector<fs::path> tried = filesBelow(kTriedAnswers / name);
        const auto rows = grade(kTriedAnswers / name, "*.scene", starter);
        std::size_t wrong = 0;
        for (const fs::path& file : tried) {
            const std::string declared = declaredGrade(readFile(file));
            const std::string key = file.filename().string();
            INFO(file.string() << ": header says " << declared);
            REQUIRE_FALSE(declared.empty());
            REQUIRE(rows.count(key) == 1);
            const GradeRow& row = rows.at(key);
            INFO("grade says: " << row.result << " " << row.note);
            if (declared == "PASS") {
                CHECK(row.result == "PASS");
                continue;
            }
            REQUIRE(declared.rfind("FAIL ", 0) == 0);
            ++wrong;
            CHECK(row.result == "FAIL");
            CHECK(withoutLocation(row.note).rfind(declared.substr(5), 0) == 0);
            CHECK(saysWhy(row.note));
        }
        CHECK(wrong >= kMinimumWrongAnswers);
    }
}

TEST_CASE("The answer table in lectures/instructors/README.md is the one the solutions and tried answers give",
          "[assignments]") {
    if (!fs::is_directory(kInstructors)) {
        WARN("no lectures/instructors/ (a student copy): no answer table to check");
        return;
    }
    const fs::path readmePath = kInstructors / "README.md";
    const std::string readme = readFile(readmePath);
    const std::size_t start = readme.find(kTableStart);
    REQUIRE(start != std::string::npos);
    const std::size_t body = readme.find('\n', start) + 1;
    const std::size_t end = readme.find(kTableEnd, body);
    REQUIRE(end != std::string::npos);
    const std::string table = answerTable();
    if (std::getenv(kUpdateTable) != nullptr) {
        std::ofstream(readmePath, std::ios::binary) << readme.substr(0, body) + table + readme.substr(end);
        WARN("rewrote the answer table of " << readmePath.string());
        return;
    }
    INFO("to rewrite it: " << kUpdateTable << "=1 build/ci/tests/stepwise_tests '[assignments]'");
    CHECK(readme.substr(body, end - body) == table);
}
