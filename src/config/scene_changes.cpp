/// @file scene_changes.cpp
/// @brief Compares a submission with its starter record by record (see scene_changes.hpp).
#include "config/scene_changes.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <tuple>
#include <utility>

#include "config/record_reader.hpp"
#include "config/scene_records.hpp"
#include "config/scene_tokenizer.hpp"
#include "config/spelling.hpp"

namespace stepwise {

namespace {

using namespace config;

/// One record line of a file, read but not built into an object.
struct ReadLine {
    const RecordSpec* spec = nullptr;  ///< Its record type.
    std::string name;                  ///< The object's name (given or default); "" for the World record.
    int line = 0;                      ///< Its line.
    int column = 0;                    ///< Column of its record name.
    RecordValues values;               ///< What it says about each field.
};

/// Records are matched by type and by name, ignoring case (names are unique ignoring case).
using RecordKey = std::pair<RecordKind, std::string>;

/// The records of @p text that grading compares, by key, in file order. Names
/// follow the loader's rule: Name=, or the record type and its index among
/// the records of that type ("DynamicObject0").
std::vector<std::pair<RecordKey, ReadLine>> readLines(std::string_view text) {
    std::vector<std::pair<RecordKey, ReadLine>> lines;
    std::map<RecordKind, int> counts;
    DiagnosticSink ignored("");  // the caller has loaded the file and reported its problems
    for (const SceneLine& line : tokenizeScene(text)) {
        const RecordSpec* spec = findRecord(line.tokens.front().text);
        if (spec == nullptr) continue;
        const int index = counts[spec->kind]++;
        if (line.parenthesisProblem || spec->kind == RecordKind::Expect || spec->kind == RecordKind::MayChange) continue;
        RecordValues values = readRecord(line, *spec, ignored);
        std::string name;
        if (spec->kind != RecordKind::World) {
            name = values.text("Name").value_or(std::string(spec->name) + std::to_string(index));
        }
        RecordKey key{spec->kind, toLower(name)};
        const bool seen = std::any_of(lines.begin(), lines.end(), [&](const auto& entry) { return entry.first == key; });
        if (seen) continue;  // a second World, or a duplicate name: the loader reports it
        lines.push_back({std::move(key), ReadLine{spec, name, line.number, line.tokens.front().column, std::move(values)}});
    }
    return lines;
}

/// The meaning of a word field's choice (Euler and ExplicitEuler mean the same integrator).
int choiceMeaning(FieldKind kind, std::size_t index) {
    switch (kind) {
        case FieldKind::Shape: return static_cast<int>(kShapeChoices.at(index).value);
        case FieldKind::Integrator: return static_cast<int>(kIntegratorChoices.at(index).value);
        case FieldKind::Solver: return static_cast<int>(kSolverChoices.at(index).value);
        case FieldKind::Broadphase: return static_cast<int>(kBroadphaseChoices.at(index).value);
        case FieldKind::Boolean: return kBooleanChoices.at(index).value ? 1 : 0;
        case FieldKind::Compare: return static_cast<int>(kCompareChoices.at(index).value);
        case FieldKind::Narrowphase: return static_cast<int>(kNarrowphaseChoices.at(index).value);
        case FieldKind::ContactOrder: return static_cast<int>(kContactOrderChoices.at(index).value);
        case FieldKind::RegionShape: return static_cast<int>(kRegionShapeChoices.at(index).value);
        case FieldKind::Effect: return static_cast<int>(kEffectChoices.at(index).value);
        case FieldKind::DragLaw: return static_cast<int>(kDragLawChoices.at(index).value);
        case FieldKind::Combine: return static_cast<int>(kCombineChoices.at(index).value);
        default: return static_cast<int>(index);
    }
}

/// Do the two files say the same thing about this part of a field?
bool same(FieldKind kind, const RecordValues::WrittenPart& a, const RecordValues::WrittenPart& b) {
    if (a.given != b.given) return false;
    if (!a.given) return true;
    if (a.number || b.number) return a.number == b.number;
    if (a.choice && b.choice) return choiceMeaning(kind, *a.choice) == choiceMeaning(kind, *b.choice);
    return equalsIgnoreCase(a.text, b.text);  // names, which are unique ignoring case
}

bool isAllowed(std::span<const MayChange> allowed, const RecordSpec& spec, const std::string& object,
               const FieldSpec& field, int component) {
    const bool world = spec.kind == RecordKind::World;
    return std::any_of(allowed.begin(), allowed.end(), [&](const MayChange& m) {
        const bool sameRecord = world ? m.object.empty() : !m.object.empty() && equalsIgnoreCase(m.object, object);
        return sameRecord && (equalsIgnoreCase(m.field, field.name) ||
                              equalsIgnoreCase(m.field, fieldName(field, component)));
    });
}

/// Every field and component of two records of the same type and name that differ.
void compareRecords(const ReadLine& starter, const ReadLine& submission, std::span<const MayChange> allowed,
                    std::vector<SceneChange>& changes) {
    const RecordSpec& spec = *starter.spec;
    for (std::size_t i = 0; i < spec.fields.size(); ++i) {
        const FieldSpec& field = spec.fields[i];
        if (field.name == "Name") continue;  // the key the records were matched by
        const std::size_t parts = componentCount(field.kind);
        for (std::size_t c = 0; c < parts; ++c) {
            const int component = parts == 1 ? kWholeField : static_cast<int>(c);
            const RecordValues::WrittenPart before = starter.values.written(i, component);
            const RecordValues::WrittenPart after = submission.values.written(i, component);
            if (same(field.kind, before, after)) continue;
            SceneChange change;
            change.record = std::string(spec.name);
            change.object = submission.name;
            change.field = fieldName(field, component);
            change.before = before.text;
            change.after = after.text;
            change.line = submission.line;
            change.column = after.given ? after.column : submission.column;
            change.starterLine = starter.line;
            change.allowed = isAllowed(allowed, spec, submission.name, field, component);
            changes.push_back(std::move(change));
        }
    }
}

/// "ball.PositionY", "World.TimeStep".
std::string owned(const std::string& object, const std::string& field) {
    return (object.empty() ? std::string("World") : object) + "." + field;
}

std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

}  // namespace

std::vector<SceneChange> compareWithStarter(std::string_view starterText, std::string_view submissionText,
                                            std::span<const MayChange> allowed) {
    const auto starter = readLines(starterText);
    const auto submission = readLines(submissionText);
    const auto find = [](const auto& lines, const RecordKey& key) -> const ReadLine* {
        for (const auto& [k, line] : lines) {
            if (k == key) return &line;
        }
        return nullptr;
    };

    std::vector<SceneChange> changes;
    for (const auto& [key, line] : submission) {
        if (const ReadLine* original = find(starter, key)) {
            compareRecords(*original, line, allowed, changes);
        } else if (key.first == RecordKind::World) {
            // No World record in the starter: each field the submission gives is a change from the default.
            const ReadLine none{line.spec, "", 0, 0, RecordValues(*line.spec)};
            compareRecords(none, line, allowed, changes);
        } else {
            changes.push_back({std::string(line.spec->name), line.name, "", "", line.name, line.line, line.column, 0,
                               false});
        }
    }
    for (const auto& [key, line] : starter) {
        if (find(submission, key) != nullptr) continue;
        if (key.first == RecordKind::World) {
            // The World record was deleted: each field the starter gave is now left out.
            const ReadLine none{line.spec, "", 0, 1, RecordValues(*line.spec)};
            compareRecords(line, none, allowed, changes);
            continue;
        }
        changes.push_back({std::string(line.spec->name), line.name, "", line.name, "", 0, 0, line.line, false});
    }
    std::stable_sort(changes.begin(), changes.end(), [](const SceneChange& a, const SceneChange& b) {
        // The submission's lines in file order, then what is missing from it in the starter's order.
        const auto order = [](const SceneChange& c) {
            return c.line > 0 ? std::tuple(0, c.line, c.column) : std::tuple(1, c.starterLine, 0);
        };
        return order(a) < order(b);
    });
    return changes;
}

std::string describeAllowed(const MayChange& allowed) { return owned(allowed.object, allowed.field); }

ConfigDiagnostic changeDiagnostic(const SceneChange& change, const std::string& submissionPath,
                                  std::span<const MayChange> allowed) {
    std::string permitted;
    for (const MayChange& m : allowed) permitted += (permitted.empty() ? "" : ", ") + describeAllowed(m);
    const std::string rule = permitted.empty() ? "the assignment lets you change nothing"
                                               : "the assignment lets you change only " + permitted;
    const std::string starterLine = change.starterLine > 0 ? " (line " + std::to_string(change.starterLine) + ")" : "";

    ConfigDiagnostic d;
    d.file = submissionPath;
    d.line = change.line;
    d.column = change.column;
    if (change.field.empty() && change.line > 0) {
        d.field = change.record;
        d.expected = "only the records of the starter";
        d.found = change.object;
        d.hint = "the starter has no " + change.record + " named " + quoted(change.object) + "; " + rule;
    } else if (change.field.empty()) {
        d.field = change.record;
        d.expected = quoted(change.object) + ", as in the starter" + starterLine;
        d.found = "";
        d.hint = "the starter's " + change.record + " " + quoted(change.object) + " is missing; " + rule;
    } else {
        d.field = owned(change.object, change.field);
        d.expected = (change.before.empty() ? "no " + change.field : change.before) + ", as in the starter" +
                     starterLine;
        d.found = change.after;
        d.hint = (change.after.empty() ? "it was removed; " : "") + rule;
    }
    return d;
}

}  // namespace stepwise
