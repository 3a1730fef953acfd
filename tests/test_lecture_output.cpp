// What the lectures quote of a command's output, checked against the program that prints it.
// Before a fenced block that shows what a command prints, or before a paragraph that quotes it,
// a page puts a marker:
//
//   <!-- output-check -->              runs the ```sh block above the marker, as the reader types it
//                                      (prose, and blocks of what it printed, may come between)
//   <!-- output-check: COMMANDS -->    runs COMMANDS, one shell line (`stepwise` is the program)
//
// Before a plain ``` (or ```text) block: the block is an excerpt of what the commands print, its
// lines consecutive lines of the output; a line `...` or `…` stands for lines left out (the stage
// timings, which vary from run to run, are always left out). Before a paragraph, a table or a list
// item (the lines up to the next blank line or item): every `code span` in it that holds a number
// is in one line of the output; markers one above the other give it the output of all of them.
//
// Two lines match when their words are the same (a run of spaces counts as one, and − as -) and
// every number is the printed one to the digits quoted: `-1.4565` matches anything printed from
// -1.45655 to -1.45645, and "6" matches "6.0000", but a last digit changed by one never matches.
//
// The commands run in a scratch folder that stands for the repository's root: config/, lectures/
// and the other folders there link to the repository's, build/PRESET/stepwise and the `stepwise`
// on the PATH are the program built with these tests, and /tmp/ is a folder of the scratch's own
// (printed back as /tmp/). The checks of one page run in the page's order in one scratch folder,
// so a command may read a file an earlier one wrote, as on the reader's machine (a --csv file
// read by awk). Output that cannot be repeated here (a run under gdb on the debug build, timings)
// is marked <!-- output-unchecked: REASON --> instead, which says why.
//
// The test also finds every block of lectures/ that shows what stepwise prints (one after a
// ```sh block that runs it, or one that reads like its report) and fails on one that no marker
// checks. Tag: [lectures].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "command_runner.hpp"
#include "markdown_lines.hpp"

namespace fs = std::filesystem;
namespace test = stepwise::test;

namespace {

const fs::path kRoot = STEPWISE_SOURCE_DIR;
constexpr const char* kMarker = "<!-- output-check";
constexpr const char* kUnchecked = "<!-- output-unchecked:";

using test::codeSpans;
using test::isFence;
using test::readLines;
using test::startsWith;
using test::trim;

std::string fenceLanguage(const std::string& line) { return trim(trim(line).substr(3)); }

bool isElision(const std::string& line) { return trim(line) == "..." || trim(line) == "…"; }

std::string shown(const fs::path& page) { return page.lexically_relative(kRoot).generic_string(); }

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

/// Every markdown file under lectures/ (at any depth) and docs/.
std::vector<fs::path> pagesWithOutput() {
    std::vector<fs::path> pages;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kRoot / "lectures"))
        if (entry.is_regular_file() && entry.path().extension() == ".md") pages.push_back(entry.path());
    for (const fs::directory_entry& entry : fs::directory_iterator(kRoot / "docs"))
        if (entry.is_regular_file() && entry.path().extension() == ".md") pages.push_back(entry.path());
    std::sort(pages.begin(), pages.end());
    return pages;
}

// ---- Comparing what a page quotes with what was printed ----

/// A piece of a line: a number, or the text between numbers.
struct Token {
    bool number = false;
    std::string text;  ///< As written (a number's own digits).
    double value = 0;
    double unit = 0;   ///< A number's last digit is worth this much: 0.0001 for 1.4565.
};

