// The values the lectures quote at their breakpoints, checked against
// `stepwise trace`: each lecture keeps, next to a gdb transcript, a hidden block
//
//   <!-- trace-check: stepwise trace config/SCENE.scene [trace options]
//   step 28 resolve-impulses ball|floor: v_c = 4.42945 ± 1e-5; j = 8.12156 ± 1e-5
//   -->
//
// Each line names a trace line by its first words (a last word "#N": the N-th such
// line), then `label = value ± tolerance`
// checks separated by ';' (a value is a number or "(x, y, z)"; "label->" is the
// value after the arrow, what the stage produced; "label.y" one component). A check fails naming the
// lecture, the line and the value, so a lecture cannot drift from the code.
// docs/trace.md describes the lines. Tag: [lectures].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "config/scene_loader.hpp"
#include "trace_values.hpp"

namespace fs = std::filesystem;
using namespace stepwise;

namespace {

const fs::path kRoot = STEPWISE_SOURCE_DIR;
constexpr const char* kBlockStart = "<!-- trace-check:";
constexpr const char* kCommand = "stepwise trace";

/// One `label = value ± tolerance` of a check line.
struct ValueCheck {
    std::string label;
    std::vector<double> expected;
    double tolerance = 0;
};

/// "(x, y, z)", "(w, x, y, z)" or "x" → the numbers; empty when it is none of them.
std::vector<double> parseValue(const std::string& text) {
    std::string inner = text;
    const bool vector = inner.find('(') != std::string::npos;
    for (char& ch : inner) {
        if (ch == '(' || ch == ')' || ch == ',') ch = ' ';
    }
    std::vector<double> values;
    std::istringstream in(inner);
    for (double x; in >> x;) values.push_back(x);
    if (!in.eof() || (vector ? values.size() < 2 : values.size() != 1)) return {};
    return values;
}

std::string trim(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::string show(const std::vector<double>& values) {
    std::ostringstream out;
    out.precision(12);
    if (values.size() == 1) {
        out << values[0];
    } else {
        out << "(";
        for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << values[i];
        out << ")";
    }
    return out.str();
}

/// The value of @p label in a trace line; "label.x", ".y", ".z" pick one component of a vector.
std::vector<double> valueOf(const std::string& line, const std::string& label) {
    const std::size_t dot = label.size() > 2 ? label.size() - 2 : 0;
    if (dot > 0 && label[dot] == '.' && std::string("xyz").find(label[dot + 1]) != std::string::npos) {
        const std::vector<double> all = test::traceValue(line, label.substr(0, dot));
        const std::size_t component = std::string("xyz").find(label[dot + 1]);
        if (all.size() != 3) return {};
        return {all[component]};
    }
    return test::traceValue(line, label);
}

std::vector<fs::path> lectureFiles() {
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(kRoot / "lectures")) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".md" && name.size() > 2 && std::isdigit(static_cast<unsigned char>(name[0])))
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// Checks every trace-check block of @p lecture; returns how many values it checked.
int checkLecture(const fs::path& lecture) {
    std::ifstream in(lecture);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    const std::string name = "lectures/" + lecture.filename().string();
    int checked = 0;
    std::map<std::string, Scene> scenes;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        // Blocks may be indented, to sit inside a list item next to its transcript.
        if (trim(lines[i]).rfind(kBlockStart, 0) != 0) continue;
        const std::string where = name + ":" + std::to_string(i + 1);
        std::vector<std::string> args = test::words(trim(lines[i]).substr(std::string(kBlockStart).size()));
        if (args.size() < 3 || args[0] + " " + args[1] != kCommand) {
            FAIL_CHECK(where << ": a trace-check block starts 'stepwise trace SCENE [options]'");
            continue;
        }
        const std::string scenePath = args[2];
        args.erase(args.begin(), args.begin() + 3);
        if (!scenes.count(scenePath)) scenes.emplace(scenePath, loadSceneFile((kRoot / scenePath).string()));
        std::string trace;
        try {
            trace = test::traceOf(scenes.at(scenePath), args);
        } catch (const std::exception& error) {
            FAIL_CHECK(where << ": stepwise trace " << scenePath << " failed: " << error.what());
            continue;
        }
        for (++i; i < lines.size() && trim(lines[i]) != "-->"; ++i) {
            const std::string at = name + ":" + std::to_string(i + 1);
            const std::string text = trim(lines[i]);
            const std::size_t colon = text.find(": ");
            if (trim(text).empty()) continue;
            if (colon == std::string::npos) {
                FAIL_CHECK(at << ": expected 'step N STAGE OBJECT: label = value ± tolerance; ...'");
                continue;
            }
            const std::string header = text.substr(0, colon);
            const std::string line = test::traceLine(trace, header);
            if (line.empty()) {
                FAIL_CHECK(at << ": stepwise trace " << scenePath << " has no line '" << header << "'");
                continue;
            }
            std::istringstream checks(text.substr(colon + 2));
            for (std::string item; std::getline(checks, item, ';');) {
                const std::size_t equals = item.find('=');
                std::size_t plusMinus = item.find("±");
                std::size_t markLength = 2;
                if (plusMinus == std::string::npos) {
                    plusMinus = item.find("+-");
                    markLength = 2;
                }
                ValueCheck check;
                if (equals != std::string::npos && plusMinus != std::string::npos && plusMinus > equals) {
                    check.label = trim(item.substr(0, equals));
                    check.expected = parseValue(item.substr(equals + 1, plusMinus - equals - 1));
                    const std::vector<double> tolerance = parseValue(item.substr(plusMinus + markLength));
                    if (tolerance.size() == 1) check.tolerance = tolerance[0];
                }
                if (check.label.empty() || check.expected.empty() || check.tolerance <= 0) {
                    FAIL_CHECK(at << ": cannot read '" << trim(item) << "' (label = value ± tolerance)");
                    continue;
                }
                const std::vector<double> actual = valueOf(line, check.label);
                bool same = actual.size() == check.expected.size();
                for (std::size_t k = 0; same && k < actual.size(); ++k) {
                    same = std::abs(actual[k] - check.expected[k]) <= check.tolerance;
                }
                if (!same) {
                    FAIL_CHECK(at << ": " << header << ": " << check.label << " is "
                                  << (actual.empty() ? std::string("missing") : show(actual)) << " in the trace, the lecture says "
                                  << show(check.expected) << " ± " << check.tolerance << "\n  trace: " << line);
                }
                ++checked;
            }
        }
    }
    return checked;
}

