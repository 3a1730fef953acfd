/// @file quoted_text.hpp
/// @brief Text from outside (a scene's token, a command-line argument) as a message may quote it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace stepwise {

/// @brief The most characters of a bad value a message quotes: a whole megabyte on one line helps no one.
inline constexpr std::size_t kMostQuoted = 60;

/// @brief @p text as a message quotes it: control bytes (a NUL, a tab, a vertical tab, an escape
/// that would drive the terminal) written as C writes them in a string, a backslash and 0, t, v or
/// x1b, and cut after kMostQuoted characters with a count of the bytes left out.
std::string quotable(std::string_view text);

}  // namespace stepwise
