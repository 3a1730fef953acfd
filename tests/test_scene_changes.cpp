// MayChange records and the comparison of a submission with its starter:
// what the loader makes of the records, what compareWithStarter counts as a
// change (what the lines say) and what not (how they are laid out), and how
// `stepwise grade --expect` fails a change no record allows, at its line and
// column. Tag: [grade] (the loader's part also [config]).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "config/scene_changes.hpp"
#include "config/scene_loader.hpp"

using namespace stepwise;
using Catch::Contains;

namespace {

std::vector<ConfigDiagnostic> problemsIn(const std::string& text) {
    try {
        (void)parseScene(text, "test.scene");
    } catch (const ConfigError& error) {
        return error.diagnostics();
    }
    FAIL("the scene loaded, but it should have been rejected:\n" << text);
    return {};
}

/// The starter every comparison below starts from.
const std::string kStarter =
    "World, Integrator=Verlet, TimeStep=1/60, Duration=1\n"
    "CollisionPlane, Name=floor\n"
    "DynamicObject, Name=ball, Position=(0, 10, 0), Velocity=(0, 0, 0), Scale=(1, 1, 1)\n"
    "MayChange, Object=ball, Field=Velocity\n"
    "MayChange, Object=ball, Field=ScaleY\n"
    "MayChange, Field=TimeStep\n"
    "Expect, Object=ball, Time=1, PositionY=6, Tolerance=0.01\n";

std::vector<SceneChange> changesTo(const std::string& submission) {
    return compareWithStarter(kStarter, submission, parseScene(kStarter, "starter.scene").mayChange);
}

/// "ball.PositionY 10 -> 11 (line 3, column 40, not allowed)": one change in words, for messages.
std::string words(const std::vector<SceneChange>& changes) {
    std::ostringstream text;
    for (const SceneChange& c : changes) {
        text << (c.object.empty() ? "World" : c.object) << "." << c.field << " '" << c.before << "' -> '" << c.after
             << "' (line " << c.line << ", column " << c.column << (c.allowed ? ", allowed" : ", not allowed") << ")\n";
    }
    return text.str();
}

using stepwise::test::runStepwise;

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The lines of @p text without the spaces at their ends.
std::vector<std::string> trimmedLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
        lines.push_back(line);
    }
    while (!lines.empty() && lines.back().empty()) lines.pop_back();
    return lines;
}

}  // namespace

// ------------------------------------------------------------------ loading

TEST_CASE("A MayChange record loads with the object's and the field's own spelling", "[grade][config]") {
    const Scene scene = parseScene(
        "MayChange, Object=BALL, Field=elasticity\n"
        "MayChange, Object=ball, Field=scaley\n"
        "MayChange, Field=timestep\n"
        "DynamicObject, Name=Ball\n",  // declared after the records that name it
        "test.scene");
    REQUIRE(scene.mayChange.size() == 3);
    CHECK(scene.mayChange[0].line == 1);
    CHECK(scene.mayChange[0].object == "Ball");
    CHECK(scene.mayChange[0].field == "Elasticity");
    CHECK(scene.mayChange[1].field == "ScaleY");
    CHECK(scene.mayChange[2].object.empty());
    CHECK(scene.mayChange[2].field == "TimeStep");
    CHECK(describeAllowed(scene.mayChange[1]) == "Ball.ScaleY");
    CHECK(describeAllowed(scene.mayChange[2]) == "World.TimeStep");
}

TEST_CASE("Each rule of the MayChange record is reported at its line and column", "[grade][config]") {
    struct Case {
        const char* line;  // the second line of the file; the first declares ball
        int column;
        const char* field;
        const char* words;  // part of the message
    };
    const Case cases[] = {
        {"MayChange, Object=ball", 1, "Field", "the field a student may change"},
        {"MayChange, Object=bal, Field=Mass", 19, "Object", "did you mean 'ball'?"},
        {"MayChange, Object=ball, Field=Elastcity", 31, "Field", "did you mean 'Elasticity'?"},
        {"MayChange, Object=ball, Field=Name", 31, "Field", "the name cannot change"},
        {"MayChange, Field=Elasticity", 18, "Field", "without Object, Field is a field of the World record"},
        {"MayChange, Object=ball, Field=ball Mass", 31, "Field", "a name of letters"},
        {"MayChange, Object=ball, Field=Mass, Expect=1", 37, "MayChange", "one of its fields (Object, Field)"},
    };
    for (const Case& c : cases) {
        const std::string text = std::string("DynamicObject, Name=ball\n") + c.line + "\n";
        INFO(c.line);
        const std::vector<ConfigDiagnostic> problems = problemsIn(text);
        for (const ConfigDiagnostic& problem : problems) INFO(problem.message());
        REQUIRE(problems.size() == 1);
        CHECK(problems[0].line == 2);
        CHECK(problems[0].column == c.column);
        CHECK(problems[0].field == c.field);
        CHECK_THAT(problems[0].message(), Contains(c.words));
    }
}

