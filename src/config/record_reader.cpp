/// @file record_reader.cpp
/// @brief Assigns each token of a record line to its field, parses it, and reports what is wrong.
#include "config/record_reader.hpp"

#include <algorithm>
#include <stdexcept>

#include "config/spelling.hpp"

namespace stepwise::config {

namespace {

/// The largest 0–255 channel value: a colour above 1 but not above this was
/// probably written on the 0–255 scale.
constexpr Real kMaxByteChannel = 255;

/// "(x, y, z)" or "(r, g, b)": the components of a triple, in order.
std::string tripleLetters(FieldKind kind) { return kind == FieldKind::Color ? "(r, g, b)" : "(x, y, z)"; }

/// "a vector (x, y, z)" or "a colour (r, g, b)": how a whole triple is written.
std::string tripleLayout(FieldKind kind) {
    return (kind == FieldKind::Color ? "a colour " : "a vector ") + tripleLetters(kind);
}

/// The words of a choice table, for parseWord().
template <typename E, std::size_t N>
std::vector<std::string_view> wordsOf(const std::array<Choice<E>, N>& choices) {
    std::vector<std::string_view> words;
    for (const Choice<E>& choice : choices) words.push_back(choice.word);
    return words;
}

std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

/// How one point of a Points field is written, and an example of the whole list.
constexpr std::string_view kPointLayout = "a point (x, y, z)";
constexpr std::string_view kPointsExample = "=(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)";

}  // namespace

// ---------------------------------------------------------------- DiagnosticSink

void DiagnosticSink::report(int line, int column, std::string field, std::string expected, std::string found,
                            std::string hint) {
    diagnostics_.push_back(ConfigDiagnostic{file_, line, column, std::move(field), std::move(expected),
                                            std::move(found), std::move(hint)});
}

void DiagnosticSink::report(int line, std::string field, const ValueProblem& problem) {
    report(line, problem.column, std::move(field), problem.expected, problem.found, problem.hint);
}

// ---------------------------------------------------------------- RecordValues

RecordValues::RecordValues(const RecordSpec& spec) : spec_(&spec), slots_(spec.fields.size()) {}

const RecordValues::Slot& RecordValues::slot(std::string_view field) const {
    for (std::size_t i = 0; i < spec_->fields.size(); ++i) {
        if (spec_->fields[i].name == field) return slots_[i];
    }
    throw std::logic_error("RecordValues: " + std::string(spec_->name) + " has no field '" + std::string(field) + "'");
}

int RecordValues::valueColumn(std::string_view field) const { return slot(field).valueColumn; }

bool RecordValues::isSet(std::string_view field, int component) const {
    const Slot& s = slot(field);
    if (component != kWholeField) return s.setAtColumn.at(static_cast<std::size_t>(component)) != 0;
    return std::any_of(s.setAtColumn.begin(), s.setAtColumn.end(), [](int column) { return column != 0; });
}

const std::string& RecordValues::asWritten(std::string_view field) const { return slot(field).asWritten; }

Real RecordValues::number(std::string_view field, Real fallback) const {
    return slot(field).numbers[0].value_or(fallback);
}

Vec3 RecordValues::triple(std::string_view field, const Vec3& fallback) const {
    const Slot& s = slot(field);
    return Vec3(s.numbers[0].value_or(fallback.x), s.numbers[1].value_or(fallback.y),
                s.numbers[2].value_or(fallback.z));
}

std::optional<std::string> RecordValues::text(std::string_view field) const { return slot(field).text; }

const std::vector<Vec3>& RecordValues::points(std::string_view field) const { return slot(field).points; }

RecordValues::WrittenPart RecordValues::written(std::size_t field, int component) const {
    const Slot& s = slots_.at(field);
    const std::size_t part = component == kWholeField ? 0 : static_cast<std::size_t>(component);
    WrittenPart written;
    written.given = s.setAtColumn.at(part) != 0;
    if (!written.given) return written;
    if (s.numbers[part] || !s.numberText[part].empty()) {
        written.number = s.numbers[part];
        written.text = s.numberText[part];
        written.column = s.numberColumn[part];
    } else {
        written.choice = s.choice;
        written.text = s.text.value_or("");
        written.column = s.valueColumn;
    }
    return written;
}

// ---------------------------------------------------------------- RecordReader

/// Reads one line into RecordValues. A class only so that the line, the
/// record type and the sink need not be passed to every helper.
class RecordReader {
public:
    /// Prepares to read @p line as a record of type @p spec, reporting problems to @p sink.
    RecordReader(const SceneLine& line, const RecordSpec& spec, DiagnosticSink& sink)
        : line_(line), spec_(spec), sink_(sink), values_(spec) {}

