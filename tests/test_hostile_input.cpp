// Hostile input: the scenes and command lines of issue 34's campaign, each of which once
// aborted, hung or was silently misread. Each must now end in exit 2 with the file, line and
// column (a scene the loader refuses), exit 1 with a message naming the cause, or a correct run.
// Tags: [cli][hostile].
#include <catch2/catch.hpp>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "command_runner.hpp"
#include "core/limits.hpp"

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

namespace {

/// A command's parser, and what to feed it: a line it accepts, an option with a number, and an
/// option that takes a value.
struct CommandParser {
    std::string command;
    std::vector<std::string> valid;  ///< A line the parser accepts.
    std::string numberOption;        ///< An option whose value is a number.
    std::string number;              ///< A value it accepts.
    std::string valueOption;         ///< An option that takes a value (any one).
};

/// Parses @p args as `stepwise COMMAND ARGS` would; the UsageError's message, or "" when accepted.
std::string refusal(const std::string& command, const std::vector<std::string>& args) {
    using namespace stepwise::cli;
    try {
        if (!parseCommandOptions(command, args, "default.scene")) return "no such command";
    } catch (const UsageError& error) {
        return error.what();
    }
    return "";
}

std::vector<std::string> operator+(std::vector<std::string> line, const std::vector<std::string>& more) {
    line.insert(line.end(), more.begin(), more.end());
    return line;
}

const std::vector<CommandParser> kParsers = {
    {"run", {"s.scene"}, "--steps", "5", "--csv"},
    {"view", {"s.scene", "--screenshot", "x.png"}, "--at", "1.5", "--dump-state"},
    {"plot", {"s.scene", "--quantity", "position", "--out", "x.png"}, "--every", "2", "--data"},
    {"grade", {"submissions"}, "--max-steps", "500", "--expect"},
    {"trace", {"s.scene"}, "--digits", "6", "--from"},
    {"raycast", {"s.scene", "--from", "0,1,0", "--dir", "0,-1,0"}, "--at", "0.25", "--max"},
    {"generate", {"sphere-rain", "--count", "10", "--out", "x.scene"}, "--seed", "3", "--broadphase"},
    {"bench", {"broadphase", "s.scene"}, "--check-every", "2", "--steps"},
};

}  // namespace

TEST_CASE("Every command reads its arguments by the same rules", "[cli][hostile]") {
    for (const CommandParser& p : kParsers) {
        INFO("stepwise " << p.command);
        REQUIRE(refusal(p.command, p.valid).empty());
        CHECK(refusal(p.command, p.valid + std::vector<std::string>{p.numberOption, p.number}).empty());
        // Once: `--steps 5 --steps 6` quietly meant 6.
        CHECK_THAT(refusal(p.command, p.valid + std::vector<std::string>{p.numberOption, p.number, p.numberOption, p.number}),
                   Contains(p.numberOption + " is given twice ('" + p.number + "' and '" + p.number + "')"));
        // Once: `run S --csv --steps 5` wrote the trajectory to a file named "--steps".
        CHECK_THAT(refusal(p.command, p.valid + std::vector<std::string>{p.valueOption, p.numberOption, p.number}),
                   Contains(p.valueOption + " needs a value, found the option '" + p.numberOption + "'"));
        CHECK_THAT(refusal(p.command, p.valid + std::vector<std::string>{p.valueOption}),
                   Contains(p.valueOption + " needs a value"));
        // Numbers as a scene file writes them: once, `--duration 0x10` was read as 16.
        for (const char* bad : {"0x10", "5m", "nan", "inf", "1e999", ""}) {
            CHECK_THAT(refusal(p.command, p.valid + std::vector<std::string>{p.numberOption, bad}),
                       Contains(p.numberOption + " expects ") && Contains("found '" + std::string(bad) + "'"));
        }
        CHECK_THAT(refusal(p.command, p.valid + std::vector<std::string>{"--no-such-option"}),
                   Contains("unknown option '--no-such-option' for '" + p.command + "'"));
        // A bad value is quoted as the scene loader quotes a token: escaped, and cut.
        CHECK_THAT(refusal(p.command, p.valid + std::vector<std::string>{p.numberOption, "\x1b[31m" + std::string(5000, '9')}),
                   Contains("found '\\x1b[31m999") && Contains("more bytes)"));
    }
}

