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
/// is at most one World record, a Spring's or a joint's bodies exist (they
/// may come later in the file, so springs and joints are resolved at the
/// end), an object's Material exists (Material records are read before every
/// other record, parseScene(), so they too may come anywhere), and a mass comes
/// from Mass or from Density, never both. Every problem is collected; only a
/// file with none becomes a Scene.
/// Last, springs too stiff for the time step are *warned* about (Scene::warnings).
#include "config/scene_loader.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>

#include "config/obj_file.hpp"
#include "config/record_reader.hpp"
#include "config/scene_records.hpp"
#include "config/scene_tokenizer.hpp"
#include "config/spelling.hpp"
#include "core/limits.hpp"
#include "core/quoted_text.hpp"
#include "objects/convex_hull.hpp"
#include "objects/inertia.hpp"
#include "objects/mass_properties.hpp"
#include "objects/triangle_mesh.hpp"
#include "forces/spring_stability.hpp"
#include "objects/soft_mesh.hpp"
#include "soft/soft_stability.hpp"

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
constexpr Shape kDefaultPartShape = Shape::Box;        ///< A Part is a box unless it says otherwise.
/// A kinematic compound has no mass; its parts are weighed by volume at this total only to
/// find its centroid and axes (any positive number gives the same ones).
constexpr Real kKinematicCompoundMass = 1;
/// What Height means, for the hints of its errors.
constexpr std::string_view kHeightMeaning =
    "Height is a Capsule's segment between its two ball centres or a Cylinder's full length";

/// A dynamic body's own elasticity and friction: a moderate bounce and grip.
constexpr Real kDynamicElasticity = Real(0.5);
constexpr Real kDynamicFriction = Real(0.5);
/// Static things (kinematic objects, planes) default to 1 because contact
/// coefficients combine by product by default, e = e_A · e_B and μ = μ_A · μ_B: with 1 on
/// the static side, the dynamic body's own value is the one that acts (under the
/// World's other combine rules only Min keeps it so; objects/materials.hpp).
constexpr Real kStaticElasticity = 1;
constexpr Real kStaticFriction = 1;

/// A sphere's Scale is its full size, i.e. its diameter; the radius is half of it.
constexpr Real kRadiusPerDiameter = Real(0.5);
/// Shorter normals than this are treated as zero: normalising them would
/// amplify rounding noise into an arbitrary direction.

/// An Expect record's apex must be one the run can count to; more than this is a typo.
constexpr Real kMaxApex = 1000;
constexpr std::string_view kApexCountHint = "Apex=3 is the third time the body stops rising";
/// Record names an Expect record's names must belong to.
constexpr std::string_view kDynamicRecord = "DynamicObject";
constexpr std::string_view kPlaneRecord = "CollisionPlane";
constexpr std::string_view kSoftBodyRecord = "SoftBody";

/// The quantity fields of an Expect record, and what each measures.
struct ExpectQuantityField {
    std::string_view name;    ///< Field name in the record table.
    ExpectQuantity quantity;  ///< What it measures.
};
constexpr ExpectQuantityField kExpectQuantityFields[] = {
    {"Position", ExpectQuantity::Position},         {"Velocity", ExpectQuantity::Velocity},
    {"Speed", ExpectQuantity::Speed},               {"AngularSpeed", ExpectQuantity::AngularSpeed},
    {"TiltDeg", ExpectQuantity::TiltDeg},           {"EnergyChange", ExpectQuantity::EnergyChange},
    {"AtRest", ExpectQuantity::AtRest},             {"Asleep", ExpectQuantity::Asleep},
    {"NotThroughPlane", ExpectQuantity::NotThroughPlane},
    {"Volume", ExpectQuantity::Volume},             {"Pressure", ExpectQuantity::Pressure},
};
const std::string kExpectQuantityList =
    "Position[XYZ], Velocity[XYZ], Speed, AngularSpeed, TiltDeg, EnergyChange, AtRest, Asleep, NotThroughPlane, "
    "Volume, Pressure";
/// A spring without Damping= has none: it oscillates for ever (with a symplectic integrator).
constexpr Real kDefaultDamping = 0;
/// An unstable spring is warned about once its swing would grow by more than
/// this factor over the scene's Duration. Symplectic Euler and Verlet past
/// h·ω = 2 grow far beyond it within a few steps; explicit Euler, whose
/// amplitude grows by √(1 + h²ω²) every step at any h, is only warned
/// about when that adds up to a visible change.
constexpr Real kTolerableGrowth = 2;

// SoftBody (docs/config-format.md#softbody, docs/soft-bodies.md)
constexpr int kDefaultSphereResolution = 2;  ///< Icosphere subdivisions: 162 nodes, 320 triangles.
constexpr int kDefaultBoxResolution = 4;     ///< Cells along a cube's edge: 98 nodes, 192 triangles.
const Vec3 kDefaultSoftHalfExtents{0.5, 0.5, 0.5};  ///< m: a 1 m cube, as a DynamicObject box's Scale.
/// ρ above 1 by more than this is growth (symplectic methods have ρ = 1 exactly, up to rounding).
constexpr Real kGrowthTolerance = Real(1e-12);
/// Two bodies whose bounding spheres are apart by less than this fraction of the sum of their
/// radii count as touching at the start, for the mass-ratio warning: a box set on another box
/// "at" its top face, written to a few decimals, may be a hair above it.
constexpr Real kTouchingMargin = Real(0.01);
/// A hinge or motor turns about Z unless told otherwise: a wheel facing the default camera.
const Vec3 kDefaultJointAxis{0, 0, 1};
/// Hinge limits are angles of a turn, in degrees: at most half a turn either way.
constexpr Real kMaxLimitDegrees = 180;
/// Joints let their bodies pass through each other unless asked (Box2D's default).
constexpr bool kDefaultCollideConnected = false;

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

std::string formatNumber(Real value) {
    std::ostringstream text;
    text << value;
    return text.str();
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
/// A Space record, its World fields read once the World record is known.
struct PendingSpace {
    SpaceDef space;
    RecordValues values;
};

/// An object's `Space=` as written: the name, and where (an empty name: the default space).
struct SpaceRef {
    std::string name;
    int line = 0;
    int column = 0;
};

/// Where a Buoyancy region was written, to point at it if a body's shape cannot float.
struct BuoyancyLine {
    int line = 0;
    int column = 0;
    std::string name;
};

class SceneAssembler {
public:
    SceneAssembler(const std::string& sourceName, const SceneReadOptions& options) : sink_(sourceName), options_(options) {
        scene_.sourcePath = sourceName;
    }

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
            case RecordKind::Expect: addExpect(values, line); break;
            case RecordKind::Spring: addSpring(values, line, index); break;
            case RecordKind::Attractor: addAttractor(values, line, index); break;
            case RecordKind::DistanceJoint: addJoint(values, line, index, JointKind::Distance); break;
            case RecordKind::Rope: addJoint(values, line, index, JointKind::Rope); break;
            case RecordKind::BallJoint: addJoint(values, line, index, JointKind::Ball); break;
            case RecordKind::HingeJoint: addJoint(values, line, index, JointKind::Hinge); break;
            case RecordKind::AngularMotor: addJoint(values, line, index, JointKind::AngularMotor); break;
            case RecordKind::MayChange: addMayChange(values, line); break;
            case RecordKind::Part:
                partLines_.emplace_back(line.number, lineText(line));
                addPart(values, line, index);
                break;
            case RecordKind::Region: addRegion(values, line, index); break;
            case RecordKind::Space: addSpace(values, line, index); break;
            case RecordKind::Material: addMaterial(values, line, index); break;
            case RecordKind::MaterialPair: addMaterialPair(values, line, index); break;
            case RecordKind::SoftBody: addSoftBody(values, line, index); break;
        }
    }

    /// Does @p line declare a Material? parseScene() adds those first, so an object may name a
    /// material declared anywhere in the file.
    static bool declaresMaterial(const SceneLine& line) {
        const RecordSpec* spec = findRecord(line.tokens.front().text);
        return spec != nullptr && spec->kind == RecordKind::Material;
    }

    /// The finished Scene, or ConfigError with every problem found.
    Scene finish() {
        resolveCompounds();  // first: springs' anchors are in the bodies' frames, which this moves
        resolveExpectNames();
        resolveMayChange();
        resolveSprings();
        resolveJoints();
        checkBuoyantShapes();
        resolveSpaces();
        if (sink_.diagnostics().empty()) {
            warnAboutUnstableSprings();
            warnAboutUnstableSoftBodies();
            warnAboutMassRatios();
            return std::move(scene_);
        }
        std::vector<ConfigDiagnostic> diagnostics = sink_.diagnostics();
        sortByPosition(diagnostics);
        throw ConfigError(std::move(diagnostics));
    }

