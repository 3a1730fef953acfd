/// @file quoted_text.cpp
/// @brief quotable(): control bytes escaped, long text cut.
#include "core/quoted_text.hpp"

#include <cstdio>

namespace stepwise {

std::string quotable(std::string_view text) {
    std::string out;
    std::size_t shown = 0;
    for (; shown < text.size() && out.size() < kMostQuoted; ++shown) {
        const unsigned char c = static_cast<unsigned char>(text[shown]);
        if (c >= 0x20 && c != 0x7f) {
            out += static_cast<char>(c);
        } else if (c == 0) {
            out += "\\0";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\v') {
            out += "\\v";
        } else if (c == '\r') {
            out += "\\r";
        } else {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
            out += escaped;
        }
    }
    if (shown < text.size()) out += "... (" + std::to_string(text.size() - shown) + " more bytes)";
    return out;
}

}  // namespace stepwise
