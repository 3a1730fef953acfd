// The lecture pages themselves: every lecture and appendix has the sections
// lectures/README.md names, the README's reading order names every page (the
// appendices as optional), its map of the step lists each solver's stages in
// the order World::step() runs them, links lead somewhere, code a page quotes
// is in the file it names, no page points at code by a line number, and every
// page shows a figure that scripts/figures.sh draws. Tag: [lectures].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "core/stages.hpp"
#include "world/step_plan.hpp"

#include "markdown_lines.hpp"

namespace fs = std::filesystem;
using namespace stepwise;

namespace {

const fs::path kRoot = STEPWISE_SOURCE_DIR;
const fs::path kLectures = kRoot / "lectures";

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

using test::codeSpans;
using test::isFence;
using test::readLines;
using test::startsWith;
using test::trim;

/// The lecture pages: lectures/NN*.md, the core lectures and their appendices (03a, 07a, …).
std::vector<fs::path> lecturePages() {
    std::vector<fs::path> pages;
    for (const fs::directory_entry& entry : fs::directory_iterator(kLectures)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".md" && name.size() > 2 && std::isdigit(static_cast<unsigned char>(name[0])))
            pages.push_back(entry.path());
    }
    std::sort(pages.begin(), pages.end());
    return pages;
}

/// Every markdown file under lectures/, at any depth: the pages, the READMEs of assignments/,
/// student-template/, instructors/ and the rest.
std::vector<fs::path> lectureMarkdown() {
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kLectures)) {
        if (entry.is_regular_file() && entry.path().extension() == ".md") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// A page's path as the failure messages name it, from the repository root.
std::string shown(const fs::path& page) { return page.lexically_relative(kRoot).generic_string(); }

/// The language word of a fence line ("cpp" of ```cpp), "" for a plain fence.
std::string fenceLanguage(const std::string& line) { return trim(trim(line).substr(3)); }

/// A line of a quoted listing that stands for lines left out: `...` or `…`.
bool isElision(const std::string& line) { return trim(line) == "..." || trim(line) == "…"; }

/// An appendix's file name has a letter after the lecture's number: 03a-appendix-….md.
bool isAppendix(const fs::path& page) {
    const std::string name = page.filename().string();
    return name.size() > 2 && std::isalpha(static_cast<unsigned char>(name[2]));
}

/// The cells of a markdown table row, `\|` kept inside a cell.
std::vector<std::string> tableCells(const std::string& row) {
    std::vector<std::string> cells;
    std::string cell;
    const std::string text = trim(row);
    for (std::size_t i = 1; i < text.size(); ++i) {  // past the leading '|'
        if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == '|') {
            cell += "\\|";
            ++i;
        } else if (text[i] == '|') {
            cells.push_back(trim(cell));
            cell.clear();
        } else {
            cell += text[i];
        }
    }
    return cells;
}

/// The rows of the markdown table that starts at @p lines[@p first]: the header's cells, then each row's.
std::vector<std::vector<std::string>> tableAt(const std::vector<std::string>& lines, std::size_t first) {
    std::vector<std::vector<std::string>> rows;
    for (std::size_t i = first; i < lines.size() && startsWith(trim(lines[i]), "|"); ++i) {
        if (i == first + 1) continue;  // |---|---|
        rows.push_back(tableCells(lines[i]));
    }
    return rows;
}

/// The column of a table whose header cell is @p name, or -1.
int columnNamed(const std::vector<std::string>& header, const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return static_cast<int>(i);
    return -1;
}

/// A path as a page names it: from the repository root, or a file name found once under src/.
fs::path resolveSource(const std::string& name) {
    if (fs::exists(kRoot / name)) return kRoot / name;
    fs::path found;
    int count = 0;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kRoot / "src")) {
        const std::string path = entry.path().generic_string();
        if (path.size() > name.size() && path.compare(path.size() - name.size() - 1, std::string::npos, "/" + name) == 0) {
            found = entry.path();
            ++count;
        }
    }
    return count == 1 ? found : fs::path();
}

