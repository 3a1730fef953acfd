// The ready assignments in lectures/assignments/: each starter scene fails its
// Expect records, each reference solution passes the same records. Tag: [assignments].
//
// The expectations themselves come from closed-form physics (each README and
// solution derives its numbers); this test checks that the engine meets them
// for the solution and not for the starter, so an assignment cannot silently
// become unsolvable, or solved before the student starts.
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

const fs::path kAssignments = fs::path(STEPWISE_SOURCE_DIR) / "lectures" / "assignments";
/// The issue asks for at least five ready assignments.
constexpr std::size_t kMinimumAssignments = 5;

/// lectures/assignments/<nn>-<name>/ folders, in order.
std::vector<fs::path> assignmentFolders() {
    std::vector<fs::path> folders;
    for (const fs::directory_entry& entry : fs::directory_iterator(kAssignments)) {
        if (entry.is_directory() && fs::exists(entry.path() / "starter.scene")) folders.push_back(entry.path());
    }
    std::sort(folders.begin(), folders.end());
    return folders;
}

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Every expectation in words, to compare the starter's with the solution's.
std::vector<std::string> described(const std::vector<Expectation>& expectations) {
    std::vector<std::string> words;
    for (const Expectation& e : expectations) words.push_back(describe(e));
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

}  // namespace

TEST_CASE("Every assignment's starter fails and its reference solution passes the same expectations",
          "[assignments]") {
    const std::vector<fs::path> folders = assignmentFolders();
    CHECK(folders.size() >= kMinimumAssignments);
    const bool solutionsHandedOut = fs::is_directory(kAssignments / "solutions");
    if (!solutionsHandedOut) WARN("no lectures/assignments/solutions/ (a student copy): only the starters are checked");

    for (const fs::path& folder : folders) {
        const std::string name = folder.filename().string();
        INFO("lectures/assignments/" << name);

        // The statement says what to edit and gives the exact command that checks it.
        const std::string readme = readText(folder / "README.md");
        CHECK(readme.find("stepwise run lectures/assignments/" + name + "/starter.scene") != std::string::npos);

        const Scene starter = loadSceneFile((folder / "starter.scene").string());
        REQUIRE_FALSE(starter.expectations.empty());
        const test::ExpectationOutcome started = test::runExpectations(starter);
        INFO("starter:\n" << report(started));
        CHECK_FALSE(started.allPassed());

        if (!solutionsHandedOut) continue;
        const fs::path solutionPath = kAssignments / "solutions" / (name + ".scene");
        REQUIRE(fs::exists(solutionPath));
        const Scene solution = loadSceneFile(solutionPath.string());
        // Passing other expectations would prove nothing.
        CHECK(described(solution.expectations) == described(starter.expectations));
        const test::ExpectationOutcome solved = test::runExpectations(solution);
        INFO("solution:\n" << report(solved));
        CHECK(solved.allPassed());
    }
}
