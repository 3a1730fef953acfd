/// @file spelling.cpp
/// @brief Edit distance and closest-word search behind the loader's "did you mean" hints.
#include "config/spelling.hpp"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace stepwise::config {

namespace {

/// Allowed typos per letter: one edit in every three letters still reads as
/// the same word; more than that and the suggestion would be a guess.
constexpr std::size_t kLettersPerAllowedEdit = 3;

char lowerAscii(char c) {
    // std::tolower takes an int that must be representable as unsigned char.
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

}  // namespace

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(),
                      [](char x, char y) { return lowerAscii(x) == lowerAscii(y); });
}

std::string toLower(std::string_view text) {
    std::string lowered(text);
    std::transform(lowered.begin(), lowered.end(), lowered.begin(), lowerAscii);
    return lowered;
}

std::size_t editDistance(std::string_view a, std::string_view b) {
    // row[j] holds d(i, j) for the current prefix a[0, i); it starts as
    // d(0, j) = j: turning "" into b's first j letters takes j insertions.
    std::vector<std::size_t> row(b.size() + 1);
    std::iota(row.begin(), row.end(), std::size_t{0});
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];  // d(i-1, j-1) for j = 1
        row[0] = i;                     // d(i, 0): delete all i letters
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];  // d(i-1, j), about to be overwritten
            const std::size_t substitution = lowerAscii(a[i - 1]) == lowerAscii(b[j - 1]) ? 0 : 1;
            row[j] = std::min({above + 1, row[j - 1] + 1, diagonal + substitution});
            diagonal = above;
        }
    }
    return row[b.size()];
}

std::optional<std::string> closestMatch(std::string_view word,
                                        const std::vector<std::string>& candidates) {
    std::optional<std::string> best;
    std::size_t bestDistance = 0;
    for (const std::string& candidate : candidates) {
        const std::size_t distance = editDistance(word, candidate);
        const std::size_t longer = std::max(word.size(), candidate.size());
        const std::size_t allowed = std::max<std::size_t>(1, longer / kLettersPerAllowedEdit);
        if (distance == 0 || distance > allowed) continue;
        if (!best || distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}

}  // namespace stepwise::config