/// The ## headings of a page, outside code blocks.
std::vector<std::string> sectionHeadings(const fs::path& page) {
    std::vector<std::string> headings;
    bool code = false;
    for (const std::string& line : readLines(page)) {
        if (isFence(line)) code = !code;
        if (!code && startsWith(line, "## ")) headings.push_back(trim(line.substr(3)));
    }
    return headings;
}

/// What GitHub makes of a heading for its anchor: lower case, letters, digits, '-' and '_'
/// kept, spaces to '-', the rest dropped (a byte above ASCII too: give such a heading a {#id}).
std::string slugOf(const std::string& heading) {
    std::string slug;
    for (char ch : heading) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if (std::isalnum(c) && c < 128) slug += static_cast<char>(std::tolower(c));
        else if (ch == ' ' || ch == '-') slug += '-';
        else if (ch == '_') slug += '_';
    }
    return slug;
}

/// The anchors a markdown file offers: every heading's slug, and every {#id}.
std::set<std::string> anchorsOf(const fs::path& page) {
    std::set<std::string> anchors;
    bool code = false;
    const std::regex explicitId(R"(\{#([\w-]+)\})");
    for (const std::string& line : readLines(page)) {
        if (isFence(line)) code = !code;
        if (code) continue;
        for (auto it = std::sregex_iterator(line.begin(), line.end(), explicitId); it != std::sregex_iterator(); ++it)
            anchors.insert((*it)[1]);
        if (startsWith(line, "#")) {
            const std::size_t text = line.find_first_not_of('#');
            if (text != std::string::npos && line[text] == ' ') anchors.insert(slugOf(trim(line.substr(text))));
        }
    }
    return anchors;
}

/// Every Catch2 tag in use, "[verlet]", from the test cases this program holds.
std::set<std::string> testTags() {
    std::set<std::string> tags;
    for (const Catch::TestCase& test : Catch::getRegistryHub().getTestCaseRegistry().getAllTests()) {
        for (const std::string& tag : test.tags) tags.insert("[" + tag + "]");
    }
    return tags;
}

}  // namespace

TEST_CASE("Every lecture and appendix has the sections lectures/README.md names, in order", "[lectures]") {
    // The README's sentence "Each lecture and each appendix has the same sections: **Goal**, …".
    const std::string readme = readText(kLectures / "README.md");
    const std::size_t start = readme.find("has the same sections:");
    REQUIRE(start != std::string::npos);
    const std::string sentence = readme.substr(start, readme.find('(', start) - start);
    std::vector<std::string> sections;
    const std::regex bold(R"(\*\*([^*]+)\*\*)");
    for (auto it = std::sregex_iterator(sentence.begin(), sentence.end(), bold); it != std::sregex_iterator(); ++it) {
        std::string name = (*it)[1];
        std::replace(name.begin(), name.end(), '\n', ' ');
        sections.push_back(name);
    }
    REQUIRE(sections.size() == 8);

    // "The scene" may be "The scenes"; "Check it against physics" may check against something else.
    const auto matches = [](const std::string& heading, const std::string& section) {
        if (section == "The scene") return heading == "The scene" || heading == "The scenes";
        if (startsWith(section, "Check it against ")) return startsWith(heading, "Check it against ");
        return heading == section;
    };
    const std::vector<fs::path> pages = lecturePages();
    REQUIRE(pages.size() >= 12);
    for (const fs::path& page : pages) {
        const std::vector<std::string> headings = sectionHeadings(page);
        INFO("lectures/" << page.filename().string() << " has the ## sections: " << [&] {
            std::string all;
            for (const std::string& h : headings) all += "\n  " + h;
            return all;
        }());
        REQUIRE(headings.size() == sections.size());
        for (std::size_t i = 0; i < sections.size(); ++i) {
            INFO("section " << i + 1 << " should be " << sections[i]);
            CHECK(matches(headings[i], sections[i]));
        }
    }
}