/// The line with − read as -, runs of blanks as one space, and no blanks at either end.
std::string normalise(const std::string& line) {
    const std::string minus = replaceAll(line, "\u2212", "-");
    std::string out;
    for (char ch : minus) {
        if (ch == ' ' || ch == '\t') {
            if (!out.empty() && out.back() != ' ') out += ' ';
        } else {
            out += ch;
        }
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

bool isDigit(char ch) { return std::isdigit(static_cast<unsigned char>(ch)) != 0; }

/// Splits @p line into numbers and the text between them. A number starts where no letter, digit,
/// '_' or '.' comes just before it (box20 is a name), with its sign, and may have a fraction
/// and an exponent (4.12115e-13).
std::vector<Token> tokens(const std::string& line) {
    std::vector<Token> out;
    std::string text;
    std::size_t i = 0;
    while (i < line.size()) {
        const char before = i > 0 ? line[i - 1] : ' ';
        const bool free = !(std::isalnum(static_cast<unsigned char>(before)) || before == '_' || before == '.');
        std::size_t at = i;
        if ((line[at] == '-' || line[at] == '+') && at + 1 < line.size() && isDigit(line[at + 1])) ++at;
        if (!free || !isDigit(line[at])) {
            text += line[i++];
            continue;
        }
        while (at < line.size() && isDigit(line[at])) ++at;
        int decimals = 0;
        if (at + 1 < line.size() && line[at] == '.' && isDigit(line[at + 1])) {
            ++at;
            while (at < line.size() && isDigit(line[at])) {
                ++at;
                ++decimals;
            }
        }
        int exponent = 0;
        if (at + 1 < line.size() && (line[at] == 'e' || line[at] == 'E')) {
            std::size_t e = at + 1;
            if (e < line.size() && (line[e] == '-' || line[e] == '+')) ++e;
            if (e < line.size() && isDigit(line[e])) {
                while (e < line.size() && isDigit(line[e])) ++e;
                exponent = std::atoi(line.substr(at + 1, e - at - 1).c_str());
                at = e;
            }
        }
        if (!text.empty()) out.push_back({false, text});
        text.clear();
        Token number{true, line.substr(i, at - i)};
        number.value = std::strtod(number.text.c_str(), nullptr);
        number.unit = std::pow(10.0, exponent - decimals);
        out.push_back(number);
        i = at;
    }
    if (!text.empty()) out.push_back({false, text});
    return out;
}

/// The printed number, rounded to the digits quoted, is the quoted one.
bool sameNumber(const Token& quoted, const Token& printed) {
    return std::abs(printed.value - quoted.value) <= 0.5 * quoted.unit * (1 + 1e-9);
}

bool sameToken(const Token& quoted, const Token& printed) {
    if (quoted.number != printed.number) return false;
    return quoted.number ? sameNumber(quoted, printed) : quoted.text == printed.text;
}

/// A quoted line of a block is the printed line, number by number.
bool sameLine(const std::string& quoted, const std::string& printed) {
    const std::vector<Token> q = tokens(normalise(quoted));
    const std::vector<Token> p = tokens(normalise(printed));
    if (q.size() != p.size()) return false;
    for (std::size_t i = 0; i < q.size(); ++i)
        if (!sameToken(q[i], p[i])) return false;
    return true;
}

/// A code span of a paragraph is part of the printed line: its first and last pieces of text
/// may be the end and the start of the printed line's, the rest match whole.
bool inLine(const std::vector<Token>& span, const std::string& printed) {
    const std::vector<Token> p = tokens(normalise(printed));
    for (std::size_t start = 0; start + span.size() <= p.size(); ++start) {
        bool all = true;
        for (std::size_t k = 0; k < span.size() && all; ++k) {
            const Token& q = span[k];
            const Token& have = p[start + k];
            if (q.number || span.size() == 1) {
                all = sameToken(q, have);
            } else if (k == 0) {
                all = !have.number && have.text.size() >= q.text.size() &&
                      have.text.compare(have.text.size() - q.text.size(), q.text.size(), q.text) == 0;
            } else if (k + 1 == span.size()) {
                all = !have.number && startsWith(have.text, q.text);
            } else {
                all = sameToken(q, have);
            }
        }
        if (all) return true;
    }
    return false;
}

/// Where a quoted block fails to be an excerpt of @p printed, or "" when it is one. The block's
/// runs of lines between elisions are found in order, each as consecutive printed lines.
std::string excerptMismatch(const std::vector<std::string>& quoted, const std::vector<std::string>& printed) {
    std::vector<std::vector<std::size_t>> runs(1);  // indices into quoted
    for (std::size_t i = 0; i < quoted.size(); ++i) {
        if (isElision(quoted[i])) {
            if (!runs.back().empty()) runs.emplace_back();
        } else {
            runs.back().push_back(i);
        }
    }
    std::size_t from = 0;
    for (const std::vector<std::size_t>& run : runs) {
        if (run.empty()) continue;
        std::size_t bestStart = printed.size();
        std::size_t bestLength = 0;
        bool found = false;
        for (std::size_t start = from; start + run.size() <= printed.size() && !found; ++start) {
            std::size_t length = 0;
            while (length < run.size() && sameLine(quoted[run[length]], printed[start + length])) ++length;
            if (length > bestLength || bestStart == printed.size()) {
                bestLength = length;
                bestStart = start;
            }
            if (length == run.size()) {
                found = true;
                from = start + run.size();
            }
        }
        if (found) continue;
        std::ostringstream why;
        const std::size_t bad = run[std::min(bestLength, run.size() - 1)];
        why << "line " << bad + 1 << " of the block, `" << trim(quoted[bad]) << "`, is not what is printed";
        if (bestStart < printed.size() && bestLength > 0 && bestStart + bestLength < printed.size())
            why << " after the lines before it: that is `" << printed[bestStart + bestLength] << "`";
        else
            why << " (no printed line like it follows the lines quoted before it)";
        return why.str();
    }
    return "";
}

// ---- Running a page's commands ----

/// A scratch folder that stands for the repository's root and the reader's /tmp, removed at
/// scope exit.
class Scratch {
public:
    Scratch() {
        static int made = 0;
        folder_ = fs::temp_directory_path() / ("stepwise-test-" + std::to_string(::getpid()) + "-output-" + std::to_string(++made));
        fs::remove_all(folder_);
        fs::create_directories(folder_ / "tmp");
        fs::create_directories(folder_ / "bin");
        for (const fs::directory_entry& entry : fs::directory_iterator(kRoot)) {
            const std::string name = entry.path().filename().string();
            if (name == "build" || name == "bin" || name == "tmp" || startsWith(name, ".")) continue;
            fs::create_directory_symlink(entry.path(), folder_ / name);
        }
        fs::create_symlink(STEPWISE_CLI_PATH, folder_ / "bin" / "stepwise");
    }
    ~Scratch() {
        std::error_code ignored;
        fs::remove_all(folder_, ignored);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;

    /// Runs @p commands (shell lines) as the reader would from the repository's root, once
    /// (the output of the same commands again is the first run's).
    const test::CommandResult& run(const std::string& commands) {
        const auto cached = runs_.find(commands);
        if (cached != runs_.end()) return cached->second;
        const std::string root = folder_.string() + "/";
        // build/debug/stepwise, build/release/stepwise, …: the program built with these tests.
        const std::regex program(R"(build/([A-Za-z0-9_-]+)/stepwise\b)");
        for (auto m = std::sregex_iterator(commands.begin(), commands.end(), program); m != std::sregex_iterator(); ++m) {
            const fs::path link = folder_ / "build" / (*m)[1].str() / "stepwise";
            if (fs::is_symlink(link)) continue;
            fs::create_directories(link.parent_path());
            fs::create_symlink(STEPWISE_CLI_PATH, link);
        }
        std::ofstream(folder_ / "commands.sh") << replaceAll(commands, "/tmp/", root + "tmp/") << "\n";
        test::CommandResult result = test::shell("cd '" + folder_.string() + "' && PATH='" + root + "bin':\"$PATH\" sh commands.sh");
        result.output = replaceAll(replaceAll(result.output, root + "tmp/", "/tmp/"), root, "");
        return runs_.emplace(commands, result).first->second;
    }

private:
    fs::path folder_;
    std::map<std::string, test::CommandResult> runs_;
};

std::vector<std::string> outputLines(const std::string& output) {
    std::vector<std::string> lines;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);) {
        while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

/// One fenced block of a page: its first line (from 0), language and lines, de-indented by
/// the fence's own indentation (as markdown reads a block inside a list item).
struct Fenced {
    std::size_t open = 0;
    std::size_t close = 0;
    std::string language;
    std::vector<std::string> lines;
};

std::vector<Fenced> fencedBlocks(const std::vector<std::string>& lines) {
    std::vector<Fenced> blocks;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (!isFence(lines[i])) continue;
        Fenced block;
        block.open = i;
        block.language = fenceLanguage(lines[i]);
        const std::size_t indent = lines[i].find_first_not_of(' ');
        std::size_t k = i + 1;
        for (; k < lines.size() && !isFence(lines[k]); ++k) {
            const std::size_t cut = std::min(indent, lines[k].find_first_not_of(' ') == std::string::npos
                                                         ? lines[k].size()
                                                         : lines[k].find_first_not_of(' '));
            block.lines.push_back(lines[k].substr(cut));
        }
        block.close = k;
        blocks.push_back(block);
        i = k;
    }
    return blocks;
}

/// The fenced block that closes last before line @p at, if nothing but prose lies between.
const Fenced* blockAbove(const std::vector<Fenced>& blocks, std::size_t at) {
    const Fenced* above = nullptr;
    for (const Fenced& block : blocks)
        if (block.close < at) above = &block;
    return above;
}

/// The ```sh block nearest above line @p at, if only prose and plain blocks (its output) come between.
const Fenced* commandsAbove(const std::vector<Fenced>& blocks, std::size_t at) {
    const Fenced* found = nullptr;
    for (const Fenced& block : blocks) {
        if (block.close >= at) break;
        if (block.language == "sh") found = &block;
        else if (!block.language.empty() && block.language != "text") found = nullptr;
    }
    return found;
}

const Fenced* blockOpeningAt(const std::vector<Fenced>& blocks, std::size_t line) {
    for (const Fenced& block : blocks)
        if (block.open == line) return &block;
    return nullptr;
}

/// The joined text of the paragraph, table or list item that starts at or after @p from.
std::string paragraphAt(const std::vector<std::string>& lines, std::size_t from) {
    while (from < lines.size() && trim(lines[from]).empty()) ++from;
    std::string text;
    const std::regex item(R"(^\s*([-*]|\d+\.) )");
    for (std::size_t i = from; i < lines.size(); ++i) {
        const std::string line = trim(lines[i]);
        if (line.empty() || isFence(line) || (i > from && (std::regex_search(lines[i], item) || startsWith(line, "<!--")))) break;
        text += line + " ";
    }
    return text;
}

/// A ```sh block that runs stepwise (not under gdb), or reads with awk a file in /tmp that a run wrote.
bool runsStepwise(const Fenced& block) {
    for (const std::string& line : block.lines) {
        const std::string text = trim(line);
        if (startsWith(text, "gdb ") || startsWith(text, "#")) continue;
        if (std::regex_search(text, std::regex(R"((^|[\s/|;&(])stepwise\s)"))) return true;
        if (text.find("awk ") != std::string::npos && text.find("/tmp/") != std::string::npos) return true;
    }
    return false;
}

/// A block that shows a build or a test run (cmake, ctest, stepwise_tests), not what stepwise prints.
bool showsBuildOrTests(const Fenced& block) {
    for (const std::string& line : block.lines) {
        const std::string text = trim(line);
        if (text.find("stepwise_tests") != std::string::npos || startsWith(text, "$ ctest") || startsWith(text, "$ cmake") ||
            startsWith(text, "-- "))
            return true;
    }
    return false;
}

/// A block that reads like a report of stepwise run, check or trace.
bool readsLikeStepwise(const Fenced& block) {
    const std::regex report(R"(^(Scene \S+\.scene|Final state at t = |Expectations: \d+ of \d+|step \d+ +t |Simulated \d))");
    for (const std::string& line : block.lines)
        if (std::regex_search(trim(line), report)) return true;
    return false;
}

/// A gdb transcript, which the [gdb] tests and trace-check blocks check instead.
bool isTranscript(const Fenced& block, const Fenced* above) {
    if (above != nullptr && above->language == "sh" && !above->lines.empty() && startsWith(trim(above->lines[0]), "gdb "))
        return true;
    for (const std::string& line : block.lines) {
        const std::string text = trim(line);
        if (startsWith(text, "(gdb)") || startsWith(text, "+break") || startsWith(text, "Breakpoint ")) return true;
    }
    return false;
}

/// The `sh block above, one stepwise trace command` form that test_lecture_values.cpp checks line for line.
bool isTraceShownInFull(const Fenced* above) {
    return above != nullptr && above->language == "sh" && above->lines.size() == 1 &&
           std::regex_match(trim(above->lines[0]), std::regex(R"((build/\w+/)?stepwise trace config/\S+\.scene( \S+)*)"));
}

/// What the checks of one page found.
struct PageCount {
    int blocks = 0;      ///< fenced blocks checked
    int paragraphs = 0;  ///< paragraphs whose spans were checked
    int values = 0;      ///< lines and spans compared
};

PageCount checkPage(const fs::path& page) {
    const std::vector<std::string> lines = readLines(page);
    const std::vector<Fenced> blocks = fencedBlocks(lines);
    PageCount count;
    std::optional<Scratch> scratch;  // made for the page's first marker
    std::vector<std::string> stacked;  // what the markers just above the next one printed
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string marker = trim(lines[i]);
        if (!startsWith(marker, kMarker)) continue;
        const std::string where = shown(page) + ":" + std::to_string(i + 1);
        INFO(where << ": " << marker);
        const std::size_t end = marker.find("-->");
        REQUIRE(end != std::string::npos);
        std::string commands = trim(marker.substr(std::string(kMarker).size(), end - std::string(kMarker).size()));
        if (commands.empty()) {
            const Fenced* above = commandsAbove(blocks, i);
            if (above == nullptr) {
                FAIL_CHECK(where << ": <!-- output-check --> runs the ```sh block above it, and there is none (only "
                                    "prose and blocks of output may come between)");
                continue;
            }
            for (const std::string& line : above->lines) commands += line + "\n";
        } else if (commands[0] == ':') {
            commands = trim(commands.substr(1));
        } else {
            FAIL_CHECK(where << ": write <!-- output-check --> or <!-- output-check: COMMANDS -->");
            continue;
        }
        if (!scratch) scratch.emplace();
        const test::CommandResult& result = scratch->run(commands);
        std::vector<std::string> printed = outputLines(result.output);
        INFO("the commands:\n" << commands << "\nexited with " << result.exitCode << " and printed:\n" << result.output);

        std::size_t next = i + 1;
        while (next < lines.size() && trim(lines[next]).empty()) ++next;
        if (next < lines.size() && startsWith(trim(lines[next]), kMarker)) {
            // Markers one above the other: the paragraph below the last quotes what all of them print.
            stacked.insert(stacked.end(), printed.begin(), printed.end());
            continue;
        }
        printed.insert(printed.begin(), stacked.begin(), stacked.end());
        const bool wasStacked = !stacked.empty();
        stacked.clear();
        if (const Fenced* block = blockOpeningAt(blocks, next)) {
            if (wasStacked) {
                FAIL_CHECK(where << ": markers one above the other check a paragraph; a block has one marker");
                continue;
            }
            if (!block->language.empty() && block->language != "text") {
                FAIL_CHECK(where << ": the block below the marker is ```" << block->language << ", not what a program prints");
                continue;
            }
            std::vector<std::string> quoted = block->lines;
            while (!quoted.empty() && trim(quoted.back()).empty()) quoted.pop_back();
            REQUIRE_FALSE(quoted.empty());
            const std::string mismatch = excerptMismatch(quoted, printed);
            if (!mismatch.empty()) FAIL_CHECK(where << ": " << mismatch);
            ++count.blocks;
            count.values += static_cast<int>(quoted.size());
            continue;
        }
        int spans = 0;
        for (const std::string& span : codeSpans(paragraphAt(lines, next))) {
            if (std::none_of(span.begin(), span.end(), isDigit)) continue;
            ++spans;
            const std::vector<Token> wanted = tokens(normalise(span));
            const bool found = std::any_of(printed.begin(), printed.end(), [&](const std::string& line) { return inLine(wanted, line); });
            if (!found) FAIL_CHECK(where << ": the paragraph below quotes `" << span << "`, which no printed line holds");
        }
        if (spans == 0) FAIL_CHECK(where << ": the paragraph below the marker quotes no number in a `code span`");
        ++count.paragraphs;
        count.values += spans;
    }
    return count;
}

}  // namespace

