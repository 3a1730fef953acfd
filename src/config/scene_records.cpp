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
#include <iterator>
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
constexpr std::string_view kSizeHint = "sizes are in metres, from a micrometre to a thousand kilometres";
constexpr std::string_view kTimeHint = "times are in seconds and must be positive, e.g. 1/60";
constexpr std::string_view kMomentHint = "moments are in seconds from the start of the run, 0 or later";
constexpr std::string_view kToleranceHint = "a tolerance is the allowed difference, in the quantity's unit, 0 or more";
constexpr std::string_view kApexHint = "apexes are counted from 1: Apex=3 is the third time the body stops rising";
constexpr std::string_view kStiffnessHint = "the spring constant k is in N/m; 0 leaves only the damper";
constexpr std::string_view kDampingHint = "the damper constant c is in N*s/m; 0 means no damping";
constexpr std::string_view kRestLengthHint = "the rest length is in metres; leave it out to use the starting distance";
constexpr std::string_view kMuHint =
    "Mu = G*M is the gravitational parameter in m^3/s^2, e.g. 3.986e14 for the Earth; it must be positive";
constexpr std::string_view kForceHint = "a force in newtons; leave MaxForce out for a joint that never breaks";
constexpr std::string_view kLengthHint = "a length in metres; leave Length out to use the distance at the start";
constexpr std::string_view kTorqueHint = "a torque in newton metres; leave MaxMotorTorque out for an unlimited motor";
constexpr std::string_view kDragHint =
    "a drag coefficient: N*s/m under Law=Linear (F = -c*v), kg/m under Law=Quadratic (F = -c*|v|*v); 0 or more";
constexpr std::string_view kFluidDensityHint = "a fluid's density in kg/m^3, e.g. 1000 for water, 1.2 for air";
constexpr std::string_view kStrengthHint = "the largest random force, in newtons";
constexpr std::string_view kSeedHint = "a whole number from 0 to 2^53; the same seed gives the same run";
constexpr std::string_view kTimeScaleHint =
    "simulated seconds per second of the shared clock: 0.5 runs at half speed, 2 at double; it must be positive";
constexpr std::string_view kDensityHint =
    "density is in kg/m^3 (water 1000, wood about 600, steel 7850); the mass is density x the shape's volume";
constexpr std::string_view kGasHint =
    "Pressure is the gas's nRT in joules (= P*V): the pressure is nRT / V, so 0 leaves the springs alone";
constexpr std::string_view kHeightHint =
    "Height is a capsule's segment between its two ball centres, or a cylinder's full length, in metres";

// clang-format off
/// DynamicObject: the classic 19 positional values, then named-only extras.
constexpr FieldSpec kDynamicFields[] = {
    {"Shape",           FieldKind::Shape,       0, Range::Any},
    {"Color",           FieldKind::Color,       1, Range::UnitInterval},             // 0–1 per channel
    {"Position",        FieldKind::Vector,      4, Range::Any},                      // m
    {"Velocity",        FieldKind::Vector,      7, Range::Any},                      // m/s
    {"Acceleration",    FieldKind::Vector,     10, Range::Any},                      // m/s², added to gravity
    {"Scale",           FieldKind::Vector,     13, Range::Size, kSizeHint},          // m, full edge lengths
    {"Radius",          FieldKind::Number,     16, Range::Radius, kSizeHint},        // m
    {"Mass",            FieldKind::Number,     17, Range::Mass, kMassHint},          // kg
    {"Elasticity",      FieldKind::Number,     18, Range::UnitInterval, kElasticityHint},
    {"Name",            FieldKind::Name,       kNamedOnly, Range::Any},
    {"Friction",        FieldKind::Number,     kNamedOnly, Range::NonNegative, kFrictionHint},
    {"Rotation",        FieldKind::Vector,     kNamedOnly, Range::Any},              // degrees about X, then Y, then Z
    {"AngularVelocity", FieldKind::Vector,     kNamedOnly, Range::Any},              // rad/s
    {"Hollow",          FieldKind::Boolean,    kNamedOnly, Range::Any},              // sphere only: a thin shell
    {"Height",          FieldKind::Number,     kNamedOnly, Range::Length, kHeightHint}, // m, Capsule and Cylinder
    {"Vertices",        FieldKind::Points,     kNamedOnly, Range::Any},              // m, Hull: the points it wraps
    {"File",            FieldKind::File,       kNamedOnly, Range::Any},              // an OBJ file: Hull points
    {"Space",           FieldKind::Name,       kNamedOnly, Range::Any},              // a Space record's Name
    {"Material",        FieldKind::Name,       kNamedOnly, Range::Any},              // a Material's Name
    {"Density",         FieldKind::Number,     kNamedOnly, Range::Positive, kDensityHint}, // kg/m³, instead of Mass
};

