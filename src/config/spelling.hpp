/// @file spelling.hpp
/// @brief Case-insensitive word comparison and "did you mean" suggestions for scene files.
///
/// Scene files are typed by hand, so a misspelt word deserves more than
/// "unknown": the loader suggests the closest word it does know. Closeness is
/// the Levenshtein edit distance: the fewest single-letter insertions,
/// deletions or substitutions that turn one word into the other.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stepwise::config {

/// @brief True when @p a and @p b are the same word ignoring ASCII letter case.
bool equalsIgnoreCase(std::string_view a, std::string_view b);

/// @brief @p text with ASCII letters lowered (used to key case-insensitive maps).
std::string toLower(std::string_view text);

/// @brief Levenshtein distance between @p a and @p b, ignoring letter case.
///
/// Computed with the classic dynamic programme, keeping one row:
/// d(i, j) = min(d(i−1, j) + 1, d(i, j−1) + 1, d(i−1, j−1) + [a_i ≠ b_j]).
std::size_t editDistance(std::string_view a, std::string_view b);

/// @brief The candidate most likely meant by @p word, if one is close enough.
///
/// A candidate is close enough when its edit distance from @p word is at most
/// a third of the longer word's length (and at least 1), so "Elastcity" finds
/// "Elasticity" but "Dog" does not find "Box". Ties go to the earlier candidate.
/// An exact (case-insensitive) match is never suggested: the caller only asks
/// about words it did not recognise.
std::optional<std::string> closestMatch(std::string_view word,
                                        const std::vector<std::string>& candidates);

}  // namespace stepwise::config