// ------------------------------------------------------------------ comparing

TEST_CASE("The same scene laid out differently is no change", "[grade]") {
    // Named fields as components, another order, comments, spacing, a synonym, a World record at the end.
    const std::string same =
        "# my answer\n"
        "CollisionPlane,Name=FLOOR\n"
        "DynamicObject, Name=ball, Scale=(1, 1, 1), PositionX=0, PositionY=10, PositionZ=0, Velocity=(0,0,0)  # unchanged\n"
        "Expect, Object=ball, Time=1, PositionY=0, Tolerance=100\n"  // Expect records are the starter's to set
        "World, Duration=1, TimeStep=1/60, Integrator=VelocityVerlet\n";
    const std::vector<SceneChange> changes = changesTo(same);
    INFO(words(changes));
    CHECK(changes.empty());
}

TEST_CASE("A changed value is a change at its line and column, and MayChange allows whole fields or one component",
          "[grade]") {
    const std::string submission =
        "World, Integrator=Verlet, TimeStep=1/120, Duration=1\n"
        "CollisionPlane, Name=floor\n"
        "DynamicObject, Name=ball, Position=(0, 11, 0), Velocity=(1, 2, 3), Scale=(1, 2, 3)\n";
    const std::vector<SceneChange> changes = changesTo(submission);
    INFO(words(changes));
    REQUIRE(changes.size() == 7);
    // In file order: TimeStep, then the ball's PositionY, VelocityX-Z, ScaleY, ScaleZ.
    CHECK(changes[0].field == "TimeStep");
    CHECK(changes[0].object.empty());
    CHECK(changes[0].before == "1/60");
    CHECK(changes[0].after == "1/120");
    CHECK(changes[0].allowed);
    CHECK(changes[1].object == "ball");
    CHECK(changes[1].field == "PositionY");
    CHECK(changes[1].before == "10");
    CHECK(changes[1].after == "11");
    CHECK(changes[1].line == 3);
    CHECK(changes[1].column == 40);  // the '11'
    CHECK(changes[1].starterLine == 3);
    CHECK_FALSE(changes[1].allowed);
    for (int i = 2; i <= 4; ++i) CHECK(changes[static_cast<std::size_t>(i)].allowed);  // Velocity: the whole field
    CHECK(changes[5].field == "ScaleY");
    CHECK(changes[5].allowed);
    CHECK(changes[6].field == "ScaleZ");
    CHECK_FALSE(changes[6].allowed);  // only ScaleY may change

    const ConfigDiagnostic d = changeDiagnostic(changes[1], "bob.scene", parseScene(kStarter, "s").mayChange);
    CHECK(d.message() ==
          "bob.scene:3:40: error: ball.PositionY: expected 10, as in the starter (line 3), found '11'; the assignment "
          "lets you change only ball.Velocity, ball.ScaleY, World.TimeStep");
}

TEST_CASE("A field added or left out, a record added or removed, and a World record removed are changes", "[grade]") {
    const std::string submission =
        "DynamicObject, Name=ball, Position=(0, 10, 0), Velocity=(0, 0, 0), Scale=(1, 1, 1), Mass=1\n"
        "DynamicObject, Name=helper, Position=(0, 5, 0)\n";
    const std::vector<SceneChange> changes = changesTo(submission);
    INFO(words(changes));
    REQUIRE(changes.size() == 6);
    // Mass=1 is the default, but the starter does not say it: a change all the same.
    CHECK(changes[0].field == "Mass");
    CHECK(changes[0].before.empty());
    CHECK(changes[0].after == "1");
    CHECK(changes[1].field.empty());
    CHECK(changes[1].object == "helper");
    CHECK(changes[1].line == 2);
    // Missing from the submission, so last: the World's three fields, then the floor.
    CHECK(changes[2].line == 0);
    CHECK(changes[2].field == "TimeStep");
    CHECK(changes[2].after.empty());
    CHECK(changes[2].allowed);  // TimeStep may change, even to the default
    CHECK(changes[3].field == "Integrator");
    CHECK_FALSE(changes[3].allowed);
    CHECK(changes[4].field == "Duration");
    CHECK(changes[5].record == "CollisionPlane");
    CHECK(changes[5].object == "floor");
    CHECK(changes[5].starterLine == 2);

    const std::vector<MayChange> allowed = parseScene(kStarter, "s").mayChange;
    CHECK_THAT(changeDiagnostic(changes[1], "x.scene", allowed).message(),
               Contains("x.scene:2:1: error: DynamicObject: expected only the records of the starter, found 'helper'"));
    CHECK_THAT(changeDiagnostic(changes[5], "x.scene", allowed).message(),
               Contains("x.scene: error: CollisionPlane: expected 'floor', as in the starter (line 2), found ''"));
}

