// scripts/student-kit.sh writes the students' copy of the repository. This
// test builds it (from the working tree, so uncommitted work is checked too),
// unpacks it, and fails if an answer is in it: a file of lectures/instructors/
// (by path, or by content under another name), or a value a reference
// solution gives. Tag: [student-kit].
//
// The forbidden values come from the solution files themselves: each field a
// solution changes against its starter (compareWithStarter) gives the value
// it writes there. A value is searched for
//   - in every file of the kit, as the value of its field, the way a scene
//     writes it ("Elasticity=0.9", "Velocity=(1, 2.5, 0)"): a copied scene line;
//   - anywhere in the pages a student of that assignment reads: its folder,
//     the lectures its README links to, the assignments' README, and
//     docs/instructors.md ("the box stands at 0.9 m").
// So a new assignment is covered as soon as its solution is in
// lectures/instructors/solutions/.
#include <catch2/catch.hpp>

#include <cctype>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "assignment_files.hpp"
#include "command_runner.hpp"
#include "config/scene_changes.hpp"
#include "config/scene_loader.hpp"

using namespace stepwise;
using namespace stepwise::test;

namespace {

/// The kit holds the whole repository but one folder: fewer files than this means it broke.
constexpr std::size_t kMinimumKitFiles = 100;
/// Folder inside the archive that holds every file.
const std::string kKitFolder = "stepwise";

/// A solution value: the text a solution writes for one field, and the field.
struct Forbidden {
    std::string value;   ///< As written, e.g. "0.9", "1/90".
    std::string field;   ///< The field's name without its component letter, e.g. "Elasticity", "Velocity".
    std::string source;  ///< Which solution gives it.
};

/// True when @p text holds @p value as a whole number: not part of a longer number or word.
bool holdsNumber(const std::string& text, const std::string& value) {
    const auto partOfNumber = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '/'; };
    for (std::size_t at = text.find(value); at != std::string::npos; at = text.find(value, at + 1)) {
        const bool before = at > 0 && partOfNumber(text[at - 1]);
        const std::size_t next = at + value.size();
        // "0.9." ends a sentence; "0.95", "10.9" or "0.9/2" is another number.
        const bool after = next < text.size() &&
                           (std::isalnum(static_cast<unsigned char>(text[next])) || text[next] == '/' ||
                            (text[next] == '.' && next + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[next + 1]))));
        if (!before && !after) return true;
    }
    return false;
}

/// A value worth searching for: a number that is not a whole number (which prose uses everywhere).
bool isAnswerNumber(const std::string& text) {
    static const std::regex number(R"(^-?[0-9.]+(/[0-9.]+)?$)");
    static const std::regex whole(R"(^-?[0-9]+$)");
    return std::regex_match(text, number) && !std::regex_match(text, whole);
}

/// The lecture pages a README links to ("](../../03-sphere-plane-impulses.md)"), inside the repository.
std::vector<fs::path> linkedPages(const fs::path& readme) {
    std::vector<fs::path> pages;
    static const std::regex link(R"(\]\(([^)#]+\.md))");
    const std::string text = readFile(readme);
    for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
        const fs::path page = fs::weakly_canonical(readme.parent_path() / (*it)[1].str());
        if (fs::exists(page)) pages.push_back(page.lexically_relative(STEPWISE_SOURCE_DIR));
    }
    return pages;
}

}  // namespace