/// KinematicsObject: 10 positional values (no velocity, mass or radius among them).
constexpr FieldSpec kKinematicFields[] = {
    {"Shape",           FieldKind::Shape,       0, Range::Any},
    {"Color",           FieldKind::Color,       1, Range::UnitInterval},
    {"Position",        FieldKind::Vector,      4, Range::Any},                      // m
    {"Scale",           FieldKind::Vector,      7, Range::Size, kSizeHint},          // m
    {"Name",            FieldKind::Name,       kNamedOnly, Range::Any},
    {"Velocity",        FieldKind::Vector,     kNamedOnly, Range::Any},              // m/s, constant
    {"AngularVelocity", FieldKind::Vector,     kNamedOnly, Range::Any},              // rad/s, constant
    {"Rotation",        FieldKind::Vector,     kNamedOnly, Range::Any},              // degrees
    {"Radius",          FieldKind::Number,     kNamedOnly, Range::Radius, kSizeHint},
    {"Elasticity",      FieldKind::Number,     kNamedOnly, Range::UnitInterval, kElasticityHint},
    {"Friction",        FieldKind::Number,     kNamedOnly, Range::NonNegative, kFrictionHint},
    {"Height",          FieldKind::Number,     kNamedOnly, Range::Length, kHeightHint}, // m, Capsule and Cylinder
    {"Vertices",        FieldKind::Points,     kNamedOnly, Range::Any},              // m, Hull
    {"File",            FieldKind::File,       kNamedOnly, Range::Any},              // an OBJ file: Hull points, Mesh triangles
    {"Space",           FieldKind::Name,       kNamedOnly, Range::Any},              // a Space record's Name
    {"Material",        FieldKind::Name,       kNamedOnly, Range::Any},              // a Material's Name
};

/// Part: one part of a Shape=Compound body (docs/config-format.md#part), named fields only.
/// Position and Rotation are in the body's frame as the scene writes it (its Position and
/// Rotation), before the loader moves the body to its centre of mass.
constexpr FieldSpec kPartFields[] = {
    {"Name",            FieldKind::Name,       kNamedOnly, Range::Any},
    {"Body",            FieldKind::Name,       kNamedOnly, Range::Any},              // a Shape=Compound object, required
    {"Shape",           FieldKind::Shape,      kNamedOnly, Range::Any},              // Sphere, Box, Capsule, Cylinder, Hull
    {"Position",        FieldKind::Vector,     kNamedOnly, Range::Any},              // m, in the body's frame
    {"Rotation",        FieldKind::Vector,     kNamedOnly, Range::Any},              // degrees, in the body's frame
    {"Scale",           FieldKind::Vector,     kNamedOnly, Range::Size, kSizeHint},  // m
    {"Radius",          FieldKind::Number,     kNamedOnly, Range::Radius, kSizeHint},// m
    {"Height",          FieldKind::Number,     kNamedOnly, Range::Length, kHeightHint}, // m
    {"Vertices",        FieldKind::Points,     kNamedOnly, Range::Any},              // m, Hull
    {"File",            FieldKind::File,       kNamedOnly, Range::Any},              // an OBJ file: Hull points
    {"Mass",            FieldKind::Number,     kNamedOnly, Range::Mass, kMassHint},  // kg; see the Part section
    {"Density",         FieldKind::Number,     kNamedOnly, Range::Positive, kDensityHint}, // kg/m³, instead of Mass
    {"Material",        FieldKind::Name,       kNamedOnly, Range::Any},              // a Material's Name: density, μ, e
};

