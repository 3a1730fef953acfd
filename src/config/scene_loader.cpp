/// @file scene_loader.cpp
/// @brief Last stage of loading a scene: record values → objects, plus the checks that span records.
///
/// The pipeline, one file per stage:
///
///     text ──scene_tokenizer──▶ lines of tokens ──record_reader──▶ field values ──here──▶ Scene
///                                                 (field_values parses each value,
///                                                  scene_records says which fields exist)
///
/// This file owns the *defaults* of the format (every one is a named
/// constant below and is listed in docs/config-format.md) and the rules that
/// involve more than one field or record: a sphere's default radius comes
/// from its scale, a plane's normal must not be zero, names are unique, there
/// is at most one World record. Every problem is collected; only a file with
/// none becomes a Scene.
#include "config/scene_loader.hpp"

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>

#include "config/record_reader.hpp"
#include "config/scene_records.hpp"
#include "config/scene_tokenizer.hpp"
#include "config/spelling.hpp"

namespace stepwise {

namespace {

using namespace config;

// ------------------------------------------------------------------ defaults
// The scene format's defaults belong to the format, not to the classes'
// member initialisers: changing a class must not silently change what
// existing scene files mean.

const Vec3 kZero{0, 0, 0};                 ///< Position, velocity, acceleration, rotation: none.
const Vec3 kUnitScale{1, 1, 1};            ///< 1 m in each direction: a sphere of radius 0.5 m.
const Vec3 kDefaultColor{0.8, 0.8, 0.8};   ///< Light grey, visible on dark and light backgrounds.
const Vec3 kDefaultNormal{0, 1, 0};        ///< A floor: the plane faces up (+Y).
const Vec3 kDefaultGravity{0, -kStandardGravity, 0};  ///< m/s², pointing down (−Y).
constexpr Shape kDefaultShape = Shape::Sphere;         ///< The shape every collision test supports.
constexpr Real kDefaultMass = 1;                       ///< kg.
constexpr IntegratorKind kDefaultIntegrator = IntegratorKind::SymplecticEuler;
constexpr BroadphaseKind kDefaultBroadphase = BroadphaseKind::Auto;  ///< Brute force for small scenes (see chooseBroadphase).
constexpr bool kDefaultHollow = false;                 ///< A sphere is a solid ball (I = 2/5 m r^2).

/// A dynamic body's own elasticity and friction: a moderate bounce and grip.
constexpr Real kDynamicElasticity = Real(0.5);
constexpr Real kDynamicFriction = Real(0.5);
/// Static things (kinematic objects, planes) default to 1 because contact
/// coefficients combine by product, e = e_A · e_B and μ = μ_A · μ_B: with 1 on
/// the static side, the dynamic body's own value is the one that acts.
constexpr Real kStaticElasticity = 1;
constexpr Real kStaticFriction = 1;

/// A sphere's Scale is its full size, i.e. its diameter; the radius is half of it.
constexpr Real kRadiusPerDiameter = Real(0.5);
/// Shorter normals than this are treated as zero: normalising them would
/// amplify rounding noise into an arbitrary direction.
constexpr Real kMinNormalLength = Real(1e-9);

const Vec3 kAxisX{1, 0, 0};
const Vec3 kAxisY{0, 1, 0};
const Vec3 kAxisZ{0, 0, 1};

// ------------------------------------------------------------------ helpers

Color toColor(const Vec3& rgb) {
    return Color{static_cast<float>(rgb.x), static_cast<float>(rgb.y), static_cast<float>(rgb.z)};
}

/// Rotation=(rx, ry, rz) in degrees → unit quaternion.
///
/// The angles are applied about the fixed *world* axes: first X by rx, then
/// Y by ry, then Z by rz. Each later rotation multiplies from the left (it
/// acts on the already-rotated body), so q = q_z · q_y · q_x, and
/// q v q⁻¹ applies q_x first.
Quat orientationFromDegrees(const Vec3& degrees) {
    const Quat aboutX = glm::angleAxis(glm::radians(degrees.x), kAxisX);
    const Quat aboutY = glm::angleAxis(glm::radians(degrees.y), kAxisY);
    const Quat aboutZ = glm::angleAxis(glm::radians(degrees.z), kAxisZ);
    return aboutZ * aboutY * aboutX;
}

std::string formatVector(const Vec3& v) {
    std::ostringstream text;
    text << '(' << v.x << ", " << v.y << ", " << v.z << ')';
    return text.str();
}

/// Orders diagnostics as they appear in the file (checks made at the end of
/// a record may point back to an earlier column).
void sortByPosition(std::vector<ConfigDiagnostic>& diagnostics) {
    std::stable_sort(diagnostics.begin(), diagnostics.end(), [](const ConfigDiagnostic& a, const ConfigDiagnostic& b) {
        return a.line != b.line ? a.line < b.line : a.column < b.column;
    });
}

std::string joinMessages(const std::vector<ConfigDiagnostic>& diagnostics) {
    std::string joined;
    for (const ConfigDiagnostic& diagnostic : diagnostics) {
        if (!joined.empty()) joined += '\n';
        joined += diagnostic.message();
    }
    return joined.empty() ? "scene could not be loaded" : joined;
}

// ------------------------------------------------------------------ SceneAssembler

/// Turns tokenized lines into a Scene, one record at a time, collecting every problem.
class SceneAssembler {
public:
    explicit SceneAssembler(const std::string& sourceName) : sink_(sourceName) { scene_.sourcePath = sourceName; }