TEST_CASE("Command-line numbers follow the scene file's rules and limits", "[cli][hostile]") {
    using namespace stepwise::cli;
    // A fraction, as in `TimeStep=1/60`.
    CHECK(*parseRunOptions({"s.scene", "--duration", "1/60"}, "").duration == Approx(1.0 / 60).epsilon(1e-15));
    CHECK(parseRunOptions({"s.scene", "--steps", "1e3"}, "").steps == std::uint64_t(1000));
    CHECK_THAT(refusal("run", {"s.scene", "--steps", "2.5"}), Contains("--steps expects a whole number"));
    CHECK_THAT(refusal("run", {"s.scene", "--threads", "257"}),
               Contains("--threads expects a whole number from 0 to " + std::to_string(stepwise::kMaxThreads)));
    // Generated scenes have a documented maximum: once, --count 1000000000 ended in bad_alloc.
    CHECK(parseGenerateOptions({"sphere-rain", "--count", "1000000", "--out", "x"}).generator.count == 1000000);
    CHECK_THAT(refusal("generate", {"sphere-rain", "--count", "1000001", "--out", "x"}),
               Contains("--count expects a whole number from 1 to 1000000"));
    // A direction must have one: once, --dir 1e308,-1e308,0 normalised to zero and the run aborted.
    for (const char* bad : {"1e308,-1e308,0", "0,0,0", "1e-10,0,0"}) {
        CHECK_THAT(refusal("raycast", {"s.scene", "--from", "0,1,0", "--dir", bad}),
                   Contains("--dir expects a direction x,y,z whose length is at least 1e-9"));
    }
    CHECK(parseRaycastOptions({"s.scene", "--from", "0,1,0", "--dir", "1e-9,0,0"}).direction.x == stepwise::Real(1e-9));
    CHECK_THAT(refusal("raycast", {"s.scene", "--from", "0,1", "--dir", "0,-1,0"}), Contains("--from expects three numbers"));
}

TEST_CASE("stepwise COMMAND --help prints that command's usage", "[cli][hostile]") {
    // Once: `raycast --help` said "--help needs a value".
    for (const std::string command : {"run", "view", "check", "grade", "raycast", "generate", "bench", "trace", "plot"}) {
        const CommandResult r = runStepwise(command + " --help");
        INFO(r.output);
        CHECK(r.exitCode == 0);
        CHECK_THAT(r.output, StartsWith("Usage:\n  stepwise " + command));
        CHECK_THAT(r.output, !Contains("stepwise: error"));
    }
    // And the raycast that once aborted is refused before any scene is read.
    const CommandResult r = runStepwise("raycast " + std::string(STEPWISE_SOURCE_DIR) +
                                        "/config/default.scene --from 0,1,0 --dir 1e308,-1e308,0");
    CHECK(r.exitCode == 2);
    CHECK_THAT(r.output, Contains("--dir expects a direction") && !Contains("Ray from"));
}

TEST_CASE("A FIFO or a device as the scene file is refused, not waited on", "[cli][hostile]") {
    // Once: a FIFO no one writes blocked `check` forever.
    const TempFile fifo("fifo.scene");
    REQUIRE(::mkfifo(fifo.path.c_str(), 0600) == 0);
    for (const std::string& target : {fifo.quoted(), std::string("/dev/zero")}) {
        for (const std::string& command :
             {"check " + target, "run " + target + " --steps 1", "trace " + target,
              "raycast " + target + " --from 0,1,0 --dir 0,-1,0", "bench broadphase " + target,
              "plot " + target + " --quantity energy --data -"}) {
            // `timeout` turns a hang into a failure of this test rather than of the test run.
            const CommandResult r = stepwise::test::shell("timeout 20 '" + std::string(STEPWISE_CLI_PATH) + "' " + command);
            INFO("stepwise " << command << "\n" << r.output);
            CHECK(r.exitCode == 2);
            CHECK_THAT(r.output, Contains("could not open the scene file (it is a ") && Contains(", not a regular file)"));
        }
    }
}

