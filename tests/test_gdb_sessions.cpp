// The lectures' gdb sessions, run for real on this build's stepwise, the way lectures/README.md
// tells students to run them. Tag: [gdb] (CTest label gdb).
//
// "Every lecture gdb session runs to its end without a gdb error" runs every lectures/gdb/*.gdb
// (not breakpoints/, which only set breakpoints) on the command line of its "all at once:" header
// line, after making the copy of a scene that its "scene copy:" line makes; the /tmp/ of those
// lines is a scratch folder of the test's own, so test runs share no file. A session fails on
// a gdb error (a symbol not in scope, a function not defined, a break-at text on no line, a
// Python exception, …), on gdb's exit status (in -batch, 1 when a command of the file failed)
// and on a breakpoint that never stops the program: a session whose program ends before its
// breakpoints stop prints nothing wrong but shows nothing either. gdb reports its stops to
// tests/gdb_session_probe.py, sourced before the session, which sees the stops of `silent`
// breakpoints too.
//
// "Lecture 3's first-impact session …" runs one session and checks what it prints against the
// physics of the first bounce.
//
// Both need a Debug build (-O0 -g3 -fno-inline, CMakeLists.txt): the debug and asan presets (CI
// runs them in the asan build; 20 to 30 s in either). Another build (Release: the ci preset) has no locals to
// print, so there they are skipped, and CTest reports them as skipped (tests/skip.hpp). A Debug
// build without gdb fails them: scripts/setup.sh installs it.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "command_runner.hpp"
#include "skip.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kRoot = STEPWISE_SOURCE_DIR;
const std::string kStepwise = STEPWISE_CLI_PATH;
constexpr bool kDebugBuild = STEPWISE_CLI_DEBUG_BUILD;  // stepwise compiled at -O0 -g3 -fno-inline
constexpr bool kSanitized = STEPWISE_CLI_SANITIZED;     // and instrumented by ASan and UBSan

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

/// The lines of @p text.
std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
        text.replace(at, from.size(), to);
    }
    return text;
}

/// A session file's header line "#   LABEL:  TEXT" ("all at once", "scene copy", "your copy"): TEXT, or "".
std::string headerLine(const fs::path& session, const std::string& label) {
    const std::string start = "#   " + label + ":";
    std::ifstream in(session);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(start, 0) != 0) continue;
        const std::size_t text = line.find_first_not_of(' ', start.size());
        return text == std::string::npos ? "" : line.substr(text);
    }
    return "";
}

/// The step-through sessions, lectures/gdb/*.gdb, by name.
std::vector<fs::path> lectureSessions() {
    std::vector<fs::path> sessions;
    for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(kRoot) / "lectures" / "gdb")) {
        if (entry.is_regular_file() && entry.path().extension() == ".gdb") sessions.push_back(entry.path());
    }
    std::sort(sessions.begin(), sessions.end());
    return sessions;
}