/// A step number gdb shows in a lecture: `(gdb) p stepCount_` answered `$N = K`, or a breakpoint
/// condition `if stepCount_ == K`. K counts the steps completed, so the step is K + 1.
struct GdbStepCount {
    std::size_t line = 0;  ///< Where the transcript shows it (from 0).
    long count = 0;        ///< K, World::stepCount_.
};

/// The steps each trace-check block names, by the block's first line (from 0).
std::map<std::size_t, std::set<long>> traceCheckSteps(const std::vector<std::string>& lines) {
    std::map<std::size_t, std::set<long>> blocks;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (trim(lines[i]).rfind(kBlockStart, 0) != 0) continue;
        std::set<long>& steps = blocks[i];
        for (std::size_t k = i + 1; k < lines.size() && trim(lines[k]) != "-->"; ++k) {
            const std::vector<std::string> w = test::words(trim(lines[k]));
            if (w.size() >= 2 && w[0] == "step") steps.insert(std::strtol(w[1].c_str(), nullptr, 10));
        }
    }
    return blocks;
}

std::vector<GdbStepCount> gdbStepCounts(const std::vector<std::string>& lines) {
    std::vector<GdbStepCount> found;
    const std::regex printed(R"(^\$\d+ = (\d+)$)");
    const std::regex condition(R"(^(?:\(gdb\) |\+)t?break-at .* if stepCount_ == (\d+)$)");
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string text = trim(lines[i]);
        std::smatch match;
        const std::string next = i + 1 < lines.size() ? trim(lines[i + 1]) : "";
        if (text == "(gdb) p stepCount_" && std::regex_match(next, match, printed)) {
            found.push_back({i, std::stol(match[1])});
        } else if (std::regex_match(text, match, condition)) {
            found.push_back({i, std::stol(match[1])});
        }
    }
    return found;
}

}  // namespace