TEST_CASE("A time budget, --max-seconds, stops run and trace between steps, with what they did", "[cli][hostile]") {
    // A hundred million steps of the default scene would take hours; the budget ends them.
    const std::string scene = "'" + std::string(STEPWISE_SOURCE_DIR) + "/config/default.scene'";
    const CommandResult run = runStepwise("run " + scene + " --steps 100000000 --max-seconds 0.2");
    INFO(run.output);
    CHECK(run.exitCode == 1);
    CHECK_THAT(run.output, Contains("stopped after --max-seconds 0.2 of wall-clock time: ") &&
                               Contains(" of 100000000 steps") && Contains("Simulated ") && Contains("Final state"));
    const CommandResult trace = runStepwise("trace " + scene + " --steps 100000000 --stage sleep --max-seconds 0.2");
    CHECK(trace.exitCode == 1);
    CHECK_THAT(trace.output, Contains("step 1  sleep") && Contains("trace stopped: --max-seconds 0.2"));
}

TEST_CASE("grade gives each file a time budget, and prints each row as the file finishes", "[cli][hostile][grade]") {
    // a.scene passes at once; b.scene asks for 600 000 steps of a ball that never sleeps.
    const TempFile folder("grade-budget");
    std::filesystem::create_directories(folder.path);
    const auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(folder.path / name) << text;
    };
    write("a.scene", "World, Duration=1\nDynamicObject, Name=ball, Position=(0, 0.5, 0)\nCollisionPlane\n"
                     "Expect, Object=ball, Time=1, PositionY=0.5, Tolerance=0.01\n");
    write("b.scene", "World, Sleep=false, Duration=10000\nDynamicObject, Name=ball, Position=(0, 0.5, 0)\n"
                     "CollisionPlane\nExpect, Object=ball, Time=10000, PositionY=0.5, Tolerance=0.01\n");
    SECTION("past its budget, a file fails with a row that says so") {
        const CommandResult r = runStepwise("grade " + folder.quoted() + " --max-seconds 0.2");
        INFO(r.output);
        CHECK(r.exitCode == 3);
        CHECK_THAT(r.output, Contains("a.scene  PASS") && Contains("b.scene  FAIL   0/1     took longer than --max-seconds 0.2: "));
        CHECK_THAT(r.output, Contains("2 file(s): 1 passed, 1 failed"));
    }
    SECTION("a row is out before the next file ends: Ctrl-C during b.scene keeps a.scene's row") {
        const TempFile out("grade-budget.out");
        // Wait (at most 20 s) for a.scene's row in the output file, then interrupt b.scene's run.
        const std::string script = "'" + std::string(STEPWISE_CLI_PATH) + "' grade " + folder.quoted() + " > " +
                                   out.quoted() + " 2>&1 & pid=$!; for i in $(seq 400); do grep -q 'a.scene  PASS' " +
                                   out.quoted() + " && break; sleep 0.05; done; kill -INT $pid; wait $pid";
        const CommandResult r = stepwise::test::shell(script);
        std::ifstream in(out.path);
        const std::string printed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        INFO(r.output << "\n" << printed);
        CHECK(r.exitCode == 130);
        CHECK_THAT(printed, Contains("a.scene  PASS") && Contains("b.scene  FAIL") && Contains("stopped by a signal"));
        CHECK_THAT(printed, Contains("grading stopped by signal 2 after 2 of 2 file(s)"));
    }
    std::filesystem::remove_all(folder.path);
}

TEST_CASE("Running out of memory is a message naming the cause, not an abort", "[cli][hostile][slow]") {
    // Once: 5000 spheres dropped on one spot ended in an uncaught std::bad_alloc. Their
    // n(n-1)/2 = 12 497 500 contacts need far more than the 2 GB of address space allowed here.
    // [slow]: the sanitizer build reserves more address space than that for itself.
    std::string text = "World, Duration=1\nCollisionPlane, Name=floor\n";
    for (int i = 0; i < 5000; ++i) text += "DynamicObject, Name=s" + std::to_string(i) + ", Position=(0, 1, 0)\n";
    const TempFile file("coincident.scene", text);
    const CommandResult r =
        stepwise::test::shell("ulimit -v 2000000; '" + std::string(STEPWISE_CLI_PATH) + "' run " + file.quoted() + " --steps 2");
    INFO(r.output.substr(0, 2000));
    CHECK(r.exitCode == 1);
    CHECK_THAT(r.output, Contains("stepwise: error: out of memory in step 1 (t = 0 s) of a scene of 5000 dynamic bodies") &&
                             Contains("n(n-1)/2 = 1.25e+07"));
}