/// CollisionPlane: a point and a normal, 6 positional values.
constexpr FieldSpec kPlaneFields[] = {
    {"Position",        FieldKind::Vector,      0, Range::Any},                      // m, any point on the plane
    {"Normal",          FieldKind::Vector,      3, Range::Any},                      // normalised on load
    {"Name",            FieldKind::Name,       kNamedOnly, Range::Any},
    {"Color",           FieldKind::Color,      kNamedOnly, Range::UnitInterval},
    {"Elasticity",      FieldKind::Number,     kNamedOnly, Range::UnitInterval, kElasticityHint},
    {"Friction",        FieldKind::Number,     kNamedOnly, Range::NonNegative, kFrictionHint},
    {"Space",           FieldKind::Name,       kNamedOnly, Range::Any},              // a Space record's Name
    {"Material",        FieldKind::Name,       kNamedOnly, Range::Any},              // a Material's Name
};

/// World: simulation settings, named fields only.
constexpr FieldSpec kWorldFields[] = {
    {"Gravity",         FieldKind::Vector,     kNamedOnly, Range::Any},              // m/s²
    {"TimeStep",        FieldKind::Number,     kNamedOnly, Range::Positive, kTimeHint}, // s
    {"Integrator",      FieldKind::Integrator, kNamedOnly, Range::Any},
    {"Duration",        FieldKind::Number,     kNamedOnly, Range::Positive, kTimeHint}, // s
    // The solver and its switches (docs/config-format.md#world-solver, lectures/08-constraint-solver.md)
    {"Solver",              FieldKind::Solver,  kNamedOnly, Range::Any},
    {"Substeps",            FieldKind::Number,  kNamedOnly, Range::Count},            // per step
    {"SubstepsPerIsland",   FieldKind::Boolean, kNamedOnly, Range::Any},              // src/dynamics/substep_rule.hpp
    {"Iterations",          FieldKind::Number,  kNamedOnly, Range::Count},            // solve passes per substep
    {"RelaxIterations",     FieldKind::Number,  kNamedOnly, Range::WholeNumber},      // relax passes per substep
    {"ContactOrder",        FieldKind::ContactOrder, kNamedOnly, Range::Any},         // dynamics/contact_colours.hpp
    {"RelaxBallFriction",   FieldKind::Boolean, kNamedOnly, Range::Any},              // relax passes re-solve a ball's friction
    {"ImpulseIterations",   FieldKind::Number,  kNamedOnly, Range::Count},            // Solver=Impulse passes
    {"WarmStarting",        FieldKind::Boolean, kNamedOnly, Range::Any},
    {"AccumulateImpulses",  FieldKind::Boolean, kNamedOnly, Range::Any},
    {"PositionCorrection",  FieldKind::Boolean, kNamedOnly, Range::Any},
    {"ContactHertz",        FieldKind::Number,  kNamedOnly, Range::NonNegative},      // Hz
    {"ContactDampingRatio", FieldKind::Number,  kNamedOnly, Range::NonNegative},
    {"JointHertz",          FieldKind::Number,  kNamedOnly, Range::NonNegative},      // Hz
    {"JointDampingRatio",   FieldKind::Number,  kNamedOnly, Range::NonNegative},
    {"Sleep",               FieldKind::Boolean, kNamedOnly, Range::Any},
    {"SleepLinearSpeed",    FieldKind::Number,  kNamedOnly, Range::NonNegative},      // m/s
    {"SleepAngularSpeed",   FieldKind::Number,  kNamedOnly, Range::NonNegative},      // rad/s
    {"SleepLinearAcceleration",  FieldKind::Number, kNamedOnly, Range::NonNegative}, // m/s²
    {"SleepAngularAcceleration", FieldKind::Number, kNamedOnly, Range::NonNegative}, // rad/s²
    {"TimeToSleep",         FieldKind::Number,  kNamedOnly, Range::Positive, kTimeHint}, // s
    {"Broadphase",          FieldKind::Broadphase, kNamedOnly, Range::Any},       // docs/broadphase.md
    {"StepPlan",            FieldKind::Boolean, kNamedOnly, Range::Any},          // src/world/step_plan.hpp
    {"FastPath",            FieldKind::Boolean, kNamedOnly, Range::Any},          // src/fast/fast_path.hpp
    {"ContinuousCollision", FieldKind::Boolean, kNamedOnly, Range::Any},              // src/collision/continuous.hpp
    {"Threads",             FieldKind::Number,  kNamedOnly, Range::ThreadCount},      // 0: one per hardware thread
    {"Narrowphase",         FieldKind::Narrowphase, kNamedOnly, Range::Any},          // convex pairs: Auto, GjkEpa, Mpr
    {"FrictionCombine",     FieldKind::Combine, kNamedOnly, Range::Any},              // objects/materials.hpp
    {"ElasticityCombine",   FieldKind::Combine, kNamedOnly, Range::Any},              // objects/materials.hpp
};