/// A folder of this test process's own that stands for the /tmp/ of the sessions' command lines,
/// so that the scene copies of two test runs never meet; removed at scope exit.
class Scratch {
public:
    Scratch() : path_(fs::temp_directory_path() / ("stepwise-test-" + std::to_string(::getpid()) + "-gdb-sessions")) {
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~Scratch() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;

    /// @p text (a shell command, a command line) with its /tmp/ paths in this folder.
    std::string local(const std::string& text) const { return replaceAll(text, "/tmp/", path_.string() + "/"); }

private:
    fs::path path_;
};

/// One session, ready to run: the shell command that runs it, or why it cannot be run.
struct SessionRun {
    std::string name;     ///< lectures/gdb/NAME.gdb
    std::string command;  ///< gdb on this build's stepwise, as the header says, from the repository's root
    std::string problem;  ///< why the header gives no command that can run, or ""
    stepwise::test::CommandResult result;
};

/// The session's "all at once:" command line, on this build's stepwise, its /tmp/ in @p scratch; first
/// makes the scene copy it runs on. The copy a student edits in an exercise ("your copy:", e.g.
/// `cp config/lesson03_bounce.scene /tmp/my_bounce.scene, elasticity 1`) is made by its `cp`, unedited:
/// the session stops at the same code whatever the student changes in the scene.
SessionRun prepare(const fs::path& session, const Scratch& scratch) {
    SessionRun run;
    run.name = "lectures/gdb/" + session.filename().string();
    const std::string expected = "gdb -q -batch -x " + run.name + " --args build/debug/stepwise ";
    const std::string allAtOnce = headerLine(session, "all at once");
    if (allAtOnce.rfind(expected, 0) != 0) {
        run.problem = "no header line \"#   all at once:  " + expected + "ARGUMENTS\"";
        return run;
    }
    const std::string arguments = allAtOnce.substr(expected.size());
    std::istringstream words(arguments);
    std::string subcommand;
    std::string scene;
    words >> subcommand >> scene;  // "run SCENE [OPTIONS]"

    const std::string copy = headerLine(session, "scene copy");
    if (!copy.empty()) {
        const stepwise::test::CommandResult made = stepwise::test::shell("cd '" + kRoot + "' && " + scratch.local(copy));
        if (made.exitCode != 0) run.problem = "the scene copy failed: " + copy + "\n" + made.output;
    } else if (scene.rfind("/tmp/", 0) == 0) {
        std::smatch cp;
        const std::string yours = headerLine(session, "your copy");
        if (!std::regex_search(yours, cp, std::regex(R"(\bcp (\S+) (/tmp/[^\s,;)]+))")) || cp[2] != scene) {
            run.problem = "runs on " + scene + ", which neither a \"scene copy:\" nor a \"your copy:\" line (cp SOURCE " +
                          scene + ") makes";
        } else {
            std::error_code failed;
            fs::copy_file(fs::path(kRoot) / cp[1].str(), scratch.local(scene), fs::copy_options::overwrite_existing, failed);
            if (failed) run.problem = "cannot copy " + cp[1].str() + " for \"your copy:\": " + failed.message();
        }
    }
    // The sanitizers' leak check cannot run under ptrace; it is not what this test is about. A session
    // that hangs fails alone (timeout's status 124), not the whole test at CTest's time limit.
    run.command = "cd '" + kRoot + "' && ASAN_OPTIONS=detect_leaks=0 timeout 120 gdb -q -batch " +
                  "-ex 'source tests/gdb_session_probe.py' -x " + run.name + " --args '" + kStepwise + "' " +
                  scratch.local(arguments);
    return run;
}

/// What gdb prints when a command fails, and what stepwise.py's break-at prints when its text is
/// on no line or on several: the session did not do what its lecture says. Lines that start with
/// "warning: " are not errors (a container without personality() warns "Error disabling address
/// space randomization", and the session still runs).
const std::regex kGdbError(
    R"((^|[^:\w])Error\b|No symbol|not defined|Undefined command|Cannot access memory|Make breakpoint pending|)"
    R"(it must be on exactly one line|files of that name under src/|usage: (t?break|until)-at|Python Exception|Traceback|)"
    R"(There is no member|syntax error|No frame selected|not being run|No stack|<optimized out>|)"
    R"(ERROR: \w*Sanitizer|runtime error:)");

/// @p line without the arguments gdb could not read, if it is a frame line ("FUNCTION (ARGUMENTS) at
/// FILE:LINE", as gdb prints where it stopped) of a sanitizer build. There GCC describes some parameters
/// of an instrumented frame by a scratch register that the frame's calls overwrite (integrateBodies()'s
/// `bodies`: `info address bodies` says DW_OP_breg0 [$rax]), so the frame line a `finish` prints shows
/// `bodies=<error reading variable: Cannot access memory at address 0x6e0>`. The session's own
/// commands print what they print in the debug build; in the debug build such a line is an error.
std::string withoutUnreadableArguments(const std::string& line) {
    static const std::regex frame(R"(^(#\d+ +)?(0x[0-9a-f]+ in )?\S.* \(.*\) at \S+:\d+$)");
    static const std::regex unreadable(R"(<error reading variable: [^>]*>)");
    if (!kSanitized || !std::regex_match(line, frame)) return line;
    return std::regex_replace(line, unreadable, "<unreadable>");
}

/// What went wrong in a session's run: gdb's errors, its exit status, breakpoints that never stopped.
std::vector<std::string> problemsOf(const stepwise::test::CommandResult& result) {
    std::vector<std::string> problems;
    if (result.exitCode == 124) {
        problems.push_back("gdb did not finish in 120 s");
    } else if (result.exitCode != 0) {
        problems.push_back("gdb's exit status is " + std::to_string(result.exitCode) +
                           " (in -batch: a command of the session failed)");
    }
    std::map<int, std::string> breakpoints;  // number → location, as the probe reports them
    std::set<int> stopped;
    const std::regex created(R"(^\[gdb-probe\] created (\d+) (.*)$)");
    const std::regex stop(R"(^\[gdb-probe\] stop ([\d,]+) )");
    for (const std::string& line : linesOf(result.output)) {
        std::smatch match;
        if (std::regex_search(line, match, created)) {
            breakpoints[std::stoi(match[1])] = match[2];
        } else if (std::regex_search(line, match, stop)) {
            std::istringstream numbers(match[1].str());
            for (std::string number; std::getline(numbers, number, ',');) stopped.insert(std::stoi(number));
        } else if (line.rfind("warning: ", 0) != 0 && std::regex_search(withoutUnreadableArguments(line), kGdbError)) {
            problems.push_back("gdb error: " + line);
        }
    }
    if (breakpoints.empty()) problems.push_back("the session sets no breakpoint (or gdb never read it)");
    for (const auto& [number, location] : breakpoints) {
        if (stopped.count(number) == 0) {
            problems.push_back("breakpoint " + std::to_string(number) + " (" + location + ") never stopped the program");
        }
    }
    return problems;
}

}  // namespace

