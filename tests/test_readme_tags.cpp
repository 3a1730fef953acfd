// README.md's paragraph of test tags ("The tags name the stages: …") against
// the tags of this test program: every tag a test case carries is named there,
// and the paragraph names no tag that no test case carries. The tags are read
// from Catch2's registry, the list `stepwise_tests --list-tags` prints; hidden
// ([.]) and special ([!mayfail]) tags are switches, not stages, and are left out,
// as tests/catch_tags_as_labels.cmake leaves them out of the CTest labels.
// Tag: [docs].
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = STEPWISE_SOURCE_DIR;
constexpr const char* kParagraphStart = "The tags name the stages:";

/// The paragraph of README.md that starts with kParagraphStart, up to the next blank line.
std::string tagParagraph() {
    std::ifstream in(kRoot / "README.md");
    std::string paragraph;
    bool inside = false;
    for (std::string line; std::getline(in, line);) {
        if (!inside && line.rfind(kParagraphStart, 0) == 0) inside = true;
        if (!inside) continue;
        if (line.find_first_not_of(" \t") == std::string::npos) break;
        paragraph += line + "\n";
    }
    return paragraph;
}

/// The tags `[name]` written in backticks in @p text.
std::set<std::string> tagsNamedIn(const std::string& text) {
    std::set<std::string> tags;
    const std::regex tag(R"(`\[([^\]`]+)\]`)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), tag); it != std::sregex_iterator(); ++it) {
        tags.insert((*it)[1]);
    }
    return tags;
}

/// Every tag of every test case of this program, without the switches ([.], [!…]).
std::set<std::string> tagsOfThisProgram() {
    std::set<std::string> tags;
    for (const Catch::TestCase& test : Catch::getRegistryHub().getTestCaseRegistry().getAllTests()) {
        for (const std::string& tag : test.tags) {
            if (!tag.empty() && tag[0] != '.' && tag[0] != '!') tags.insert(tag);
        }
    }
    return tags;
}

}  // namespace

TEST_CASE("README.md's tag paragraph names every test tag, and only those", "[docs]") {
    const std::string paragraph = tagParagraph();
    INFO("README.md, the paragraph that starts '" << kParagraphStart << "'");
    REQUIRE(!paragraph.empty());
    const std::set<std::string> named = tagsNamedIn(paragraph);
    const std::set<std::string> tagged = tagsOfThisProgram();
    REQUIRE(tagged.size() >= 20);  // the registry is read: the program has dozens of tags
    for (const std::string& tag : tagged) {
        INFO("the tag [" << tag << "] is on a test case, and the paragraph does not name it");
        CHECK(named.count(tag) == 1);
    }
    // Tests a build leaves out: the sanitizer build has no [allocations] tests (they count
    // operator new, which AddressSanitizer replaces: tests/test_step_allocations.cpp).
#if defined(__SANITIZE_ADDRESS__)
    const std::set<std::string> notInThisBuild = {"allocations"};
#else
    const std::set<std::string> notInThisBuild;
#endif
    for (const std::string& tag : named) {
        if (notInThisBuild.count(tag) == 1) continue;
        INFO("the paragraph names the tag [" << tag << "], which no test case has");
        CHECK(tagged.count(tag) == 1);
    }
}
