/// @file field_values.hpp
/// @brief Second stage of loading a scene: one token's text → a checked value.
///
/// Every function here either returns the value or a ValueProblem saying
/// what was expected, what was found and where, so the loader can turn it
/// into a diagnostic without knowing how the value was parsed. The grammar
/// (see docs/config-format.md):
///
///     number   = decimal | decimal "/" decimal        e.g. 9.81, -2.5e-3, 1/60
///     vector   = "(" number "," number "," number ")" e.g. (0, 5, 0)
///     choice   = one word of a fixed list, any case   e.g. sphere, BOX
///     name     = letters, digits, '_', '-', '.'       e.g. Ball_1
///     points   = vector { "," vector }                 e.g. (0, 0, 0), (1, 0, 0), (0, 1, 0)
///     file     = name characters and '/'               e.g. models/ramp.obj
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "config/scene_tokenizer.hpp"
#include "core/limits.hpp"
#include "core/types.hpp"

namespace stepwise::config {

/// @brief The values a number (or each component of a vector) may take.
enum class Range : std::uint8_t {
    Any,           ///< Any finite number (positions, velocities, angles).
    Positive,      ///< > 0 (mass, radius, scale, time step, duration).
    NonNegative,   ///< ≥ 0 (friction).
    UnitInterval,  ///< 0 to 1 inclusive (elasticity, colour channels).
    Count,         ///< A whole number from 1 to kMaxRepetitions (substeps, iterations).
    WholeNumber,   ///< A whole number from 0 to kMaxRepetitions (relax iterations).
    ThreadCount,   ///< A whole number from 0 to kMaxThreads (0: one per hardware thread).
    Size,          ///< A box's edge or a sphere's diameter: kMinBodySize to kMaxBodySize, m.
    Radius,        ///< Half of a Size, m.
    Mass,          ///< kMinMass to kMaxMass, kg.
    JointLength,   ///< At least kMinJointLength, m.
    Length,        ///< 0 to kMaxBodySize, m (a capsule's segment may be 0: a ball).
};

/// @brief A limit as a person writes it: 1e-06 as "1e-6", 1000000 as "1e6".
std::string formatLimit(Real value);

/// @brief Words for an expected value, e.g. "a number > 0", as used in diagnostics.
std::string describe(Range range);

/// @brief Why a token was rejected: the parts of a diagnostic a value parser knows.
struct ValueProblem {
    int column = 0;        ///< 1-based column of the offending text.
    std::string expected;  ///< e.g. "a number > 0".
    std::string found;     ///< The offending text as written.
    std::string hint;      ///< Optional advice; "" when there is none.
};

/// @brief Either a parsed value or the problem that prevented it.
template <typename T>
class Parsed {
public:
    /// @brief A successfully parsed value.
    Parsed(T value) : result_(std::move(value)) {}  // implicit, so parsers can `return value;`
    /// @brief A failure.
    Parsed(ValueProblem problem) : result_(std::move(problem)) {}

    /// @brief True when a value was parsed.
    bool ok() const { return std::holds_alternative<T>(result_); }
    /// @brief The value; only call when ok().
    const T& value() const { return std::get<T>(result_); }
    /// @brief The problem; only call when !ok().
    const ValueProblem& problem() const { return std::get<ValueProblem>(result_); }

private:
    std::variant<T, ValueProblem> result_;
};

/// @brief Parses @p token as a number (decimal, scientific or a fraction p/q) and checks @p range.
///
/// The whole token must be the number: "5m" and "1.5.2" are rejected, and
/// so are NaN, infinity and values too large for a double, because any of
/// them would silently poison every later step of the simulation.
Parsed<Real> parseNumber(const Token& token, Range range);

/// @brief Splits a parenthesised triple "(a, b, c)" into its three component tokens.
///
/// Only the layout is checked here; the caller parses each component with
/// parseNumber() so that a bad component is reported at its own column.
/// @param layout how a whole triple is described in messages, e.g. "a vector (x, y, z)".
Parsed<std::array<Token, 3>> splitTriple(const Token& token, std::string_view layout);

/// @brief One accepted spelling of an enumerated value, e.g. {"Cube", Shape::Box}.
template <typename E>
struct Choice {
    std::string_view word;  ///< Spelling in the file (matched ignoring case).
    E value;                ///< What it means.
};

/// @brief Finds @p token among @p words, ignoring case; returns its index.
///
/// On failure the problem lists the words and, when one is close, says
/// "did you mean …?".
Parsed<std::size_t> parseWord(const Token& token, const std::vector<std::string_view>& words);

/// @brief Checks that @p token is a usable file path: a name's characters and '/' (no spaces,
/// quotes or separators), not empty, not ending in '/'.
Parsed<std::string> parseFilePath(const Token& token);

/// @brief Checks that @p token is a usable object name (letters, digits, '_', '-', '.').
///
/// Names appear in output files, on command lines and in messages, so
/// they may not contain spaces, quotes or separators.
Parsed<std::string> parseName(const Token& token);

}  // namespace stepwise::config