TEST_CASE("Every lecture gdb session runs to its end without a gdb error", "[gdb]") {
    if (!kDebugBuild) {
        STEPWISE_SKIP(kStepwise << " is not a Debug build (-O0 -g3): the sessions print locals it does not keep; "
                                   "the debug and asan presets run this test");
    }
    requireGdb();
    const std::vector<fs::path> sessions = lectureSessions();
    REQUIRE(sessions.size() >= 25);

    const Scratch scratch;
    std::vector<SessionRun> runs;
    for (const fs::path& session : sessions) runs.push_back(prepare(session, scratch));
    // Two at a time: a session is a second or two in the debug build and several under the
    // sanitizers, mostly gdb reading the program's debugging information.
    std::atomic<std::size_t> next{0};
    const auto worker = [&] {
        for (std::size_t i = next++; i < runs.size(); i = next++) {
            if (runs[i].problem.empty()) runs[i].result = stepwise::test::shell(runs[i].command);
        }
    };
    std::thread second(worker);
    worker();
    second.join();

    std::size_t ran = 0;
    for (const SessionRun& run : runs) {
        if (!run.problem.empty()) {
            FAIL_CHECK(run.name << ": " << run.problem);
            continue;
        }
        ++ran;
        const std::vector<std::string> problems = problemsOf(run.result);
        if (problems.empty()) continue;
        std::string listed;
        for (const std::string& problem : problems) listed += "  " + problem + "\n";
        FAIL_CHECK(run.name << ":\n" << listed << "command: " << run.command << "\noutput:\n" << run.result.output);
    }
    // Every session ran: none can pass by being left out.
    CHECK(ran == sessions.size());
}

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
