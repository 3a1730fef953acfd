// A lecture's gdb session, run for real: lectures/gdb/03-first-impact.gdb in
// batch mode on this build's stepwise, as lectures/README.md tells students
// to. It checks that the anchored breakpoints (lectures/gdb/stepwise.py) stop
// where the lecture says and that the locals it prints hold the physics of
// the first bounce. Tag: [gdb] (CTest label gdb). It needs a Debug build
// (-O0 -g3 -fno-inline, CMakeLists.txt: the debug and asan presets, about 5 s);
// another build (Release: the ci preset) has no locals to print, so there it is
// skipped, and CTest reports it as skipped (tests/skip.hpp). A Debug build
// without gdb fails it: scripts/setup.sh installs it.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <regex>
#include <string>

#include "command_runner.hpp"
#include "skip.hpp"

namespace {

const std::string kRoot = STEPWISE_SOURCE_DIR;
const std::string kStepwise = STEPWISE_CLI_PATH;
constexpr bool kDebugBuild = STEPWISE_CLI_DEBUG_BUILD;  // stepwise compiled at -O0 -g3 -fno-inline

/// The `$N = number` lines gdb printed, by N.
std::map<int, double> printedNumbers(const std::string& output) {
    std::map<int, double> values;
    const std::regex line(R"(^\$(\d+) = (-?[0-9.e+-]+)\s*$)", std::regex::multiline);
    for (auto it = std::sregex_iterator(output.begin(), output.end(), line); it != std::sregex_iterator(); ++it) {
        values[std::stoi((*it)[1])] = std::stod((*it)[2]);
    }
    return values;
}

/// Fails the test case unless gdb is installed and finds this build's line information.
void requireGdb() {
    if (stepwise::test::shell("command -v gdb").exitCode != 0) {
        FAIL("gdb is not installed, and this Debug build is the one the [gdb] tests are for: "
             "scripts/setup.sh installs it (Debian package gdb)");
    }
    const std::string line = stepwise::test::shell("gdb -q -batch -ex 'info line stepwise::correctPositions' '" + kStepwise + "'").output;
    if (line.find("starts at address") == std::string::npos) {
        FAIL(kStepwise << " is a Debug build, but gdb finds no line information in it:\n" << line);
    }
}

}  // namespace

TEST_CASE("Lecture 3's first-impact session stops at its anchors and prints the bounce", "[gdb]") {
    if (!kDebugBuild) {
        STEPWISE_SKIP(kStepwise << " is not a Debug build (-O0 -g3): the session prints locals it does not keep; "
                                   "the debug and asan presets run this test");
    }
    requireGdb();
    // The sanitizers' leak check cannot run under ptrace; it is not what this test is about.
    const stepwise::test::CommandResult run = stepwise::test::shell(
        "cd '" + kRoot + "' && ASAN_OPTIONS=detect_leaks=0 gdb -q -batch -x lectures/gdb/03-first-impact.gdb --args '" +
        kStepwise + "' run config/lesson03_bounce.scene");
    INFO(run.output);
    CHECK(run.output.find("<optimized out>") == std::string::npos);
    CHECK(run.output.find("No symbol") == std::string::npos);
    // Each anchor stopped at the line holding its text (gdb shows "LINE<tab>SOURCE" at a
    // stop): prepare()'s bounce target, then solve()'s accumulated normal impulse.
    CHECK(std::regex_search(run.output, std::regex(R"(Breakpoint 1, stepwise::\(anonymous namespace\)::prepare .*\n\d+\t\s*)"
                                                   R"(c\.targetSeparation = e \* approachAtTouch;)")));
    CHECK(std::regex_search(run.output, std::regex(R"(Breakpoint 2, stepwise::\(anonymous namespace\)::solve .*\n\d+\t\s*)"
                                                   R"(applyImpulse\(c, \(c\.normalImpulse - previous\) \* c\.normal\);)")));

    // The scene: a 1 kg ball (r = 0.1 m, e = 0.8) dropped from rest with its centre at
    // 1.1 m, g = 9.81 m/s², h = 1/60 s, Verlet (exact under constant gravity).
    const double g = 9.81, h = 1.0 / 60.0, e = 0.8, mass = 1.0, fall = 1.1 - 0.1;
    const int steps = 28;  // 27 whole steps in the air, found 0.0682 m deep after the 28th ($9 = 27)
    const double vn = -g * steps * h;                  // v_n at the end of the step, m/s
    const double vc = std::sqrt(2.0 * g * fall);       // v_c, the speed at the touch, m/s
    const double j = mass * (e * vc - vn);             // the impulse that leaves at e·v_c, N·s
    const std::map<int, double> printed = printedNumbers(run.output);
    REQUIRE(printed.count(14) == 1);
    CHECK(printed.at(3) == Approx(vn).margin(1e-12));   // p vn
    CHECK(printed.at(6) == Approx(vc).margin(1e-12));   // p approachAtTouch
    CHECK(printed.at(8) == Approx(e).margin(1e-15));    // p e
    CHECK(printed.at(9) == steps - 1);                  // p stepCount_
    CHECK(printed.at(14) == Approx(j).margin(1e-12));   // p c.normalImpulse, after the first pass
}