/// Space: a simulation of its own (src/world/spaces.hpp): its name, how fast it runs against the
/// shared clock, whether it starts paused, then every World field but Duration (the loader refuses
/// that one: the run's length is the World record's), over the World record's values.
constexpr FieldSpec kSpaceOwnFields[] = {
    {"Name",            FieldKind::Name,       kNamedOnly, Range::Any},              // required
    {"TimeScale",       FieldKind::Number,     kNamedOnly, Range::Positive, kTimeScaleHint},
    {"Paused",          FieldKind::Boolean,    kNamedOnly, Range::Any},
};

/// The rows of two tables, one after the other, as one table.
template <std::size_t A, std::size_t B>
constexpr std::array<FieldSpec, A + B> joined(const FieldSpec (&a)[A], const FieldSpec (&b)[B]) {
    std::array<FieldSpec, A + B> rows{};
    for (std::size_t i = 0; i < A; ++i) rows[i] = a[i];
    for (std::size_t i = 0; i < B; ++i) rows[A + i] = b[i];
    return rows;
}
constexpr auto kSpaceFields = joined(kSpaceOwnFields, kWorldFields);

/// Expect: one checked outcome (src/world/expectations.hpp), named fields only.
/// Exactly one quantity field (Position … NotThroughPlane) per record; at most
/// one of Time, Apex, or a From/Until window; the loader checks these rules.
constexpr FieldSpec kExpectFields[] = {
    {"Object",          FieldKind::Name,       kNamedOnly, Range::Any},              // a DynamicObject's or SoftBody's name
    {"Time",            FieldKind::Number,     kNamedOnly, Range::NonNegative, kMomentHint}, // s
    {"Apex",            FieldKind::Number,     kNamedOnly, Range::Positive, kApexHint},      // 1, 2, 3, …
    {"From",            FieldKind::Number,     kNamedOnly, Range::NonNegative, kMomentHint}, // s
    {"Until",           FieldKind::Number,     kNamedOnly, Range::NonNegative, kMomentHint}, // s
    {"Position",        FieldKind::Vector,     kNamedOnly, Range::Any},              // m
    {"Velocity",        FieldKind::Vector,     kNamedOnly, Range::Any},              // m/s
    {"Speed",           FieldKind::Number,     kNamedOnly, Range::NonNegative},      // m/s
    {"AngularSpeed",    FieldKind::Number,     kNamedOnly, Range::NonNegative},      // rad/s
    {"TiltDeg",         FieldKind::Number,     kNamedOnly, Range::NonNegative},      // degrees
    {"EnergyChange",    FieldKind::Number,     kNamedOnly, Range::Any},              // fraction of |E0|
    {"AtRest",          FieldKind::Boolean,    kNamedOnly, Range::Any},
    {"Asleep",          FieldKind::Boolean,    kNamedOnly, Range::Any},              // needs Sleep=true
    {"NotThroughPlane", FieldKind::Name,       kNamedOnly, Range::Any},              // a CollisionPlane's name
    {"Volume",          FieldKind::Number,     kNamedOnly, Range::NonNegative},      // m³, a SoftBody's
    {"Pressure",        FieldKind::Number,     kNamedOnly, Range::NonNegative},      // Pa, a SoftBody's
    {"Tolerance",       FieldKind::Number,     kNamedOnly, Range::NonNegative, kToleranceHint},
    {"Compare",         FieldKind::Compare,    kNamedOnly, Range::Any},
};