    void add(const SceneLine& line) {
        const Token& recordName = line.tokens.front();
        const RecordSpec* spec = findRecord(recordName.text);
        if (spec == nullptr) {
            reportUnknownRecord(recordName, line.number);
            return;
        }
        // Counted before anything can fail, so default names never depend on errors elsewhere.
        const int index = counts_[static_cast<std::size_t>(spec->kind)]++;
        if (line.parenthesisProblem) {
            // Unbalanced parentheses make the field boundaries unreliable: report once, skip the line.
            reportParenthesisProblem(line, *spec);
            return;
        }
        const RecordValues values = readRecord(line, *spec, sink_);
        switch (spec->kind) {
            case RecordKind::DynamicObject: addDynamic(values, line, index); break;
            case RecordKind::KinematicsObject: addKinematic(values, line, index); break;
            case RecordKind::CollisionPlane: addPlane(values, line, index); break;
            case RecordKind::World: setWorld(values, line); break;
        }
    }

    /// The finished Scene, or ConfigError with every problem found.
    Scene finish() {
        if (sink_.diagnostics().empty()) return std::move(scene_);
        std::vector<ConfigDiagnostic> diagnostics = sink_.diagnostics();
        sortByPosition(diagnostics);
        throw ConfigError(std::move(diagnostics));
    }

private:
    void addDynamic(const RecordValues& values, const SceneLine& line, int index) {
        DynamicObject body;
        body.name = claimName(values, line, index);
        body.shape = values.choice<Shape>("Shape", kShapeChoices, kDefaultShape);
        body.color = toColor(values.triple("Color", kDefaultColor));
        body.position = values.triple("Position", kZero);
        body.velocity = values.triple("Velocity", kZero);
        body.constantAcceleration = values.triple("Acceleration", kZero);
        body.scale = values.triple("Scale", kUnitScale);
        body.radius = values.number("Radius", kRadiusPerDiameter * body.scale.x);
        body.setMass(values.number("Mass", kDefaultMass));
        body.elasticity = values.number("Elasticity", kDynamicElasticity);
        body.friction = values.number("Friction", kDynamicFriction);
        body.orientation = orientationFromDegrees(values.triple("Rotation", kZero));
        body.angularVelocity = values.triple("AngularVelocity", kZero);
        body.hollow = values.choice<bool>("Hollow", kBooleanChoices, kDefaultHollow);
        if (body.hollow && body.shape == Shape::Box) {
            // A hollow box would need a wall thickness; rather than guess one, refuse.
            sink_.report(line.number, values.valueColumn("Hollow"), "Hollow", "false for a Box",
                         values.text("Hollow").value_or("true"),
                         "only a sphere can be hollow (a thin shell, I = 2/3 m r^2); boxes are solid");
        }
        scene_.dynamics.push_back(std::move(body));
    }