TEST_CASE("lectures/README.md's reading order names every lecture, each appendix as optional after its lecture", "[lectures]") {
    const std::vector<std::string> lines = readLines(kLectures / "README.md");
    const auto begin = std::find(lines.begin(), lines.end(), "## Reading order");
    REQUIRE(begin != lines.end());
    const auto end = std::find_if(begin + 1, lines.end(), [](const std::string& l) { return startsWith(l, "## "); });

    // The first line of the section that links each page.
    std::vector<std::pair<std::string, int>> linked;
    const std::regex link(R"(\]\(([^)#]+\.md)\))");
    for (auto it = begin; it != end; ++it) {
        for (auto m = std::sregex_iterator(it->begin(), it->end(), link); m != std::sregex_iterator(); ++m) {
            linked.emplace_back((*m)[1], static_cast<int>(it - lines.begin()));
        }
    }
    const auto lineOf = [&](const std::string& name) {
        for (const auto& [file, line] : linked)
            if (file == name) return line;
        return -1;
    };
    for (const fs::path& page : lecturePages()) {
        const std::string name = page.filename().string();
        INFO("lectures/" << name);
        const int line = lineOf(name);
        REQUIRE(line >= 0);
        if (!isAppendix(page)) {
            CHECK(lines[line].find("ptional") == std::string::npos);
            continue;
        }
        // 03a-… follows lecture 03's page, on a line that says it is optional.
        CHECK(lines[line].find("*Optional*") != std::string::npos);
        std::string core;
        for (const fs::path& other : lecturePages())
            if (!isAppendix(other) && other.filename().string().substr(0, 2) == name.substr(0, 2)) core = other.filename().string();
        REQUIRE_FALSE(core.empty());
        CHECK(lineOf(core) >= 0);
        CHECK(lineOf(core) < line);
    }
}

TEST_CASE("lectures/README.md's map of the step lists each solver's stages in the order World::step() runs them", "[lectures]") {
    const std::vector<std::string> lines = readLines(kLectures / "README.md");
    const std::set<std::string> tags = testTags();
    for (const auto& [solver, marker] : {std::pair{SolverKind::Impulse, "<!-- step map: Impulse -->"},
                                         std::pair{SolverKind::SequentialImpulse, "<!-- step map: SequentialImpulse -->"}}) {
        INFO(marker);
        const auto at = std::find(lines.begin(), lines.end(), marker);
        REQUIRE(at != lines.end());
        const std::vector<std::vector<std::string>> table = tableAt(lines, static_cast<std::size_t>(at - lines.begin()) + 1);
        REQUIRE(table.size() >= 2);
        const int stageColumn = columnNamed(table[0], "stage");
        const int fileColumn = columnNamed(table[0], "file");
        const int lectureColumn = columnNamed(table[0], "lecture");
        const int testsColumn = columnNamed(table[0], "tests");
        REQUIRE(stageColumn >= 0);
        REQUIRE(fileColumn >= 0);
        REQUIRE(lectureColumn >= 0);
        REQUIRE(testsColumn >= 0);

        // The stages, row by row, are the pipeline's.
        std::vector<std::string> listed;
        for (std::size_t row = 1; row < table.size(); ++row) {
            const std::vector<std::string> spans = codeSpans(table[row].at(stageColumn));
            listed.push_back(spans.empty() ? "(none)" : spans[0]);
        }
        std::vector<std::string> runs;
        for (const PipelineSlot& slot : pipelineOrder(solver)) runs.push_back(stageName(slot.stage));
        CHECK(listed == runs);

        for (std::size_t row = 1; row < table.size(); ++row) {
            const std::vector<std::string>& cells = table[row];
            INFO("the row of " << listed[row - 1]);
            const std::vector<std::string> files = codeSpans(cells.at(fileColumn));
            CHECK_FALSE(files.empty());
            for (const std::string& file : files) {
                INFO(file);
                CHECK(fs::exists(kRoot / file));
            }
            const std::regex link(R"(\]\(([^)]+)\))");
            const std::string& lectures = cells.at(lectureColumn);
            int lectureLinks = 0;
            for (auto m = std::sregex_iterator(lectures.begin(), lectures.end(), link); m != std::sregex_iterator(); ++m) {
                INFO((*m)[1]);
                CHECK(fs::exists(kLectures / std::string((*m)[1])));
                ++lectureLinks;
            }
            CHECK(lectureLinks >= 1);
            const std::vector<std::string> named = codeSpans(cells.at(testsColumn));
            CHECK_FALSE(named.empty());
            for (const std::string& tag : named) {
                INFO(tag << " is not a tag of any test case");
                CHECK(tags.count(tag) == 1);
            }
        }
    }
}

