/// @file arguments.hpp
/// @brief The rules every `stepwise` command reads its arguments by.
///
/// One reader, so that the commands cannot disagree about them:
///  - an option that takes a value gets one, and never another option: in
///    `run S --csv --steps 5` the CSV path is missing, not "--steps";
///  - an option given twice is an error (except those that collect a list,
///    such as `--object`), so `--steps 5 --steps 6` is not silently 6;
///  - numbers follow the scene file's rules (config::parseNumber(): decimal,
///    scientific or a fraction p/q; no hex, no units, no NaN or infinity),
///    and whole numbers and directions are checked against the same limits
///    (src/core/limits.hpp).
/// A value may start with '-' when it is a number ("-2") or standard output ("-").
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace stepwise::cli {

/// @brief Walks the arguments after a command name, one at a time.
///
/// @code
///     Arguments in(args, "run");
///     while (in.next()) {
///         if (in.is("--steps")) steps = parseWholeNumber(in.option(), in.value(), 1, kMaxSteps);
///         else if (in.isFlag("--explain")) explain = true;
///         else if (in.isOption()) in.refuseUnknown();
///         else scene = in.current();
///     }
/// @endcode
class Arguments {
public:
    /// @param args the arguments after the command's name; @param command its name, for messages.
    Arguments(const std::vector<std::string>& args, std::string command);

    /// @brief Moves to the next argument; false when none is left.
    bool next();
    /// @brief The current argument.
    const std::string& current() const { return args_[at_]; }
    /// @brief True when the current argument is an option ("--name", "-h"), not a word or a value.
    bool isOption() const { return looksLikeOption(current()); }

    /// @brief True when the current argument is @p name, an option that takes one value.
    /// Read the value with value(); an option that collects a list is marked by isList().
    bool is(const char* name);
    /// @brief As is(), for an option that may be given more than once (each value adds to a list).
    bool isList(const char* name);
    /// @brief True when the current argument is the flag @p name (no value). @throws UsageError when repeated.
    bool isFlag(const char* name);

    /// @brief The option matched by the last is() or isList().
    const std::string& option() const { return option_; }
    /// @brief The value of that option: the next argument. @throws UsageError when it is missing,
    /// is another option, or the option was already given.
    const std::string& value();

    /// @brief Throws the UsageError for an option this command does not have.
    [[noreturn]] void refuseUnknown() const;

    /// @brief True when @p text is an option rather than a value: it starts with "--", or is "-h".
    static bool looksLikeOption(const std::string& text);

private:
    const std::vector<std::string>& args_;
    std::string command_;
    std::size_t at_ = 0;
    bool started_ = false;
    std::string option_;       ///< The option matched last.
    bool optionIsList_ = false;
    std::map<std::string, std::string> given_;  ///< Each option given so far, and its value ("" for a flag).
};

/// @brief True when @p args ask for help: "--help" or "-h" among them.
bool asksForHelp(const std::vector<std::string>& args);

/// @brief A time in seconds > 0 (`--duration`, `--max-seconds`). @throws UsageError naming @p option.
double parseSeconds(const std::string& option, const std::string& text);

/// @brief A number ≥ 0 (`--at`, `--max`); @p what says what it is, e.g. "a time >= 0 in seconds".
double parseNonNegative(const std::string& option, const std::string& text, const std::string& what);

/// @brief A whole number from @p least to @p most, written as a scene's counts are (1000, 1e3).
std::uint64_t parseWholeNumber(const std::string& option, const std::string& text, std::uint64_t least,
                               std::uint64_t most);

/// @brief "x,y,z": three numbers, each as a scene file writes one.
Vec3 parseVector(const std::string& option, const std::string& text);

/// @brief "x,y,z" that can be normalised (core/limits.hpp, usableDirection()): not zero, and
/// not so long that its length overflows (1e308,-1e308,0).
Vec3 parseDirection(const std::string& option, const std::string& text);

/// @brief The most steps `--steps` accepts: 2^53, the largest whole number a double counts exactly.
inline constexpr std::uint64_t kMaxSteps = std::uint64_t(1) << 53;

}  // namespace stepwise::cli
