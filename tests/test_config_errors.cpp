/// @file test_config_errors.cpp
/// @brief Scene files that must be rejected: each error class, located to line and column, with its hint.
///
/// Columns are counted by hand in the comments (1-based) so a reader can
/// check them against the text.
#include <catch2/catch.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "config/scene_loader.hpp"

using namespace stepwise;
using Catch::Contains;

namespace {

/// Every diagnostic of a file that must not load.
std::vector<ConfigDiagnostic> problemsIn(std::string_view text) {
    try {
        (void)parseScene(text, "test.scene");
    } catch (const ConfigError& error) {
        return error.diagnostics();
    }
    FAIL("the scene loaded, but it should have been rejected:\n" << text);
    return {};
}

/// The single diagnostic of a file with exactly one problem.
ConfigDiagnostic theProblemIn(std::string_view text) {
    const std::vector<ConfigDiagnostic> problems = problemsIn(text);
    INFO("text: " << text);
    for (const ConfigDiagnostic& problem : problems) INFO(problem.message());
    REQUIRE(problems.size() == 1);
    return problems.front();
}

/// Checks where a diagnostic points and what it is about.
void checkLocation(const ConfigDiagnostic& problem, int line, int column, const std::string& field) {
    INFO(problem.message());
    CHECK(problem.file == "test.scene");
    CHECK(problem.line == line);
    CHECK(problem.column == column);
    CHECK(problem.field == field);
}

}  // namespace

// ------------------------------------------------------------------ message format

TEST_CASE("A diagnostic reads file:line:column: error: field: expected, found, and a hint", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("DynamicObject, Mass=-2\n");
    //                                              1234567890123456789012
    checkLocation(problem, 1, 21, "Mass");
    CHECK(problem.expected == "a mass from 1e-12 to 1e12 kg");
    CHECK(problem.found == "-2");
    CHECK(problem.message() ==
          "test.scene:1:21: error: Mass: expected a mass from 1e-12 to 1e12 kg, found '-2'; every simulated body "
          "needs a positive "
          "mass; for something that never moves, use a KinematicsObject or a CollisionPlane");
}

TEST_CASE("A diagnostic without a hint ends with the found text", "[config]") {
    ConfigDiagnostic problem{"a.scene", 3, 7, "Radius", "a number > 0", "x", ""};
    CHECK(problem.message() == "a.scene:3:7: error: Radius: expected a number > 0, found 'x'");
}

// ------------------------------------------------------------------ numbers

TEST_CASE("A value that is not a number is rejected at its first character", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("\nDynamicObject, Position=(0, five, 0)\n");
    //                                                1234567890123456789012345678
    checkLocation(problem, 2, 29, "PositionY");
    CHECK(problem.expected == "a number");
    CHECK(problem.found == "five");
}

TEST_CASE("Only whole-token numbers are accepted", "[config]") {
    for (const std::string bad : {"1.5.2", "0x10", "1/2/3", "abc", "--1", "1e", "2 3"}) {
        INFO("Mass=" << bad);
        const std::vector<ConfigDiagnostic> problems = problemsIn("DynamicObject, Mass=" + bad + "\n");
        REQUIRE_FALSE(problems.empty());
        CHECK(problems.front().column == 21);
    }
}

TEST_CASE("A decimal comma splits the value into two fields", "[config]") {
    // "Mass=1,5" is Mass=1 followed by a positional 5, which may not follow a named field.
    const ConfigDiagnostic problem = theProblemIn("DynamicObject, Mass=1,5\n");
    checkLocation(problem, 1, 23, "DynamicObject");
    CHECK(problem.found == "5");
}

TEST_CASE("A number followed by a unit gets a hint about SI units", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("DynamicObject, Mass=2kg\n");
    checkLocation(problem, 1, 21, "Mass");
    CHECK(problem.found == "2kg");
    CHECK_THAT(problem.hint, Contains("SI units"));
}

TEST_CASE("NaN, infinity and overflowing numbers are rejected", "[config]") {
    for (const std::string bad : {"nan", "NaN", "inf", "-inf", "infinity", "1e999", "-1e400", "1e300/1e-300"}) {
        INFO("PositionX=" << bad);
        const ConfigDiagnostic problem = theProblemIn("DynamicObject, PositionX=" + bad + "\n");
        checkLocation(problem, 1, 26, "PositionX");
        CHECK(problem.found == bad);
        CHECK_FALSE(problem.hint.empty());
    }
}