TEST_CASE("Links in the lectures lead to files and headings that exist", "[lectures]") {
    std::vector<fs::path> pages = lecturePages();
    pages.push_back(kLectures / "README.md");
    const std::regex link(R"(\]\(([^)\s]+)\))");
    int links = 0;
    for (const fs::path& page : pages) {
        const std::vector<std::string> lines = readLines(page);
        bool code = false;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (isFence(lines[i])) code = !code;
            if (code) continue;
            // Inline code may hold a lambda, [](const Body& b): not a link.
            const std::string text = std::regex_replace(lines[i], std::regex("`[^`]*`"), "``");
            for (auto m = std::sregex_iterator(text.begin(), text.end(), link); m != std::sregex_iterator(); ++m) {
                const std::string target = (*m)[1];
                if (target.find("://") != std::string::npos || startsWith(target, "mailto:")) continue;
                INFO("lectures/" << page.filename().string() << ":" << i + 1 << ": (" << target << ")");
                const std::size_t hash = target.find('#');
                const std::string file = target.substr(0, hash);
                const fs::path path = file.empty() ? page : page.parent_path() / file;
                CHECK(fs::exists(path));
                if (hash != std::string::npos && fs::exists(path) && path.extension() == ".md") {
                    CHECK(anchorsOf(path).count(target.substr(hash + 1)) == 1);
                }
                ++links;
            }
        }
    }
    CHECK(links >= 50);
}

TEST_CASE("Code a lecture quotes is in the file it names, on exactly one line", "[lectures]") {
    // <!-- code-quotes: FILE --> before a table: each `span` of its "code" column is on exactly
    // one line of FILE (as break-at needs). Without ": FILE", each row names its file in a
    // "file" column. Before a ```cpp block: each of the block's lines is a line of FILE, in order;
    // a line `...` stands for lines left out.
    int blocks = 0;
    int quotes = 0;
    for (const fs::path& page : lectureMarkdown()) {
        const std::vector<std::string> lines = readLines(page);
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string marker = trim(lines[i]);
            if (!startsWith(marker, "<!-- code-quotes")) continue;
            const std::string where = shown(page) + ":" + std::to_string(i + 1);
            INFO(where);
            std::string named;
            const std::size_t colon = marker.find(':');
            if (colon != std::string::npos) named = trim(marker.substr(colon + 1, marker.find("-->") - colon - 1));
            std::size_t next = i + 1;
            while (next < lines.size() && trim(lines[next]).empty()) ++next;
            REQUIRE(next < lines.size());
            ++blocks;
            if (isFence(lines[next])) {
                REQUIRE_FALSE(named.empty());
                const fs::path file = resolveSource(named);
                REQUIRE_FALSE(file.empty());
                const std::vector<std::string> source = readLines(file);
                std::size_t from = 0;
                for (std::size_t k = next + 1; k < lines.size() && !isFence(lines[k]); ++k) {
                    const std::string quoted = trim(lines[k]);
                    if (quoted.empty() || isElision(quoted)) continue;
                    INFO(where << ": line " << k + 1 << " quotes `" << quoted << "`, not the next line of " << named << " that holds it");
                    const auto found = std::find_if(source.begin() + static_cast<std::ptrdiff_t>(from), source.end(),
                                                    [&](const std::string& line) { return trim(line) == quoted; });
                    CHECK(found != source.end());
                    if (found != source.end()) from = static_cast<std::size_t>(found - source.begin()) + 1;
                    ++quotes;
                }
                continue;
            }
            REQUIRE(startsWith(trim(lines[next]), "|"));
            const std::vector<std::vector<std::string>> table = tableAt(lines, next);
            const int codeColumn = columnNamed(table.at(0), "code");
            const int fileColumn = columnNamed(table.at(0), "file");
            REQUIRE(codeColumn >= 0);
            REQUIRE((!named.empty() || fileColumn >= 0));
            for (std::size_t row = 1; row < table.size(); ++row) {
                std::string name = named;
                if (name.empty()) {
                    const std::vector<std::string> files = codeSpans(table[row].at(fileColumn));
                    name = files.empty() ? "" : files[0];
                }
                const fs::path file = resolveSource(name);
                INFO(where << ": row " << row << ", file " << name);
                REQUIRE_FALSE(file.empty());
                for (const std::string& quoted : codeSpans(table[row].at(codeColumn))) {
                    INFO("`" << quoted << "` must be on exactly one line of " << name);
                    int count = 0;
                    for (const std::string& line : readLines(file)) count += line.find(quoted) != std::string::npos ? 1 : 0;
                    CHECK(count == 1);
                    ++quotes;
                }
            }
        }
    }
    CHECK(blocks >= 6);
    CHECK(quotes >= 40);
}

