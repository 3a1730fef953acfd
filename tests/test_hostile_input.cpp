// Hostile input: the scenes and command lines of issue 34's campaign, each of which once
// aborted, hung or was silently misread. Each must now end in exit 2 with the file, line and
// column (a scene the loader refuses), exit 1 with a message naming the cause, or a correct run.
// Tags: [cli][hostile].
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "command_runner.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using stepwise::test::CommandResult;
using stepwise::test::runStepwise;
using stepwise::test::TempFile;

namespace {

/// A reproducer: a one-line scene and where its loader error must point.
struct HostileScene {
    std::string text;      ///< The scene file (one record, or a body and the record that uses it).
    int line;              ///< The line the error must name.
    int column;            ///< The column the error must name.
    std::string field;     ///< The field the error must name.
    std::string expected;  ///< Words the "expected ..." part must contain.
};

/// Every command that loads a scene must refuse @p scene the same way, before it runs a step.
void checkRefusedEverywhere(const HostileScene& scene, const std::string& fileName) {
    const TempFile file(fileName, scene.text);
    const std::string where =
        file.path.string() + ":" + std::to_string(scene.line) + ":" + std::to_string(scene.column) + ": error: ";
    for (const std::string& command :
         {"check " + file.quoted(), "run " + file.quoted() + " --steps 1", "trace " + file.quoted() + " --steps 1",
          "raycast " + file.quoted() + " --from 0,5,0 --dir 0,-1,0",
          "bench broadphase " + file.quoted() + " --steps 1"}) {
        INFO("stepwise " << command << "\nscene: " << scene.text);
        const CommandResult r = runStepwise(command);
        INFO(r.output);
        CHECK(r.exitCode == 2);
        CHECK_THAT(r.output, Contains(where + scene.field + ": expected ") && Contains(scene.expected));
        CHECK_THAT(r.output, Contains("nothing was loaded"));
    }
}

}  // namespace

TEST_CASE("Counts that do not fit an int, or are absurdly large, are refused where they are written",
          "[cli][hostile]") {
    // Once: check printed "-2147483648 substeps", and run, trace, raycast and bench aborted.
    std::vector<HostileScene> scenes;
    for (const char* field : {"Substeps", "Iterations", "ImpulseIterations"}) {
        for (const char* value : {"2147483648", "1e10", "1000000000"}) {
            const std::string name = field;
            scenes.push_back({"World, " + name + "=" + value + "\n", 1, int(name.size()) + 9, name,
                              "a whole number from 1 to 1024"});
        }
    }
    scenes.push_back({"World, RelaxIterations=2147483648\n", 1, 24, "RelaxIterations", "a whole number from 0 to 1024"});
    // Once: Threads=40000 passed check, and run aborted creating the threads.
    scenes.push_back({"World, Threads=40000\n", 1, 16, "Threads", "a whole number from 0 to 256"});
    scenes.push_back({"World, Threads=2147483648\n", 1, 16, "Threads", "a whole number from 0 to 256"});
    for (std::size_t i = 0; i < scenes.size(); ++i) checkRefusedEverywhere(scenes[i], "count-" + std::to_string(i) + ".scene");
}

TEST_CASE("Values the engine cannot compute with are refused by the loader, not by the run", "[cli][hostile]") {
    // Once: each passed check and aborted run, because the loader and the World disagreed.
    const std::string direction = "a direction (a vector of length > 0, whose squares do not overflow)";
    const std::vector<HostileScene> scenes = {
        // A normal whose squares overflow normalises to zero.
        {"CollisionPlane, Normal=(1e200, 0, 0)\n", 1, 24, "Normal", direction},
        {"DynamicObject, Name=door\nHingeJoint, BodyA=door, Axis=(1e200, 0, 0)\n", 2, 30, "Axis", direction},
        {"DynamicObject, Name=wheel\nAngularMotor, BodyA=wheel, Axis=(0, 1e200, 0)\n", 2, 33, "Axis", direction},
        // A rod of a nanometre.
        {"DynamicObject, Name=bob\nRope, BodyA=bob, AnchorB=(0, 1, 0), Length=1e-9\n", 2, 44, "Length",
         "a length of at least 1e-6 m"},
        {"DynamicObject, Name=bob\nDistanceJoint, BodyA=bob, AnchorB=(0, 1, 0), Length=1e-9\n", 2, 53, "Length",
         "a length of at least 1e-6 m"},
        // A size that underflows to a zero radius, and one whose inertia overflows.
        {"DynamicObject, Scale=(5e-324, 1, 1)\n", 1, 23, "ScaleX", "a size from 1e-6 to 1e6 m"},
        {"DynamicObject, Radius=1e200\n", 1, 23, "Radius", "a radius from 5e-7 to 500000 m"},
        {"DynamicObject, Mass=1e300\n", 1, 21, "Mass", "a mass from 1e-12 to 1e12 kg"},
        // Five positional numbers: NormalZ was silently kept at its default.
        {"CollisionPlane, 0, 0, 0, 0, 1\n", 1, 29, "Normal", "all 3 components of Normal"},
    };
    for (std::size_t i = 0; i < scenes.size(); ++i) checkRefusedEverywhere(scenes[i], "value-" + std::to_string(i) + ".scene");
}