/// Spring: Hooke spring plus damper between two anchors (src/forces/spring.hpp), named fields only.
constexpr FieldSpec kSpringFields[] = {
    {"Name",            FieldKind::Name,       kNamedOnly, Range::Any},
    {"BodyA",           FieldKind::Name,       kNamedOnly, Range::Any},              // a DynamicObject's Name
    {"BodyB",           FieldKind::Name,       kNamedOnly, Range::Any},              // optional; without it AnchorB is a world point
    {"AnchorA",         FieldKind::Vector,     kNamedOnly, Range::Any},              // m, in body A's frame
    {"AnchorB",         FieldKind::Vector,     kNamedOnly, Range::Any},              // m, in body B's frame, or in the world
    {"Stiffness",       FieldKind::Number,     kNamedOnly, Range::NonNegative, kStiffnessHint},  // N/m, required
    {"Damping",         FieldKind::Number,     kNamedOnly, Range::NonNegative, kDampingHint},    // N·s/m
    {"RestLength",      FieldKind::Number,     kNamedOnly, Range::NonNegative, kRestLengthHint}, // m
};

/// Attractor: a fixed point pulling by the inverse-square law (src/forces/attractor.hpp), named fields only.
constexpr FieldSpec kAttractorFields[] = {
    {"Name",            FieldKind::Name,       kNamedOnly, Range::Any},
    {"Position",        FieldKind::Vector,     kNamedOnly, Range::Any},              // m
    {"Mu",              FieldKind::Number,     kNamedOnly, Range::Positive, kMuHint},  // m³/s², required
    {"Space",           FieldKind::Name,       kNamedOnly, Range::Any},              // a Space record's Name
};

/// Region: a volume with an effect (src/forces/region.hpp), named fields only. Which fields an
/// effect needs, and which it refuses, the loader checks (scene_loader.cpp, addRegion()).
constexpr FieldSpec kRegionFields[] = {
    {"Name",               FieldKind::Name,        kNamedOnly, Range::Any},
    {"Shape",              FieldKind::RegionShape, kNamedOnly, Range::Any},            // Box (default), Sphere, HalfSpace
    {"Position",           FieldKind::Vector,      kNamedOnly, Range::Any},            // m: the centre, or a point of the plane
    {"Scale",              FieldKind::Vector,      kNamedOnly, Range::Size, kSizeHint},  // m: a Box's full edges
    {"Radius",             FieldKind::Number,      kNamedOnly, Range::Radius, kSizeHint},// m: a Sphere's
    {"Normal",             FieldKind::Vector,      kNamedOnly, Range::Any},            // a HalfSpace's, out of the region
    {"Effect",             FieldKind::Effect,      kNamedOnly, Range::Any},            // required
    {"Law",                FieldKind::DragLaw,     kNamedOnly, Range::Any},            // Linear (default) or Quadratic
    {"Coefficient",        FieldKind::Number,      kNamedOnly, Range::NonNegative, kDragHint},  // N·s/m or kg/m
    {"AngularCoefficient", FieldKind::Number,      kNamedOnly, Range::NonNegative, kDragHint},  // N·m·s
    {"Velocity",           FieldKind::Vector,      kNamedOnly, Range::Any},            // m/s: the fluid's, the wind's or the belt's
    {"Gravity",            FieldKind::Vector,      kNamedOnly, Range::Any},            // m/s²: inside a Gravity region
    {"Density",            FieldKind::Number,      kNamedOnly, Range::Positive, kFluidDensityHint},  // kg/m³: the fluid's
    {"Strength",           FieldKind::Number,      kNamedOnly, Range::Positive, kStrengthHint}, // N: RandomForce's largest
    {"Seed",               FieldKind::Number,      kNamedOnly, Range::NonNegative, kSeedHint},  // a whole number
    {"Space",           FieldKind::Name,       kNamedOnly, Range::Any},              // a Space record's Name
};

// Joints (docs/config-format.md#joints): named fields only. Bodies are
// DynamicObject names; points and axes are in WORLD space at the start
// (the World turns them into each body's frame).

/// DistanceJoint and Rope: two anchors; Length is the rod's length or the rope's maximum.
constexpr FieldSpec kTwoAnchorJointFields[] = {
    {"Name",             FieldKind::Name,    kNamedOnly, Range::Any},
    {"BodyA",            FieldKind::Name,    kNamedOnly, Range::Any},              // a DynamicObject
    {"BodyB",            FieldKind::Name,    kNamedOnly, Range::Any},              // a DynamicObject; omitted: the world
    {"AnchorA",          FieldKind::Vector,  kNamedOnly, Range::Any},              // m, world point on A
    {"AnchorB",          FieldKind::Vector,  kNamedOnly, Range::Any},              // m, world point on B (or fixed)
    {"Length",           FieldKind::Number,  kNamedOnly, Range::JointLength, kLengthHint}, // m
    {"MaxForce",         FieldKind::Number,  kNamedOnly, Range::Positive, kForceHint},  // N
    {"CollideConnected", FieldKind::Boolean, kNamedOnly, Range::Any},
};