TEST_CASE("A trace shown in full in the lectures or docs/trace.md is what stepwise trace prints", "[lectures]") {
    // A ```sh block whose one line is `[build/PRESET/]stepwise trace config/SCENE [options]`, then
    // (after blank lines) a plain ``` block: that block is the command's output, line for line.
    std::vector<fs::path> pages = lectureFiles();
    pages.push_back(kRoot / "docs" / "trace.md");
    const std::regex command(R"(^(?:build/\w+/)?stepwise trace (config/\S+\.scene)((?: \S+)*)$)");
    int shown = 0;
    for (const fs::path& page : pages) {
        std::ifstream in(page);
        std::vector<std::string> lines;
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        for (std::size_t i = 0; i + 3 < lines.size(); ++i) {
            std::smatch match;
            const std::string commandLine = trim(lines[i + 1]);
            if (trim(lines[i]) != "```sh" || trim(lines[i + 2]) != "```" || !std::regex_match(commandLine, match, command)) {
                continue;
            }
            std::size_t open = i + 3;
            while (open < lines.size() && trim(lines[open]).empty()) ++open;
            if (open >= lines.size() || trim(lines[open]) != "```") continue;  // the command alone, no output shown
            std::vector<std::string> quoted;
            std::size_t k = open + 1;
            for (; k < lines.size() && trim(lines[k]) != "```"; ++k) quoted.push_back(trim(lines[k]));
            const std::string where = page.lexically_relative(kRoot).generic_string() + ":" + std::to_string(open + 2);
            INFO(where << ": the output of " << commandLine);
            const std::vector<std::string> args = test::words(match[2]);
            const std::vector<std::string> printed =
                test::textLines(test::traceOf(loadSceneFile((kRoot / match[1].str()).string()), args));
            CHECK(quoted.size() == printed.size());
            for (std::size_t n = 0; n < quoted.size() && n < printed.size(); ++n) {
                INFO("line " << n + 1 << " of the block");
                CHECK(quoted[n] == printed[n]);
            }
            ++shown;
            i = k;
        }
    }
    CHECK(shown >= 2);  // docs/trace.md's example and appendix 3a's end of the bouncing
}

TEST_CASE("Every step number gdb shows in a lecture is the trace's step number minus one", "[lectures]") {
    // One convention everywhere: step 1 is the first step. The trace and a SimulationError name
    // the step being taken; gdb's World::stepCount_ counts the steps completed before it, so a
    // transcript that prints stepCount_ = K (or breaks "if stepCount_ == K") is in step K + 1.
    // The first trace-check block after it (the last one before it, when none follows) must name
    // step K + 1: then the lecture's gdb numbers and its trace numbers, both checked, cannot drift apart.
    int counts = 0;
    for (const fs::path& lecture : lectureFiles()) {
        std::ifstream in(lecture);
        std::vector<std::string> lines;
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        const auto blocks = traceCheckSteps(lines);
        for (const GdbStepCount& shown : gdbStepCounts(lines)) {
            ++counts;
            INFO("lectures/" << lecture.filename().string() << ":" << shown.line + 1 << ": stepCount_ = " << shown.count
                             << ", so step " << shown.count + 1);
            REQUIRE_FALSE(blocks.empty());
            auto block = blocks.upper_bound(shown.line);  // the first block after the transcript line
            if (block == blocks.end()) block = std::prev(blocks.end());
            INFO("its trace-check block: line " << block->first + 1);
            CHECK(block->second.count(shown.count + 1) == 1);
        }
    }
    CHECK(counts >= 10);  // the lectures show stepCount_ in many transcripts
}

TEST_CASE("The breakpoint values the lectures quote are what stepwise trace prints", "[lectures]") {
    const std::vector<fs::path> lectures = lectureFiles();
    REQUIRE(lectures.size() >= 9);
    for (const fs::path& lecture : lectures) {
        const std::string name = lecture.filename().string();
        const int checked = checkLecture(lecture);
        INFO("lectures/" << name << " checks " << checked << " values");
        // Lectures 01-08 quote breakpoint values; each must vouch for at least one.
        if (name < "09") CHECK(checked >= 1);
    }
}

TEST_CASE("The trace-check reader reads trace values and rejects what is not one", "[lectures]") {
    const std::string line = "step 1  integrate  ball  x (0.0000, 1.0000, 0.0000) m -> (0.0000, 0.9990, 0.0000) m";
    CHECK(test::traceValue(line, "x->") == std::vector<double>{0, 0.999, 0});
    CHECK(test::traceValue(line, "x") == std::vector<double>{0, 1, 0});
    CHECK(test::traceValue(line, "v").empty());
    CHECK(parseValue("(1, 2, 3)") == std::vector<double>{1, 2, 3});
    CHECK(parseValue(" 4.5 ") == std::vector<double>{4.5});
    CHECK(parseValue("four").empty());
    CHECK(valueOf(line, "x->.y") == std::vector<double>{0.999});
}
