/// @file scene_records.hpp
/// @brief The scene-file vocabulary as data: which records exist and which fields each takes.
///
/// The tables themselves are in scene_records.cpp, one per record, one row
/// per field: read them to learn the file format. The loader never spells a
/// field's position or range anywhere else, so the tables, the parser and
/// docs/config-format.md cannot drift apart without a test noticing.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "config/field_values.hpp"
#include "forces/region.hpp"
#include "objects/game_object.hpp"
#include "world/expectations.hpp"
#include "core/world_settings.hpp"

namespace stepwise::config {

/// @brief How a field's value is written in the file.
enum class FieldKind : std::uint8_t {
    Number,      ///< One number: `Mass=2`.
    Vector,      ///< Three numbers with components X, Y, Z: `Position=(0, 5, 0)` or `PositionY=5`.
    Color,       ///< Three numbers with components R, G, B: `Color=(1, 0, 0)` or `ColorR=1`.
    Shape,       ///< A word from kShapeChoices.
    Integrator,  ///< A word from kIntegratorChoices.
    Solver,      ///< A word from kSolverChoices.
    Broadphase,  ///< A word from kBroadphaseChoices.
    Boolean,     ///< Yes or no, a word from kBooleanChoices: `Hollow=true`, `Hollow=yes`, `Hollow=1`.
    Name,        ///< An object name (see parseName()).
    Compare,     ///< A word from kCompareChoices: `Compare=AtLeast` (Expect records).
    Narrowphase, ///< A word from kNarrowphaseChoices.
    ContactOrder, ///< A word from kContactOrderChoices.
    Points,      ///< A list of points, each a vector: `Vertices=(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)`.
    File,        ///< A file's path, relative to the scene file's folder: `File=models/ramp.obj`.
    RegionShape, ///< A word from kRegionShapeChoices (Region records).
    Effect,      ///< A word from kEffectChoices (Region records).
    DragLaw,     ///< A word from kDragLawChoices (Region records).
    Combine,     ///< A word from kCombineChoices: `FrictionCombine=GeometricMean`.
};

/// @brief firstPositional of a field that can only be given as `Field=Value`.
inline constexpr int kNamedOnly = -1;

/// @brief One field of a record: one row of a record table.
struct FieldSpec {
    std::string_view name;    ///< Canonical spelling, e.g. "Position".
    FieldKind kind;           ///< How the value is written.
    int firstPositional;      ///< Index among the record's positional values of the value (or
                              ///< of its first component), or kNamedOnly.
    Range range;              ///< Valid values of the number, or of each component.
    std::string_view hint{};  ///< Advice shown when a value is out of range ("" if none).
};

/// @brief The kinds of line a scene file may contain: objects, the World, checks, forces, joints.
enum class RecordKind : std::uint8_t {
    DynamicObject,     ///< A simulated body.
    KinematicsObject,  ///< A body with prescribed motion.
    CollisionPlane,    ///< An infinite plane.
    World,             ///< The simulation settings.
    Expect,            ///< An outcome the run must reach (src/world/expectations.hpp).
    Spring,            ///< A Hooke spring and damper between two anchors (src/forces/spring.hpp).
    Attractor,         ///< A fixed inverse-square pull (src/forces/attractor.hpp).
    DistanceJoint,     ///< A rigid rod between two bodies, or a body and the world.
    Rope,              ///< A rope: a maximum distance.
    BallJoint,         ///< A shared point.
    HingeJoint,        ///< A shared point and axis; limits, motor.
    AngularMotor,      ///< A torque-limited spin about one axis.
    MayChange,         ///< A field a student may edit (`stepwise grade --expect` compares the rest with the starter).
    Part,              ///< One part of a `Shape=Compound` body.
    Region,            ///< A volume with an effect on the bodies inside (src/forces/region.hpp).
    Material,          ///< Density, friction and elasticity that objects share (src/objects/materials.hpp).
    MaterialPair,      ///< The friction and elasticity of contacts between two materials.
    Space,             ///< A simulation of its own, beside the others (src/world/spaces.hpp).
    SoftBody,          ///< A pressure soft body: nodes, springs and a gas inside (src/objects/soft_body.hpp).
};

/// @brief Number of RecordKind values.
inline constexpr std::size_t kRecordKindCount = 19;

/// @brief One record type: its name and its field table.
struct RecordSpec {
    RecordKind kind;                    ///< Which record this is.
    std::string_view name;              ///< Canonical spelling, e.g. "DynamicObject".
    std::span<const FieldSpec> fields;  ///< Every field it accepts.
};

/// @brief Component given by a field reference that names the whole field.
inline constexpr int kWholeField = -1;

/// @brief A field, or one component of it, as named in a file ("Position", "PositionY").
struct FieldRef {
    std::size_t field = 0;       ///< Index into RecordSpec::fields.
    int component = kWholeField; ///< 0–2 for X/Y/Z (R/G/B), or kWholeField.
};

/// @brief Accepted spellings of Shape (any case). `Cube` is a synonym of `Box`.
extern const std::array<Choice<Shape>, 8> kShapeChoices;

/// @brief Accepted spellings of IntegratorKind (any case), with synonyms.
extern const std::array<Choice<IntegratorKind>, 6> kIntegratorChoices;

/// @brief Accepted spellings of SolverKind (any case).
extern const std::array<Choice<SolverKind>, 2> kSolverChoices;
/// @brief Accepted spellings of BroadphaseKind (any case), with synonyms.
extern const std::array<Choice<BroadphaseKind>, 10> kBroadphaseChoices;

/// @brief Accepted spellings of a Boolean field (any case): true/false, yes/no, 1/0.
extern const std::array<Choice<bool>, 6> kBooleanChoices;

/// @brief Accepted spellings of ExpectCompare (any case): Within, AtLeast, AtMost.
extern const std::array<Choice<ExpectCompare>, 3> kCompareChoices;

/// @brief Accepted spellings of NarrowphaseKind (any case): Auto, GjkEpa, Mpr.
extern const std::array<Choice<NarrowphaseKind>, 3> kNarrowphaseChoices;

/// @brief Accepted spellings of ContactOrder (any case): Colours (or Colors), Found.
extern const std::array<Choice<ContactOrder>, 3> kContactOrderChoices;

/// @brief Accepted spellings of RegionShape (any case): Box, Sphere, HalfSpace.
extern const std::array<Choice<RegionShape>, 3> kRegionShapeChoices;

/// @brief Accepted spellings of RegionEffect (any case): Drag, Wind, Gravity, Buoyancy, RandomForce, Kill, Conveyor.
extern const std::array<Choice<RegionEffect>, 7> kEffectChoices;

/// @brief Accepted spellings of DragLaw (any case): Linear, Quadratic.
extern const std::array<Choice<DragLaw>, 2> kDragLawChoices;

/// @brief Accepted spellings of CombineRule (any case): Product, Min, Max, Average, GeometricMean.
extern const std::array<Choice<CombineRule>, 5> kCombineChoices;

/// @brief Every record type, in the order the documentation lists them.
std::span<const RecordSpec> allRecords();

/// @brief The record called @p name (ignoring case), or nullptr.
const RecordSpec* findRecord(std::string_view name);

/// @brief The field or component of @p record called @p name (ignoring case).
std::optional<FieldRef> findField(const RecordSpec& record, std::string_view name);

/// @brief How many numbers (or words) a field of this kind holds: 3 for vectors, else 1.
std::size_t componentCount(FieldKind kind);

/// @brief Canonical name of a field or of one of its components: "Position", "PositionY", "ColorR".
std::string fieldName(const FieldSpec& field, int component);

/// @brief How many values @p record accepts positionally (0 for World).
int positionalCount(const RecordSpec& record);

/// @brief The field (and component) that positional value number @p index fills.
/// @pre 0 ≤ index < positionalCount(record).
FieldRef positionalField(const RecordSpec& record, int index);

/// @brief Every spelling a file may use for a field of @p record (fields and components).
std::vector<std::string> fieldSpellings(const RecordSpec& record);

/// @brief "Shape, Color, Position, …": the record's field names for messages.
std::string fieldList(const RecordSpec& record);

}  // namespace stepwise::config