/// BallJoint: one shared point.
constexpr FieldSpec kBallJointFields[] = {
    {"Name",             FieldKind::Name,    kNamedOnly, Range::Any},
    {"BodyA",            FieldKind::Name,    kNamedOnly, Range::Any},
    {"BodyB",            FieldKind::Name,    kNamedOnly, Range::Any},
    {"Anchor",           FieldKind::Vector,  kNamedOnly, Range::Any},              // m, world point
    {"MaxForce",         FieldKind::Number,  kNamedOnly, Range::Positive, kForceHint},
    {"CollideConnected", FieldKind::Boolean, kNamedOnly, Range::Any},
};

/// HingeJoint: a shared point and axis, optional limits (degrees) and motor.
constexpr FieldSpec kHingeJointFields[] = {
    {"Name",             FieldKind::Name,    kNamedOnly, Range::Any},
    {"BodyA",            FieldKind::Name,    kNamedOnly, Range::Any},
    {"BodyB",            FieldKind::Name,    kNamedOnly, Range::Any},
    {"Anchor",           FieldKind::Vector,  kNamedOnly, Range::Any},              // m, world point
    {"Axis",             FieldKind::Vector,  kNamedOnly, Range::Any},              // world direction, normalised
    {"LowerAngle",       FieldKind::Number,  kNamedOnly, Range::Any},              // degrees, -180..180
    {"UpperAngle",       FieldKind::Number,  kNamedOnly, Range::Any},              // degrees, -180..180
    {"MotorSpeed",       FieldKind::Number,  kNamedOnly, Range::Any},              // rad/s, A relative to B
    {"MaxMotorTorque",   FieldKind::Number,  kNamedOnly, Range::NonNegative, kTorqueHint}, // N m
    {"MaxForce",         FieldKind::Number,  kNamedOnly, Range::Positive, kForceHint},
    {"CollideConnected", FieldKind::Boolean, kNamedOnly, Range::Any},
};

/// AngularMotor: a spin about one axis, no position constraint.
constexpr FieldSpec kAngularMotorFields[] = {
    {"Name",             FieldKind::Name,    kNamedOnly, Range::Any},
    {"BodyA",            FieldKind::Name,    kNamedOnly, Range::Any},
    {"BodyB",            FieldKind::Name,    kNamedOnly, Range::Any},
    {"Axis",             FieldKind::Vector,  kNamedOnly, Range::Any},              // world direction (fixed in B)
    {"MotorSpeed",       FieldKind::Number,  kNamedOnly, Range::Any},              // rad/s
    {"MaxMotorTorque",   FieldKind::Number,  kNamedOnly, Range::NonNegative, kTorqueHint}, // N m
    {"CollideConnected", FieldKind::Boolean, kNamedOnly, Range::Any},
};

/// MayChange: one field an assignment lets students edit (docs/config-format.md#maychange).
/// `stepwise grade --expect STARTER` compares every other field of every
/// record of a submission with the starter's; the loader checks that the
/// object exists and has the field.
constexpr FieldSpec kMayChangeFields[] = {
    {"Object",           FieldKind::Name,    kNamedOnly, Range::Any},              // an object's Name; left out: the World record
    {"Field",            FieldKind::Name,    kNamedOnly, Range::Any},              // one of its fields, or one component: ScaleY
};

/// Material: values objects share by naming it (src/objects/materials.hpp), named fields only.
/// Name is required. An object's own Friction, Elasticity and Mass win over its material's.
constexpr FieldSpec kMaterialFields[] = {
    {"Name",             FieldKind::Name,    kNamedOnly, Range::Any},
    {"Density",          FieldKind::Number,  kNamedOnly, Range::Positive, kDensityHint},        // kg/m³
    {"Friction",         FieldKind::Number,  kNamedOnly, Range::NonNegative, kFrictionHint},
    {"Elasticity",       FieldKind::Number,  kNamedOnly, Range::UnitInterval, kElasticityHint},
};