TEST_CASE("A fraction with a zero denominator is rejected", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("World, TimeStep=1/0\n");
    checkLocation(problem, 1, 17, "TimeStep");
    CHECK_THAT(problem.hint, Contains("denominator"));
}

TEST_CASE("A missing value is reported as found ''", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("DynamicObject, Mass=\n");
    checkLocation(problem, 1, 21, "Mass");
    CHECK(problem.found.empty());
    CHECK_THAT(problem.message(), Contains("found ''"));
}

// ------------------------------------------------------------------ ranges

TEST_CASE("Mass, Radius, Scale, TimeStep and Duration must be positive and in range", "[config]") {
    // Sizes and masses have a finite range as well as a sign: a 1e-300 m box or a 1e300 kg
    // ball loads as a number but overflows (or underflows) the inertia tensor, m (a^2 + b^2) / 12.
    const std::string mass = "a mass from 1e-12 to 1e12 kg";
    const std::string radius = "a radius from 5e-7 to 500000 m";
    const std::string size = "a size from 1e-6 to 1e6 m";
    struct Case {
        std::string text;
        int column;
        std::string field;
        std::string found;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {"DynamicObject, Mass=0", 21, "Mass", "0", mass},
        {"DynamicObject, Mass=-1", 21, "Mass", "-1", mass},
        {"DynamicObject, Mass=1e13", 21, "Mass", "1e13", mass},
        {"DynamicObject, Mass=1e-300", 21, "Mass", "1e-300", mass},
        {"DynamicObject, Radius=-0.5", 23, "Radius", "-0.5", radius},
        {"KinematicsObject, Radius=0", 26, "Radius", "0", radius},
        {"DynamicObject, Radius=1e6", 23, "Radius", "1e6", radius},
        //          1234567890123456789012345678
        {"DynamicObject, Scale=(1, 0, 1)", 26, "ScaleY", "0", size},
        {"KinematicsObject, ScaleZ=-2", 26, "ScaleZ", "-2", size},
        {"DynamicObject, ScaleX=1e-300", 23, "ScaleX", "1e-300", size},
        // Positional: Sphere,1,1,1 (colour),0,0,0 (position),0,0,0 (velocity),0,0,0 (acceleration),1,1,-1 (scale)
        {"DynamicObject,Sphere,1,1,1,0,0,0,0,0,0,0,0,0,1,1,-1", 50, "ScaleZ", "-1", size},
        {"World, TimeStep=0", 17, "TimeStep", "0", "a number > 0"},
        {"World, Duration=-10", 17, "Duration", "-10", "a number > 0"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        const ConfigDiagnostic problem = theProblemIn(c.text + "\n");
        checkLocation(problem, 1, c.column, c.field);
        CHECK(problem.expected == c.expected);
        CHECK(problem.found == c.found);
    }
    // The ends of each range are valid.
    CHECK_NOTHROW(parseScene("DynamicObject, Mass=1e12\nDynamicObject, Mass=1e-12\n"
                             "DynamicObject, Shape=Cube, Scale=(1e6, 1e-6, 1)\n",
                             "edges.scene"));
}

TEST_CASE("Elasticity must lie in [0, 1] and Friction must not be negative", "[config]") {
    for (const std::string bad : {"1.5", "-0.1"}) {
        const ConfigDiagnostic problem = theProblemIn("CollisionPlane, Elasticity=" + bad + "\n");
        checkLocation(problem, 1, 28, "Elasticity");
        CHECK(problem.expected == "a number from 0 to 1");
        CHECK(problem.found == bad);
    }
    const ConfigDiagnostic friction = theProblemIn("KinematicsObject, Friction=-0.2\n");
    checkLocation(friction, 1, 28, "Friction");
    CHECK(friction.expected == "a number >= 0");
    // Edges of the ranges are valid.
    CHECK_NOTHROW(parseScene("DynamicObject, Elasticity=0, Friction=0\nDynamicObject, Elasticity=1, Friction=3\n",
                             "edges.scene"));
}

TEST_CASE("Colour channels must lie from 0 to 1, and 0-255 values get a hint", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("DynamicObject, Sphere, 1, 200, 0\n");
    //                                              12345678901234567890123456
    checkLocation(problem, 1, 27, "ColorG");
    CHECK(problem.expected == "a number from 0 to 1");
    CHECK(problem.found == "200");
    CHECK_THAT(problem.message(), Contains("divide 0-255 values by 255, e.g. write 200/255"));

    const ConfigDiagnostic negative = theProblemIn("CollisionPlane, Color=(0, 0, -1)\n");
    checkLocation(negative, 1, 30, "ColorB");
}

TEST_CASE("A zero or near-zero plane normal is rejected", "[config]") {
    const ConfigDiagnostic whole = theProblemIn("CollisionPlane, Normal=(0, 0, 0)\n");
    checkLocation(whole, 1, 24, "Normal");
    CHECK(whole.expected == "a direction (a vector of length > 0, whose squares do not overflow)");
    CHECK(whole.found == "(0, 0, 0)");

    const ConfigDiagnostic tiny = theProblemIn("CollisionPlane, Normal=(1e-10, 0, 0)\n");
    checkLocation(tiny, 1, 24, "Normal");

    // Positionally: the normal starts at the 4th value.
    const ConfigDiagnostic positional = theProblemIn("CollisionPlane, 0, 0, 0, 0, 0, 0\n");
    //                                                 1234567890123456789012345
    checkLocation(positional, 1, 26, "Normal");
    CHECK(positional.found == "(0, 0, 0)");

    // A single component replaces one of the default (0, 1, 0).
    const ConfigDiagnostic component = theProblemIn("CollisionPlane, NormalY=0\n");
    checkLocation(component, 1, 25, "Normal");
}

// ------------------------------------------------------------------ names

TEST_CASE("A duplicate Name is reported at the second use with the line of the first", "[config]") {
    const ConfigDiagnostic problem =
        theProblemIn("DynamicObject, Name=Ball\nCollisionPlane\nKinematicsObject, Name=ball\n");
    //                                                                 12345678901234567890123
    checkLocation(problem, 3, 24, "Name");
    CHECK(problem.found == "ball");
    CHECK_THAT(problem.hint, Contains("line 1"));
    CHECK_THAT(problem.hint, Contains("'Ball'"));
}

TEST_CASE("A Name may not clash with a default name", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("DynamicObject, Name=DynamicObject1\nDynamicObject\n");
    checkLocation(problem, 2, 1, "Name");
    CHECK(problem.found == "DynamicObject1");
    CHECK_THAT(problem.hint, Contains("line 1"));
}

TEST_CASE("A Name must be letters, digits, '_', '-' and '.'", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("DynamicObject, Name=Red Ball\n");
    checkLocation(problem, 1, 21, "Name");
    CHECK_THAT(problem.hint, Contains("'_'"));
}

// ------------------------------------------------------------------ records and fields

TEST_CASE("An unknown record is reported with a did-you-mean", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("# header\n  DynamicObjet, Mass=2\n");
    checkLocation(problem, 2, 3, "record");
    CHECK(problem.found == "DynamicObjet");
    CHECK_THAT(problem.message(), Contains("; did you mean 'DynamicObject'?"));

    const ConfigDiagnostic kinematic = theProblemIn("KinematicObject\n");
    CHECK(kinematic.hint == "did you mean 'KinematicsObject'?");

    const ConfigDiagnostic unknown = theProblemIn("Teapot, 1, 2\n");  // no record is close to it
    CHECK(unknown.hint.empty());
    CHECK_THAT(unknown.expected, Contains("DynamicObject, KinematicsObject, CollisionPlane, World"));
}

TEST_CASE("A field the record does not have is named in the message", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("CollisionPlane, Mass=2\n");
    //                                              1234567890123456789
    checkLocation(problem, 1, 17, "CollisionPlane");
    CHECK(problem.found == "Mass");
    CHECK_THAT(problem.message(), Contains("CollisionPlane has no field 'Mass'"));
    CHECK_THAT(problem.message(), Contains("it is a field of DynamicObject"));
    CHECK_THAT(problem.expected, Contains("Normal"));

    const ConfigDiagnostic world = theProblemIn("World, Name=Earth\n");
    CHECK_THAT(world.message(), Contains("World has no field 'Name'"));
}

TEST_CASE("A misspelt field gets a did-you-mean", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("DynamicObject, Elastcity=0.5\n");
    checkLocation(problem, 1, 16, "DynamicObject");
    CHECK(problem.hint == "did you mean 'Elasticity'?");
    CHECK_THAT(problem.message(), Contains("found 'Elastcity'; did you mean 'Elasticity'?"));

    CHECK(theProblemIn("DynamicObject, PositonY=5\n").hint == "did you mean 'PositionY'?");
    CHECK(theProblemIn("World, Gravty=(0, -1, 0)\n").hint == "did you mean 'Gravity'?");
    CHECK(theProblemIn("CollisionPlane, Colour=(1, 0, 0)\n").hint == "did you mean 'Color'?");
}

TEST_CASE("An unknown Shape or Integrator lists the choices and suggests one", "[config]") {
    const ConfigDiagnostic shape = theProblemIn("DynamicObject, Sphear\n");
    checkLocation(shape, 1, 16, "Shape");
    CHECK(shape.expected == "one of Sphere, Box, Cube, Capsule, Cylinder, Hull, Compound, Mesh");
    CHECK(shape.found == "Sphear");
    CHECK(shape.hint == "did you mean 'Sphere'?");

    const ConfigDiagnostic integrator = theProblemIn("World, Integrator=RK4\n");
    checkLocation(integrator, 1, 19, "Integrator");
    CHECK_THAT(integrator.expected, Contains("SymplecticEuler"));
    CHECK(integrator.hint.empty());

    CHECK(theProblemIn("World, Integrator=Verlett\n").hint == "did you mean 'Verlet'?");
}

TEST_CASE("An unknown Broadphase lists the choices and suggests one", "[config][broadphase]") {
    const ConfigDiagnostic problem = theProblemIn("World, Broadphase=KdTree\n");
    checkLocation(problem, 1, 19, "Broadphase");
    CHECK_THAT(problem.expected,
               Contains("SweepAndPrune") && Contains("AabbTree") && Contains("Grid") && Contains("Octree"));
    CHECK(theProblemIn("World, Broadphase=AabbTre\n").hint == "did you mean 'AabbTree'?");
}

TEST_CASE("Setting a field twice is an error, however it is set", "[config]") {
    SECTION("named twice") {
        const ConfigDiagnostic problem = theProblemIn("DynamicObject, Mass=1, Mass=2\n");
        //                                              12345678901234567890123
        checkLocation(problem, 1, 24, "Mass");
        CHECK(problem.found == "Mass=2");
        CHECK_THAT(problem.hint, Contains("column 16"));
    }
    SECTION("whole vector, then a component") {
        const ConfigDiagnostic problem = theProblemIn("DynamicObject, Position=(0, 5, 0), PositionY=3\n");
        //                                              123456789012345678901234567890123456
        checkLocation(problem, 1, 36, "PositionY");
        CHECK_THAT(problem.hint, Contains("PositionY was already set at column 16"));
    }
    SECTION("a component, then the whole vector") {
        const ConfigDiagnostic problem = theProblemIn("DynamicObject, VelocityZ=1, Velocity=(1, 2, 3)\n");
        checkLocation(problem, 1, 29, "Velocity");
        CHECK_THAT(problem.hint, Contains("VelocityZ"));
    }
    SECTION("positional, then named") {
        const ConfigDiagnostic problem = theProblemIn("DynamicObject, Sphere, Shape=Box\n");
        checkLocation(problem, 1, 24, "Shape");
        CHECK_THAT(problem.hint, Contains("column 16"));
    }
}

TEST_CASE("Too many positional values are reported once, at the first extra one", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("CollisionPlane, 0, 0, 0, 0, 1, 0, 7, 8\n");
    //                                              123456789012345678901234567890123456
    checkLocation(problem, 1, 35, "CollisionPlane");
    CHECK(problem.expected == "at most 6 positional fields");
    CHECK(problem.found == "7");
    CHECK_THAT(problem.hint, Contains("NormalZ"));

    const ConfigDiagnostic dynamic = theProblemIn(
        "DynamicObject, Sphere, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0.5, 1, 0.5, 0.5\n");
    CHECK(dynamic.expected == "at most 19 positional fields");
    CHECK(dynamic.found == "0.5");
    CHECK(dynamic.column == 82);

    const ConfigDiagnostic world = theProblemIn("World, 0.01\n");
    checkLocation(world, 1, 8, "World");
    CHECK(world.expected == "a named field (Field=Value)");
}

TEST_CASE("A positional value after a named field is an error", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("DynamicObject, Mass=2, 0.5\n");
    checkLocation(problem, 1, 24, "DynamicObject");
    CHECK(problem.expected == "a named field (Field=Value)");
    CHECK(problem.found == "0.5");
    CHECK_THAT(problem.hint, Contains("'Mass=2' at column 16"));
}

TEST_CASE("A second World record is an error that names the first", "[config]") {
    const ConfigDiagnostic problem = theProblemIn("World, TimeStep=0.01\nDynamicObject\nWorld, Duration=5\n");
    checkLocation(problem, 3, 1, "World");
    CHECK(problem.expected == "at most one World record");
    CHECK_THAT(problem.hint, Contains("line 1"));
}

// ------------------------------------------------------------------ vectors

TEST_CASE("A vector needs three components in parentheses", "[config]") {
    SECTION("too few components") {
        const ConfigDiagnostic problem = theProblemIn("DynamicObject, Position=(1, 2)\n");
        checkLocation(problem, 1, 25, "Position");
        CHECK(problem.expected == "a vector (x, y, z)");
        CHECK(problem.found == "(1, 2)");
        CHECK_THAT(problem.hint, Contains("has 2"));
    }
    SECTION("too many components") {
        const ConfigDiagnostic problem = theProblemIn("CollisionPlane, Color=(1, 0, 0, 1)\n");
        checkLocation(problem, 1, 23, "Color");
        CHECK(problem.expected == "a colour (r, g, b)");
    }
    SECTION("no parentheses") {
        const ConfigDiagnostic problem = theProblemIn("DynamicObject, Velocity=5\n");
        checkLocation(problem, 1, 25, "Velocity");
        CHECK_THAT(problem.hint, Contains("VelocityX=5"));
    }
    SECTION("a whole vector in a positional slot") {
        const ConfigDiagnostic problem = theProblemIn("CollisionPlane, (0, 1, 0)\n");
        checkLocation(problem, 1, 17, "PositionX");
        CHECK_THAT(problem.hint, Contains("Position=(0, 1, 0)"));
    }
}

TEST_CASE("Unbalanced parentheses are reported at the parenthesis", "[config]") {
    SECTION("an unclosed '('") {
        const ConfigDiagnostic problem = theProblemIn("DynamicObject, Position=(0, 5, 0, Mass=2\n");
        //                                              1234567890123456789012345
        checkLocation(problem, 1, 25, "Position");
        CHECK(problem.expected == "a ')' to close this '('");
        CHECK(problem.found == "(0, 5, 0, Mass=2");
    }
    SECTION("a ')' without '('") {
        const ConfigDiagnostic problem = theProblemIn("DynamicObject, Position=0, 5, 0), Mass=2\n");
        //                                              12345678901234567890123456789012
        checkLocation(problem, 1, 32, "DynamicObject");
        CHECK(problem.expected == "a '(' before this ')'");
        CHECK(problem.found == "0)");
    }
}

// ------------------------------------------------------------------ all problems, nothing half-loaded

TEST_CASE("Every problem in the file is reported, in file order", "[config]") {
    const std::string text =
        "World, Integrator=Verlat\n"                    // line 1: unknown integrator
        "DynamicObject, Mass=0, Elasticity=2\n"         // line 2: two bad values
        "CollisionPlane, Normal=(0, 0, 0), Mass=1\n"    // line 3: unknown field, then zero normal (reported first)
        "DynamicObject, Sphere\n"                       // line 4: fine
        "Floor\n";                                      // line 5: unknown record
    const std::vector<ConfigDiagnostic> problems = problemsIn(text);
    REQUIRE(problems.size() == 6);
    CHECK(problems[0].line == 1);
    CHECK(problems[0].field == "Integrator");
    CHECK(problems[1].field == "Mass");
    CHECK(problems[2].field == "Elasticity");
    CHECK(problems[3].field == "Normal");
    CHECK(problems[4].field == "CollisionPlane");
    CHECK(problems[5].line == 5);
    CHECK(problems[5].field == "record");

    try {
        (void)parseScene(text, "test.scene");
        FAIL("should have thrown");
    } catch (const ConfigError& error) {
        std::string joined;
        for (const ConfigDiagnostic& problem : error.diagnostics()) {
            joined += (joined.empty() ? "" : "\n") + problem.message();
        }
        CHECK(std::string(error.what()) == joined);
    }
}

TEST_CASE("One bad line means no Scene at all", "[config]") {
    CHECK_THROWS_AS(parseScene("DynamicObject\nDynamicObject\nCollisionPlane, Mass=1\n", "test.scene"), ConfigError);
}

TEST_CASE("A file that cannot be opened is a ConfigError at line 0", "[config]") {
    const std::string path = "/nonexistent/stepwise/missing.scene";
    try {
        (void)loadSceneFile(path);
        FAIL("should have thrown");
    } catch (const ConfigError& error) {
        REQUIRE(error.diagnostics().size() == 1);
        const ConfigDiagnostic& problem = error.diagnostics().front();
        CHECK(problem.line == 0);
        CHECK(problem.file == path);
        CHECK_THAT(std::string(error.what()), Contains("could not open"));
        CHECK_THAT(std::string(error.what()), Contains(path));
    }
    CHECK_THROWS_AS(loadSceneFile("/"), ConfigError);  // a directory is not a scene file
}