    /// Assigns every token of the line to a field; returns the values found.
    RecordValues read() {
        const int positionalLimit = positionalCount(spec_);
        int nextPositional = 0;
        const Token* firstNamed = nullptr;
        const Token* lastPositional = nullptr;
        bool reportedTooMany = false;
        const std::size_t problemsBefore = sink_.diagnostics().size();

        for (std::size_t i = 1; i < line_.tokens.size(); ++i) {
            const Token& token = line_.tokens[i];
            if (const std::optional<NamedToken> named = splitNamed(token)) {
                if (firstNamed == nullptr) firstNamed = &token;
                openList_ = nullptr;
                readNamed(token, *named);
            } else if (openList_ != nullptr && !token.text.empty() && token.text.front() == '(') {
                // `Vertices=(0, 0, 0), (1, 0, 0), …`: the commas between points split the
                // line into tokens, and every later "(…)" continues the list.
                readPoint(*openList_, values_.slots_[openListSlot_], token);
            } else if (firstNamed != nullptr) {
                // Once a field has been named, the position of later values
                // no longer says which field they are.
                report(token.column, std::string(spec_.name), "a named field (Field=Value)", token.text,
                       "positional values must come before the first named field (" + quoted(firstNamed->text) +
                           " at column " + std::to_string(firstNamed->column) + ")");
            } else if (nextPositional >= positionalLimit) {
                if (!reportedTooMany) reportTooManyPositional(token, positionalLimit);
                reportedTooMany = true;  // once per line: the rest are all "too many" as well
            } else {
                assign(positionalField(spec_, nextPositional++), token, token);
                lastPositional = &token;
            }
        }
        // A vector cut short is only worth saying about a line that is otherwise well formed: after a
        // bad positional token, the count of values no longer tells which vector was meant.
        const bool lineWasClean = sink_.diagnostics().size() == problemsBefore;
        if (lastPositional != nullptr && nextPositional < positionalLimit && lineWasClean) {
            reportVectorCutShort(*lastPositional, nextPositional);
        }
        return std::move(values_);
    }

private:
    void report(int column, std::string field, std::string expected, std::string_view found, std::string hint = "") {
        sink_.report(line_.number, column, std::move(field), std::move(expected), std::string(found), std::move(hint));
    }

    void readNamed(const Token& token, const NamedToken& named) {
        if (const std::optional<FieldRef> ref = findField(spec_, named.name.text)) {
            assign(*ref, named.value, token);
        } else {
            reportUnknownField(named.name);
        }
    }

    /// A vector is given whole or not at all: positional values that stop inside one (five numbers for a
    /// plane's Position and Normal) are almost always a number left out, not a component meant to keep its default.
    void reportVectorCutShort(const Token& last, int given) {
        const FieldRef next = positionalField(spec_, given);
        if (next.component <= 0) return;  // the values stop at the end of a field: nothing cut short
        const FieldSpec& field = spec_.fields[next.field];
        std::string missing;
        for (int c = next.component; c < int(componentCount(field.kind)); ++c) {
            missing += (missing.empty() ? "" : ", ") + fieldName(field, c);
        }
        report(last.column, std::string(field.name), "all " + std::to_string(componentCount(field.kind)) +
                                                         " components of " + std::string(field.name),
               last.text, "the positional values stop inside " + std::string(field.name) + ": " + missing +
                              " is missing; give every component, or name the fields you mean (e.g. " +
                              fieldName(field, 0) + "=...)");
    }

    void reportTooManyPositional(const Token& token, int limit) {
        if (limit == 0) {
            report(token.column, std::string(spec_.name), "a named field (Field=Value)", token.text,
                   std::string(spec_.name) + " takes named fields only, e.g. " +
                       std::string(spec_.fields.front().name) + "=...");
            return;
        }
        const FieldRef last = positionalField(spec_, limit - 1);
        report(token.column, std::string(spec_.name), "at most " + std::to_string(limit) + " positional fields",
               token.text,
               "the last positional field is " + fieldName(spec_.fields[last.field], last.component) +
                   "; give further fields by name (Field=Value)");
    }