/// MaterialPair: the coefficients of contacts between materials A and B (in either order), named fields only.
constexpr FieldSpec kMaterialPairFields[] = {
    {"Name",             FieldKind::Name,    kNamedOnly, Range::Any},
    {"A",                FieldKind::Name,    kNamedOnly, Range::Any},              // a Material's Name, required
    {"B",                FieldKind::Name,    kNamedOnly, Range::Any},              // a Material's Name, required
    {"Friction",         FieldKind::Number,  kNamedOnly, Range::NonNegative, kFrictionHint},
    {"Elasticity",       FieldKind::Number,  kNamedOnly, Range::UnitInterval, kElasticityHint},
};

/// SoftBody: a pressure soft body (src/objects/soft_body.hpp, docs/soft-bodies.md), named fields only.
/// Which size field a shape takes, and the bounds of Resolution, the loader checks (addSoftBody()).
constexpr FieldSpec kSoftBodyFields[] = {
    {"Name",            FieldKind::Name,    kNamedOnly, Range::Any},
    {"Shape",           FieldKind::Shape,   kNamedOnly, Range::Any},              // Sphere (default) or Box
    {"Position",        FieldKind::Vector,  kNamedOnly, Range::Any},              // m, the centre
    {"Velocity",        FieldKind::Vector,  kNamedOnly, Range::Any},              // m/s, every node's at the start
    {"AngularVelocity", FieldKind::Vector,  kNamedOnly, Range::Any},              // rad/s: node i starts at v + w x r_i
    {"Radius",          FieldKind::Number,  kNamedOnly, Range::Radius, kSizeHint},   // m, Sphere
    {"HalfExtents",     FieldKind::Vector,  kNamedOnly, Range::Radius, kSizeHint},   // m, Box
    {"Resolution",      FieldKind::Number,  kNamedOnly, Range::Any},              // subdivisions, or cells per edge
    {"Mass",            FieldKind::Number,  kNamedOnly, Range::Mass, kMassHint},  // kg, spread evenly over the nodes
    {"Stiffness",       FieldKind::Number,  kNamedOnly, Range::NonNegative, kStiffnessHint}, // N/m, required
    {"Damping",         FieldKind::Number,  kNamedOnly, Range::NonNegative, kDampingHint},   // N·s/m
    {"BendStiffness",   FieldKind::Number,  kNamedOnly, Range::NonNegative, kStiffnessHint}, // N/m
    {"Pressure",        FieldKind::Number,  kNamedOnly, Range::NonNegative, kGasHint},       // J: nRT = P·V
    {"Material",        FieldKind::Name,    kNamedOnly, Range::Any},              // a Material's Name
    {"Friction",        FieldKind::Number,  kNamedOnly, Range::NonNegative, kFrictionHint},
    {"Elasticity",      FieldKind::Number,  kNamedOnly, Range::UnitInterval, kElasticityHint},
    {"Color",           FieldKind::Color,   kNamedOnly, Range::UnitInterval},
    {"Space",           FieldKind::Name,    kNamedOnly, Range::Any},              // a Space record's Name
};

constexpr RecordSpec kRecords[] = {
    {RecordKind::DynamicObject,    "DynamicObject",    kDynamicFields},
    {RecordKind::KinematicsObject, "KinematicsObject", kKinematicFields},
    {RecordKind::CollisionPlane,   "CollisionPlane",   kPlaneFields},
    {RecordKind::World,            "World",            kWorldFields},
    {RecordKind::Expect,           "Expect",           kExpectFields},
    {RecordKind::MayChange,        "MayChange",        kMayChangeFields},
    {RecordKind::Spring,           "Spring",           kSpringFields},
    {RecordKind::Attractor,        "Attractor",        kAttractorFields},
    {RecordKind::DistanceJoint,    "DistanceJoint",    kTwoAnchorJointFields},
    {RecordKind::Rope,             "Rope",             kTwoAnchorJointFields},
    {RecordKind::BallJoint,        "BallJoint",        kBallJointFields},
    {RecordKind::HingeJoint,       "HingeJoint",       kHingeJointFields},
    {RecordKind::AngularMotor,     "AngularMotor",     kAngularMotorFields},
    {RecordKind::Part,             "Part",             kPartFields},
    {RecordKind::Region,           "Region",           kRegionFields},
    {RecordKind::Material,         "Material",         kMaterialFields},
    {RecordKind::MaterialPair,     "MaterialPair",     kMaterialPairFields},
    {RecordKind::Space,            "Space",            kSpaceFields},
    {RecordKind::SoftBody,         "SoftBody",         kSoftBodyFields},
};
// clang-format on
static_assert(std::size(kRecords) == kRecordKindCount, "one record table per RecordKind");

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

