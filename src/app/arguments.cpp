/// @file arguments.cpp
/// @brief The argument reader and the number rules of the command line (see arguments.hpp).
#include "app/arguments.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "app/cli.hpp"
#include "config/field_values.hpp"
#include "core/limits.hpp"
#include "core/quoted_text.hpp"

namespace stepwise::cli {

Arguments::Arguments(const std::vector<std::string>& args, std::string command)
    : args_(args), command_(std::move(command)) {}

bool Arguments::next() {
    if (started_) ++at_;
    started_ = true;
    return at_ < args_.size();
}

bool Arguments::looksLikeOption(const std::string& text) {
    return (text.size() > 2 && text[0] == '-' && text[1] == '-') || text == "-h";
}

bool Arguments::is(const char* name) {
    if (current() != name) return false;
    option_ = name;
    optionIsList_ = false;
    return true;
}

bool Arguments::isList(const char* name) {
    if (!is(name)) return false;
    optionIsList_ = true;
    return true;
}

bool Arguments::isFlag(const char* name) {
    if (current() != name) return false;
    if (given_.count(name) != 0) throw UsageError(std::string(name) + " is given twice; give it once");
    given_[name] = "";
    return true;
}

const std::string& Arguments::value() {
    if (at_ + 1 >= args_.size()) throw UsageError(option_ + " needs a value");
    const std::string& text = args_[at_ + 1];
    if (looksLikeOption(text)) {
        throw UsageError(option_ + " needs a value, found the option '" + quotable(text) +
                         "' (a value that starts with '--' must be written e.g. ./" + quotable(text) + ")");
    }
    if (!optionIsList_) {
        if (const auto before = given_.find(option_); before != given_.end()) {
            throw UsageError(option_ + " is given twice ('" + quotable(before->second) + "' and '" + quotable(text) +
                             "'); give it once");
        }
        given_[option_] = text;
    }
    ++at_;
    return text;
}

void Arguments::refuseUnknown() const {
    throw UsageError("unknown option '" + quotable(current()) + "' for '" + command_ + "' (stepwise " + command_ +
                     " --help lists its options)");
}

bool asksForHelp(const std::vector<std::string>& args) {
    return std::any_of(args.begin(), args.end(), [](const std::string& a) { return a == "--help" || a == "-h"; });
}

namespace {

/// @p text read as one number of a scene file (config::parseNumber()), in @p range; on failure the
/// UsageError says "OPTION expects WHAT, found 'TEXT'" and the scene reader's hint.
double readNumber(const std::string& option, const std::string& text, config::Range range, const std::string& what) {
    const config::Parsed<Real> number = config::parseNumber(config::Token{text, 1}, range);
    if (number.ok()) return double(number.value());
    std::string message = option + " expects " + what + ", found '" + quotable(text) + "'";
    if (!number.problem().hint.empty()) message += " (" + number.problem().hint + ")";
    throw UsageError(message);
}

}  // namespace

double parseSeconds(const std::string& option, const std::string& text) {
    return readNumber(option, text, config::Range::Positive, "a number of seconds > 0");
}

double parseNonNegative(const std::string& option, const std::string& text, const std::string& what) {
    return readNumber(option, text, config::Range::NonNegative, what);
}

std::uint64_t parseWholeNumber(const std::string& option, const std::string& text, std::uint64_t least,
                               std::uint64_t most) {
    const std::string what = "a whole number from " + std::to_string(least) + " to " + std::to_string(most);
    const double value = readNumber(option, text, config::Range::Any, what);
    if (value != std::floor(value) || value < double(least) || value > double(most)) {
        throw UsageError(option + " expects " + what + ", found '" + quotable(text) + "'");
    }
    return static_cast<std::uint64_t>(value);
}

Vec3 parseVector(const std::string& option, const std::string& text) {
    const std::string what = "three numbers x,y,z such as 0,1.5,-2";
    Vec3 v(0);
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = text.find(',', start);
        if ((i < 2) == (comma == std::string::npos)) throw UsageError(option + " expects " + what + ", found '" + quotable(text) + "'");
        const std::string part = text.substr(start, i < 2 ? comma - start : std::string::npos);
        v[i] = Real(readNumber(option, part, config::Range::Any, what));
        start = comma + 1;
    }
    return v;
}

Vec3 parseDirection(const std::string& option, const std::string& text) {
    const Vec3 v = parseVector(option, text);
    if (!usableDirection(v)) {
        throw UsageError(option + " expects a direction x,y,z whose length is at least " +
                         config::formatLimit(kMinDirectionLength) +
                         " and does not overflow a double, found '" + quotable(text) + "'");
    }
    return v;
}

}  // namespace stepwise::cli
