/// @file scene_tokenizer.hpp
/// @brief First stage of loading a scene: text → lines → comma-separated tokens, each with its column.
///
/// The tokenizer knows the *layout* rules of docs/config-format.md and
/// nothing about records or fields:
///   - one record per line; `\n` or `\r\n` line ends (a UTF-8 byte-order mark is skipped);
///   - `#` starts a comment that runs to the end of the line;
///   - fields are separated by commas, except inside parentheses, so
///     `Position=(0, 5, 0)` stays one token;
///   - spaces and tabs around every token are trimmed;
///   - one trailing comma at the end of a line is allowed;
///   - blank (or comment-only) lines produce nothing.
///
/// Every token remembers its 1-based column so that any later stage can say
/// *where* a problem is. Columns count bytes, which equals characters for the
/// ASCII text scene files are written in. Tokens are views into the text
/// passed in, which must outlive them.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace stepwise::config {

/// @brief A piece of a line, trimmed, with the column of its first character.
struct Token {
    std::string_view text;  ///< Trimmed text (may be empty: "a,,b" has an empty middle token).
    int column = 0;         ///< 1-based column of the first character (where it would be, if empty).
};

/// @brief A token of the form `Name=Value`, split at its first '='.
struct NamedToken {
    Token name;   ///< The part before '=', trimmed.
    Token value;  ///< The part after '=', trimmed.
};

/// @brief A parenthesis without a partner, found while splitting a line.
struct ParenthesisProblem {
    int column = 0;        ///< Column of the unmatched '(' or ')'.
    bool unclosed = false; ///< true: a '(' is never closed; false: a ')' was never opened.
};

/// @brief One non-blank line of a scene file, split into tokens.
struct SceneLine {
    int number = 0;              ///< 1-based line number in the file.
    std::vector<Token> tokens;   ///< At least one token; tokens[0] should be the record name.
    std::optional<ParenthesisProblem> parenthesisProblem; ///< Set when the parentheses do not balance.
};

/// @brief Splits scene text into its non-blank lines and their tokens.
std::vector<SceneLine> tokenizeScene(std::string_view text);

/// @brief Splits @p token at its first '=' into name and value, or nullopt if it has none.
std::optional<NamedToken> splitNamed(const Token& token);

/// @brief The token for @p part, a piece of @p whole.text: trimmed, with its own column.
///
/// Lets later stages (e.g. the components of a vector) report exact columns
/// without re-counting from the start of the line.
Token subToken(const Token& whole, std::string_view part);

/// @brief @p text without leading and trailing spaces, tabs and carriage returns.
std::string_view trim(std::string_view text);

}  // namespace stepwise::config
