/// @file record_reader.hpp
/// @brief Third stage of loading a scene: one tokenized line → the values of its fields.
///
/// readRecord() walks the tokens of one record line, decides which field
/// each token sets (by position, or by `Field=Value`), parses and checks the
/// value, and reports every problem to a DiagnosticSink. What it produces,
/// RecordValues, only answers "what did the file say for field F, or else
/// what is the default?": turning those values into objects is the loader's job.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "config/field_values.hpp"
#include "config/scene_loader.hpp"
#include "config/scene_records.hpp"
#include "config/scene_tokenizer.hpp"

namespace stepwise::config {

/// @brief Collects the diagnostics of one file, in the order they are found.
class DiagnosticSink {
public:
    /// @brief Starts an empty list for the file called @p file.
    explicit DiagnosticSink(std::string file) : file_(std::move(file)) {}

    /// @brief Records one problem.
    void report(int line, int column, std::string field, std::string expected, std::string found,
                std::string hint = "");
    /// @brief Records a value parser's problem as a problem with @p field on @p line.
    void report(int line, std::string field, const ValueProblem& problem);

    /// @brief Name of the file the diagnostics are about.
    const std::string& file() const { return file_; }
    /// @brief Every problem so far.
    const std::vector<ConfigDiagnostic>& diagnostics() const { return diagnostics_; }

private:
    std::string file_;
    std::vector<ConfigDiagnostic> diagnostics_;
};

/// @brief What one record line said about each of its fields.
///
/// Accessors take the field's canonical name from the record table; asking
/// for a field the record does not have is a programming error and throws
/// std::logic_error (the tests catch such slips at once).
class RecordValues {
public:
    /// @brief Empty values (every field at its default) for a record of type @p spec.
    explicit RecordValues(const RecordSpec& spec);

    /// @brief The record type.
    const RecordSpec& spec() const { return *spec_; }

    /// @brief Column of the first character of the field's value where it was first given (0 if not).
    int valueColumn(std::string_view field) const;

    /// @brief Did the line give the field (any part of it), or one @p component (0–2) of it?
    bool isSet(std::string_view field, int component = kWholeField) const;

    /// @brief The whole value as written when given whole, e.g. "(0, 0, 0)"; "" otherwise.
    const std::string& asWritten(std::string_view field) const;

    /// @brief The field's number, or @p fallback when not given.
    Real number(std::string_view field, Real fallback) const;

    /// @brief The field's three numbers; each component not given keeps @p fallback's value.
    Vec3 triple(std::string_view field, const Vec3& fallback) const;

    /// @brief The field's enumerated value from @p choices, or @p fallback when not given.
    template <typename E>
    E choice(std::string_view field, std::span<const Choice<E>> choices, E fallback) const {
        const Slot& s = slot(field);
        return s.choice ? choices[*s.choice].value : fallback;
    }

    /// @brief The field's text as written (a Name, a File, or the word of a choice field), or nullopt when not given.
    std::optional<std::string> text(std::string_view field) const;

    /// @brief A Points field's points, in the order written (empty when not given).
    const std::vector<Vec3>& points(std::string_view field) const;

    /// @brief One part of a field as the line gave it: what comparing two files record by record needs.
    struct WrittenPart {
        bool given = false;                 ///< Did the line set this part?
        std::string text;                   ///< As written: "1/60", "Euler", "ball"; "" when not given.
        int column = 0;                     ///< Column of that text; 0 when not given.
        std::optional<Real> number;         ///< Number, vector and colour fields: the value.
        std::optional<std::size_t> choice;  ///< Word fields: the index into the field kind's choice table.
    };

    /// @brief Field number @p field of the record table; @p component 0–2 for one number of a
    ///        vector or colour, kWholeField for any other kind.
    WrittenPart written(std::size_t field, int component) const;

private:
    /// Everything the file said about one field.
    struct Slot {
        std::array<std::optional<Real>, 3> numbers;  ///< [0] for a number; X, Y, Z (or R, G, B) for triples.
        std::array<int, 3> setAtColumn{};            ///< Token column that set each part; 0 = not set yet.
        std::array<std::string, 3> numberText;       ///< Each number as written, e.g. "1/60".
        std::array<int, 3> numberColumn{};           ///< Column of each number as written.
        int valueColumn = 0;                         ///< Column of the value where first set.
        std::optional<std::size_t> choice;           ///< Index into the kind's choice table.
        std::optional<std::string> text;             ///< A name's text, or a choice's word, as written.
        std::string asWritten;                       ///< The whole triple (or list of points) as written, if given whole.
        std::vector<Vec3> points;                    ///< A Points field's points.
    };

    const Slot& slot(std::string_view field) const;

    const RecordSpec* spec_;
    std::vector<Slot> slots_;  ///< Parallel to spec_->fields.

    friend class RecordReader;
};

/// @brief Reads the fields of @p line (tokens after the record name) as a record of type @p spec.
///
/// Problems go to @p sink; reading continues with the next token after
/// each one, so a single pass finds every problem on the line. A field that
/// had a problem keeps its default, so the values are always safe to use
/// (e.g. a rejected mass never leads to a division by zero).
RecordValues readRecord(const SceneLine& line, const RecordSpec& spec, DiagnosticSink& sink);

}  // namespace stepwise::config