    void reportUnknownField(const Token& name) {
        std::string hint;
        if (const auto suggestion = closestMatch(name.text, fieldSpellings(spec_))) {
            hint = "did you mean '" + *suggestion + "'?";
        } else {
            hint = std::string(spec_.name) + " has no field " + quoted(name.text);
            // A field that exists on another record is a common slip, e.g. Mass on a plane.
            std::string owners;
            for (const RecordSpec& other : allRecords()) {
                if (&other == &spec_ || !findField(other, name.text)) continue;
                owners += owners.empty() ? "" : " and ";
                owners += other.name;
            }
            if (!owners.empty()) hint += " (it is a field of " + owners + ")";
        }
        report(name.column, std::string(spec_.name), "one of its fields (" + fieldList(spec_) + ")", name.text,
               std::move(hint));
    }

    /// Gives @p value to the field (or component) @p ref; @p origin is the
    /// whole token, where "set twice" problems are reported.
    void assign(const FieldRef& ref, const Token& value, const Token& origin) {
        const FieldSpec& field = spec_.fields[ref.field];
        RecordValues::Slot& slot = values_.slots_[ref.field];

        // Which parts does this token set? A whole triple sets all three.
        const bool whole = ref.component == kWholeField;
        const std::size_t first = whole ? 0 : static_cast<std::size_t>(ref.component);
        const std::size_t last = whole ? componentCount(field.kind) : first + 1;
        for (std::size_t c = first; c < last; ++c) {
            if (slot.setAtColumn[c] == 0) continue;
            const int part = componentCount(field.kind) == 1 ? kWholeField : static_cast<int>(c);
            report(origin.column, fieldName(field, ref.component), "each field at most once", origin.text,
                   fieldName(field, part) + " was already set at column " + std::to_string(slot.setAtColumn[c]));
            return;
        }
        for (std::size_t c = first; c < last; ++c) slot.setAtColumn[c] = origin.column;
        if (slot.valueColumn == 0) slot.valueColumn = value.column;

        switch (field.kind) {
            case FieldKind::Number:
                readComponent(field, slot, 0, value);
                break;
            case FieldKind::Vector:
            case FieldKind::Color:
                if (whole) {
                    readTriple(field, slot, value);
                } else {
                    readComponent(field, slot, first, value);
                }
                break;
            case FieldKind::Shape:
                readChoice(field, slot, value, wordsOf(kShapeChoices));
                break;
            case FieldKind::Integrator:
                readChoice(field, slot, value, wordsOf(kIntegratorChoices));
                break;
            case FieldKind::Solver:
                readChoice(field, slot, value, wordsOf(kSolverChoices));
                break;
            case FieldKind::Broadphase:
                readChoice(field, slot, value, wordsOf(kBroadphaseChoices));
                break;
            case FieldKind::Boolean:
                readChoice(field, slot, value, wordsOf(kBooleanChoices));
                break;
            case FieldKind::Compare:
                readChoice(field, slot, value, wordsOf(kCompareChoices));
                break;
            case FieldKind::Narrowphase:
                readChoice(field, slot, value, wordsOf(kNarrowphaseChoices));
                break;
            case FieldKind::ContactOrder:
                readChoice(field, slot, value, wordsOf(kContactOrderChoices));
                break;
            case FieldKind::RegionShape:
                readChoice(field, slot, value, wordsOf(kRegionShapeChoices));
                break;
            case FieldKind::Effect:
                readChoice(field, slot, value, wordsOf(kEffectChoices));
                break;
            case FieldKind::DragLaw:
                readChoice(field, slot, value, wordsOf(kDragLawChoices));
                break;
            case FieldKind::Combine:
                readChoice(field, slot, value, wordsOf(kCombineChoices));
                break;
            case FieldKind::Points:
                openList_ = &field;
                openListSlot_ = ref.field;
                readPoint(field, slot, value);
                break;
            case FieldKind::File: {
                const Parsed<std::string> path = parseFilePath(value);
                if (path.ok()) {
                    slot.text = path.value();
                } else {
                    sink_.report(line_.number, fieldName(field, kWholeField), path.problem());
                }
                break;
            }
            case FieldKind::Name: {
                const Parsed<std::string> name = parseName(value);
                if (name.ok()) {
                    slot.text = name.value();
                } else {
                    sink_.report(line_.number, fieldName(field, kWholeField), name.problem());
                }
                break;
            }
        }
    }

