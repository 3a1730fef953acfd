/// @file field_values.cpp
/// @brief Numbers, fractions, parenthesised triples, enumerated words and names, each checked.
#include "config/field_values.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <cstdio>
#include <system_error>

#include "config/spelling.hpp"

namespace stepwise::config {

namespace {

constexpr char kFractionBar = '/';
constexpr char kTripleOpen = '(';
constexpr char kTripleClose = ')';
constexpr char kComponentSeparator = ',';
constexpr std::size_t kTripleSize = 3;

/// How reading one decimal number can end.
enum class DecimalStatus : std::uint8_t {
    Ok,
    NotANumber,    ///< no number at all, or something after it: "abc", "1.2.3"
    HasUnit,       ///< a number followed by letters: "5m", "2kg"
    OutOfRange,    ///< too large (or too small) for Real: "1e999"
    NotFinite,     ///< "nan", "inf", "infinity"
};

struct Decimal {
    DecimalStatus status = DecimalStatus::NotANumber;
    Real value = 0;
};

bool isLetter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

/// Reads @p text as one decimal or scientific number that fills the whole text.
Decimal readDecimal(std::string_view text) {
    // std::from_chars follows strtod but refuses a leading '+'; people write
    // "+5" in files, so accept it when a digit or '.' follows (never "+-5").
    if (text.size() > 1 && text[0] == '+' && (isDigit(text[1]) || text[1] == '.')) text.remove_prefix(1);

    Decimal result;
    const char* const end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, result.value, std::chars_format::general);
    if (error == std::errc::invalid_argument) return {DecimalStatus::NotANumber, 0};
    if (stop != end) {
        // "5m" or "2kg": a unit was written. ("1e" is a broken exponent, not a
        // unit, and "nano" is a word that merely starts like "nan".)
        const std::string_view unsignedText = text.substr(text[0] == '-' ? 1 : 0);
        const bool digitsFirst = !unsignedText.empty() && (isDigit(unsignedText[0]) || unsignedText[0] == '.');
        const bool unitFollows =
            digitsFirst && *stop != 'e' && *stop != 'E' && std::all_of(stop, end, isLetter);
        return {unitFollows ? DecimalStatus::HasUnit : DecimalStatus::NotANumber, 0};
    }
    if (error == std::errc::result_out_of_range) return {DecimalStatus::OutOfRange, 0};
    // from_chars accepts the words "nan" and "inf"; they are valid doubles, not usable values.
    if (!std::isfinite(result.value)) return {DecimalStatus::NotFinite, 0};
    result.status = DecimalStatus::Ok;
    return result;
}

/// The advice that goes with each way of failing to read a number.
std::string hintFor(DecimalStatus status) {
    switch (status) {
        case DecimalStatus::HasUnit:
            return "write the number alone: scene values are in SI units (m, kg, s) and angles in degrees";
        case DecimalStatus::OutOfRange:
            return "the number is too large (or too close to 0) to be stored in a double";
        case DecimalStatus::NotFinite:
            return "NaN and infinity cannot be simulated";
        case DecimalStatus::Ok:
        case DecimalStatus::NotANumber:
            break;
    }
    return "";
}

bool inRange(Real value, Range range) {
    switch (range) {
        case Range::Any: return true;
        case Range::Positive: return value > 0;
        case Range::NonNegative: return value >= 0;
        case Range::UnitInterval: return value >= 0 && value <= 1;
        case Range::Count: return value >= 1 && value <= kMaxRepetitions && value == std::floor(value);
        case Range::WholeNumber: return value >= 0 && value <= kMaxRepetitions && value == std::floor(value);
        case Range::ThreadCount: return value >= 0 && value <= kMaxThreads && value == std::floor(value);
        case Range::Size: return value >= kMinBodySize && value <= kMaxBodySize;
        case Range::Radius: return value >= kMinBodySize / 2 && value <= kMaxBodySize / 2;
        case Range::Mass: return value >= kMinMass && value <= kMaxMass;
        case Range::JointLength: return value >= kMinJointLength;
        case Range::Length: return value >= 0 && value <= kMaxBodySize;
    }
    return false;
}

bool isNameCharacter(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
}

std::string joinWords(const std::vector<std::string_view>& words) {
    std::string joined;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (i > 0) joined += ", ";
        joined += words[i];
    }
    return joined;
}

}  // namespace

std::string formatLimit(Real value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(value));
    std::string s = text;
    if (const std::size_t e = s.find("e"); e != std::string::npos) {
        std::size_t digits = e + 1;
        if (s[digits] == '+') s.erase(digits, 1);
        else if (s[digits] == '-') ++digits;
        while (digits + 1 < s.size() && s[digits] == '0') s.erase(digits, 1);
    }
    return s;
}

