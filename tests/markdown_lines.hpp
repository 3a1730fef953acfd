// Reading the project's Markdown pages line by line: what the lecture checks share
// (tests/test_lecture_pages.cpp, tests/test_lecture_output.cpp).
#pragma once

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace stepwise::test {

/// The lines of @p path, without their line ends.
inline std::vector<std::string> readLines(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

/// @p text without the spaces and tabs at either end.
inline std::string trim(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

inline bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

/// A fence line (```, possibly indented inside a list item) opens or closes a code block.
inline bool isFence(const std::string& line) { return startsWith(trim(line), "```"); }

/// The backtick spans of a piece of markdown, `\|` read as `|` (a table cell escapes it).
inline std::vector<std::string> codeSpans(const std::string& text) {
    std::vector<std::string> spans;
    std::size_t at = 0;
    while ((at = text.find('`', at)) != std::string::npos) {
        const std::size_t end = text.find('`', at + 1);
        if (end == std::string::npos) break;
        spans.push_back(std::regex_replace(text.substr(at + 1, end - at - 1), std::regex(R"(\\\|)"), "|"));
        at = end + 1;
    }
    return spans;
}

}  // namespace stepwise::test