TEST_CASE("Every C++ block of the lectures quotes the source, or is code the reader writes", "[lectures]") {
    // A ```cpp block that shows the engine's code goes under <!-- code-quotes: FILE -->, so the
    // test above holds it to the file; one that shows code the reader writes (a test, an
    // exercise's change, a template's answer) says so with <!-- new code -->.
    int quoted = 0;
    int written = 0;
    for (const fs::path& page : lectureMarkdown()) {
        const std::vector<std::string> lines = readLines(page);
        bool code = false;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (!isFence(lines[i])) continue;
            code = !code;
            if (!code || fenceLanguage(lines[i]) != "cpp") continue;
            std::size_t above = i;
            while (above > 0 && trim(lines[above - 1]).empty()) --above;
            const std::string marker = above > 0 ? trim(lines[above - 1]) : "";
            if (startsWith(marker, "<!-- code-quotes:")) {
                ++quoted;
            } else if (marker == "<!-- new code -->") {
                ++written;
            } else {
                FAIL_CHECK(shown(page) << ":" << i + 1
                                       << ": a ```cpp block needs <!-- code-quotes: FILE --> (it quotes the source) "
                                          "or <!-- new code --> (the reader writes it) on the line above");
            }
        }
    }
    CHECK(quoted >= 10);
    CHECK(written >= 3);
}

TEST_CASE("Lectures point at code by function and quoted text, not by line number", "[lectures]") {
    // What a program prints (a gdb transcript, a test's failure) is quoted in plain ``` blocks and
    // keeps its line numbers. Everything the page says itself names a line by its code
    // (break-at FILE "TEXT"): the prose, the code it writes (```cpp, ```sh, ```scene), and the
    // gdb commands a transcript has the reader type.
    const std::regex lineNumber(R"((\b[Ll]ines? \d+)|(\.(cpp|hpp|py|gdb):\d+))");
    const std::regex typedAtLine(R"(^\(gdb\) (break|b|tbreak|until|u|advance|dprintf|list|l|jump|clear) \S+:\d+)");
    int scanned = 0;
    int transcripts = 0;
    for (const fs::path& page : lectureMarkdown()) {
        const std::vector<std::string> lines = readLines(page);
        bool code = false;
        bool output = false;  // a plain ``` or ```text block: what a program printed
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (isFence(lines[i])) {
                code = !code;
                const std::string language = fenceLanguage(lines[i]);
                output = code && (language.empty() || language == "text");
                continue;
            }
            ++scanned;
            const std::string where = shown(page) + ":" + std::to_string(i + 1);
            if (code && output) {
                ++transcripts;
                if (std::regex_search(trim(lines[i]), typedAtLine))
                    FAIL_CHECK(where << " has the reader type a line number into gdb (use break-at FILE \"TEXT\"): " << lines[i]);
                continue;
            }
            if (std::regex_search(lines[i], lineNumber)) FAIL_CHECK(where << " names a line by its number: " << lines[i]);
        }
    }
    CHECK(scanned >= 8000);
    CHECK(transcripts >= 1000);
}