TEST_CASE("A bad token is quoted with control bytes escaped, NUL bytes named, and long text cut",
          "[cli][hostile]") {
    SECTION("a NUL byte inside a word no longer cuts the message short") {
        const TempFile file("nul.scene", std::string("World, Integrator=Eu\0ler\n", 25));
        const CommandResult r = runStepwise("check " + file.quoted());
        CHECK(r.exitCode == 2);
        CHECK_THAT(r.output, Contains(":1:19: error: Integrator: expected one of") && Contains("found 'Eu\\0ler'"));
    }
    SECTION("a vertical tab after a number is shown, not hidden") {
        const TempFile file("vt.scene", "DynamicObject, Mass=2\v\n");
        const CommandResult r = runStepwise("check " + file.quoted());
        CHECK(r.exitCode == 2);
        CHECK_THAT(r.output, Contains(":1:21: error: Mass:") && Contains("found '2\\v'"));
    }
    SECTION("escape bytes never reach the terminal, and a megabyte token is cut") {
        const std::string junk = "\x1b[31m" + std::string(1 << 20, 'a');
        const TempFile file("junk.scene", "DynamicObject, Mass=" + junk + "\n");
        const CommandResult r = runStepwise("check " + file.quoted());
        CHECK(r.exitCode == 2);
        CHECK(r.output.find('\x1b') == std::string::npos);
        CHECK_THAT(r.output, Contains("found '\\x1b[31maaa") && Contains("more bytes)'"));
        CHECK(r.output.size() < 1000);  // one line of message, not the megabyte
    }
    SECTION("a hint never contradicts the error") {
        // Once: "give a whole vector by name, e.g. Mass=(1,2,3)" for a field that is one number.
        const TempFile file("mass-vector.scene", "DynamicObject, Mass=(1,2,3)\n");
        const CommandResult r = runStepwise("check " + file.quoted());
        CHECK(r.exitCode == 2);
        CHECK_THAT(r.output, Contains("Mass is one number, not a vector"));
        CHECK_THAT(r.output, !Contains("e.g. Mass=("));
    }
}

TEST_CASE("Every limit in the config reference is accepted at its ends", "[cli][hostile]") {
    // The other side of the refusals above: the ends of each range load and run one step.
    const TempFile file("edges.scene",
                        "World, Substeps=1024, Iterations=1, RelaxIterations=0, Threads=256, Duration=1/60\n"
                        "CollisionPlane, Normal=(0, 1e-9, 0)\n"
                        "DynamicObject, Name=heavy, Shape=Box, Position=(0, 0.5, 0), Mass=1e12, Scale=(1e6, 1, 1e6)\n"
                        "DynamicObject, Name=light, Position=(0, 5, 0), Mass=1e-12, Radius=5e-7\n"
                        "DynamicObject, Name=bob, Position=(0, 10, 0)\n"
                        "Rope, BodyA=bob, AnchorB=(0, 10.000001, 0), Length=1e-6\n");
    const CommandResult check = runStepwise("check " + file.quoted());
    INFO(check.output);
    CHECK(check.exitCode == 0);
    const CommandResult run = runStepwise("run " + file.quoted() + " --steps 1");
    INFO(run.output);
    CHECK(run.exitCode == 0);
}

TEST_CASE("A light body crushed through the floor by a heavy one is reported, not hidden", "[cli][hostile]") {
    // Once: a 1e-12 kg box under a 1e12 kg box ended with its centre at y = -0.45, exit 0, and no word.
    const TempFile file("crushed.scene", "World, Duration=1\n"
                                         "CollisionPlane, Name=floor\n"
                                         "DynamicObject, Name=light, Shape=Box, Position=(0, 0.5, 0), Mass=1e-12\n"
                                         "DynamicObject, Name=heavy, Shape=Box, Position=(0, 1.5, 0), Mass=1e12\n");
    const CommandResult check = runStepwise("check " + file.quoted());
    CHECK(check.exitCode == 0);
    CHECK_THAT(check.output, Contains(":3: warning: DynamicObject 'light' (1e-12 kg) presses on 'heavy' (1e+12 kg)"));
    const CommandResult run = runStepwise("run " + file.quoted());
    INFO(run.output);
    CHECK(run.exitCode == 0);  // a warning, not an error: the run is what the scene asked for
    CHECK_THAT(run.output, Contains("stepwise: warning: step ") &&
                               Contains("DynamicObject 'light' has gone through CollisionPlane 'floor'"));
}