TEST_CASE("The output the lectures quote is what the commands print", "[lectures]") {
    PageCount all;
    for (const fs::path& page : pagesWithOutput()) {
        const PageCount count = checkPage(page);
        all.blocks += count.blocks;
        all.paragraphs += count.paragraphs;
        all.values += count.values;
    }
    CHECK(all.blocks >= 20);
    CHECK(all.paragraphs >= 5);
    CHECK(all.values >= 200);
}

TEST_CASE("Every block of the lectures that shows what stepwise prints is checked", "[lectures]") {
    // Each one has an output-check (or, for output that cannot be repeated, an output-unchecked
    // with the reason) on the line above; a whole `stepwise trace` under its command, and gdb
    // transcripts, are checked by test_lecture_values.cpp and the [gdb] tests.
    int found = 0;
    for (const fs::path& page : pagesWithOutput()) {
        if (!startsWith(shown(page), "lectures/")) continue;
        const std::vector<std::string> lines = readLines(page);
        const std::vector<Fenced> blocks = fencedBlocks(lines);
        for (const Fenced& block : blocks) {
            if (!block.language.empty() && block.language != "text") continue;
            const Fenced* above = blockAbove(blocks, block.open);
            const bool afterRun = above != nullptr && above->language == "sh" && runsStepwise(*above);
            if (!(afterRun || readsLikeStepwise(block)) || isTranscript(block, above) || isTraceShownInFull(above) ||
                showsBuildOrTests(block))
                continue;
            ++found;
            std::size_t at = block.open;
            while (at > 0 && trim(lines[at - 1]).empty()) --at;
            const std::string marker = at > 0 ? trim(lines[at - 1]) : "";
            if (startsWith(marker, kMarker) || startsWith(marker, kUnchecked)) continue;
            FAIL_CHECK(shown(page) << ":" << block.open + 1
                                   << ": this block shows what stepwise prints: put <!-- output-check --> (or "
                                      "<!-- output-check: COMMANDS -->) on the line above it");
        }
    }
    CHECK(found >= 15);
}