TEST_CASE("Lectures quote no count of tests or assertions, and name only test cases that exist", "[lectures]") {
    // A count grows as tests are added, so what a test run prints is quoted with "…" for its
    // numbers (`--list-tests "[tag]"` lists a tag's test cases). The names a CTest summary lists
    // as failed are test cases of the program.
    const std::regex count(
        R"((\d+ (matching )?test cases?)|(\d+ assertions?)|(tests? failed out of \d+)|(test cases?: +\d)|(assertions?: +\d))");
    const std::regex failed(R"(^\s*\S+ - (.+) \(Failed\)$)");
    std::set<std::string> names;
    for (const Catch::TestCase& test : Catch::getRegistryHub().getTestCaseRegistry().getAllTests()) names.insert(test.name);
    int runs = 0;
    int named = 0;
    for (const fs::path& page : lectureMarkdown()) {
        const std::vector<std::string> lines = readLines(page);
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string where = shown(page) + ":" + std::to_string(i + 1);
            if (lines[i].find("tests passed") != std::string::npos) ++runs;
            if (std::regex_search(lines[i], count)) FAIL_CHECK(where << " quotes a count of tests: " << lines[i]);
            std::smatch match;
            if (!std::regex_search(lines[i], match, failed)) continue;
            ++named;
            INFO(where << ": no test case is named \"" << match[1] << "\"");
            CHECK(names.count(match[1]) == 1);
        }
    }
    CHECK(runs >= 5);
    CHECK(named >= 3);
}

TEST_CASE("Every lecture shows a figure scripts/figures.sh draws, with a caption, and the script draws every image", "[lectures]") {
    // What the script makes, by its own list: a figure not on it would be drawn by hand.
    const stepwise::test::CommandResult listed = stepwise::test::shell("bash '" + (kRoot / "scripts/figures.sh").string() + "' --list");
    INFO(listed.output);
    REQUIRE(listed.exitCode == 0);
    std::set<std::string> made;
    std::istringstream names(listed.output);
    for (std::string name; std::getline(names, name);) made.insert(name);
    std::set<std::string> present;
    for (const fs::directory_entry& entry : fs::directory_iterator(kLectures / "images")) present.insert(entry.path().filename().string());
    CHECK(made.size() >= 12);
    CHECK(present == made);

    // <img src="images/NAME.png" …> or ![…](images/NAME.png): the page's own figures.
    const std::regex image(R"re(<img src="([^"]+)"|!\[[^\]]*\]\(([^)\s]+\.png)\))re");
    std::set<std::string> shown;
    for (const fs::path& page : lecturePages()) {
        const std::vector<std::string> lines = readLines(page);
        int figures = 0;
        bool code = false;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (isFence(lines[i])) code = !code;
            if (code) continue;
            for (auto m = std::sregex_iterator(lines[i].begin(), lines[i].end(), image); m != std::sregex_iterator(); ++m) {
                const std::string source = (*m)[1].matched ? (*m)[1].str() : (*m)[2].str();
                INFO("lectures/" << page.filename().string() << ":" << i + 1 << ": " << source);
                CHECK(fs::exists(page.parent_path() / source));  // every image a page shows exists
                if (!startsWith(source, "images/")) continue;
                shown.insert(source.substr(7));
                // The caption: the next line that is not blank is an italic sentence saying what it shows.
                std::size_t next = i + 1;
                while (next < lines.size() && trim(lines[next]).empty()) ++next;
                INFO("the line after it must begin a caption in *italics*");
                CHECK((next < lines.size() && startsWith(trim(lines[next]), "*")));
                ++figures;
            }
        }
        INFO("lectures/" << page.filename().string() << " shows no figure of lectures/images/");
        CHECK(figures >= 1);
    }
    CHECK(shown == present);  // and no image there is shown nowhere
}