    void addKinematic(const RecordValues& values, const SceneLine& line, int index) {
        KinematicsObject mover;
        mover.name = claimName(values, line, index);
        // Set explicitly: the class's own default shape is Box, the format's is Sphere.
        mover.shape = values.choice<Shape>("Shape", kShapeChoices, kDefaultShape);
        mover.color = toColor(values.triple("Color", kDefaultColor));
        mover.position = values.triple("Position", kZero);
        mover.scale = values.triple("Scale", kUnitScale);
        mover.radius = values.number("Radius", kRadiusPerDiameter * mover.scale.x);
        mover.velocity = values.triple("Velocity", kZero);
        mover.angularVelocity = values.triple("AngularVelocity", kZero);
        mover.orientation = orientationFromDegrees(values.triple("Rotation", kZero));
        mover.elasticity = values.number("Elasticity", kStaticElasticity);
        mover.friction = values.number("Friction", kStaticFriction);
        scene_.kinematics.push_back(std::move(mover));
    }

    void addPlane(const RecordValues& values, const SceneLine& line, int index) {
        CollisionPlane plane;
        plane.name = claimName(values, line, index);
        plane.position = values.triple("Position", kZero);
        plane.color = toColor(values.triple("Color", kDefaultColor));
        plane.elasticity = values.number("Elasticity", kStaticElasticity);
        plane.friction = values.number("Friction", kStaticFriction);

        const Vec3 normal = values.triple("Normal", kDefaultNormal);
        const Real length = glm::length(normal);
        if (length < kMinNormalLength) {
            const std::string& written = values.asWritten("Normal");
            sink_.report(line.number, values.valueColumn("Normal"), "Normal", "a non-zero vector",
                         written.empty() ? formatVector(normal) : written,
                         "the normal gives the direction the plane faces, e.g. (0, 1, 0) for a floor");
        } else {
            plane.normal = normal / length;  // the collision code relies on a unit normal
        }
        scene_.planes.push_back(std::move(plane));
    }

    void setWorld(const RecordValues& values, const SceneLine& line) {
        const Token& recordName = line.tokens.front();
        if (worldLine_ != 0) {
            // Its fields were still checked by readRecord, so their problems are reported too.
            sink_.report(line.number, recordName.column, "World", "at most one World record",
                         std::string(recordName.text),
                         "the World record on line " + std::to_string(worldLine_) + " already sets the simulation");
            return;
        }
        worldLine_ = line.number;
        WorldSettings& settings = scene_.settings;
        settings.gravity = values.triple("Gravity", kDefaultGravity);
        settings.timeStep = values.number("TimeStep", kDefaultTimeStep);
        settings.integrator = values.choice<IntegratorKind>("Integrator", kIntegratorChoices, kDefaultIntegrator);
        settings.duration = values.number("Duration", kDefaultDuration);
        settings.broadphase = values.choice<BroadphaseKind>("Broadphase", kBroadphaseChoices, kDefaultBroadphase);
    }

    /// The object's name: its Name field, or the record type plus its index
    /// within that type ("DynamicObject0"). Names are unique ignoring case, so
    /// "Ball" and "ball" cannot both exist; the second one is reported.
    std::string claimName(const RecordValues& values, const SceneLine& line, int index) {
        const std::optional<std::string> given = values.text("Name");
        std::string name = given ? *given : std::string(values.spec().name) + std::to_string(index);
        const int column = given ? values.valueColumn("Name") : line.tokens.front().column;

        const auto [first, inserted] = names_.try_emplace(toLower(name), NameUse{name, values.spec().name, line.number});
        if (!inserted) {
            const NameUse& earlier = first->second;
            std::string hint = quoted(earlier.name) + " is already the name of the " + std::string(earlier.record) +
                               " on line " + std::to_string(earlier.line);
            if (!given) hint += "; give this object its own Name=...";
            sink_.report(line.number, column, "Name", "a name not used before", name, std::move(hint));
        }
        return name;
    }