    void readTriple(const FieldSpec& field, RecordValues::Slot& slot, const Token& value) {
        const Parsed<std::array<Token, 3>> parts = splitTriple(value, tripleLayout(field.kind));
        if (!parts.ok()) {
            ValueProblem problem = parts.problem();
            if (problem.hint.empty()) {
                // Echo the user's number in the example when there is one: "Position=5" → "PositionX=5".
                const bool isNumber = parseNumber(value, Range::Any).ok();
                problem.hint = "write " + std::string(field.name) + "=" + tripleLetters(field.kind) + ", or set one "
                               "component alone, e.g. " + fieldName(field, 0) + "=" +
                               (isNumber ? std::string(value.text) : std::string("1"));
            }
            sink_.report(line_.number, fieldName(field, kWholeField), problem);
            return;
        }
        slot.asWritten = std::string(value.text);
        for (std::size_t c = 0; c < parts.value().size(); ++c) readComponent(field, slot, c, parts.value()[c]);
    }

    /// One point of a Points field: a triple, each number checked at its own column.
    void readPoint(const FieldSpec& field, RecordValues::Slot& slot, const Token& value) {
        slot.asWritten += (slot.asWritten.empty() ? "" : ", ") + std::string(value.text);
        slot.text = slot.asWritten;  // what grading compares (RecordValues::written)
        const std::string name(field.name);
        const Parsed<std::array<Token, 3>> parts = splitTriple(value, kPointLayout);
        if (!parts.ok()) {
            ValueProblem problem = parts.problem();
            problem.expected = std::string(kPointLayout) + " (point " + std::to_string(slot.points.size() + 1) +
                               " of " + name + ")";
            if (problem.hint.empty()) {
                problem.hint = name + " is a list of points in parentheses, e.g. " + name + std::string(kPointsExample);
            }
            sink_.report(line_.number, name, problem);
            return;
        }
        Vec3 point(0);
        for (std::size_t c = 0; c < parts.value().size(); ++c) {
            const Parsed<Real> number = parseNumber(parts.value()[c], field.range);
            if (!number.ok()) {
                sink_.report(line_.number, name, number.problem());
                return;
            }
            point[static_cast<int>(c)] = number.value();
        }
        slot.points.push_back(point);
    }

    void readComponent(const FieldSpec& field, RecordValues::Slot& slot, std::size_t component, const Token& value) {
        slot.numberText[component] = std::string(value.text);
        slot.numberColumn[component] = value.column;
        const Parsed<Real> number = parseNumber(value, field.range);
        if (number.ok()) {
            slot.numbers[component] = number.value();
            return;
        }
        const int part = componentCount(field.kind) == 1 ? kWholeField : static_cast<int>(component);
        ValueProblem problem = number.problem();
        if (problem.hint.empty()) problem.hint = rangeHint(field, value);
        sink_.report(line_.number, fieldName(field, part), problem);
    }

    /// Advice for a number that parsed but lies outside the field's range.
    std::string rangeHint(const FieldSpec& field, const Token& value) const {
        const Parsed<Real> unchecked = parseNumber(value, Range::Any);
        if (!unchecked.ok()) {
            // Not a number at all. A vector where one number belongs: either the field is a number
            // (Mass=(1,2,3)), or the value stands in a positional slot, which holds one component.
            if (!value.text.empty() && value.text.front() == '(') {
                if (field.kind == FieldKind::Number) return std::string(field.name) + " is one number, not a vector";
                return "a positional value is one component; give a whole vector by name, e.g. " +
                       std::string(field.name) + "=" + std::string(value.text);
            }
            return "";
        }
        if (field.kind == FieldKind::Color && unchecked.value() > 1 && unchecked.value() <= kMaxByteChannel) {
            return "colour channels run from 0 to 1; divide 0-255 values by 255, e.g. write " +
                   std::string(value.text) + "/255";
        }
        return std::string(field.hint);
    }

    void readChoice(const FieldSpec& field, RecordValues::Slot& slot, const Token& value,
                    const std::vector<std::string_view>& words) {
        const Parsed<std::size_t> index = parseWord(value, words);
        if (index.ok()) {
            slot.choice = index.value();
            slot.text = std::string(value.text);  // as written, for messages about the choice
        } else {
            sink_.report(line_.number, fieldName(field, kWholeField), index.problem());
        }
    }

    const SceneLine& line_;
    const RecordSpec& spec_;
    DiagnosticSink& sink_;
    RecordValues values_;
    const FieldSpec* openList_ = nullptr;  ///< The Points field later "(…)" tokens continue, if any.
    std::size_t openListSlot_ = 0;         ///< Its index in the record table.
};

RecordValues readRecord(const SceneLine& line, const RecordSpec& spec, DiagnosticSink& sink) {
    return RecordReader(line, spec, sink).read();
}

}  // namespace stepwise::config