std::string describe(Range range) {
    switch (range) {
        case Range::Any: return "a number";
        case Range::Positive: return "a number > 0";
        case Range::NonNegative: return "a number >= 0";
        case Range::UnitInterval: return "a number from 0 to 1";
        case Range::Count: return "a whole number from 1 to " + std::to_string(kMaxRepetitions);
        case Range::WholeNumber: return "a whole number from 0 to " + std::to_string(kMaxRepetitions);
        case Range::ThreadCount: return "a whole number from 0 to " + std::to_string(kMaxThreads);
        case Range::Size: return "a size from " + formatLimit(kMinBodySize) + " to " + formatLimit(kMaxBodySize) + " m";
        case Range::Radius:
            return "a radius from " + formatLimit(kMinBodySize / 2) + " to " + formatLimit(kMaxBodySize / 2) + " m";
        case Range::Mass: return "a mass from " + formatLimit(kMinMass) + " to " + formatLimit(kMaxMass) + " kg";
        case Range::JointLength: return "a length of at least " + formatLimit(kMinJointLength) + " m";
        case Range::Length: return "a length from 0 to " + formatLimit(kMaxBodySize) + " m";
    }
    return "a number";
}

Parsed<Real> parseNumber(const Token& token, Range range) {
    ValueProblem problem{token.column, describe(range), std::string(token.text), ""};
    if (token.text.empty()) {
        problem.hint = "the value is missing";
        return problem;
    }

    Real value = 0;
    if (const std::size_t bar = token.text.find(kFractionBar); bar != std::string_view::npos) {
        // A fraction p/q: exact-looking values such as 1/60 without rounding by hand.
        const Decimal numerator = readDecimal(trim(token.text.substr(0, bar)));
        const Decimal denominator = readDecimal(trim(token.text.substr(bar + 1)));
        if (numerator.status != DecimalStatus::Ok || denominator.status != DecimalStatus::Ok) {
            problem.hint = "a fraction is written p/q with two numbers, e.g. 1/60";
            return problem;
        }
        if (denominator.value == 0) {
            problem.hint = "the denominator of a fraction must not be 0";
            return problem;
        }
        value = numerator.value / denominator.value;
        if (!std::isfinite(value)) {
            problem.hint = hintFor(DecimalStatus::OutOfRange);
            return problem;
        }
    } else {
        const Decimal decimal = readDecimal(token.text);
        if (decimal.status != DecimalStatus::Ok) {
            problem.hint = hintFor(decimal.status);
            return problem;
        }
        value = decimal.value;
    }

    if (!inRange(value, range)) return problem;
    return value;
}

Parsed<std::array<Token, 3>> splitTriple(const Token& token, std::string_view layout) {
    ValueProblem problem{token.column, std::string(layout), std::string(token.text), ""};
    const std::string_view text = token.text;
    if (text.size() < 2 || text.front() != kTripleOpen || text.back() != kTripleClose) return problem;

    std::vector<Token> components;
    const std::string_view inside = text.substr(1, text.size() - 2);
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = inside.find(kComponentSeparator, start);
        components.push_back(subToken(token, inside.substr(start, comma - start)));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    if (components.size() != kTripleSize) {
        problem.hint = "3 components are needed, this has " + std::to_string(components.size());
        return problem;
    }
    return std::array<Token, 3>{components[0], components[1], components[2]};
}

Parsed<std::size_t> parseWord(const Token& token, const std::vector<std::string_view>& words) {
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (equalsIgnoreCase(token.text, words[i])) return i;
    }
    ValueProblem problem{token.column, "one of " + joinWords(words), std::string(token.text), ""};
    const std::vector<std::string> candidates(words.begin(), words.end());
    if (const auto suggestion = closestMatch(token.text, candidates)) {
        problem.hint = "did you mean '" + *suggestion + "'?";
    }
    return problem;
}

Parsed<std::string> parseFilePath(const Token& token) {
    const auto pathCharacter = [](char c) { return isNameCharacter(c) || c == '/'; };
    if (!token.text.empty() && token.text.back() != '/' &&
        std::all_of(token.text.begin(), token.text.end(), pathCharacter)) {
        return std::string(token.text);
    }
    ValueProblem problem{token.column, "a file path of letters, digits, '_', '-', '.' and '/'",
                         std::string(token.text), ""};
    if (token.text.empty()) {
        problem.hint = "the value is missing: name an OBJ file, e.g. File=models/ramp.obj";
    } else if (token.text.find(' ') != std::string_view::npos) {
        problem.hint = "rename the file without spaces ('_' instead)";
    } else if (token.text.back() == '/') {
        problem.hint = "that is a folder: name the file in it";
    }
    return problem;
}

Parsed<std::string> parseName(const Token& token) {
    if (!token.text.empty() && std::all_of(token.text.begin(), token.text.end(), isNameCharacter)) {
        return std::string(token.text);
    }
    ValueProblem problem{token.column, "a name of letters, digits, '_', '-' and '.'",
                         std::string(token.text), ""};
    if (token.text.find(' ') != std::string_view::npos) problem.hint = "use '_' instead of spaces";
    return problem;
}

}  // namespace stepwise::config
