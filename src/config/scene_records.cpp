/// @file scene_records.cpp
/// @brief The record tables: every field of every record, its position, kind and valid range.
///
/// How to read a table row:
///
///     {"Mass", FieldKind::Number, 17, Range::Positive, kMassHint}
///       │      │                  │   │                └ advice when out of range
///       │      │                  │   └ valid values
///       │      │                  └ positional index, counted from 0 after the record
///       │      │                    name (Mass is the 18th value), or kNamedOnly
///       │      └ how it is written: a number, a vector (X, Y, Z), a colour (R, G, B), a word, a name
///       └ the name used in `Mass=2`
///
/// A vector field's components take consecutive positional indices, so
/// Position at 4 means PositionX = 4, PositionY = 5, PositionZ = 6.
/// Defaults are not here: they live with the code that builds each object
/// (scene_loader.cpp), because some depend on other fields (a sphere's radius
/// on its scale).
#include "config/scene_records.hpp"

#include <algorithm>
#include <stdexcept>

#include "config/spelling.hpp"

namespace stepwise::config {

namespace {

constexpr std::string_view kMassHint =
    "every simulated body needs a positive mass; for something that never moves, use a "
    "KinematicsObject or a CollisionPlane";
constexpr std::string_view kElasticityHint =
    "0 means the contact absorbs all bounce, 1 means a perfectly elastic bounce";
constexpr std::string_view kFrictionHint = "0 means frictionless; friction cannot be negative";
constexpr std::string_view kSizeHint = "sizes are in metres and must be positive";
constexpr std::string_view kTimeHint = "times are in seconds and must be positive, e.g. 1/60";

// clang-format off
/// DynamicObject: the classic 19 positional values, then named-only extras.
constexpr FieldSpec kDynamicFields[] = {
    {"Shape",           FieldKind::Shape,       0, Range::Any},
    {"Color",           FieldKind::Color,       1, Range::UnitInterval},             // 0–1 per channel
    {"Position",        FieldKind::Vector,      4, Range::Any},                      // m
    {"Velocity",        FieldKind::Vector,      7, Range::Any},                      // m/s
    {"Acceleration",    FieldKind::Vector,     10, Range::Any},                      // m/s², added to gravity
    {"Scale",           FieldKind::Vector,     13, Range::Positive, kSizeHint},      // m, full edge lengths
    {"Radius",          FieldKind::Number,     16, Range::Positive, kSizeHint},      // m
    {"Mass",            FieldKind::Number,     17, Range::Positive, kMassHint},      // kg
    {"Elasticity",      FieldKind::Number,     18, Range::UnitInterval, kElasticityHint},
    {"Name",            FieldKind::Name,       kNamedOnly, Range::Any},
    {"Friction",        FieldKind::Number,     kNamedOnly, Range::NonNegative, kFrictionHint},
    {"Rotation",        FieldKind::Vector,     kNamedOnly, Range::Any},              // degrees about X, then Y, then Z
    {"AngularVelocity", FieldKind::Vector,     kNamedOnly, Range::Any},              // rad/s
    {"Hollow",          FieldKind::Boolean,    kNamedOnly, Range::Any},              // sphere only: a thin shell
};

/// KinematicsObject: 10 positional values (no velocity, mass or radius among them).
constexpr FieldSpec kKinematicFields[] = {
    {"Shape",           FieldKind::Shape,       0, Range::Any},
    {"Color",           FieldKind::Color,       1, Range::UnitInterval},
    {"Position",        FieldKind::Vector,      4, Range::Any},                      // m
    {"Scale",           FieldKind::Vector,      7, Range::Positive, kSizeHint},      // m
    {"Name",            FieldKind::Name,       kNamedOnly, Range::Any},
    {"Velocity",        FieldKind::Vector,     kNamedOnly, Range::Any},              // m/s, constant
    {"AngularVelocity", FieldKind::Vector,     kNamedOnly, Range::Any},              // rad/s, constant
    {"Rotation",        FieldKind::Vector,     kNamedOnly, Range::Any},              // degrees
    {"Radius",          FieldKind::Number,     kNamedOnly, Range::Positive, kSizeHint},
    {"Elasticity",      FieldKind::Number,     kNamedOnly, Range::UnitInterval, kElasticityHint},
    {"Friction",        FieldKind::Number,     kNamedOnly, Range::NonNegative, kFrictionHint},
};

/// CollisionPlane: a point and a normal, 6 positional values.
constexpr FieldSpec kPlaneFields[] = {
    {"Position",        FieldKind::Vector,      0, Range::Any},                      // m, any point on the plane
    {"Normal",          FieldKind::Vector,      3, Range::Any},                      // normalised on load
    {"Name",            FieldKind::Name,       kNamedOnly, Range::Any},
    {"Color",           FieldKind::Color,      kNamedOnly, Range::UnitInterval},
    {"Elasticity",      FieldKind::Number,     kNamedOnly, Range::UnitInterval, kElasticityHint},
    {"Friction",        FieldKind::Number,     kNamedOnly, Range::NonNegative, kFrictionHint},
};

/// World: simulation settings, named fields only.
constexpr FieldSpec kWorldFields[] = {
    {"Gravity",         FieldKind::Vector,     kNamedOnly, Range::Any},              // m/s²
    {"TimeStep",        FieldKind::Number,     kNamedOnly, Range::Positive, kTimeHint}, // s
    {"Integrator",      FieldKind::Integrator, kNamedOnly, Range::Any},
    {"Duration",        FieldKind::Number,     kNamedOnly, Range::Positive, kTimeHint}, // s
    {"Broadphase",      FieldKind::Broadphase, kNamedOnly, Range::Any},
};

constexpr RecordSpec kRecords[] = {
    {RecordKind::DynamicObject,    "DynamicObject",    kDynamicFields},
    {RecordKind::KinematicsObject, "KinematicsObject", kKinematicFields},
    {RecordKind::CollisionPlane,   "CollisionPlane",   kPlaneFields},
    {RecordKind::World,            "World",            kWorldFields},
};
// clang-format on

/// Component letters of the two three-number kinds.
constexpr std::string_view kVectorAxes = "XYZ";
constexpr std::string_view kColorChannels = "RGB";

/// The letters that name a field's components ("" for single-value kinds).
std::string_view componentLetters(FieldKind kind) {
    switch (kind) {
        case FieldKind::Vector: return kVectorAxes;
        case FieldKind::Color: return kColorChannels;
        default: return "";
    }
}

}  // namespace

const std::array<Choice<Shape>, 3> kShapeChoices = {{
    {"Sphere", Shape::Sphere},
    {"Box", Shape::Box},
    {"Cube", Shape::Box},  // what most people call a box with equal edges
}};

const std::array<Choice<IntegratorKind>, 6> kIntegratorChoices = {{
    {"Euler", IntegratorKind::ExplicitEuler},
    {"ExplicitEuler", IntegratorKind::ExplicitEuler},
    {"SymplecticEuler", IntegratorKind::SymplecticEuler},
    {"SemiImplicitEuler", IntegratorKind::SymplecticEuler},
    {"Verlet", IntegratorKind::Verlet},
    {"VelocityVerlet", IntegratorKind::Verlet},
}};

const std::array<Choice<BroadphaseKind>, 8> kBroadphaseChoices = {{
    {"Auto", BroadphaseKind::Auto},
    {"BruteForce", BroadphaseKind::BruteForce},
    {"SweepAndPrune", BroadphaseKind::SweepAndPrune},
    {"SAP", BroadphaseKind::SweepAndPrune},
    {"AabbTree", BroadphaseKind::AabbTree},
    {"DynamicTree", BroadphaseKind::AabbTree},
    {"Grid", BroadphaseKind::Grid},
    {"UniformGrid", BroadphaseKind::Grid},
}};

const std::array<Choice<bool>, 6> kBooleanChoices = {{
    {"true", true},
    {"false", false},
    {"yes", true},
    {"no", false},
    {"1", true},
    {"0", false},
}};

std::span<const RecordSpec> allRecords() { return kRecords; }

const RecordSpec* findRecord(std::string_view name) {
    for (const RecordSpec& record : kRecords) {
        if (equalsIgnoreCase(name, record.name)) return &record;
    }
    return nullptr;
}

std::size_t componentCount(FieldKind kind) { return componentLetters(kind).empty() ? 1 : 3; }

std::string fieldName(const FieldSpec& field, int component) {
    std::string name(field.name);
    if (component != kWholeField) name += componentLetters(field.kind).at(static_cast<std::size_t>(component));
    return name;
}

std::optional<FieldRef> findField(const RecordSpec& record, std::string_view name) {
    for (std::size_t i = 0; i < record.fields.size(); ++i) {
        const FieldSpec& field = record.fields[i];
        if (equalsIgnoreCase(name, field.name)) return FieldRef{i, kWholeField};
        // "PositionY": the field's name followed by one component letter.
        const std::string_view letters = componentLetters(field.kind);
        const bool fieldThenOneLetter = name.size() == field.name.size() + 1 &&
                                        equalsIgnoreCase(name.substr(0, field.name.size()), field.name);
        if (!letters.empty() && fieldThenOneLetter) {
            const std::size_t component = toLower(letters).find(toLower(name.substr(field.name.size())));
            if (component != std::string::npos) return FieldRef{i, static_cast<int>(component)};
        }
    }
    return std::nullopt;
}

int positionalCount(const RecordSpec& record) {
    int count = 0;
    for (const FieldSpec& field : record.fields) {
        if (field.firstPositional == kNamedOnly) continue;
        count = std::max(count, field.firstPositional + static_cast<int>(componentCount(field.kind)));
    }
    return count;
}

FieldRef positionalField(const RecordSpec& record, int index) {
    for (std::size_t i = 0; i < record.fields.size(); ++i) {
        const FieldSpec& field = record.fields[i];
        if (field.firstPositional == kNamedOnly) continue;
        const int offset = index - field.firstPositional;
        if (offset >= 0 && offset < static_cast<int>(componentCount(field.kind))) {
            return FieldRef{i, componentLetters(field.kind).empty() ? kWholeField : offset};
        }
    }
    throw std::logic_error("positionalField: " + std::string(record.name) + " has no positional value " +
                           std::to_string(index));
}

std::vector<std::string> fieldSpellings(const RecordSpec& record) {
    std::vector<std::string> spellings;
    for (const FieldSpec& field : record.fields) {
        spellings.push_back(fieldName(field, kWholeField));
        for (std::size_t c = 0; c < componentLetters(field.kind).size(); ++c) {
            spellings.push_back(fieldName(field, static_cast<int>(c)));
        }
    }
    return spellings;
}

std::string fieldList(const RecordSpec& record) {
    std::string list;
    for (const FieldSpec& field : record.fields) {
        if (!list.empty()) list += ", ";
        list += field.name;
    }
    return list;
}

}  // namespace stepwise::config