TEST_CASE("The output-check reader compares numbers to the digits quoted", "[lectures]") {
    CHECK(sameLine("ball Sphere (6.0000, -1.4565, 0.0000)", "  ball    Sphere  (6.0000, -1.4565, 0.0000)  "));
    CHECK_FALSE(sameLine("ball Sphere (6.0000, -1.4566, 0.0000)", "ball Sphere (6.0000, -1.4565, 0.0000)"));
    CHECK_FALSE(sameLine("ball Sphere (6.0000, -1.4564, 0.0000)", "ball Sphere (6.0000, -1.4565, 0.0000)"));
    CHECK(sameLine("(6, \u22121.4565, 0)", "(6.0000, -1.4565, 0.0000)"));
    CHECK(sameLine("change -4.12115e-13 (-0.000 %)", "change -4.12115e-13 (-0.000 %)"));
    CHECK_FALSE(sameLine("change -4.12116e-13 (-0.000 %)", "change -4.12115e-13 (-0.000 %)"));
    CHECK(sameLine("box20 Box (0.0000)", "box20 Box (-0.0000)"));
    CHECK_FALSE(sameLine("box20 Box", "box21 Box"));
    CHECK(inLine(tokens("change +1.60394"), "  change +1.60394 (+1.450 %)"));
    CHECK_FALSE(inLine(tokens("change +1.60395"), "  change +1.60394 (+1.450 %)"));
    CHECK(inLine(tokens("(3.5677, 0.5000, -9.3158)"), "  box20  Box  (3.5677, 0.5000, -9.3158)  (-0.0000, -0.0000, -0.0000)"));
    CHECK(excerptMismatch({"a 1", "...", "c 3"}, {"a 1", "b 2", "c 3", "timings 4"}).empty());
    CHECK_FALSE(excerptMismatch({"a 1", "c 3"}, {"a 1", "b 2", "c 3"}).empty());  // left out without "..."
    CHECK_FALSE(excerptMismatch({"c 3", "a 1"}, {"a 1", "b 2", "c 3"}).empty());  // out of order
}