const std::array<Choice<Shape>, 8> kShapeChoices = {{
    {"Sphere", Shape::Sphere},
    {"Box", Shape::Box},
    {"Cube", Shape::Box},  // what most people call a box with equal edges
    {"Capsule", Shape::Capsule},
    {"Cylinder", Shape::Cylinder},
    {"Hull", Shape::Hull},
    {"Compound", Shape::Compound},
    {"Mesh", Shape::Mesh},
}};

const std::array<Choice<IntegratorKind>, 6> kIntegratorChoices = {{
    {"Euler", IntegratorKind::ExplicitEuler},
    {"ExplicitEuler", IntegratorKind::ExplicitEuler},
    {"SymplecticEuler", IntegratorKind::SymplecticEuler},
    {"SemiImplicitEuler", IntegratorKind::SymplecticEuler},
    {"Verlet", IntegratorKind::Verlet},
    {"VelocityVerlet", IntegratorKind::Verlet},
}};

const std::array<Choice<SolverKind>, 2> kSolverChoices = {{
    {"Impulse", SolverKind::Impulse},
    {"SequentialImpulse", SolverKind::SequentialImpulse},
}};

const std::array<Choice<BroadphaseKind>, 10> kBroadphaseChoices = {{
    {"Auto", BroadphaseKind::Auto},
    {"BruteForce", BroadphaseKind::BruteForce},
    {"SweepAndPrune", BroadphaseKind::SweepAndPrune},
    {"SAP", BroadphaseKind::SweepAndPrune},
    {"AabbTree", BroadphaseKind::AabbTree},
    {"DynamicTree", BroadphaseKind::AabbTree},
    {"Grid", BroadphaseKind::Grid},
    {"UniformGrid", BroadphaseKind::Grid},
    {"Octree", BroadphaseKind::Octree},
    {"LooseOctree", BroadphaseKind::Octree},
}};

const std::array<Choice<bool>, 6> kBooleanChoices = {{
    {"true", true},
    {"false", false},
    {"yes", true},
    {"no", false},
    {"1", true},
    {"0", false},
}};

const std::array<Choice<ExpectCompare>, 3> kCompareChoices = {{
    {"Within", ExpectCompare::Within},
    {"AtLeast", ExpectCompare::AtLeast},
    {"AtMost", ExpectCompare::AtMost},
}};

const std::array<Choice<RegionShape>, 3> kRegionShapeChoices = {{
    {"Box", RegionShape::Box},
    {"Sphere", RegionShape::Sphere},
    {"HalfSpace", RegionShape::HalfSpace},
}};

const std::array<Choice<RegionEffect>, 7> kEffectChoices = {{
    {"Drag", RegionEffect::Drag},
    {"Wind", RegionEffect::Wind},
    {"Gravity", RegionEffect::Gravity},
    {"Buoyancy", RegionEffect::Buoyancy},
    {"RandomForce", RegionEffect::RandomForce},
    {"Kill", RegionEffect::Kill},
    {"Conveyor", RegionEffect::Conveyor},
}};

const std::array<Choice<DragLaw>, 2> kDragLawChoices = {{
    {"Linear", DragLaw::Linear},
    {"Quadratic", DragLaw::Quadratic},
}};

const std::array<Choice<ContactOrder>, 3> kContactOrderChoices = {{
    {"Colours", ContactOrder::Colours},
    {"Colors", ContactOrder::Colours},
    {"Found", ContactOrder::Found},
}};

const std::array<Choice<NarrowphaseKind>, 3> kNarrowphaseChoices = {{
    {"Auto", NarrowphaseKind::Auto},
    {"GjkEpa", NarrowphaseKind::GjkEpa},
    {"Mpr", NarrowphaseKind::Mpr},
}};

const std::array<Choice<CombineRule>, 5> kCombineChoices = {{
    {"Product", CombineRule::Product},
    {"Min", CombineRule::Min},
    {"Max", CombineRule::Max},
    {"Average", CombineRule::Average},
    {"GeometricMean", CombineRule::GeometricMean},
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