private:
    /// A Shape=Compound object waiting for its Part records.
    struct PendingCompound {
        bool dynamic = true;      ///< In scene_.dynamics (else scene_.kinematics).
        std::size_t index = 0;    ///< Its index there.
        int line = 0;             ///< Its line.
        int column = 0;           ///< Column of its Shape value.
        int massColumn = 0;       ///< Column of its Mass value; 0 when not given.
        std::optional<Real> density;  ///< kg/m³ that makes its mass, its own or its material's; nullopt: none.
        int densityColumn = 0;    ///< Column of its own Density value; 0 when not given (or from its material).
    };

    /// A Part record as read, before it is joined to its compound.
    struct PendingPart {
        CompoundPart part;                  ///< The part; its mass is 0 until shared out if not given.
        std::string name;                   ///< The record's Name (or Part0, Part1, …).
        std::optional<std::string> body;    ///< Body as written (nullopt when missing or malformed).
        int line = 0;                       ///< Line of the record.
        int column = 0;                     ///< Column of the record's name.
        int bodyColumn = 0;                 ///< Column of Body's value.
        int massColumn = 0;                 ///< Column of Mass's value; 0 when not given.
        bool massFromMaterial = false;      ///< Its mass is its Material's density × its volume.
        bool usable = true;                 ///< False when its shape or hull was refused (reported).
    };

    /// A joint record waiting for finish(), when every body is known.
    struct PendingJoint {
        RecordValues values;  ///< What the record said.
        int line = 0;         ///< Its line.
        int column = 0;       ///< Column of its record name.
    };

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
        // The object's own fields win over its material's, which win over the format's defaults.
        const Material* material = materialOf(values, line, body.material);
        body.elasticity = values.number("Elasticity", materialValue(material, &Material::elasticity, kDynamicElasticity));
        body.friction = values.number("Friction", materialValue(material, &Material::friction, kDynamicFriction));
        const std::optional<Real> density = densityOf(values, line, material);
        body.orientation = orientationFromDegrees(values.triple("Rotation", kZero));
        body.angularVelocity = values.triple("AngularVelocity", kZero);
        body.hollow = values.choice<bool>("Hollow", kBooleanChoices, kDefaultHollow);
        if (body.hollow && body.shape != Shape::Sphere) {
            // A hollow box would need a wall thickness; rather than guess one, refuse.
            sink_.report(line.number, values.valueColumn("Hollow"), "Hollow",
                         std::string("false for a ") + toString(body.shape), values.text("Hollow").value_or("true"),
                         std::string("only a sphere can be hollow (a thin shell, I = 2/3 m r^2); ") +
                             (body.shape == Shape::Box ? "boxes are solid" : "every other shape is solid"));
        }
        if (body.shape == Shape::Mesh) {
            sink_.report(line.number, shapeColumn(values, line), "Shape", "a shape with an inside (Sphere, Box, "
                         "Capsule, Cylinder, Hull or Compound) for a DynamicObject", values.text("Shape").value_or("Mesh"),
                         "a triangle mesh is a surface with no volume, so no mass: use it on a KinematicsObject, or "
                         "Shape=Hull for a convex solid read from the same OBJ file");
        }
        body.height = values.number("Height", body.scale.y);
        BodyFrame frame;
        if (checkShapeFields(values, line, body.shape)) {
            if (body.shape == Shape::Hull) {
                if (std::shared_ptr<ConvexHull> hull = readHull(values, line, body.scale)) {
                    frame = moveToPrincipalFrame(*hull);
                    body.hull = std::move(hull);
                    body.scale = kUnitScale;  // the vertices carry the size now
                }
            } else if (body.shape == Shape::Compound) {
                pendingCompounds_.push_back({true, scene_.dynamics.size(), line.number, shapeColumn(values, line),
                                             values.isSet("Mass") ? values.valueColumn("Mass") : 0, density,
                                             values.isSet("Density") ? values.valueColumn("Density") : 0});
            }
            // A compound's volume is known once its parts are (shareMass()).
            const bool solid = body.shape != Shape::Compound && body.shape != Shape::Mesh &&
                               (body.shape != Shape::Hull || body.hull != nullptr);
            if (density && solid) setMassFromDensity(body, *density, values, line);
        }
        moveTo(body, frame);
        dynamicFrames_.push_back(frame);
        noteSpace(values, line.number, dynamicSpaceRefs_);
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
        const Material* material = materialOf(values, line, mover.material);
        mover.elasticity = values.number("Elasticity", materialValue(material, &Material::elasticity, kStaticElasticity));
        mover.friction = values.number("Friction", materialValue(material, &Material::friction, kStaticFriction));
        mover.height = values.number("Height", mover.scale.y);
        if (checkShapeFields(values, line, mover.shape)) {
            if (mover.shape == Shape::Hull) {
                if (std::shared_ptr<ConvexHull> hull = readHull(values, line, mover.scale)) {
                    moveTo(mover, moveToPrincipalFrame(*hull));
                    mover.hull = std::move(hull);
                    mover.scale = kUnitScale;
                }
            } else if (mover.shape == Shape::Mesh) {
                if (std::shared_ptr<TriangleMesh> mesh = readMesh(values, line, mover.scale)) {
                    mover.mesh = std::move(mesh);
                    mover.scale = kUnitScale;
                }
            } else if (mover.shape == Shape::Compound) {
                pendingCompounds_.push_back({false, scene_.kinematics.size(), line.number, shapeColumn(values, line), 0,
                                             std::nullopt, 0});
            }
        }
        noteSpace(values, line.number, kinematicSpaceRefs_);
        scene_.kinematics.push_back(std::move(mover));
    }

    // ---------------------------------------------------------- materials

    /// A Material record: Name is required, every value optional. parseScene() adds the
    /// Material records before any other, so the objects of the whole file can name them.
    void addMaterial(const RecordValues& values, const SceneLine& line, int index) {
        if (!values.isSet("Name")) {
            sink_.report(line.number, line.tokens.front().column, "Name", "a Name for the Material", lineText(line),
                         "objects name their material, e.g. Material, Name=rubber, Density=1100, Friction=0.9, "
                         "Elasticity=0.8 and DynamicObject, Material=rubber");
        }
        Material material;
        material.name = claimName(values, line, index);
        const auto optional = [&](std::string_view field) {
            return values.isSet(field) ? std::optional<Real>(values.number(field, 0)) : std::nullopt;
        };
        material.density = optional("Density");
        material.friction = optional("Friction");
        material.elasticity = optional("Elasticity");
        materialIndex_.emplace(toLower(material.name), static_cast<std::uint32_t>(scene_.materials.size()));
        scene_.materials.push_back(std::move(material));
    }

    /// A MaterialPair record: two materials (A and B, in either order) and the Friction or
    /// Elasticity, or both, of their contacts.
    void addMaterialPair(const RecordValues& values, const SceneLine& line, int index) {
        (void)claimName(values, line, index);
        MaterialPair pair;
        std::uint32_t a = kNoMaterial;
        std::uint32_t b = kNoMaterial;
        const Material* materialA = materialOf(values, line, a, "A");
        const Material* materialB = materialOf(values, line, b, "B");
        for (const std::string_view side : {"A", "B"}) {
            if (values.isSet(side)) continue;
            sink_.report(line.number, line.tokens.front().column, std::string(side), "the Name of a Material",
                         lineText(line), "a pair names two materials, e.g. MaterialPair, A=rubber, B=ice, Friction=0.05");
        }
        if (!values.isSet("Friction") && !values.isSet("Elasticity")) {
            sink_.report(line.number, line.tokens.front().column, "MaterialPair", "Friction=..., Elasticity=... or both",
                         lineText(line), "a pair gives its contacts their own coefficients; without any it changes nothing");
        }
        if (materialA == nullptr || materialB == nullptr) return;
        pair.a = a;
        pair.b = b;
        if (values.isSet("Friction")) pair.friction = values.number("Friction", 0);
        if (values.isSet("Elasticity")) pair.elasticity = values.number("Elasticity", 0);
        scene_.materialPairs.push_back(pair);
    }

    /// The Material that @p field names, with its index in @p index; nullptr (and kNoMaterial) when the
    /// record names none, or after reporting a name no Material has.
    const Material* materialOf(const RecordValues& values, const SceneLine& line, std::uint32_t& index,
                               std::string_view field = "Material") {
        index = kNoMaterial;
        const std::optional<std::string> name = values.text(field);
        if (!name) return nullptr;  // not given, or a malformed name (reported by the reader)
        if (const auto found = materialIndex_.find(toLower(*name)); found != materialIndex_.end()) {
            index = found->second;
            return &scene_.materials[found->second];
        }
        std::vector<std::string> known;
        for (const Material& material : scene_.materials) known.push_back(material.name);
        std::string hint;
        if (const auto other = names_.find(toLower(*name)); other != names_.end()) {
            hint = quoted(other->second.name) + " is the " + std::string(other->second.record) + " on line " +
                   std::to_string(other->second.line) + ", not a Material";
        } else if (const auto suggestion = closestMatch(*name, known)) {
            hint = "did you mean '" + *suggestion + "'?";
        } else {
            hint = "declare it anywhere in the file, e.g. Material, Name=" + *name + ", Friction=0.5, Elasticity=0.5";
        }
        sink_.report(line.number, values.valueColumn(field), std::string(field), "the Name of a Material in this file",
                     *name, std::move(hint));
        return nullptr;
    }

    /// A material's value for a field the object leaves out, or @p fallback when it has none.
    static Real materialValue(const Material* material, std::optional<Real> Material::*value, Real fallback) {
        return material != nullptr && (material->*value) ? *(material->*value) : fallback;
    }

    /// The density that makes the object's mass: its own Density, or its material's when it gives
    /// neither Mass nor Density; nullopt when its Mass is given or defaults. Mass and Density on one
    /// record are an error (reported at Density).
    std::optional<Real> densityOf(const RecordValues& values, const SceneLine& line, const Material* material) {
        const bool mass = values.isSet("Mass");
        if (values.isSet("Density")) {
            if (mass) {
                sink_.report(line.number, values.valueColumn("Density"), "Density", "either Mass or Density, not both",
                             formatNumber(values.number("Density", 0)),
                             "Mass is given at column " + std::to_string(values.valueColumn("Mass")) +
                                 "; with Density the mass is density x the shape's volume");
                return std::nullopt;
            }
            return values.number("Density", 0);
        }
        if (!mass && material != nullptr) return material->density;
        return std::nullopt;
    }

    /// Is m = ρ·V a mass the World accepts? Reports it at @p column when not.
    bool massInRange(Real mass, Real density, Real volume, int line, int column) {
        if (mass >= kMinMass && mass <= kMaxMass) return true;
        sink_.report(line, column, "Density", describe(Range::Mass) + " as density x volume",
                     formatNumber(density) + " kg/m^3 x " + formatNumber(volume) + " m^3 = " + formatNumber(mass) + " kg",
                     "the mass is the density times the shape's volume; give Mass=... instead");
        return false;
    }

    /// m = ρ·V for a body whose shape is known (not a compound, whose parts come later).
    void setMassFromDensity(DynamicObject& body, Real density, const RecordValues& values, const SceneLine& line) {
        const int column = values.isSet("Density") ? values.valueColumn("Density") : values.valueColumn("Material");
        if (body.hollow) {
            sink_.report(line.number, column, "Density", "Mass for a hollow sphere",
                         formatNumber(density), "a thin shell has no volume for a density to fill; give its Mass");
            return;
        }
        const Real volume = shapeVolume(body);
        const Real mass = density * volume;
        if (massInRange(mass, density, volume, line.number, column)) body.setMass(mass);
    }

    // ---------------------------------------------------------- shapes with data

    /// Column of the Shape value, or of the record's name when Shape was left out.
    static int shapeColumn(const RecordValues& values, const SceneLine& line) {
        const int column = values.valueColumn("Shape");
        return column != 0 ? column : line.tokens.front().column;
    }

    /// Height, Vertices and File only where the shape uses them; a Hull has exactly one of
    /// Vertices and File, a Mesh a File. Reports each misuse; true when none.
    bool checkShapeFields(const RecordValues& values, const SceneLine& line, Shape shape) {
        const std::size_t before = sink_.diagnostics().size();
        const std::string shapeName = toString(shape);
        const bool hasHeight = shape == Shape::Capsule || shape == Shape::Cylinder;
        if (values.isSet("Height") && !hasHeight) {
            sink_.report(line.number, values.valueColumn("Height"), "Height", "no Height for a " + shapeName,
                         formatNumber(values.number("Height", 0)), std::string(kHeightMeaning));
        }
        if (shape == Shape::Cylinder && values.isSet("Height") && values.number("Height", 1) < kMinBodySize) {
            sink_.report(line.number, values.valueColumn("Height"), "Height", describe(Range::Size) + " for a Cylinder",
                         formatNumber(values.number("Height", 0)),
                         "a cylinder of length 0 is a disc with no volume; a Capsule may have Height=0 (a ball)");
        }
        const bool vertices = values.isSet("Vertices");
        const bool file = values.isSet("File");
        if (vertices && shape != Shape::Hull) {
            sink_.report(line.number, values.valueColumn("Vertices"), "Vertices", "no Vertices for a " + shapeName,
                         values.asWritten("Vertices"),
                         shape == Shape::Mesh ? "a Mesh reads its triangles from File=model.obj"
                                              : "Vertices are the points a Shape=Hull wraps");
        }
        if (file && shape != Shape::Hull && shape != Shape::Mesh) {
            sink_.report(line.number, values.valueColumn("File"), "File", "no File for a " + shapeName,
                         values.text("File").value_or(""),
                         "File=model.obj gives a Shape=Hull its points or a Shape=Mesh its triangles");
        }
        if (shape == Shape::Hull && vertices && file) {
            sink_.report(line.number, values.valueColumn("File"), "File", "either Vertices or File for a Hull, not both",
                         values.text("File").value_or(""), "the hull wraps the points of one of them");
        }
        if (shape == Shape::Hull && !vertices && !file) {
            sink_.report(line.number, shapeColumn(values, line), "Shape",
                         "Vertices=(x, y, z), ... or File=model.obj with a Hull", values.text("Shape").value_or("Hull"),
                         "a hull is the convex solid around at least 4 points that are not coplanar, e.g. "
                         "Vertices=(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)");
        }
        if (shape == Shape::Mesh && !file) {
            sink_.report(line.number, shapeColumn(values, line), "Shape", "File=model.obj with a Mesh",
                         values.text("Shape").value_or("Mesh"), "a Mesh's triangles come from an OBJ file");
        }
        return sink_.diagnostics().size() == before;
    }

    /// The path of a File field, relative to the scene file's folder.
    std::filesystem::path resolvedFile(const std::string& written) const {
        const std::filesystem::path file(written);
        if (file.is_absolute()) return file;
        return std::filesystem::path(scene_.sourcePath).parent_path() / file;
    }

    /// The OBJ file the record's File names, or nullopt after reporting why it cannot be read.
    std::optional<ObjModel> readModel(const RecordValues& values, const SceneLine& line) {
        const std::optional<std::string> written = values.text("File");
        if (!written) return std::nullopt;  // malformed: reported by the reader
        const int column = values.valueColumn("File");
        if (!options_.readFiles) {
            sink_.report(line.number, column, "File", "no File (this loader reads no files)", *written,
                         "scenes parsed with SceneReadOptions::readFiles off must give a hull's points as Vertices");
            return std::nullopt;
        }
        const std::string path = resolvedFile(*written).string();
        try {
            return readObjFile(path);
        } catch (const ObjError& error) {
            sink_.report(line.number, column, "File", "a readable OBJ file with vertices", *written,
                         "cannot read " + path + ": " + error.what());
            return std::nullopt;
        }
    }

    /// Where a record's points came from, for messages: "Vertices" or the OBJ file's name.
    static std::string pointsSource(const RecordValues& values) {
        return values.isSet("Vertices") ? std::string("Vertices") : values.text("File").value_or("File");
    }

    /// The hull of the record's Vertices or File points, each scaled component-wise by
    /// @p scale, in the record's own frame; nullptr after reporting a problem.
    std::shared_ptr<ConvexHull> readHull(const RecordValues& values, const SceneLine& line, const Vec3& scale) {
        std::vector<Vec3> points;
        const bool fromFile = values.isSet("File");
        if (fromFile) {
            std::optional<ObjModel> model = readModel(values, line);
            if (!model) return nullptr;
            points = std::move(model->vertices);
        } else {
            points = values.points("Vertices");
            if (reportedOn(line.number, "Vertices")) return nullptr;  // a bad point: reported by the reader
        }
        for (Vec3& p : points) p *= scale;
        const std::string field = fromFile ? "File" : "Vertices";
        const int column = values.valueColumn(field);
        try {
            return std::make_shared<ConvexHull>(buildConvexHull(points));
        } catch (const HullError& error) {
            const std::string found = fromFile ? values.text("File").value_or("") + " (" +
                                                     std::to_string(points.size()) + " points)"
                                               : std::to_string(points.size()) + " points";
            sink_.report(line.number, column, field, "at least 4 points that are not coplanar (a hull with volume)",
                         found, error.what());
            return nullptr;
        }
    }

    /// The triangles of the record's File as a mesh (points scaled by @p scale); nullptr after reporting.
    std::shared_ptr<TriangleMesh> readMesh(const RecordValues& values, const SceneLine& line, const Vec3& scale) {
        std::optional<ObjModel> model = readModel(values, line);
        if (!model) return nullptr;
        const std::string written = values.text("File").value_or("");
        const int column = values.valueColumn("File");
        if (model->triangles.empty()) {
            sink_.report(line.number, column, "File", "an OBJ file with faces (f lines) for a Mesh", written,
                         "it has " + std::to_string(model->vertices.size()) + " vertices but no faces");
            return nullptr;
        }
        for (Vec3& p : model->vertices) p *= scale;
        try {
            return std::make_shared<TriangleMesh>(buildTriangleMesh(std::move(model->vertices), std::move(model->triangles)));
        } catch (const MeshError& error) {
            sink_.report(line.number, column, "File", "a mesh of triangles that each have an area", written,
                         error.what());
            return nullptr;
        }
    }

    /// Has a problem with @p field on line @p line been reported?
    bool reportedOn(int line, std::string_view field) const {
        return std::any_of(sink_.diagnostics().begin(), sink_.diagnostics().end(),
                           [&](const ConfigDiagnostic& d) { return d.line == line && d.field == field; });
    }

    /// The scene put the shape's frame at (position, orientation); its centre of mass and
    /// principal axes are @p frame within it: x = x_scene + R_scene·c, q = q_scene·q_axes.
    template <typename Object>
    static void moveTo(Object& object, const BodyFrame& frame) {
        object.position += object.orientation * frame.centre;
        object.orientation = glm::normalize(object.orientation * frame.axes);
    }

    /// A Part record, checked now, joined to its body in finish() (the body may come later).
    void addPart(const RecordValues& values, const SceneLine& line, int index) {
        PendingPart pending;
        pending.name = claimName(values, line, index);
        pending.line = line.number;
        pending.column = line.tokens.front().column;
        pending.body = values.text("Body");
        pending.bodyColumn = values.valueColumn("Body");
        if (!values.isSet("Body")) {
            sink_.report(line.number, pending.column, "Body", "the Name of a Shape=Compound object", lineText(line),
                         "every Part names the compound it belongs to, e.g. Part, Body=robot, Shape=Box");
        }
        CompoundPart& part = pending.part;
        part.shape = values.choice<Shape>("Shape", kShapeChoices, kDefaultPartShape);
        part.position = values.triple("Position", kZero);
        part.orientation = orientationFromDegrees(values.triple("Rotation", kZero));
        part.scale = values.triple("Scale", kUnitScale);
        part.radius = values.number("Radius", kRadiusPerDiameter * part.scale.x);
        part.height = values.number("Height", part.scale.y);
        pending.massColumn = values.isSet("Mass") ? values.valueColumn("Mass") : 0;
        part.mass = values.number("Mass", 0);
        // A part's Material gives its density here, and its friction and elasticity in resolveCompounds().
        const Material* material = materialOf(values, line, part.material);
        const std::optional<Real> density = densityOf(values, line, material);
        if (part.shape == Shape::Compound || part.shape == Shape::Mesh) {
            sink_.report(line.number, values.valueColumn("Shape"), "Shape",
                         "a convex part (Sphere, Box, Capsule, Cylinder or Hull)", values.text("Shape").value_or(""),
                         part.shape == Shape::Mesh ? "a mesh has no volume, so it cannot be part of a body's mass"
                                                   : "a compound cannot hold a compound: give its parts to this body");
            pending.usable = false;
        } else if (!checkShapeFields(values, line, part.shape)) {
            pending.usable = false;
        } else if (part.shape == Shape::Hull) {
            if (std::shared_ptr<ConvexHull> hull = readHull(values, line, part.scale)) {
                // The part's own frame moves to the hull's centroid and axes, as a body's would.
                const BodyFrame frame = moveToPrincipalFrame(*hull);
                moveTo(part, frame);
                part.hull = std::move(hull);
                part.scale = kUnitScale;
            } else {
                pending.usable = false;
            }
        }
        if (density && pending.usable) {
            // A part's Density (its own or its material's) stands for its Mass: the every-part-or-none
            // rule counts it as given.
            part.mass = *density * partVolume(part);
            pending.massColumn = values.valueColumn(values.isSet("Density") ? "Density" : "Material");
            pending.massFromMaterial = !values.isSet("Density");
        }
        pendingParts_.push_back(std::move(pending));
    }

    /// Joins every Part to its compound, shares out the mass, and moves each compound to its
    /// centre of mass and principal axes. A Shape=Compound object with no Part is an error.
    void resolveCompounds() {
        std::vector<std::vector<const PendingPart*>> partsOf(pendingCompounds_.size());
        for (const PendingPart& pending : pendingParts_) {
            if (!pending.body) continue;  // missing or malformed: reported
            const std::optional<std::size_t> owner = compoundNamed(*pending.body, pending.line, pending.bodyColumn);
            if (owner) partsOf[*owner].push_back(&pending);
        }
        for (std::size_t c = 0; c < pendingCompounds_.size(); ++c) {
            const PendingCompound& compound = pendingCompounds_[c];
            const std::string& name = compound.dynamic ? scene_.dynamics[compound.index].name
                                                       : scene_.kinematics[compound.index].name;
            if (partsOf[c].empty()) {
                sink_.report(compound.line, compound.column, "Shape", "at least one Part record with Body=" + name,
                             "Compound", "a compound body is made of its parts, e.g. Part, Body=" + name +
                                             ", Shape=Box, Position=(0, 0, 0), Scale=(1, 1, 1)");
                continue;
            }
            // A refused part was reported at its own line; the compound's sums would mean nothing.
            const bool usable = std::all_of(partsOf[c].begin(), partsOf[c].end(),
                                            [](const PendingPart* part) { return part->usable; });
            if (!usable) continue;
            auto shape = std::make_shared<CompoundShape>();
            for (const PendingPart* part : partsOf[c]) shape->parts.push_back(part->part);
            // A part with a Material touches with its material's Friction and Elasticity, and with the
            // body's where the material gives none (contactCoefficients()).
            const Real friction = compound.dynamic ? scene_.dynamics[compound.index].friction
                                                   : scene_.kinematics[compound.index].friction;
            const Real elasticity = compound.dynamic ? scene_.dynamics[compound.index].elasticity
                                                     : scene_.kinematics[compound.index].elasticity;
            for (CompoundPart& part : shape->parts) {
                if (part.material == kNoMaterial) continue;
                const Material& material = scene_.materials[part.material];
                part.friction = material.friction.value_or(friction);
                part.elasticity = material.elasticity.value_or(elasticity);
            }
            if (!shareMass(compound, partsOf[c], *shape)) continue;
            const BodyFrame frame = moveToPrincipalFrame(*shape);
            if (compound.dynamic) {
                DynamicObject& body = scene_.dynamics[compound.index];
                moveTo(body, frame);
                dynamicFrames_[compound.index] = frame;
                body.compound = std::move(shape);
            } else {
                KinematicsObject& mover = scene_.kinematics[compound.index];
                moveTo(mover, frame);
                mover.compound = std::move(shape);
            }
        }
    }

    /// The index in pendingCompounds_ of the compound called @p name; nullopt after reporting.
    std::optional<std::size_t> compoundNamed(const std::string& name, int line, int column) {
        std::vector<std::string> compounds;
        for (std::size_t c = 0; c < pendingCompounds_.size(); ++c) {
            const PendingCompound& compound = pendingCompounds_[c];
            const std::string& candidate = compound.dynamic ? scene_.dynamics[compound.index].name
                                                            : scene_.kinematics[compound.index].name;
            if (equalsIgnoreCase(candidate, name)) return c;
            compounds.push_back(candidate);
        }
        std::string hint;
        if (const auto other = names_.find(toLower(name)); other != names_.end()) {
            hint = quoted(other->second.name) + " is the " + std::string(other->second.record) + " on line " +
                   std::to_string(other->second.line) + ", not a Shape=Compound object; parts belong to compounds";
        } else if (const auto suggestion = closestMatch(name, compounds)) {
            hint = "did you mean '" + *suggestion + "'?";
        } else {
            hint = "no object is called " + quoted(name) + "; a compound is a DynamicObject or KinematicsObject "
                   "with Shape=Compound";
        }
        sink_.report(line, column, "Body", "the Name of a Shape=Compound object", name, std::move(hint));
        return std::nullopt;
    }

    /// The mass rule: every part gives Mass (the body's is their sum, and the body gives
    /// none), or no part does (the body's Mass is shared by volume: uniform density). A
    /// kinematic compound has no mass: its parts give none. False after reporting.
    bool shareMass(const PendingCompound& compound, const std::vector<const PendingPart*>& parts, CompoundShape& shape) {
        // A kinematic body has no mass: its parts' materials' densities do not count, their own Mass does.
        const auto givesMass = [&](const PendingPart* p) {
            return p->massColumn != 0 && (compound.dynamic || !p->massFromMaterial);
        };
        const std::size_t given = static_cast<std::size_t>(std::count_if(parts.begin(), parts.end(), givesMass));
        const std::string& name = compound.dynamic ? scene_.dynamics[compound.index].name
                                                   : scene_.kinematics[compound.index].name;
        if (!compound.dynamic && given > 0) {
            const PendingPart& first = **std::find_if(parts.begin(), parts.end(), givesMass);
            sink_.report(first.line, first.massColumn, "Mass", "no Mass for a part of a KinematicsObject",
                         formatNumber(first.part.mass), quoted(name) + " moves as prescribed and has no mass");
            return false;
        }
        if (given > 0 && given < parts.size()) {
            const PendingPart& missing = **std::find_if(parts.begin(), parts.end(), [&](const PendingPart* p) { return !givesMass(p); });
            sink_.report(missing.line, missing.column, "Mass", "a Mass on every Part of " + quoted(name) + " or on none",
                         lineText(missing.line),
                         "give each part of a compound its Mass, or give none and the body's Mass is shared by "
                         "volume (uniform density)");
            return false;
        }
        if (given == parts.size()) {
            DynamicObject& body = scene_.dynamics[compound.index];
            if (compound.massColumn != 0) {
                sink_.report(compound.line, compound.massColumn, "Mass", "no Mass on a compound whose parts give theirs",
                             formatNumber(body.mass), "the body's mass is the sum of its parts' Mass; leave one out");
                return false;
            }
            if (compound.densityColumn != 0) {
                sink_.report(compound.line, compound.densityColumn, "Density",
                             "no Density on a compound whose parts give their Mass", formatNumber(*compound.density),
                             "the body's mass is the sum of its parts' Mass; leave one out");
                return false;
            }
            Real total = 0;
            for (const CompoundPart& part : shape.parts) total += part.mass;
            body.setMass(total);
            return true;
        }
        Real volume = 0;
        for (const CompoundPart& part : shape.parts) volume += partVolume(part);
        if (compound.dynamic && compound.density) {
            // m = ρ·ΣV: the parts' masses are then ρ·V each, shared out below as for a given Mass.
            DynamicObject& body = scene_.dynamics[compound.index];
            const Real mass = *compound.density * volume;
            if (!massInRange(mass, *compound.density, volume, compound.line,
                             compound.densityColumn != 0 ? compound.densityColumn : compound.column)) {
                return false;
            }
            body.setMass(mass);
        }
        const Real total = compound.dynamic ? scene_.dynamics[compound.index].mass : kKinematicCompoundMass;
        for (CompoundPart& part : shape.parts) part.mass = total * partVolume(part) / volume;
        return true;
    }

    /// The text of line @p number as the tokenizer saw it (for messages about a whole Part).
    std::string lineText(int number) const {
        for (const auto& [key, text] : partLines_) {
            if (key == number) return text;
        }
        return "";
    }

    void addPlane(const RecordValues& values, const SceneLine& line, int index) {
        CollisionPlane plane;
        plane.name = claimName(values, line, index);
        plane.position = values.triple("Position", kZero);
        plane.color = toColor(values.triple("Color", kDefaultColor));
        const Material* material = materialOf(values, line, plane.material);
        plane.elasticity = values.number("Elasticity", materialValue(material, &Material::elasticity, kStaticElasticity));
        plane.friction = values.number("Friction", materialValue(material, &Material::friction, kStaticFriction));

        const Vec3 normal = values.triple("Normal", kDefaultNormal);
        if (!usableDirection(normal)) {  // core/limits.hpp: what World::World requires too
            const std::string& written = values.asWritten("Normal");
            sink_.report(line.number, values.valueColumn("Normal"), "Normal", "a direction (a vector of length > 0, "
                         "whose squares do not overflow)", written.empty() ? formatVector(normal) : written,
                         "the normal gives the direction the plane faces, e.g. (0, 1, 0) for a floor");
        } else {
            plane.normal = normal / glm::length(normal);  // the collision code relies on a unit normal
        }
        noteSpace(values, line.number, planeSpaceRefs_);
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
        WorldSettings defaults;
        defaults.gravity = kDefaultGravity;
        defaults.timeStep = kDefaultTimeStep;
        defaults.integrator = kDefaultIntegrator;
        defaults.duration = kDefaultDuration;
        defaults.broadphase = kDefaultBroadphase;
        scene_.settings = readSettings(values, defaults);
    }

    /// The World fields of a World or Space record: each one given, or @p defaults' value.
    static WorldSettings readSettings(const RecordValues& values, const WorldSettings& defaults) {
        WorldSettings settings = defaults;
        settings.gravity = values.triple("Gravity", defaults.gravity);
        settings.timeStep = values.number("TimeStep", defaults.timeStep);
        settings.integrator = values.choice<IntegratorKind>("Integrator", kIntegratorChoices, defaults.integrator);
        settings.duration = values.number("Duration", defaults.duration);
        settings.broadphase = values.choice<BroadphaseKind>("Broadphase", kBroadphaseChoices, defaults.broadphase);
        auto count = [&](std::string_view field, int fallback) {
            return static_cast<int>(values.number(field, static_cast<Real>(fallback)));
        };
        settings.solver = values.choice<SolverKind>("Solver", kSolverChoices, defaults.solver);
        settings.substeps = count("Substeps", defaults.substeps);
        settings.substepsPerIsland = values.choice<bool>("SubstepsPerIsland", kBooleanChoices, defaults.substepsPerIsland);
        settings.velocityIterations = count("Iterations", defaults.velocityIterations);
        settings.relaxIterations = count("RelaxIterations", defaults.relaxIterations);
        settings.relaxBallFriction = values.choice<bool>("RelaxBallFriction", kBooleanChoices, defaults.relaxBallFriction);
        settings.contactOrder = values.choice<ContactOrder>("ContactOrder", kContactOrderChoices, defaults.contactOrder);
        settings.impulseIterations = count("ImpulseIterations", defaults.impulseIterations);
        settings.warmStarting = values.choice<bool>("WarmStarting", kBooleanChoices, defaults.warmStarting);
        settings.accumulateImpulses = values.choice<bool>("AccumulateImpulses", kBooleanChoices, defaults.accumulateImpulses);
        settings.positionCorrection = values.choice<bool>("PositionCorrection", kBooleanChoices, defaults.positionCorrection);
        settings.contactHertz = values.number("ContactHertz", defaults.contactHertz);
        settings.contactDampingRatio = values.number("ContactDampingRatio", defaults.contactDampingRatio);
        settings.jointHertz = values.number("JointHertz", defaults.jointHertz);
        settings.jointDampingRatio = values.number("JointDampingRatio", defaults.jointDampingRatio);
        settings.sleeping = values.choice<bool>("Sleep", kBooleanChoices, defaults.sleeping);
        settings.sleepLinearSpeed = values.number("SleepLinearSpeed", defaults.sleepLinearSpeed);
        settings.sleepAngularSpeed = values.number("SleepAngularSpeed", defaults.sleepAngularSpeed);
        settings.sleepLinearAcceleration = values.number("SleepLinearAcceleration", defaults.sleepLinearAcceleration);
        settings.sleepAngularAcceleration = values.number("SleepAngularAcceleration", defaults.sleepAngularAcceleration);
        settings.timeToSleep = values.number("TimeToSleep", defaults.timeToSleep);
        settings.stepPlan = values.choice<bool>("StepPlan", kBooleanChoices, defaults.stepPlan);
        settings.fastPath = values.choice<bool>("FastPath", kBooleanChoices, defaults.fastPath);
        settings.continuousCollision =
            values.choice<bool>("ContinuousCollision", kBooleanChoices, defaults.continuousCollision);
        settings.threads = count("Threads", defaults.threads);
        settings.narrowphase = values.choice<NarrowphaseKind>("Narrowphase", kNarrowphaseChoices, defaults.narrowphase);
        settings.frictionCombine = values.choice<CombineRule>("FrictionCombine", kCombineChoices, defaults.frictionCombine);
        settings.elasticityCombine =
            values.choice<CombineRule>("ElasticityCombine", kCombineChoices, defaults.elasticityCombine);
        return settings;
    }

    /// An Expect record (src/world/expectations.hpp): exactly one quantity,
    /// at most one timing (Time, Apex, or a From/Until window), and the
    /// Tolerance or Compare its quantity needs. The names it refers to are
    /// checked in finish(), when every object of the file is known.
    void addExpect(const RecordValues& values, const SceneLine& line) {
        Expectation e;
        e.line = line.number;
        const ExpectParts parts = expectParts(values, line);
        const Token& recordName = line.tokens.front();
        const std::string written = lineText(line);

        if (parts.quantity == nullptr) {
            sink_.report(line.number, recordName.column, "Expect", "one quantity to check (" + kExpectQuantityList + ")",
                         written, "e.g. Expect, Object=ball, Time=1, PositionY=0.5, Tolerance=0.01");
            return;
        }
        const std::string_view quantity = parts.quantityField;
        e.quantity = parts.kind;
        e.component = parts.component;
        const bool vector = quantity == "Position" || quantity == "Velocity";
        if (vector && e.component >= 0) {
            e.target = values.triple(quantity, kZero)[e.component];
        } else if (vector) {
            e.targetVector = values.triple(quantity, kZero);
        } else if (e.quantity == ExpectQuantity::AtRest || e.quantity == ExpectQuantity::Asleep) {
            e.flag = values.choice<bool>(quantity, kBooleanChoices, true);
        } else if (e.quantity == ExpectQuantity::NotThroughPlane) {
            e.plane = values.text(quantity).value_or("");
        } else {
            e.target = values.number(quantity, 0);
        }

        // When: one moment, one apex, or a window (the whole run by default).
        if (values.isSet("Time")) {
            e.when = ExpectWhen::Instant;
            e.time = values.number("Time", 0);
        } else if (values.isSet("Apex")) {
            e.when = ExpectWhen::Apex;
            const Real apex = values.number("Apex", 1);
            e.apex = static_cast<int>(apex);
            if (apex != std::floor(apex) || apex > kMaxApex) {
                sink_.report(line.number, values.valueColumn("Apex"), "Apex", "a whole number from 1 to 1000",
                             formatNumber(apex), std::string(kApexCountHint));
            }
        } else {
            e.from = values.number("From", 0);
            e.until = values.number("Until", -1);
            if (values.isSet("Until") && values.isSet("From") && e.until < e.from) {
                sink_.report(line.number, values.valueColumn("Until"), "Until", "a time not before From (" +
                             formatNumber(e.from) + " s)", formatNumber(e.until), "the window runs from From to Until");
            }
        }
        if (parts.secondTiming != nullptr) {
            sink_.report(line.number, parts.secondTiming->column, std::string(splitNamed(*parts.secondTiming)->name.text),
                         "one timing per Expect record (Time, Apex, or a From/Until window)",
                         std::string(parts.secondTiming->text),
                         std::string(splitNamed(*parts.timing)->name.text) + " is given at column " +
                             std::to_string(parts.timing->column) + "; write a second Expect line");
        }
        if (parts.secondQuantity != nullptr) {
            sink_.report(line.number, parts.secondQuantity->column,
                         std::string(splitNamed(*parts.secondQuantity)->name.text), "one quantity per Expect record",
                         std::string(parts.secondQuantity->text),
                         std::string(splitNamed(*parts.quantity)->name.text) + " at column " +
                             std::to_string(parts.quantity->column) + " is this record's quantity; write a second "
                             "Expect line for the other one");
        }

        // How: Tolerance and Compare, as the quantity needs them.
        e.compare = values.choice<ExpectCompare>("Compare", kCompareChoices, ExpectCompare::Within);
        const bool numeric = !vector || e.component >= 0;
        const bool comparable = numeric && e.quantity != ExpectQuantity::AtRest &&
                                e.quantity != ExpectQuantity::Asleep && e.quantity != ExpectQuantity::NotThroughPlane;
        const std::string name = quantityLabel(values, parts);
        if (values.isSet("Compare") && !comparable) {
            sink_.report(line.number, values.valueColumn("Compare"), "Compare",
                         "no Compare for " + name, values.text("Compare").value_or(""),
                         "Compare (Within, AtLeast, AtMost) goes with a single number, e.g. PositionY or Speed");
        }
        const bool oneSided = comparable && e.compare != ExpectCompare::Within;
        // A misspelt Compare was reported already; guessing what it meant would add a second, wrong error.
        const bool compareUnreadable = values.isSet("Compare") && !values.text("Compare");
        const bool toleranceOptional = e.quantity == ExpectQuantity::AtRest || e.quantity == ExpectQuantity::NotThroughPlane;
        const bool toleranceAllowed = !oneSided && e.quantity != ExpectQuantity::Asleep;
        if (values.isSet("Tolerance") && !toleranceAllowed) {
            sink_.report(line.number, values.valueColumn("Tolerance"), "Tolerance", "no Tolerance for " + name +
                         (oneSided ? " with Compare=" + values.text("Compare").value_or("") : std::string()),
                         formatNumber(values.number("Tolerance", 0)),
                         oneSided ? "a one-sided bound is the target itself" : "there is nothing to tolerate");
        } else if (!values.isSet("Tolerance") && toleranceAllowed && !toleranceOptional && !compareUnreadable) {
            sink_.report(line.number, recordName.column, "Tolerance", "a Tolerance for " + name +
                         (numeric ? " (it passes when |measured - target| <= Tolerance)"
                                  : " (it passes when the distance from the target <= Tolerance)"),
                         written,
                         numeric ? "e.g. Tolerance=0.01; or Compare=AtLeast / AtMost for a one-sided bound"
                                 : "e.g. Tolerance=0.01, in the quantity's unit");
        }
        const Real defaultTolerance = e.quantity == ExpectQuantity::AtRest ? kDefaultRestSpeed : 0;
        e.tolerance = values.number("Tolerance", defaultTolerance);

        // Who: a body (checked against the file's names in finish()).
        if (const std::optional<std::string> object = values.text("Object")) {
            e.object = *object;
            pendingNames_.push_back({line.number, values.valueColumn("Object"), "Object", *object,
                                     kDynamicRecord, scene_.expectations.size(), parts.quantity->column,
                                     quantityLabel(values, parts)});
        } else if (e.quantity != ExpectQuantity::EnergyChange && !values.isSet("Object")) {
            sink_.report(line.number, recordName.column, "Object", "the name of the DynamicObject or SoftBody to check", written,
                         "every Expect except EnergyChange names its body, e.g. Object=ball");
        }
        if (e.quantity == ExpectQuantity::NotThroughPlane && values.text(quantity)) {
            pendingNames_.push_back({line.number, values.valueColumn(quantity), std::string(quantity), e.plane,
                                     kPlaneRecord, scene_.expectations.size()});
        }
        scene_.expectations.push_back(std::move(e));
    }

    /// The tokens of an Expect line that set its quantity and its timing.
    struct ExpectParts {
        const Token* quantity = nullptr;        ///< The first quantity field, e.g. `PositionY=0.5`.
        std::string_view quantityField;         ///< Its field's canonical name ("Position").
        ExpectQuantity kind = ExpectQuantity::Position;
        int component = kWholeField;            ///< Its component (0–2), or kWholeField.
        std::size_t field = 0;                  ///< Its index in the record table.
        const Token* secondQuantity = nullptr;  ///< A second quantity field: an error.
        const Token* timing = nullptr;          ///< The first of Time, Apex, From, Until.
        const Token* secondTiming = nullptr;    ///< A timing that conflicts with the first: an error.
    };

    static ExpectParts expectParts(const RecordValues& values, const SceneLine& line) {
        ExpectParts parts;
        bool timingIsWindow = false;
        for (std::size_t i = 1; i < line.tokens.size(); ++i) {
            const std::optional<NamedToken> named = splitNamed(line.tokens[i]);
            if (!named) continue;
            const std::optional<FieldRef> ref = findField(values.spec(), named->name.text);
            if (!ref) continue;
            const std::string_view field = values.spec().fields[ref->field].name;
            for (const ExpectQuantityField& q : kExpectQuantityFields) {
                if (q.name != field) continue;
                if (parts.quantity == nullptr) {
                    parts.quantity = &line.tokens[i];
                    parts.quantityField = q.name;
                    parts.kind = q.quantity;
                    parts.component = ref->component;
                    parts.field = ref->field;
                } else if (parts.secondQuantity == nullptr) {
                    parts.secondQuantity = &line.tokens[i];
                }
            }
            const bool window = field == "From" || field == "Until";
            if (field == "Time" || field == "Apex" || window) {
                if (parts.timing == nullptr) {
                    parts.timing = &line.tokens[i];
                    timingIsWindow = window;
                } else if (parts.secondTiming == nullptr && !(window && timingIsWindow)) {
                    parts.secondTiming = &line.tokens[i];
                }
            }
        }
        return parts;
    }

    /// "PositionY", "AtRest": the quantity's canonical name, for messages.
    static std::string quantityLabel(const RecordValues& values, const ExpectParts& parts) {
        return config::fieldName(values.spec().fields[parts.field], parts.component);
    }

    /// The record as written, fields joined by ", ": what a missing-field message shows as found.
    static std::string lineText(const SceneLine& line) {
        std::string text;
        for (const Token& token : line.tokens) text += (text.empty() ? "" : ", ") + std::string(token.text);
        return text;
    }

    /// The Expect records' Object and NotThroughPlane must name a body (a DynamicObject or a
    /// SoftBody) and a plane of the file; the name is replaced by the object's own spelling. A
    /// quantity only one kind of body has is refused for the other: Volume and Pressure are a soft
    /// body's, AngularSpeed and TiltDeg a rigid body's (a soft body has no single rotation).
    void resolveExpectNames() {
        // An Expect record's quantity must be one its body has
        const auto refuseQuantityOfOtherKind = [&](const PendingName& pending, ExpectQuantity quantity,
                                                   const NameUse& body) {
            const bool soft = body.record == kSoftBodyRecord;
            const bool softOnly = quantity == ExpectQuantity::Volume || quantity == ExpectQuantity::Pressure;
            const bool rigidOnly = quantity == ExpectQuantity::AngularSpeed || quantity == ExpectQuantity::TiltDeg;
            const std::string whose = "'" + body.name + "' is the " + std::string(body.record) + " on line " +
                                      std::to_string(body.line);
            if (soft && rigidOnly) {
                sink_.report(pending.line, pending.quantityColumn, pending.quantity,
                             "a quantity a SoftBody has (Position[XYZ], Velocity[XYZ], Speed, EnergyChange, AtRest, "
                             "Asleep, NotThroughPlane, Volume, Pressure)",
                             pending.quantity, whose + ": a soft body has no single rotation to measure");
            } else if (!soft && softOnly) {
                sink_.report(pending.line, pending.quantityColumn, pending.quantity,
                             "a quantity a DynamicObject has (every one but Volume and Pressure)", pending.quantity,
                             whose + ": Volume and Pressure are a SoftBody's (the gas inside it)");
            }
        };
        for (const PendingName& pending : pendingNames_) {
            const bool object = pending.field == "Object";
            const auto accepts = [&](std::string_view record) {
                return record == pending.record || (object && record == kSoftBodyRecord);
            };
            const auto found = names_.find(toLower(pending.name));
            if (found == names_.end() || !accepts(found->second.record)) {
                std::string hint;
                if (found != names_.end()) {
                    hint = "'" + found->second.name + "' is the " + std::string(found->second.record) + " on line " +
                           std::to_string(found->second.line);
                } else {
                    std::vector<std::string> known;
                    for (const auto& [key, use] : names_) {
                        if (accepts(use.record)) known.push_back(use.name);
                    }
                    if (const auto suggestion = closestMatch(pending.name, known)) {
                        hint = "did you mean '" + *suggestion + "'?";
                    }
                }
                const std::string kinds = std::string(pending.record) + (object ? " or SoftBody" : "");
                sink_.report(pending.line, pending.column, pending.field, "the name of a " + kinds + " in this file",
                             pending.name, hint);
                continue;
            }
            Expectation& e = scene_.expectations[pending.expectation];
            (object ? e.object : e.plane) = found->second.name;
            if (object) refuseQuantityOfOtherKind(pending, e.quantity, found->second);
        }
    }

    /// A MayChange record: the field (or one component of it) that a student
    /// may edit, of the object named by Object, or of the World record when
    /// Object is left out. Its object may come later in the file, so the
    /// names are checked in finish(), by resolveMayChange().
    void addMayChange(const RecordValues& values, const SceneLine& line) {
        const std::optional<std::string> field = values.text("Field");
        if (!values.isSet("Field")) {
            sink_.report(line.number, line.tokens.front().column, "Field", "the field a student may change",
                         lineText(line),
                         "e.g. MayChange, Object=ball, Field=Elasticity, or MayChange, Field=TimeStep for the World "
                         "record");
            return;
        }
        const std::optional<std::string> object = values.text("Object");
        if (!field || (values.isSet("Object") && !object)) return;  // a malformed name: reported already
        pendingChanges_.push_back({line.number, object, values.valueColumn("Object"), *field, values.valueColumn("Field")});
    }

    /// Each MayChange record's Object must name an object of the file, and its
    /// Field must be a field of that object's record (of the World record
    /// without an Object). Name cannot change: grading matches records by it.
    void resolveMayChange() {
        for (const PendingChange& pending : pendingChanges_) {
            const RecordSpec* spec = findRecord("World");
            std::string object;
            if (pending.object) {
                const auto found = names_.find(toLower(*pending.object));
                if (found == names_.end()) {
                    std::vector<std::string> known;
                    for (const auto& [key, use] : names_) known.push_back(use.name);
                    const auto suggestion = closestMatch(*pending.object, known);
                    sink_.report(pending.line, pending.objectColumn, "Object", "the name of an object in this file",
                                 *pending.object,
                                 suggestion ? "did you mean '" + *suggestion + "'?"
                                            : "leave Object out for a field of the World record");
                    continue;
                }
                object = found->second.name;
                spec = findRecord(found->second.record);
            }
            const std::optional<FieldRef> ref = findField(*spec, pending.field);
            if (ref && spec->fields[ref->field].name != "Name") {
                scene_.mayChange.push_back({pending.line, object, fieldName(spec->fields[ref->field], ref->component)});
                continue;
            }
            std::vector<std::string> spellings;
            std::string names;
            for (const FieldSpec& f : spec->fields) {
                if (f.name == "Name") continue;
                names += (names.empty() ? "" : ", ") + std::string(f.name);
            }
            for (const std::string& spelling : fieldSpellings(*spec)) {
                if (spelling != "Name") spellings.push_back(spelling);
            }
            const std::string owner = object.empty() ? std::string("the World record")
                                                     : "the " + std::string(spec->name) + " " + quoted(object);
            std::string hint;
            if (ref) {
                hint = "grading finds each object by its name, so the name cannot change";
            } else if (const auto suggestion = closestMatch(pending.field, spellings)) {
                hint = "did you mean '" + *suggestion + "'?";
            } else if (object.empty()) {
                hint = "without Object, Field is a field of the World record; name the object it belongs to, "
                       "e.g. Object=ball";
            }
            sink_.report(pending.line, pending.fieldColumn, "Field", "a field of " + owner + " (" + names + ")",
                         pending.field, std::move(hint));
        }
    }

    void addSpring(const RecordValues& values, const SceneLine& line, int index) {
        const Token& recordName = line.tokens.front();
        PendingSpring pending;
        pending.spring.name = claimName(values, line, index);
        pending.line = line.number;
        pending.bodyA = values.text("BodyA");
        pending.bodyAColumn = values.valueColumn("BodyA");
        pending.bodyB = values.text("BodyB");
        pending.bodyBColumn = values.valueColumn("BodyB");
        pending.spring.anchorA = values.triple("AnchorA", kZero);
        pending.spring.anchorB = values.triple("AnchorB", kZero);
        pending.spring.stiffness = values.number("Stiffness", 0);
        pending.spring.damping = values.number("Damping", kDefaultDamping);
        pending.restLengthGiven = values.valueColumn("RestLength") != 0;
        pending.spring.restLength = values.number("RestLength", 0);
        if (pending.bodyAColumn == 0) {
            sink_.report(line.number, recordName.column, "Spring", "a BodyA field (every spring needs one)",
                         std::string(recordName.text), "name the DynamicObject it pulls, e.g. BodyA=Ball");
        }
        if (values.valueColumn("Stiffness") == 0) {
            sink_.report(line.number, recordName.column, "Spring", "a Stiffness field (every spring needs one)",
                         std::string(recordName.text), "give the spring constant k in N/m, e.g. Stiffness=100");
        }
        pendingSprings_.push_back(std::move(pending));
    }

    void addAttractor(const RecordValues& values, const SceneLine& line, int index) {
        const Token& recordName = line.tokens.front();
        Attractor attractor;
        attractor.name = claimName(values, line, index);
        attractor.position = values.triple("Position", kZero);
        attractor.mu = values.number("Mu", 0);
        if (values.valueColumn("Mu") == 0) {
            sink_.report(line.number, recordName.column, "Attractor", "a Mu field (every attractor needs one)",
                         std::string(recordName.text),
                         "give its gravitational parameter G*M in m^3/s^2, e.g. Mu=3.986e14 for the Earth");
        }
        noteSpace(values, line.number, attractorSpaceRefs_);
        scene_.attractors.push_back(std::move(attractor));
    }

    // ---------------------------------------------------------- soft bodies

    /// A SoftBody: a closed mesh of nodes and springs with a gas inside (src/objects/soft_body.hpp).
    /// Shape is Sphere or Box; Radius belongs to a sphere and HalfExtents to a box; Resolution is a
    /// whole number within the mesh's bounds (soft_mesh.hpp), so nobody asks for a million nodes.
    void addSoftBody(const RecordValues& values, const SceneLine& line, int index) {
        const Token& recordName = line.tokens.front();
        const std::size_t before = sink_.diagnostics().size();
        SoftBody body;
        body.name = claimName(values, line, index);
        body.color = toColor(values.triple("Color", kDefaultColor));
        const Material* material = materialOf(values, line, body.material);
        body.elasticity = values.number("Elasticity", materialValue(material, &Material::elasticity, kDynamicElasticity));
        body.friction = values.number("Friction", materialValue(material, &Material::friction, kDynamicFriction));

        SoftBodyMaking making;
        making.shape = values.choice<Shape>("Shape", kShapeChoices, kDefaultShape);
        const bool sphere = making.shape == Shape::Sphere;
        if (!sphere && making.shape != Shape::Box) {
            sink_.report(line.number, shapeColumn(values, line), "Shape", "Sphere or Box for a SoftBody",
                         values.text("Shape").value_or(toString(making.shape)),
                         "a soft body's surface is an icosphere (Sphere) or a subdivided cube (Box)");
        }
        const std::string_view otherSize = sphere ? "HalfExtents" : "Radius";
        if (values.isSet(otherSize)) {
            sink_.report(line.number, values.valueColumn(otherSize), std::string(otherSize),
                         std::string("no ") + std::string(otherSize) + " for a " + (sphere ? "Sphere" : "Box"),
                         values.asWritten(otherSize),
                         sphere ? "a Sphere takes Radius; HalfExtents sizes a Box" : "a Box takes HalfExtents; Radius sizes a Sphere");
        }
        making.position = values.triple("Position", kZero);
        making.velocity = values.triple("Velocity", kZero);
        making.angularVelocity = values.triple("AngularVelocity", kZero);
        making.radius = values.number("Radius", kRadiusPerDiameter);
        making.halfExtents = values.triple("HalfExtents", kDefaultSoftHalfExtents);
        making.mass = values.number("Mass", kDefaultMass);
        making.stiffness = values.number("Stiffness", 0);
        making.damping = values.number("Damping", kDefaultDamping);
        making.bendStiffness = values.number("BendStiffness", 0);
        making.nRT = values.number("Pressure", 0);
        if (!values.isSet("Stiffness")) {
            sink_.report(line.number, recordName.column, "SoftBody", "a Stiffness field (every soft body needs one)",
                         std::string(recordName.text), "give the edge springs' constant k in N/m, e.g. Stiffness=200");
        }
        const int least = sphere ? 0 : 1;
        const int most = sphere ? kMaxIcosphereSubdivisions : kMaxCubeCells;
        const Real resolution = values.number("Resolution", sphere ? kDefaultSphereResolution : kDefaultBoxResolution);
        making.resolution = static_cast<int>(resolution);
        if (resolution != std::floor(resolution) || resolution < least || resolution > most) {
            making.resolution = least;
            sink_.report(line.number, values.valueColumn("Resolution"), "Resolution",
                         "a whole number from " + std::to_string(least) + " to " + std::to_string(most) + " for a " +
                             (sphere ? "Sphere" : "Box"),
                         formatNumber(resolution),
                         sphere ? "the icosahedron's triangles are cut in 4 that many times: 2 gives 162 nodes, 3 gives "
                                  "642, 5 gives 10242"
                                : "the cells along each edge of the cube: 4 gives 98 nodes, 8 gives 386, 32 gives 6146");
        }
        if (sink_.diagnostics().size() == before) buildSoftBody(making, body);
        softBodyLines_.push_back(line.number);
        noteSpace(values, line.number, softBodySpaceRefs_);
        scene_.softBodies.push_back(std::move(body));
    }

    /// The explicit limit h·ω < 2 of each soft body's springs (src/soft/soft_stability.hpp): a warning, as for springs.
    void warnAboutUnstableSoftBodies() {
        for (std::size_t i = 0; i < scene_.softBodies.size(); ++i) {
            const SoftBody& body = scene_.softBodies[i];
            // Its space's step, substeps and integrator (a Space record may set its own); the one clock's
            // Duration, TimeScale times over in simulated time
            const std::uint32_t space = scene_.softBodySpace.empty() ? kDefaultSpace : scene_.softBodySpace[i];
            const WorldSettings& settings = space == kDefaultSpace ? scene_.settings : scene_.spaces[space - 1].settings;
            const Real timeScale = space == kDefaultSpace ? Real(1) : scene_.spaces[space - 1].timeScale;
            const Real h = integrationStep(settings);  // the nodes move by the substep under SequentialImpulse
            const Real steps = std::round(timeScale * scene_.settings.duration / h);
            const SoftStability s = analyseSoftBody(body, settings.integrator, h);
            if (s.growthPerStep <= 1 + kGrowthTolerance) continue;
            const Real growthOverRun = std::pow(s.growthPerStep, steps);
            if (settings.integrator == IntegratorKind::ExplicitEuler && growthOverRun <= kTolerableGrowth) continue;
            char text[512];
            std::snprintf(text, sizeof text,
                          "the step is past its springs' stability limit for %s: h*w = %.4g s * %.4g rad/s = %.3g > %.3g "
                          "(w = sqrt(k_eff/m_node), k_eff = 2 x the stiffness at its busiest node = %.4g N/m, m_node = "
                          "%.4g kg%s); its swing can grow x%.3g every step; use a step below %.4g s (TimeStep, or more "
                          "Substeps), a lower Stiffness or Damping, or a lower Resolution",
                          toString(settings.integrator), double(h), double(s.omega), double(h * s.omega),
                          double(s.largestStableStep * s.omega), double(s.effectiveStiffness), double(s.nodeMass),
                          s.dampingRatio > 0 ? ", the limit is below 2 because of Damping" : "", double(s.growthPerStep),
                          double(s.largestStableStep));
            scene_.warnings.push_back(scene_.sourcePath + ":" + std::to_string(softBodyLines_[i]) + ": warning: SoftBody " +
                                      quoted(body.name) + ": " + text);
        }
    }

    /// A Space: a simulation of its own (src/world/spaces.hpp). Its World fields are read in
    /// resolveSpaces(), over the World record's, which may come later in the file.
    void addSpace(const RecordValues& values, const SceneLine& line, int index) {
        const Token& recordName = line.tokens.front();
        if (!values.isSet("Name")) {
            sink_.report(line.number, recordName.column, "Space", "a Name field (every space needs one)",
                         std::string(recordName.text), "objects join it with Space=NAME, e.g. Space, Name=verlet");
        }
        if (values.isSet("Duration")) {
            sink_.report(line.number, values.valueColumn("Duration"), "Duration", "no Duration on a Space",
                         "Duration=" + values.asWritten("Duration"),
                         "every space runs for the World record's Duration, on one shared clock (TimeScale sets its pace)");
        }
        PendingSpace pending{SpaceDef{}, values};
        pending.space.name = claimName(values, line, index);
        pending.space.timeScale = values.number("TimeScale", 1);
        pending.space.paused = values.choice<bool>("Paused", kBooleanChoices, false);
        pending.space.line = line.number;
        pendingSpaces_.push_back(std::move(pending));
    }

    /// Remembers the `Space=` of the object just read (parallel to its list in the Scene).
    void noteSpace(const RecordValues& values, int lineNumber, std::vector<SpaceRef>& refs) {
        SpaceRef ref;
        if (const std::optional<std::string> name = values.text("Space")) {
            ref.name = *name;
            ref.column = values.valueColumn("Space");
            ref.line = lineNumber;
        }
        refs.push_back(std::move(ref));
    }

    /// Each space's settings (the World record's, with its own fields over them), each object's
    /// space, and the rule that spaces never touch: a spring or joint joins bodies of one space.
    void resolveSpaces() {
        std::vector<std::string> names;
        for (PendingSpace& pending : pendingSpaces_) {
            pending.space.settings = readSettings(pending.values, scene_.settings);
            names.push_back(pending.space.name);
            scene_.spaces.push_back(pending.space);
        }
        const auto resolve = [&](const std::vector<SpaceRef>& refs, std::vector<std::uint32_t>& out) {
            out.clear();
            for (const SpaceRef& ref : refs) {
                if (ref.name.empty()) {
                    out.push_back(kDefaultSpace);
                    continue;
                }
                const auto found = std::find_if(names.begin(), names.end(),
                                                 [&](const std::string& n) { return equalsIgnoreCase(n, ref.name); });
                if (found == names.end()) {
                    std::string hint = "declare it first, e.g. Space, Name=" + ref.name;
                    if (const std::optional<std::string> close = closestMatch(ref.name, names)) {
                        hint = "did you mean '" + *close + "'?";
                    }
                    sink_.report(ref.line, ref.column, "Space", "the Name of a Space record", ref.name, hint);
                    out.push_back(kDefaultSpace);
                } else {
                    out.push_back(static_cast<std::uint32_t>(found - names.begin()) + 1);
                }
            }
        };
        resolve(dynamicSpaceRefs_, scene_.dynamicSpace);
        resolve(kinematicSpaceRefs_, scene_.kinematicSpace);
        resolve(planeSpaceRefs_, scene_.planeSpace);
        resolve(attractorSpaceRefs_, scene_.attractorSpace);
        resolve(regionSpaceRefs_, scene_.regionSpace);
        resolve(softBodySpaceRefs_, scene_.softBodySpace);
        if (scene_.spaces.empty()) {  // a scene of one simulation, as before spaces
            scene_.dynamicSpace.clear();
            scene_.kinematicSpace.clear();
            scene_.planeSpace.clear();
            scene_.attractorSpace.clear();
            scene_.regionSpace.clear();
            scene_.softBodySpace.clear();
            return;
        }
        const auto spaceOfBody = [&](const std::string& name) -> std::optional<std::uint32_t> {
            for (std::size_t i = 0; i < scene_.dynamics.size(); ++i) {
                if (equalsIgnoreCase(scene_.dynamics[i].name, name)) return scene_.dynamicSpace[i];
            }
            return std::nullopt;
        };
        const auto spaceName = [&](std::uint32_t space) {
            return space == kDefaultSpace ? std::string("the default space") : "space '" + scene_.spaces[space - 1].name + "'";
        };
        for (std::size_t k = 0; k < scene_.springs.size(); ++k) {
            const Spring& spring = scene_.springs[k];
            if (spring.bodyB == kFixedInWorld) continue;
            const std::uint32_t a = scene_.dynamicSpace[spring.bodyA];
            const std::uint32_t b = scene_.dynamicSpace[spring.bodyB];
            if (a == b) continue;
            sink_.report(springLines_.at(k), 1, "Spring", "two bodies of one space",
                         "'" + scene_.dynamics[spring.bodyA].name + "' in " + spaceName(a) + " and '" +
                             scene_.dynamics[spring.bodyB].name + "' in " + spaceName(b),
                         "spaces never touch: each has its own bodies, broadphase and solver");
        }
        for (std::size_t k = 0; k < scene_.joints.size(); ++k) {
            const JointDef& joint = scene_.joints[k];
            if (joint.bodyB.empty()) continue;
            const std::optional<std::uint32_t> a = spaceOfBody(joint.bodyA);
            const std::optional<std::uint32_t> b = spaceOfBody(joint.bodyB);
            if (!a || !b || *a == *b) continue;
            sink_.report(pendingJoints_.at(k).line, 1, toString(joint.kind), "two bodies of one space",
                         "'" + joint.bodyA + "' in " + spaceName(*a) + " and '" + joint.bodyB + "' in " + spaceName(*b),
                         "spaces never touch: each has its own bodies, broadphase and solver");
        }
    }

    /// A Region: its volume, its effect, and the fields that effect takes (src/forces/region.hpp).
    ///
    /// A field the effect does not use is an error rather than ignored: `Density=1000` on a Drag
    /// region most likely meant Buoyancy, and a silent region that does nothing is the hardest
    /// mistake to find.
    void addRegion(const RecordValues& values, const SceneLine& line, int index) {
        const Token& recordName = line.tokens.front();
        Region region;
        region.name = claimName(values, line, index);
        region.shape = values.choice<RegionShape>("Shape", kRegionShapeChoices, RegionShape::Box);
        region.position = values.triple("Position", kZero);
        region.halfExtents = values.triple("Scale", Vec3(1)) * Real(0.5);
        region.radius = values.number("Radius", region.radius);
        region.normal = values.triple("Normal", kDefaultNormal);
        region.law = values.choice<DragLaw>("Law", kDragLawChoices, DragLaw::Linear);
        region.coefficient = values.number("Coefficient", 0);
        region.angularCoefficient = values.number("AngularCoefficient", 0);
        region.velocity = values.triple("Velocity", kZero);
        region.gravity = values.triple("Gravity", kZero);
        region.density = values.number("Density", 0);
        region.strength = values.number("Strength", 0);
        const Real seed = values.number("Seed", 0);
        if (!values.isSet("Effect")) {
            sink_.report(line.number, recordName.column, "Region", "an Effect field (every region needs one)",
                         std::string(recordName.text),
                         "say what it does: Effect=Drag, Wind, Gravity, Buoyancy, RandomForce, Kill or Conveyor");
            return;
        }
        region.effect = values.choice<RegionEffect>("Effect", kEffectChoices, RegionEffect::Drag);
        const std::string effect = toString(region.effect);

        // The size fields of the other shapes
        const auto refuse = [&](std::string_view field, const std::string& why, const std::string& hint) {
            if (!values.isSet(field)) return;
            sink_.report(line.number, values.valueColumn(field), std::string(field), why,
                         std::string(field) + "=" + values.asWritten(field), hint);
        };
        const char* shape = region.shape == RegionShape::Box      ? "Box"
                            : region.shape == RegionShape::Sphere ? "Sphere"
                                                                  : "HalfSpace";
        if (region.shape != RegionShape::Box) refuse("Scale", std::string("no Scale on a ") + shape + " region", "Scale is a Box region's edges");
        if (region.shape != RegionShape::Sphere) refuse("Radius", std::string("no Radius on a ") + shape + " region", "Radius is a Sphere region's");
        if (region.shape != RegionShape::HalfSpace) refuse("Normal", std::string("no Normal on a ") + shape + " region", "Normal is a HalfSpace region's");

        // What each effect takes: required (R) and optional (O); anything else is refused
        struct Use { std::string_view field; bool required; };
        std::vector<Use> uses;
        switch (region.effect) {
            case RegionEffect::Drag: uses = {{"Coefficient", false}, {"AngularCoefficient", false}, {"Law", false}, {"Velocity", false}}; break;
            case RegionEffect::Wind: uses = {{"Velocity", true}, {"Coefficient", true}, {"AngularCoefficient", false}, {"Law", false}}; break;
            case RegionEffect::Gravity: uses = {{"Gravity", true}}; break;
            case RegionEffect::Buoyancy: uses = {{"Density", true}, {"Coefficient", false}, {"AngularCoefficient", false}, {"Law", false}, {"Velocity", false}}; break;
            case RegionEffect::RandomForce: uses = {{"Strength", true}, {"Seed", false}}; break;
            case RegionEffect::Kill: break;
            case RegionEffect::Conveyor: uses = {{"Velocity", true}}; break;
        }
        constexpr std::string_view kEffectFields[] = {"Law", "Coefficient", "AngularCoefficient", "Velocity", "Gravity", "Density", "Strength", "Seed"};
        for (const std::string_view field : kEffectFields) {
            const auto use = std::find_if(uses.begin(), uses.end(), [&](const Use& u) { return u.field == field; });
            if (use == uses.end()) {
                refuse(field, "no " + std::string(field) + " on an Effect=" + effect + " region",
                       "docs/config-format.md#region lists the fields each effect takes");
            } else if (use->required && !values.isSet(field)) {
                sink_.report(line.number, recordName.column, "Region",
                             "a " + std::string(field) + " field (every Effect=" + effect + " region needs one)",
                             std::string(recordName.text), "docs/config-format.md#region lists the fields each effect takes");
            }
        }
        if (region.effect == RegionEffect::Drag && region.coefficient == 0 && region.angularCoefficient == 0) {
            sink_.report(line.number, recordName.column, "Region", "a Coefficient or AngularCoefficient > 0",
                         std::string(recordName.text), "a drag of 0 does nothing: give Coefficient=c in N*s/m");
        }
        if (region.effect == RegionEffect::Buoyancy && region.shape == RegionShape::Sphere) {
            sink_.report(line.number, values.valueColumn("Shape"), "Shape", "Box or HalfSpace for Effect=Buoyancy",
                         "Shape=" + values.asWritten("Shape"),
                         "a fluid has a flat surface: the top of a Box region, or the plane of a HalfSpace");
        }
        if (seed != std::floor(seed) || seed > Real(9007199254740992.0)) {
            sink_.report(line.number, values.valueColumn("Seed"), "Seed", "a whole number from 0 to 2^53",
                         "Seed=" + values.asWritten("Seed"), "the same seed gives the same run");
        }
        region.seed = static_cast<std::uint64_t>(seed);
        if (region.effect == RegionEffect::Buoyancy) buoyancyLines_.push_back({line.number, recordName.column, region.name});
        noteSpace(values, line.number, regionSpaceRefs_);
        scene_.regions.push_back(std::move(region));
    }

    /// Buoyancy has exact submerged volumes for spheres and boxes only (src/forces/buoyancy.hpp):
    /// a scene with a buoyancy region and another dynamic shape would float it wrongly, so it is refused.
    void checkBuoyantShapes() {
        if (buoyancyLines_.empty()) return;
        for (const DynamicObject& body : scene_.dynamics) {
            if (body.shape == Shape::Sphere || body.shape == Shape::Box) continue;
            const BuoyancyLine& where = buoyancyLines_.front();
            sink_.report(where.line, where.column, "Region",
                         "only spheres and boxes among the dynamic bodies of a scene with a Buoyancy region",
                         "DynamicObject '" + body.name + "' of another shape",
                         "buoyancy computes the submerged volume of spheres and boxes exactly, and of no other shape yet");
            return;
        }
    }

    /// Looks up each spring's bodies by name, now that every DynamicObject is
    /// known, and sets a missing RestLength to the anchors' starting distance.
    void resolveSprings() {
        std::map<std::string, std::size_t> dynamicIndex;  // lower-cased name → index in scene_.dynamics
        std::vector<std::string> dynamicNames;
        for (std::size_t i = 0; i < scene_.dynamics.size(); ++i) {
            dynamicIndex.emplace(toLower(scene_.dynamics[i].name), i);
            dynamicNames.push_back(scene_.dynamics[i].name);
        }
        for (PendingSpring& pending : pendingSprings_) {
            const auto find = [&](const std::optional<std::string>& name, int column,
                                  const char* field) -> std::optional<std::size_t> {
                if (!name) return std::nullopt;  // not given, or not a valid name: reported already
                const auto found = dynamicIndex.find(toLower(*name));
                if (found != dynamicIndex.end()) return found->second;
                reportMissingBody(pending.line, column, field, *name, dynamicNames);
                return std::nullopt;
            };
            const std::optional<std::size_t> a = find(pending.bodyA, pending.bodyAColumn, "BodyA");
            const std::optional<std::size_t> b =
                pending.bodyBColumn == 0 ? std::optional<std::size_t>(kFixedInWorld)
                                         : find(pending.bodyB, pending.bodyBColumn, "BodyB");
            if (!a || !b) continue;
            if (*a == *b) {
                sink_.report(pending.line, pending.bodyBColumn, "BodyB", "a body other than BodyA", *pending.bodyB,
                             "a spring joins two different bodies; leave BodyB out to fix this end in the world "
                             "at AnchorB");
                continue;
            }
            Spring& spring = pending.spring;
            spring.bodyA = *a;
            spring.bodyB = *b;
            // Anchors are written in the body's frame as the scene placed it; a hull or compound
            // body's frame has moved to its centre of mass and axes: a' = q_axes⁻¹·(a − c).
            const auto toBodyFrame = [&](std::size_t body, const Vec3& anchor) {
                const BodyFrame& frame = dynamicFrames_[body];
                return glm::conjugate(frame.axes) * (anchor - frame.centre);
            };
            spring.anchorA = toBodyFrame(*a, spring.anchorA);
            if (*b != kFixedInWorld) spring.anchorB = toBodyFrame(*b, spring.anchorB);
            if (!pending.restLengthGiven) {
                const SpringEnds ends = springEnds(spring, scene_.dynamics);
                spring.restLength = glm::length(ends.b - ends.a);  // it starts relaxed
            }
            scene_.springs.push_back(spring);
            springLines_.push_back(pending.line);
        }
    }

    void reportMissingBody(int line, int column, const char* field, const std::string& name,
                           const std::vector<std::string>& dynamicNames) {
        std::string hint;
        const auto other = names_.find(toLower(name));
        if (other != names_.end()) {
            hint = quoted(other->second.name) + " is a " + std::string(other->second.record) +
                   "; a spring pulls on DynamicObjects only";
            if (std::string_view(field) == "BodyB") hint += " (leave BodyB out to fix this end in the world at AnchorB)";
        } else if (const auto suggestion = closestMatch(name, dynamicNames)) {
            hint = "did you mean '" + *suggestion + "'?";
        } else {
            hint = "no DynamicObject in this file is called " + quoted(name);
        }
        sink_.report(line, column, field, "the Name of a DynamicObject", name, std::move(hint));
    }

    /// Adds a warning for every spring whose swing this integrator and time
    /// step would blow up (spring_stability.hpp has the analysis). The
    /// warning says how far past the limit the step is and which step is safe.
    void warnAboutUnstableSprings() {
        if (scene_.springs.empty()) return;
        // The effective mass of an off-centre spring needs the bodies' inertia, which the World sets up later.
        std::vector<DynamicObject> bodies = scene_.dynamics;
        for (DynamicObject& body : bodies) initialiseMassProperties(body);
        const WorldSettings& settings = scene_.settings;
        const Real h = integrationStep(settings);  // the step the integrator takes: a substep under SequentialImpulse
        const Real steps = std::round(settings.duration / h);
        for (std::size_t i = 0; i < scene_.springs.size(); ++i) {
            const Spring& spring = scene_.springs[i];
            const SpringStability s = analyseSpring(spring, bodies, settings.integrator, h);
            if (s.growthPerStep <= 1 + kGrowthTolerance) continue;
            const Real growthOverRun = std::pow(s.growthPerStep, steps);
            const bool explicitEuler = settings.integrator == IntegratorKind::ExplicitEuler;
            if (explicitEuler && growthOverRun <= kTolerableGrowth) continue;
            scene_.warnings.push_back(scene_.sourcePath + ":" + std::to_string(springLines_[i]) +
                                      ": warning: Spring " + quoted(spring.name) + ": " +
                                      describeInstability(s, settings, growthOverRun));
        }
    }

    /// Adds a warning for each pair of DynamicObjects more than kMaxMassRatio apart in mass that
    /// will press on each other: joined by a joint or a spring, or touching at the start (their
    /// bounding spheres overlap). Bodies that never meet may differ as much as they like. The
    /// warning is at the lighter body's line, since it is the one that would be pushed through.
    /// `stepwise run` warns again about any such pair that comes into contact later.
    void warnAboutMassRatios() {
        const std::vector<DynamicObject>& bodies = scene_.dynamics;
        if (bodies.size() < 2) return;
        const auto byMass = [](const DynamicObject& a, const DynamicObject& b) { return a.mass < b.mass; };
        const auto [lightest, heaviest] = std::minmax_element(bodies.begin(), bodies.end(), byMass);
        if (heaviest->mass <= kMaxMassRatio * lightest->mass) return;  // the common case: nothing to look for

        std::vector<std::pair<std::size_t, std::size_t>> pairs;
        for (const JointDef& joint : scene_.joints) {
            if (joint.bodyB.empty()) continue;
            pairs.emplace_back(indexOfDynamic(joint.bodyA), indexOfDynamic(joint.bodyB));
        }
        for (const Spring& spring : scene_.springs) {
            if (spring.bodyB != kFixedInWorld) pairs.emplace_back(spring.bodyA, spring.bodyB);
        }
        // Touching at the start: sweep along x over the bounding spheres (sort and sweep, Ericson 7.5.1).
        std::vector<std::size_t> order(bodies.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        const auto reach = [](const DynamicObject& body) {
            switch (body.shape) {
                case Shape::Sphere: return body.radius;
                case Shape::Capsule: return body.height / 2 + body.radius;
                case Shape::Cylinder: return std::hypot(body.radius, body.height / 2);
                case Shape::Hull: return body.hull ? body.hull->boundingRadius : Real(0);
                case Shape::Compound: return body.compound ? body.compound->boundingRadius : Real(0);
                case Shape::Box:
                case Shape::Mesh: break;
            }
            return Real(0.5) * glm::length(body.scale);
        };
        std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
            return bodies[i].position.x - reach(bodies[i]) < bodies[j].position.x - reach(bodies[j]);
        });
        for (std::size_t k = 0; k < order.size(); ++k) {
            const DynamicObject& a = bodies[order[k]];
            for (std::size_t m = k + 1; m < order.size(); ++m) {
                const DynamicObject& b = bodies[order[m]];
                if (b.position.x - reach(b) > a.position.x + reach(a)) break;  // no later body reaches back to a
                const Real apart = glm::length(b.position - a.position);
                if (apart <= (reach(a) + reach(b)) * (1 + kTouchingMargin)) pairs.emplace_back(order[k], order[m]);
            }
        }
        std::vector<std::size_t> warned;  // each light body once
        for (auto [i, j] : pairs) {
            if (i >= bodies.size() || j >= bodies.size()) continue;
            if (bodies[i].mass > bodies[j].mass) std::swap(i, j);
            const DynamicObject& light = bodies[i];
            const DynamicObject& heavy = bodies[j];
            if (heavy.mass <= kMaxMassRatio * light.mass) continue;
            if (std::find(warned.begin(), warned.end(), i) != warned.end()) continue;
            warned.push_back(i);
            const auto use = names_.find(toLower(light.name));
            const int line = use != names_.end() ? use->second.line : 0;
            char text[512];
            std::snprintf(text, sizeof text,
                          ": warning: DynamicObject %s (%.6g kg) presses on %s (%.6g kg), %.3g times heavier; the "
                          "solver holds two bodies apart only up to a mass ratio of %.6g, so the lighter one may "
                          "be pushed into what it rests on",
                          quoted(light.name).c_str(), double(light.mass), quoted(heavy.name).c_str(),
                          double(heavy.mass), double(heavy.mass / light.mass), double(kMaxMassRatio));
            scene_.warnings.push_back(scene_.sourcePath + ":" + std::to_string(line) + text);
        }
    }

    /// Index among scene_.dynamics of the body called @p name (joints are resolved by now).
    std::size_t indexOfDynamic(const std::string& name) const {
        for (std::size_t i = 0; i < scene_.dynamics.size(); ++i) {
            if (toLower(scene_.dynamics[i].name) == toLower(name)) return i;
        }
        return scene_.dynamics.size();
    }

    static std::string describeInstability(const SpringStability& s, const WorldSettings& settings,
                                           Real growthOverRun) {
        const Real h = integrationStep(settings);
        char text[512];
        if (settings.integrator == IntegratorKind::ExplicitEuler) {
            std::snprintf(text, sizeof text,
                          "explicit Euler feeds energy into its swing: the amplitude grows x%.6g per step "
                          "(h*w = %.3g, w = sqrt(k/m_eff) = %.4g rad/s), x%.3g over the Duration of %.4g s; "
                          "use SymplecticEuler or Verlet (stable up to h*w = 2)%s",
                          double(s.growthPerStep), double(h * s.omega), double(s.omega), double(growthOverRun),
                          double(settings.duration), s.largestStableStep > 0 ? ", or a smaller TimeStep" : "");
            return text;
        }
        const double limit = double(s.largestStableStep * s.omega);
        std::snprintf(text, sizeof text,
                      "the time step is past its stability limit for %s: h*w = %.4g s * %.4g rad/s = %.3g > %.3g "
                      "(w = sqrt(k/m_eff), m_eff = %.4g kg%s); its swing grows x%.3g every step; "
                      "use TimeStep < %.4g s",
                      toString(settings.integrator), double(h), double(s.omega), double(h * s.omega), limit,
                      double(s.effectiveMass), s.dampingRatio > 0 ? ", the limit is below 2 because of Damping" : "",
                      double(s.growthPerStep), double(s.largestStableStep * settings.timeStep / h));
        return text;
    }

    /// A joint is read now but built in finish(): its bodies may come later in the file.
    void addJoint(const RecordValues& values, const SceneLine& line, int index, JointKind kind) {
        JointDef joint;
        joint.name = claimName(values, line, index);
        joint.kind = kind;
        pendingJoints_.push_back({values, line.number, line.tokens.front().column});
        scene_.joints.push_back(std::move(joint));
    }

    /// Fills every joint from its record, now that every body is known.
    void resolveJoints() {
        for (std::size_t i = 0; i < pendingJoints_.size(); ++i) {
            buildJoint(pendingJoints_[i], scene_.joints[i]);
        }
        if (!pendingJoints_.empty() && scene_.settings.solver == SolverKind::Impulse) {
            const PendingJoint& first = pendingJoints_.front();
            sink_.report(first.line, first.column, std::string(first.values.spec().name),
                         "a World with Solver=SequentialImpulse", "Solver=Impulse",
                         "joints are solved only by the sequential-impulse solver; remove Solver=Impulse from the "
                         "World record on line " + std::to_string(worldLine_));
        }
    }

    void buildJoint(const PendingJoint& pending, JointDef& joint) {
        const RecordValues& values = pending.values;
        const std::optional<const DynamicObject*> a = jointBody(pending, "BodyA", true);
        const std::optional<const DynamicObject*> b = jointBody(pending, "BodyB", false);
        if (!a || !b) return;  // reported; nothing below can be checked without the bodies
        const DynamicObject& bodyA = **a;
        const DynamicObject* bodyB = *b;
        joint.bodyA = bodyA.name;
        joint.bodyB = bodyB ? bodyB->name : "";
        if (bodyB == &bodyA) {
            sink_.report(pending.line, values.valueColumn("BodyB"), "BodyB", "a body other than BodyA", bodyA.name,
                         "a joint holds two different bodies; leave BodyB out to fix BodyA to the world");
            return;
        }
        switch (joint.kind) {
            case JointKind::Distance:
            case JointKind::Rope: readTwoAnchors(pending, bodyA, bodyB, joint); break;
            case JointKind::Ball: joint.anchorA = values.triple("Anchor", bodyA.position); break;
            case JointKind::Hinge:
                joint.anchorA = values.triple("Anchor", bodyA.position);
                joint.axis = jointAxis(pending);
                joint.lowerAngle = limitAngle(pending, "LowerAngle");
                joint.upperAngle = limitAngle(pending, "UpperAngle");
                if (joint.lowerAngle && joint.upperAngle && *joint.lowerAngle > *joint.upperAngle) {
                    sink_.report(pending.line, values.valueColumn("UpperAngle"), "UpperAngle",
                                 "an angle >= LowerAngle (" + formatNumber(glm::degrees(*joint.lowerAngle)) + ")",
                                 formatNumber(glm::degrees(*joint.upperAngle)),
                                 "the hinge turns between LowerAngle and UpperAngle (degrees)");
                }
                readMotor(values, joint);
                break;
            case JointKind::AngularMotor:
                joint.axis = jointAxis(pending);
                readMotor(values, joint);
                break;
        }
        if (joint.kind != JointKind::AngularMotor) joint.maxForce = values.number("MaxForce", kUnbreakable);
        joint.collideConnected = values.choice<bool>("CollideConnected", kBooleanChoices, kDefaultCollideConnected);
    }

    /// The DynamicObject a joint's @p field names: nullopt after reporting a problem,
    /// nullptr for an omitted optional body (the world).
    std::optional<const DynamicObject*> jointBody(const PendingJoint& pending, std::string_view field, bool required) {
        const std::optional<std::string> name = pending.values.text(field);
        if (!name) {
            if (!required) return nullptr;
            sink_.report(pending.line, pending.column, std::string(field), "the name of a DynamicObject", "",
                         "every joint needs " + std::string(field) + "=..., the body it holds");
            return std::nullopt;
        }
        std::vector<std::string> candidates;
        for (const DynamicObject& body : scene_.dynamics) {
            if (equalsIgnoreCase(body.name, *name)) return &body;
            candidates.push_back(body.name);
        }
        std::string hint;
        if (const auto other = names_.find(toLower(*name)); other != names_.end()) {
            hint = quoted(other->second.name) + " is the " + std::string(other->second.record) + " on line " +
                   std::to_string(other->second.line) + "; joints hold DynamicObjects";
            if (!required) hint += " (leave BodyB out to fix the joint to the world)";
        } else if (const auto suggestion = closestMatch(*name, candidates)) {
            hint = "did you mean '" + *suggestion + "'?";
        } else {
            hint = "no DynamicObject has that name";
        }
        sink_.report(pending.line, pending.values.valueColumn(field), std::string(field), "the name of a DynamicObject",
                     *name, std::move(hint));
        return std::nullopt;
    }

    void readTwoAnchors(const PendingJoint& pending, const DynamicObject& bodyA, const DynamicObject* bodyB,
                        JointDef& joint) {
        const RecordValues& values = pending.values;
        joint.anchorA = values.triple("AnchorA", bodyA.position);
        if (!bodyB && values.valueColumn("AnchorB") == 0) {
            sink_.report(pending.line, pending.column, "AnchorB", "a point (x, y, z)", "",
                         "a " + std::string(values.spec().name) + " fixed to the world needs AnchorB=(x, y, z), "
                         "the fixed point it hangs from");
            return;
        }
        joint.anchorB = values.triple("AnchorB", bodyB ? bodyB->position : kZero);
        if (values.valueColumn("Length") != 0) {
            joint.length = values.number("Length", 0);
        } else if (!(glm::length(joint.anchorB - joint.anchorA) >= kMinJointLength)) {
            sink_.report(pending.line, pending.column, "Length", describe(Range::JointLength), "",
                         "the anchors (almost) coincide, so the distance at the start is 0: give Length=..., or "
                         "use a BallJoint");
        }
    }

    Vec3 jointAxis(const PendingJoint& pending) {
        const Vec3 axis = pending.values.triple("Axis", kDefaultJointAxis);
        if (!usableDirection(axis)) {  // core/limits.hpp: what makeJoints() requires too
            const std::string& written = pending.values.asWritten("Axis");
            sink_.report(pending.line, pending.values.valueColumn("Axis"), "Axis", "a direction (a vector of length > 0, "
                         "whose squares do not overflow)", written.empty() ? formatVector(axis) : written,
                         "the axis is the direction the joint turns about, e.g. (0, 0, 1)");
            return kDefaultJointAxis;
        }
        return axis / glm::length(axis);
    }

    /// A hinge limit in degrees → radians; empty when not given.
    std::optional<Real> limitAngle(const PendingJoint& pending, std::string_view field) {
        const int column = pending.values.valueColumn(field);
        if (column == 0) return std::nullopt;
        const Real degrees = pending.values.number(field, 0);
        if (std::abs(degrees) > kMaxLimitDegrees) {
            sink_.report(pending.line, column, std::string(field), "an angle from -180 to 180 degrees",
                         formatNumber(degrees), "the hinge angle is measured from the start, within half a turn");
            return std::nullopt;
        }
        return glm::radians(degrees);
    }

    static void readMotor(const RecordValues& values, JointDef& joint) {
        joint.motor = values.valueColumn("MotorSpeed") != 0 || values.valueColumn("MaxMotorTorque") != 0;
        joint.motorSpeed = values.number("MotorSpeed", 0);
        joint.maxMotorTorque = values.number("MaxMotorTorque", kUnlimitedTorque);
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

    /// A name an Expect record refers to, checked once the whole file is read.
    struct PendingName {
        int line = 0;                 ///< Line of the Expect record.
        int column = 0;               ///< Column of the name.
        std::string field;            ///< "Object" or "NotThroughPlane".
        std::string name;             ///< As written.
        std::string_view record;      ///< The record type it must name (Object: or a SoftBody).
        std::size_t expectation = 0;  ///< Index into Scene::expectations.
        int quantityColumn = 0;       ///< Object: column of the record's quantity field.
        std::string quantity{};       ///< Object: the quantity's name ("TiltDeg"), for a message.
    };

    /// A MayChange record as read from its line, before its object is looked up by name.
    struct PendingChange {
        int line = 0;                       ///< Line of the record.
        std::optional<std::string> object;  ///< Object as written; nullopt: the World record.
        int objectColumn = 0;               ///< Column of the Object's value.
        std::string field;                  ///< Field as written.
        int fieldColumn = 0;                ///< Column of the Field's value.
    };

    /// A Spring as read from its line, before its bodies are looked up by name.
    struct PendingSpring {
        Spring spring;                      ///< Everything but the body indices (and maybe the rest length).
        int line = 0;                       ///< Line of the record.
        std::optional<std::string> bodyA;   ///< BodyA as written (nullopt when missing or malformed).
        std::optional<std::string> bodyB;   ///< BodyB as written.
        int bodyAColumn = 0;                ///< Column of BodyA's value; 0 when not given.
        int bodyBColumn = 0;                ///< Column of BodyB's value; 0 when not given (a world end).
        bool restLengthGiven = false;       ///< False: the rest length is the starting distance.
    };

    Scene scene_;
    DiagnosticSink sink_;
    std::vector<PendingName> pendingNames_;  ///< Names used by Expect records.
    std::vector<PendingChange> pendingChanges_;  ///< MayChange records, resolved by finish().
    std::map<std::string, NameUse> names_;  ///< Lower-cased name → first use.
    std::vector<int> softBodyLines_;  ///< The line of each SoftBody record, for its warnings.
    std::array<int, kRecordKindCount> counts_{};  ///< Records seen so far, per RecordKind (for default names).
    std::vector<PendingSpring> pendingSprings_;   ///< Springs in file order, resolved by finish().
    std::vector<int> springLines_;                ///< Line of each resolved spring in scene_.springs.
    std::vector<BuoyancyLine> buoyancyLines_;     ///< Where each Buoyancy region was written.
    std::vector<PendingSpace> pendingSpaces_;     ///< Space records, resolved by finish().
    std::vector<SpaceRef> dynamicSpaceRefs_, kinematicSpaceRefs_, planeSpaceRefs_, attractorSpaceRefs_,
        regionSpaceRefs_, softBodySpaceRefs_;     ///< Each object's Space=, parallel to its list in scene_.
    std::vector<PendingJoint> pendingJoints_;    ///< Parallel to scene_.joints.
    int worldLine_ = 0;                     ///< Line of the World record; 0 before one is seen.
    SceneReadOptions options_;              ///< What the loader may read besides the text.
    std::vector<PendingCompound> pendingCompounds_;  ///< Shape=Compound objects, in file order.
    std::vector<PendingPart> pendingParts_;          ///< Part records, joined in finish().
    std::vector<std::pair<int, std::string>> partLines_;  ///< Each Part's line number and text.
    std::vector<BodyFrame> dynamicFrames_;  ///< Parallel to scene_.dynamics: where each body's frame moved.
    std::map<std::string, std::uint32_t> materialIndex_;  ///< Lower-cased Material name → index in scene_.materials.
};

}  // namespace