TEST_CASE("The student kit leaves out every solution file and every solution value", "[student-kit]") {
    if (!fs::is_directory(kInstructors)) {
        WARN("no lectures/instructors/ (a student copy): there are no answers to keep out");
        return;
    }
    const fs::path scratch = fs::temp_directory_path() / "stepwise-test-student-kit";
    fs::remove_all(scratch);
    fs::create_directories(scratch / "unpacked");
    const fs::path archive = scratch / "kit.tar.gz";
    const CommandResult made = shell("bash '" + std::string(STEPWISE_SOURCE_DIR) + "/scripts/student-kit.sh' --worktree --output '" +
                                     archive.string() + "'");
    INFO(made.output);
    REQUIRE(made.exitCode == 0);
    const CommandResult unpacked = shell("tar -xzf '" + archive.string() + "' -C '" + (scratch / "unpacked").string() + "'");
    INFO(unpacked.output);
    REQUIRE(unpacked.exitCode == 0);
    const fs::path kit = scratch / "unpacked" / kKitFolder;

    // Every file of the kit, by path below the repository, with its text.
    std::map<std::string, std::string> files;
    for (const fs::path& file : filesBelow(kit)) files[file.lexically_relative(kit).generic_string()] = readFile(file);
    REQUIRE(files.size() >= kMinimumKitFiles);

    // No file of the instructors' folder, under its own name or another.
    std::set<std::string> contents;
    for (const auto& [path, text] : files) contents.insert(text);
    const std::vector<fs::path> answers = filesBelow(kInstructors);
    REQUIRE_FALSE(answers.empty());
    for (const fs::path& answer : answers) {
        const std::string path = answer.lexically_relative(STEPWISE_SOURCE_DIR).generic_string();
        INFO("answer file " << path);
        CHECK(files.count(path) == 0);
        CHECK(contents.count(readFile(answer)) == 0);
    }

    // No solution value.
    for (const fs::path& folder : assignmentFolders()) {
        const std::string name = folder.filename().string();
        INFO("lectures/assignments/" << name);
        const fs::path starter = folder / "starter.scene";
        const fs::path solution = kSolutions / (name + ".scene");
        REQUIRE(fs::exists(solution));
        // The students get the assignment itself.
        CHECK(files.count(starter.lexically_relative(STEPWISE_SOURCE_DIR).generic_string()) == 1);

        std::vector<Forbidden> forbidden;
        const std::vector<MayChange> allowed = loadSceneFile(starter.string()).mayChange;
        for (const SceneChange& change : compareWithStarter(readFile(starter), readFile(solution), allowed)) {
            if (!isAnswerNumber(change.after)) continue;
            std::string field = change.field;
            // "VelocityY" → "Velocity": a vector's component is written inside its whole value too.
            static const std::regex component(R"(^(.*[a-z])[XYZRGB]$)");
            field = std::regex_replace(field, component, "$1");
            forbidden.push_back({change.after, field, solution.filename().string()});
        }
        // A solution that changes no number would leave this test nothing to look for.
        REQUIRE_FALSE(forbidden.empty());

        std::vector<std::string> pages = {(folder / "README.md").lexically_relative(STEPWISE_SOURCE_DIR).generic_string(),
                                          starter.lexically_relative(STEPWISE_SOURCE_DIR).generic_string(),
                                          "lectures/assignments/README.md", "docs/instructors.md"};
        for (const fs::path& page : linkedPages(folder / "README.md")) pages.push_back(page.generic_string());

        for (const Forbidden& f : forbidden) {
            INFO(f.source << " writes " << f.field << " " << f.value);
            for (const std::string& page : pages) {
                REQUIRE(files.count(page) == 1);
                if (holdsNumber(files.at(page), f.value)) FAIL_CHECK("the kit's " << page << " gives " << f.value);
            }
            // "Elasticity=0.9", "Velocity = (1, 2.5, 0)", "PositionY=0.4": the field's value as a scene writes it.
            const std::regex written("\\b" + f.field + R"([XYZRGB]?\s*=\s*(\([^)]*\)|[^,\s]+))");
            for (const auto& [path, text] : files) {
                if (text.find(f.value) == std::string::npos) continue;  // std::regex is slow: look only where it can match
                for (std::sregex_iterator it(text.begin(), text.end(), written), end; it != end; ++it) {
                    if (holdsNumber((*it)[1].str(), f.value)) {
                        FAIL_CHECK("the kit's " << path << " gives " << f.value << ": " << (*it)[0].str());
                    }
                }
            }
        }
    }
    fs::remove_all(scratch);
}
