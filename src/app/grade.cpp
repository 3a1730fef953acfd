/// @file grade.cpp
/// @brief The pass/fail table of `stepwise run`, and `stepwise grade`: a folder of scenes, one row per file.
///
/// Grading runs each scene exactly as `stepwise run FILE` would (its own
/// World record, its own Duration) and checks the expectations after every
/// step with an ExpectationMonitor. A file that cannot be loaded or run is a
/// row that says why, never the end of the grading: one student's broken
/// file must not hide the others' results.
///
/// With `--expect STARTER`, a starter that has MayChange records also fixes
/// everything else: each submission is compared with it record by record
/// (compareWithStarter, config/scene_changes.hpp), and a change no MayChange
/// record allows fails the file, whatever its expectations measured.
#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/interrupt.hpp"
#include "config/scene_changes.hpp"
#include "config/scene_loader.hpp"
#include "core/errors.hpp"
#include "world/world.hpp"

namespace stepwise::cli {

namespace {

namespace fs = std::filesystem;

/// A table cell longer than this is cut with "...": a row stays one line on a terminal.
constexpr std::size_t kMaxCellWidth = 110;

/// How one graded file ended.
enum class Outcome { Pass, Fail, Error };

/// One row of the grading table.
struct GradeRow {
    std::string file;     ///< Path below the graded folder.
    Outcome outcome = Outcome::Error;
    std::size_t passed = 0;
    std::size_t total = 0;
    std::string note;     ///< The first failure, or the error.
    std::vector<ConfigDiagnostic> changes;  ///< Changes against the starter that no MayChange record allows.
};

/// The file given with --expect: the instructor's records every submission is graded on.
struct AnswerKey {
    std::string path;                       ///< As given on the command line.
    std::string text;                       ///< Its text, which submissions are compared with.
    std::vector<Expectation> expectations;  ///< Its Expect records.
    std::vector<MayChange> mayChange;       ///< Its MayChange records; none: any change is allowed.
};

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// "line 14:109: error: …": a diagnostic without its file name, which the row already shows.
std::string rowNote(const ConfigDiagnostic& diagnostic, std::size_t count) {
    std::string note = diagnostic.message();
    const std::string prefix = diagnostic.file + ":";
    if (note.rfind(prefix, 0) == 0) note = (diagnostic.line > 0 ? "line " : "") + note.substr(prefix.size());
    if (count > 1) note += " (and " + std::to_string(count - 1) + " more)";
    return note;
}

const char* outcomeText(Outcome outcome) {
    switch (outcome) {
        case Outcome::Pass: return "PASS";
        case Outcome::Fail: return "FAIL";
        case Outcome::Error: return "ERROR";
    }
    return "?";
}

std::string cut(std::string text) {
    if (text.size() > kMaxCellWidth) text = text.substr(0, kMaxCellWidth - 3) + "...";
    return text;
}

/// The scene files below @p folder whose relative path matches @p glob, in name order.
std::vector<fs::path> sceneFiles(const fs::path& folder, const std::string& glob) {
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder)) {
        if (!entry.is_regular_file()) continue;
        const std::string relative = entry.path().lexically_relative(folder).generic_string();
        // No FNM_PATHNAME: '*' also matches '/', so "*.scene" finds alice/answer.scene too.
        if (fnmatch(glob.c_str(), relative.c_str(), 0) == 0) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// Loads, simulates and checks one file; every way it can go wrong becomes the row's note.
GradeRow gradeFile(const fs::path& path, const fs::path& folder, const AnswerKey* key, const GradeOptions& options) {
    const std::uint64_t maxSteps = options.maxSteps;
    GradeRow row;
    row.file = path.lexically_relative(folder).generic_string();
    std::unique_ptr<Scene> scene;
    try {
        scene = std::make_unique<Scene>(loadSceneFile(path.string()));
    } catch (const ConfigError& error) {
        // The row already names the file: "line 14:109: error: Mass: …" leaves room for the message.
        row.note = rowNote(error.diagnostics().front(), error.diagnostics().size());
        return row;
    }
    if (key != nullptr && !key->mayChange.empty()) {
        for (const SceneChange& change : compareWithStarter(key->text, readText(path), key->mayChange)) {
            if (!change.allowed) row.changes.push_back(changeDiagnostic(change, path.string(), key->mayChange));
        }
    }
    // A change the assignment does not allow fails the file, whatever the expectations measure.
    const auto reportChanges = [&row]() {
        if (row.changes.empty()) return;
        row.outcome = Outcome::Fail;
        row.note = rowNote(row.changes.front(), row.changes.size());
    };
    const std::vector<Expectation> expectations = key ? key->expectations : scene->expectations;
    row.total = expectations.size();
    if (expectations.empty()) {
        row.note = "no Expect records: nothing to check";
        return row;
    }
    try {
        World world(std::move(*scene));
        const double h = double(world.settings().timeStep);
        const double steps = std::round(double(world.settings().duration) / h);
        if (steps > double(maxSteps)) {
            row.note = "needs " + std::to_string(static_cast<unsigned long long>(steps)) + " steps, more than --max-steps " +
                       std::to_string(maxSteps) + " (check its TimeStep and Duration)";
            reportChanges();
            return row;
        }
        ExpectationMonitor monitor(world, expectations);
        monitor.observe(world);
        std::string failure;
        // One submission that never ends must not stall the class: past its budget, the file fails.
        const Deadline deadline(options.maxSecondsPerFile);
        try {
            for (std::uint64_t i = 0; i < static_cast<std::uint64_t>(steps); ++i) {
                world.step();
                monitor.observe(world);
                if (InterruptGuard::signalReceived() != 0) {
                    failure = "stopped by a signal";
                    break;
                }
                if (i + 1 < static_cast<std::uint64_t>(steps) && deadline.passed()) {
                    char text[160];
                    std::snprintf(text, sizeof text, "took longer than --max-seconds %g: %llu of %.0f steps", deadline.seconds(),
                                  static_cast<unsigned long long>(world.stepCount()), steps);
                    failure = text;
                    break;
                }
            }
        } catch (const SimulationError& error) {
            failure = std::string("simulation failed: ") + error.what();
        } catch (const std::bad_alloc&) {
            failure = outOfMemoryMessage(world);
        }
        const std::vector<ExpectationResult> results = monitor.results(world);
        for (std::size_t i = 0; i < results.size(); ++i) {
            if (results[i].passed) {
                ++row.passed;
            } else if (row.note.empty()) {
                row.note = describe(expectations[i]) + " -> " + describeMeasurement(expectations[i], results[i]);
            }
        }
        if (!failure.empty()) row.note = failure;
        row.outcome = row.passed == row.total && failure.empty() ? Outcome::Pass : Outcome::Fail;
    } catch (const std::bad_alloc&) {
        row.note = "out of memory building the scene's world";
        return row;
    } catch (const std::exception& error) {
        row.note = std::string("the scene cannot be simulated: ") + error.what();
        return row;
    }
    reportChanges();
    return row;
}

}  // namespace

bool printExpectationTable(const std::vector<Expectation>& expectations, const std::vector<ExpectationResult>& results) {
    std::size_t passed = 0;
    std::size_t width = std::string("expectation").size();
    std::vector<std::string> described;
    for (std::size_t i = 0; i < expectations.size(); ++i) {
        described.push_back(cut(describe(expectations[i])));
        width = std::max(width, described.back().size());
        if (results[i].passed) ++passed;
    }
    std::printf("\nExpectations: %zu of %zu passed\n", passed, expectations.size());
    std::printf("  %-6s %-5s %-*s  %s\n", "result", "line", static_cast<int>(width), "expectation", "measured");
    for (std::size_t i = 0; i < expectations.size(); ++i) {
        std::printf("  %-6s %-5d %-*s  %s\n", results[i].passed ? "PASS" : "FAIL", expectations[i].line,
                    static_cast<int>(width), described[i].c_str(),
                    describeMeasurement(expectations[i], results[i]).c_str());
    }
    return passed == expectations.size();
}

int gradeCommand(const GradeOptions& options) {
    std::error_code status;
    if (!fs::is_directory(options.folder, status)) {
        std::fprintf(stderr, "stepwise: error: '%s' is not a folder\n", options.folder.c_str());
        return kExitUsageError;
    }
    AnswerKey key;
    if (options.expectPath) {
        key.path = *options.expectPath;
        try {
            Scene scene = loadSceneFile(key.path);
            key.expectations = std::move(scene.expectations);
            key.mayChange = std::move(scene.mayChange);
        } catch (const ConfigError& error) {
            for (const ConfigDiagnostic& d : error.diagnostics()) std::fprintf(stderr, "%s\n", d.message().c_str());
            std::fprintf(stderr, "stepwise: the --expect file does not load; nothing was graded.\n");
            return kExitUsageError;
        }
        key.text = readText(key.path);
        if (key.expectations.empty()) {
            std::fprintf(stderr, "stepwise: error: %s has no Expect records\n", options.expectPath->c_str());
            return kExitUsageError;
        }
    }
    const std::vector<fs::path> files = sceneFiles(options.folder, options.glob);
    if (files.empty()) {
        std::fprintf(stderr, "stepwise: error: no files matching '%s' in %s\n", options.glob.c_str(),
                     options.folder.c_str());
        return kExitUsageError;
    }

    std::printf("Grading %zu file(s) in %s against %s\n", files.size(), options.folder.c_str(),
                options.expectPath ? ("the Expect records of " + *options.expectPath).c_str()
                                   : "each file's own Expect records");
    if (!key.mayChange.empty()) {
        std::string permitted;
        for (const MayChange& m : key.mayChange) permitted += (permitted.empty() ? "" : ", ") + describeAllowed(m);
        std::printf("Only its MayChange fields may differ from it: %s\n", permitted.c_str());
    } else if (options.expectPath) {
        std::printf("It has no MayChange records: submissions may change anything\n");
    }
    // Each row is printed as its file finishes, so a long grading shows its progress, and a
    // grading stopped by Ctrl-C has printed every row it finished.
    std::size_t fileWidth = std::string("file").size();
    for (const fs::path& file : files) fileWidth = std::max(fileWidth, file.lexically_relative(options.folder).generic_string().size());
    std::printf("  %-*s  %-6s %-7s %s\n", static_cast<int>(fileWidth), "file", "result", "passed", "first failure");
    std::fflush(stdout);
    std::vector<GradeRow> rows;
    std::size_t counts[3] = {0, 0, 0};
    const InterruptGuard interrupts;
    for (const fs::path& file : files) {
        rows.push_back(gradeFile(file, options.folder, options.expectPath ? &key : nullptr, options));
        const GradeRow& row = rows.back();
        ++counts[static_cast<int>(row.outcome)];
        const std::string passed =
            row.total > 0 && row.outcome != Outcome::Error ? std::to_string(row.passed) + "/" + std::to_string(row.total)
                                                           : "-";
        std::printf("  %-*s  %-6s %-7s %s\n", static_cast<int>(fileWidth), row.file.c_str(), outcomeText(row.outcome),
                    passed.c_str(), cut(row.note).c_str());
        std::fflush(stdout);
        if (InterruptGuard::signalReceived() != 0) break;
    }
    std::printf("%zu file(s): %zu passed, %zu failed, %zu could not be run\n", rows.size(), counts[0], counts[1],
                counts[2]);
    // Every change, in full: the table shows only the first of each file.
    bool heading = false;
    for (const GradeRow& row : rows) {
        for (const ConfigDiagnostic& change : row.changes) {
            if (!heading) std::printf("\nChanges that %s does not allow:\n", key.path.c_str());
            heading = true;
            std::printf("%s\n", change.message().c_str());
        }
    }
    if (const int signal = InterruptGuard::signalReceived(); signal != 0) {
        std::fprintf(stderr, "stepwise: grading stopped by signal %d after %zu of %zu file(s)\n", signal, rows.size(),
                     files.size());
        return exitCodeForSignal(signal);
    }
    return counts[0] == rows.size() ? kExitOk : kExitExpectationFailed;
}

}  // namespace stepwise::cli