namespace {

}  // namespace

std::string ConfigDiagnostic::message() const {
    std::string text = file;
    if (line > 0) text += ":" + std::to_string(line) + ":" + std::to_string(column);
    text += ": error: ";
    if (!field.empty()) text += quotable(field) + ": ";
    if (expected.empty()) return text + hint;  // e.g. a file that could not be opened
    text += "expected " + expected + ", found '" + quotable(found) + "'";
    if (!hint.empty()) text += "; " + hint;
    return text;
}

ConfigError::ConfigError(std::vector<ConfigDiagnostic> diagnostics)
    : std::runtime_error(joinMessages(diagnostics)), diagnostics_(std::move(diagnostics)) {}

Scene parseScene(std::string_view text, const std::string& sourceName) {
    return parseScene(text, sourceName, SceneReadOptions{});
}

Scene parseScene(std::string_view text, const std::string& sourceName, const SceneReadOptions& options) {
    SceneAssembler assembler(sourceName, options);
    const std::vector<SceneLine> lines = tokenizeScene(text);
    // Materials first: an object may name a Material declared anywhere in the file, before it or after.
    for (const SceneLine& line : lines) {
        if (SceneAssembler::declaresMaterial(line)) assembler.add(line);
    }
    for (const SceneLine& line : lines) {
        if (!SceneAssembler::declaresMaterial(line)) assembler.add(line);
    }
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
    const std::filesystem::file_status type = std::filesystem::status(path, status);
    if (std::filesystem::is_directory(type)) throw cannotOpen("it is a directory");
    // A FIFO or a device would block the read forever (a FIFO no one writes) or never end
    // (/dev/zero): a scene is a file on disk.
    if (std::filesystem::exists(type) && !std::filesystem::is_regular_file(type)) {
        const char* kind = std::filesystem::is_fifo(type)             ? "a FIFO"
                           : std::filesystem::is_character_file(type) ? "a character device"
                           : std::filesystem::is_block_file(type)     ? "a block device"
                           : std::filesystem::is_socket(type)         ? "a socket"
                                                                      : "not a regular file";
        throw cannotOpen(std::string("it is ") + kind + ", not a regular file");
    }

    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw cannotOpen(errno != 0 ? std::generic_category().message(errno) : "unknown reason");
    std::ostringstream contents;
    contents << in.rdbuf();
    if (in.bad()) throw cannotOpen("read error");
    return parseScene(contents.str(), path);
}

}  // namespace stepwise
