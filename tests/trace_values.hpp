// Reads numbers back out of `stepwise trace` lines (src/io/trace_writer.hpp),
// for the [trace] tests and the lectures' trace-check blocks.
#pragma once

#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "io/trace_writer.hpp"

namespace stepwise::test {

/// The whitespace-separated words of @p text.
inline std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> all;
    for (std::string w; in >> w;) all.push_back(w);
    return all;
}

/// The lines of @p text.
inline std::vector<std::string> textLines(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> all;
    for (std::string line; std::getline(in, line);) all.push_back(line);
    return all;
}

/// The first line of @p trace whose first words are @p header (e.g. "step 28 resolve-impulses ball|floor"), or "".
/// A last word "#N" picks the N-th such line instead (from 1: "step 6 narrowphase crate|table #3").
inline std::string traceLine(const std::string& trace, const std::string& header) {
    std::vector<std::string> wanted = words(header);
    int skip = 0;
    if (!wanted.empty() && wanted.back().size() > 1 && wanted.back()[0] == '#') {
        skip = std::atoi(wanted.back().c_str() + 1) - 1;
        wanted.pop_back();
        if (skip < 0) return "";
    }
    for (const std::string& line : textLines(trace)) {
        const std::vector<std::string> have = words(line);
        if (have.size() < wanted.size()) continue;
        bool same = true;
        for (std::size_t i = 0; i < wanted.size() && same; ++i) same = have[i] == wanted[i];
        if (same && skip-- == 0) return line;
    }
    return "";
}

/// Every line of @p trace whose words include @p word.
inline std::vector<std::string> linesWith(const std::string& trace, const std::string& word) {
    std::vector<std::string> found;
    for (const std::string& line : textLines(trace)) {
        for (const std::string& w : words(line)) {
            if (w == word) {
                found.push_back(line);
                break;
            }
        }
    }
    return found;
}

/// The value after the word @p label in @p line: one number, or those of a tuple "(x, y, z)" or "(w, x, y, z)".
/// "label->" reads the value after the arrow that follows it (the stage's result). Empty when not found.
inline std::vector<double> traceValue(const std::string& line, std::string label) {
    const bool after = label.size() > 2 && label.compare(label.size() - 2, 2, "->") == 0;
    if (after) label.resize(label.size() - 2);
    const std::string key = " " + label + " ";
    std::size_t at = line.find(key);
    if (at == std::string::npos) return {};
    at += key.size();
    if (after) {
        at = line.find(" -> ", at);
        if (at == std::string::npos) return {};
        at += 4;
    }
    std::vector<double> values;
    const char* p = line.c_str() + at;
    const bool tuple = *p == '(';
    if (tuple) ++p;
    do {
        char* end = nullptr;
        values.push_back(std::strtod(p, &end));
        if (end == p) return {};
        p = end;
        if (tuple && *p == ',') ++p;
    } while (tuple && *p != ')' && *p != '\0');
    return values;
}

/// The trace of @p scene for the arguments @p args (as on the command line, after the scene file).
inline std::string traceOf(const Scene& scene, const std::vector<std::string>& args) {
    std::ostringstream out;
    // The command line's own parser (src/app/options.cpp), given a placeholder for the scene file.
    std::vector<std::string> line{"scene.scene"};
    line.insert(line.end(), args.begin(), args.end());
    writeTrace(scene, cli::parseTraceOptions(line).trace, out);
    return out.str();
}

}  // namespace stepwise::test