    void reportUnknownRecord(const Token& recordName, int line) {
        std::vector<std::string> known;
        for (const RecordSpec& record : allRecords()) known.emplace_back(record.name);
        std::string hint;
        if (const auto suggestion = closestMatch(recordName.text, known)) {
            hint = "did you mean '" + *suggestion + "'?";
        } else if (recordName.text.empty()) {
            hint = "every line starts with a record name";
        }
        std::string expected = "a record name (";
        for (std::size_t i = 0; i < known.size(); ++i) expected += (i > 0 ? ", " : "") + known[i];
        sink_.report(line, recordName.column, "record", expected + ")", std::string(recordName.text), std::move(hint));
    }

    void reportParenthesisProblem(const SceneLine& line, const RecordSpec& spec) {
        const ParenthesisProblem& problem = *line.parenthesisProblem;
        // The token holding the parenthesis says which field the problem is in.
        const auto holder = std::find_if(line.tokens.begin(), line.tokens.end(), [&](const Token& token) {
            return problem.column >= token.column && problem.column < token.column + static_cast<int>(token.text.size());
        });
        std::string field(spec.name);
        std::string found;
        if (holder != line.tokens.end()) {
            if (const auto named = splitNamed(*holder)) {
                const auto ref = findField(spec, named->name.text);
                field = ref ? fieldName(spec.fields[ref->field], ref->component) : std::string(named->name.text);
            }
            found = problem.unclosed ? std::string(holder->text.substr(static_cast<std::size_t>(problem.column - holder->column)))
                                     : std::string(holder->text);
        }
        if (problem.unclosed) {
            sink_.report(line.number, problem.column, field, "a ')' to close this '('", found,
                         "a vector is written in parentheses, e.g. Position=(0, 5, 0)");
        } else {
            sink_.report(line.number, problem.column, field, "a '(' before this ')'", found,
                         "a vector is written in parentheses, e.g. Position=(0, 5, 0)");
        }
    }

    static std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

    /// Where a name was first used, for the duplicate-name hint.
    struct NameUse {
        std::string name;         ///< As first written.
        std::string_view record;  ///< Record type that used it.
        int line = 0;             ///< Line of that record.
    };

    Scene scene_;
    DiagnosticSink sink_;
    std::map<std::string, NameUse> names_;  ///< Lower-cased name → first use.
    std::array<int, 4> counts_{};           ///< Records seen so far, per RecordKind (for default names).
    int worldLine_ = 0;                     ///< Line of the World record; 0 before one is seen.
};

}  // namespace

std::string ConfigDiagnostic::message() const {
    std::string text = file;
    if (line > 0) text += ":" + std::to_string(line) + ":" + std::to_string(column);
    text += ": error: ";
    if (!field.empty()) text += field + ": ";
    if (expected.empty()) return text + hint;  // e.g. a file that could not be opened
    text += "expected " + expected + ", found '" + found + "'";
    if (!hint.empty()) text += "; " + hint;
    return text;
}

ConfigError::ConfigError(std::vector<ConfigDiagnostic> diagnostics)
    : std::runtime_error(joinMessages(diagnostics)), diagnostics_(std::move(diagnostics)) {}

Scene parseScene(std::string_view text, const std::string& sourceName) {
    SceneAssembler assembler(sourceName);
    for (const SceneLine& line : tokenizeScene(text)) assembler.add(line);
    return assembler.finish();
}

Scene loadSceneFile(const std::string& path) {
    const auto cannotOpen = [&path](const std::string& reason) {
        ConfigDiagnostic diagnostic;
        diagnostic.file = path;
        diagnostic.found = path;
        diagnostic.hint = "could not open the scene file (" + reason + ")";
        return ConfigError({diagnostic});
    };
    std::error_code status;
    if (std::filesystem::is_directory(path, status)) throw cannotOpen("it is a directory");

    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw cannotOpen(errno != 0 ? std::generic_category().message(errno) : "unknown reason");
    std::ostringstream contents;
    contents << in.rdbuf();
    if (in.bad()) throw cannotOpen("read error");
    return parseScene(contents.str(), path);
}

}  // namespace stepwise