TEST_CASE("Records without a Name are matched by their default name", "[grade]") {
    const std::string starter = "CollisionPlane\nDynamicObject, Position=(0, 1, 0)\nMayChange, Object=DynamicObject0, Field=PositionY\n";
    const std::vector<MayChange> allowed = parseScene(starter, "s").mayChange;
    const auto moved = compareWithStarter(starter, "DynamicObject, PositionY=2, PositionX=0, PositionZ=0\nCollisionPlane\n", allowed);
    INFO(words(moved));
    REQUIRE(moved.size() == 1);
    CHECK(moved[0].object == "DynamicObject0");
    CHECK(moved[0].allowed);
}

// ------------------------------------------------------------------ stepwise grade

TEST_CASE("grade --expect fails a change no MayChange record allows, and lists every change with file, line and column",
          "[grade][cli]") {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "stepwise-test-grade-changes";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder / "submissions");
    const auto write = [&](const std::string& file, const std::string& text) { std::ofstream(folder / file) << text; };
    write("starter.scene", kStarter);
    // Verlet is exact under gravity: thrown up at 0.905 m/s from 10 m, the ball is at 10 + 0.905 - 4.905 = 6 m after 1 s.
    write("submissions/right.scene", std::regex_replace(kStarter, std::regex("Velocity=\\(0, 0, 0\\)"), "Velocity=(0, 0.905, 0)"));
    // Dropped from 0.905 m higher, it is at 6 m too: the right outcome, by a change the starter forbids.
    write("submissions/moved.scene", std::regex_replace(kStarter, std::regex("Position=\\(0, 10, 0\\)"), "Position=(0, 10.905, 0)"));
    const auto graded = runStepwise("grade '" + (folder / "submissions").string() + "' --expect '" +
                                    (folder / "starter.scene").string() + "'");
    INFO(graded.output);
    CHECK(graded.exitCode == 3);
    CHECK_THAT(graded.output, Contains("Only its MayChange fields may differ from it: ball.Velocity, ball.ScaleY, World.TimeStep"));
    CHECK(std::regex_search(graded.output, std::regex(R"(\n  right\.scene\s+PASS\s+1/1)")));
    CHECK(std::regex_search(graded.output,
                            std::regex(R"(\n  moved\.scene\s+FAIL\s+1/1\s+line 3:40: error: ball\.PositionY: expected 10)")));
    CHECK_THAT(graded.output, Contains((folder / "submissions" / "moved.scene").string() +
                                       ":3:40: error: ball.PositionY: expected 10, as in the starter (line 3), found '10.905'"));

    // Without MayChange records in the starter, only the outcomes count: the moved ball passes.
    write("outcomes-only.scene", "World, Integrator=Verlet, TimeStep=1/60, Duration=1\n"
                                 "DynamicObject, Name=ball\nExpect, Object=ball, Time=1, PositionY=6, Tolerance=0.01\n");
    const auto outcomes = runStepwise("grade '" + (folder / "submissions").string() + "' --expect '" +
                                      (folder / "outcomes-only.scene").string() + "'");
    INFO(outcomes.output);
    CHECK(outcomes.exitCode == 0);
    CHECK_THAT(outcomes.output, Contains("It has no MayChange records: submissions may change anything"));
    std::filesystem::remove_all(folder);
}

TEST_CASE("The grading example of docs/instructors.md prints what the page shows", "[grade][cli]") {
    // The page's starter is its ```scene block in "Grading a folder", its output the ```text block after it;
    // the four submissions are the ones the page describes.
    const std::string page = readText(STEPWISE_SOURCE_DIR "/docs/instructors.md");
    const std::size_t section = page.find("## Grading a folder");
    REQUIRE(section != std::string::npos);
    const auto block = [&](const std::string& fence) {
        const std::size_t open = page.find(fence + "\n", section);
        REQUIRE(open != std::string::npos);
        const std::size_t start = open + fence.size() + 1;
        return page.substr(start, page.find("```\n", start) - start);
    };
    const std::string starter = block("```scene");
    const std::string shown = block("```text");

    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "stepwise-test-grade-example";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder / "submissions");
    const auto write = [&](const std::string& file, const std::string& text) {
        std::ofstream(folder / file) << text;
    };
    const auto edited = [&](const std::string& from, const std::string& to) {
        std::string text = starter;
        const std::size_t at = text.find(from);
        REQUIRE(at != std::string::npos);
        return text.replace(at, from.size(), to);
    };
    write("throw.scene", starter);
    write("submissions/alice.scene", edited("Velocity=(0, 0, 0)", "Velocity=(0, 0.905, 0)"));
    write("submissions/bob.scene", starter);
    write("submissions/carol.scene", edited("Velocity=(0, 0, 0)", "Velocity=(0, 0.905, 0), Mass=2kg"));
    write("submissions/dave.scene", edited("Position=(0, 10, 0)", "Position=(0, 10.905, 0)"));
    const auto graded = stepwise::test::shell("cd '" + folder.string() + "' && '" + STEPWISE_CLI_PATH +
                                              "' grade submissions --expect throw.scene");
    CHECK(graded.exitCode == 3);
    CHECK(trimmedLines(graded.output) == trimmedLines(shown));
    std::filesystem::remove_all(folder);
}
