/// @file scene_tokenizer.cpp
/// @brief Splits scene text into lines and comma-separated tokens, keeping columns.
#include "config/scene_tokenizer.hpp"

namespace stepwise::config {

namespace {

constexpr char kCommentStart = '#';
constexpr char kFieldSeparator = ',';
constexpr char kNameValueSeparator = '=';
/// Editors on Windows may start a UTF-8 file with these three bytes (U+FEFF).
constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// Tokenizes one line (without its '\n'); columns are measured from the line's start.
SceneLine tokenizeLine(std::string_view line, int number) {
    SceneLine result;
    result.number = number;

    // The comment goes first: a '#' inside parentheses still starts a comment,
    // which keeps the rule simple enough to state in one sentence.
    if (const std::size_t hash = line.find(kCommentStart); hash != std::string_view::npos) {
        line = line.substr(0, hash);
    }
    if (trim(line).empty()) return result;

    const Token wholeLine{line, 1};
    int depth = 0;                 // how many '(' are open at the current character
    int lastOpenColumn = 0;        // column of the outermost '(' still open
    std::size_t tokenStart = 0;
    for (std::size_t i = 0; i <= line.size(); ++i) {
        const bool atEnd = i == line.size();
        const char c = atEnd ? kFieldSeparator : line[i];
        const int column = static_cast<int>(i) + 1;
        if (c == '(') {
            if (depth == 0) lastOpenColumn = column;
            ++depth;
        } else if (c == ')') {
            if (depth == 0) {
                // Keep going so the rest of the line still splits sensibly;
                // only the first problem of a line is recorded.
                if (!result.parenthesisProblem) result.parenthesisProblem = ParenthesisProblem{column, false};
            } else {
                --depth;
            }
        }
        if (atEnd || (c == kFieldSeparator && depth == 0)) {
            result.tokens.push_back(subToken(wholeLine, line.substr(tokenStart, i - tokenStart)));
            tokenStart = i + 1;
        }
    }
    if (depth > 0 && !result.parenthesisProblem) {
        result.parenthesisProblem = ParenthesisProblem{lastOpenColumn, true};
    }

    // "a, b," ends with an empty token after the last comma: the allowed trailing comma.
    if (result.tokens.size() > 1 && result.tokens.back().text.empty()) result.tokens.pop_back();
    return result;
}

}  // namespace

std::string_view trim(std::string_view text) {
    while (!text.empty() && isBlank(text.front())) text.remove_prefix(1);
    while (!text.empty() && isBlank(text.back())) text.remove_suffix(1);
    return text;
}

Token subToken(const Token& whole, std::string_view part) {
    const std::string_view trimmed = trim(part);
    // Both views point into the same line, so the distance between their
    // first characters is the distance between their columns.
    const auto offset = trimmed.data() - whole.text.data();
    return Token{trimmed, whole.column + static_cast<int>(offset)};
}

std::optional<NamedToken> splitNamed(const Token& token) {
    const std::size_t equals = token.text.find(kNameValueSeparator);
    if (equals == std::string_view::npos) return std::nullopt;
    return NamedToken{subToken(token, token.text.substr(0, equals)),
                      subToken(token, token.text.substr(equals + 1))};
}

std::vector<SceneLine> tokenizeScene(std::string_view text) {
    if (text.substr(0, kUtf8ByteOrderMark.size()) == kUtf8ByteOrderMark) {
        text.remove_prefix(kUtf8ByteOrderMark.size());
    }
    std::vector<SceneLine> lines;
    int number = 0;
    while (!text.empty()) {
        ++number;
        const std::size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end);  // a trailing '\r' is trimmed as blank
        SceneLine tokenized = tokenizeLine(line, number);
        if (!tokenized.tokens.empty()) lines.push_back(std::move(tokenized));
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
    return lines;
}

}  // namespace stepwise::config
