/// @file test_config.cpp
/// @brief Scene files that load: every record, field, default and layout rule of docs/config-format.md.
///
/// Error cases are in test_config_errors.cpp; the documentation examples and
/// the shipped scenes in test_config_files.cpp.
#include <catch2/catch.hpp>

#include <string>
#include <string_view>

#include "config/scene_loader.hpp"
#include "config/scene_records.hpp"
#include "config/scene_tokenizer.hpp"
#include "config/spelling.hpp"

using namespace stepwise;

namespace {

/// Tolerance for values that went through a rotation or a normalisation.
constexpr double kTolerance = 1e-12;

Scene load(std::string_view text) { return parseScene(text, "test.scene"); }

void requireNear(const Vec3& actual, const Vec3& expected) {
    INFO("actual (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected (" << expected.x << ", "
                    << expected.y << ", " << expected.z << ")");
    REQUIRE(actual.x == Approx(expected.x).margin(kTolerance));
    REQUIRE(actual.y == Approx(expected.y).margin(kTolerance));
    REQUIRE(actual.z == Approx(expected.z).margin(kTolerance));
}

void requireColor(const Color& actual, float r, float g, float b) {
    REQUIRE(actual.r == Approx(r));
    REQUIRE(actual.g == Approx(g));
    REQUIRE(actual.b == Approx(b));
}

/// Where the orientation sends @p v (rotating a vector is the test that
/// does not depend on the sign convention of the quaternion).
Vec3 rotate(const Quat& q, const Vec3& v) { return q * v; }

}  // namespace

// ------------------------------------------------------------------ positional records

TEST_CASE("A positional DynamicObject fills every field in the classic order", "[config]") {
    const Scene scene = load(
        "DynamicObject, Sphere, 0.1, 0.2, 0.3, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0.25, 4, 0.75\n");
    REQUIRE(scene.dynamics.size() == 1);
    const DynamicObject& body = scene.dynamics[0];
    CHECK(body.shape == Shape::Sphere);
    requireColor(body.color, 0.1f, 0.2f, 0.3f);
    requireNear(body.position, {1, 2, 3});
    requireNear(body.velocity, {4, 5, 6});
    requireNear(body.constantAcceleration, {7, 8, 9});
    requireNear(body.acceleration, {0, 0, 0});  // the per-step total is the engine's, not the file's
    requireNear(body.scale, {10, 11, 12});
    CHECK(body.radius == 0.25);
    CHECK(body.mass == 4);
    CHECK(body.inverseMass == 0.25);
    CHECK(body.elasticity == 0.75);
    // Not positional: defaults.
    CHECK(body.friction == 0.5);
    CHECK(body.name == "DynamicObject0");
    requireNear(body.angularVelocity, {0, 0, 0});
    requireNear(rotate(body.orientation, {1, 0, 0}), {1, 0, 0});
    CHECK(scene.warnings.empty());
}

TEST_CASE("A positional KinematicsObject fills shape, colour, position and scale", "[config]") {
    const Scene scene = load("KinematicsObject, Box, 0.5, 0.25, 1, -1, 2, -3, 4, 5, 6\n");
    REQUIRE(scene.kinematics.size() == 1);
    const KinematicsObject& mover = scene.kinematics[0];
    CHECK(mover.shape == Shape::Box);
    requireColor(mover.color, 0.5f, 0.25f, 1.0f);
    requireNear(mover.position, {-1, 2, -3});
    requireNear(mover.scale, {4, 5, 6});
    CHECK(mover.radius == 2);  // ScaleX / 2
    requireNear(mover.velocity, {0, 0, 0});
    CHECK(mover.elasticity == 1);
    CHECK(mover.friction == 1);
    CHECK(scene.warnings.empty());
}

TEST_CASE("A positional CollisionPlane fills position and a normalised normal", "[config]") {
    const Scene scene = load("CollisionPlane, 1, -2, 3, 0, 5, 0\nCollisionPlane, 0, 0, 0, 1, 1, 0\n");
    REQUIRE(scene.planes.size() == 2);
    requireNear(scene.planes[0].position, {1, -2, 3});
    requireNear(scene.planes[0].normal, {0, 1, 0});
    const double inverseRoot2 = 1 / std::sqrt(2.0);
    requireNear(scene.planes[1].normal, {inverseRoot2, inverseRoot2, 0});
}

TEST_CASE("A record may give a prefix of its positional fields and name the rest", "[config]") {
    const Scene scene = load("DynamicObject, Box, 1, 0, 0, Mass=2, Name=RedBox, Friction=0.1\n");
    const DynamicObject& body = scene.dynamics.at(0);
    CHECK(body.shape == Shape::Box);
    requireColor(body.color, 1, 0, 0);
    CHECK(body.mass == 2);
    CHECK(body.inverseMass == 0.5);
    CHECK(body.name == "RedBox");
    CHECK(body.friction == 0.1);
    requireNear(body.position, {0, 0, 0});
}

// ------------------------------------------------------------------ named fields

TEST_CASE("Named fields may come in any order", "[config]") {
    const Scene a = load("DynamicObject, Mass=3, Position=(1, 2, 3), Elasticity=0.2, Shape=Sphere, Radius=0.1\n");
    const Scene b = load("DynamicObject, Radius=0.1, Shape=Sphere, Elasticity=0.2, Position=(1, 2, 3), Mass=3\n");
    for (const Scene* scene : {&a, &b}) {
        const DynamicObject& body = scene->dynamics.at(0);
        CHECK(body.mass == 3);
        CHECK(body.inverseMass == Approx(1.0 / 3));
        requireNear(body.position, {1, 2, 3});
        CHECK(body.elasticity == 0.2);
        CHECK(body.radius == 0.1);
    }
}

TEST_CASE("Every named field of a DynamicObject lands in its member", "[config]") {
    const Scene scene = load(
        "DynamicObject, Name=Probe, Shape=Sphere, Color=(0, 0.5, 1), Position=(1, 2, 3), Velocity=(4, 5, 6),"
        " Acceleration=(0, 0, -1), Scale=(2, 2, 2), Radius=0.3, Mass=5, Elasticity=0.9, Friction=0.2,"
        " AngularVelocity=(0.1, 0.2, 0.3)\n");
    const DynamicObject& body = scene.dynamics.at(0);
    CHECK(body.name == "Probe");
    requireColor(body.color, 0, 0.5f, 1);
    requireNear(body.position, {1, 2, 3});
    requireNear(body.velocity, {4, 5, 6});
    requireNear(body.constantAcceleration, {0, 0, -1});
    requireNear(body.scale, {2, 2, 2});
    CHECK(body.radius == 0.3);
    CHECK(body.mass == 5);
    CHECK(body.inverseMass == Approx(0.2));
    CHECK(body.elasticity == 0.9);
    CHECK(body.friction == 0.2);
    requireNear(body.angularVelocity, {0.1, 0.2, 0.3});
}

TEST_CASE("KinematicsObject and CollisionPlane take their named-only fields", "[config]") {
    const Scene scene = load(
        "KinematicsObject, Name=Paddle, Velocity=(1, 0, 0), AngularVelocity=(0, 2, 0), Radius=0.75,"
        " Elasticity=0.5, Friction=0.25, Rotation=(0, 90, 0)\n"
        "CollisionPlane, Name=Floor, Color=(0.2, 0.3, 0.4), Elasticity=0.6, Friction=0.7, Normal=(0, 0, 2)\n");
    const KinematicsObject& mover = scene.kinematics.at(0);
    CHECK(mover.name == "Paddle");
    requireNear(mover.velocity, {1, 0, 0});
    requireNear(mover.angularVelocity, {0, 2, 0});
    CHECK(mover.radius == 0.75);
    CHECK(mover.elasticity == 0.5);
    CHECK(mover.friction == 0.25);
    requireNear(rotate(mover.orientation, {1, 0, 0}), {0, 0, -1});
    const CollisionPlane& floor = scene.planes.at(0);
    CHECK(floor.name == "Floor");
    requireColor(floor.color, 0.2f, 0.3f, 0.4f);
    CHECK(floor.elasticity == 0.6);
    CHECK(floor.friction == 0.7);
    requireNear(floor.normal, {0, 0, 1});
}

TEST_CASE("A vector may be given whole or one component at a time", "[config]") {
    const Scene scene = load(
        "DynamicObject, PositionY=5\n"
        "DynamicObject, PositionZ=3, PositionX=1\n"
        "DynamicObject, ScaleX=2\n"
        "DynamicObject, ColorG=0, Velocity=(1, 2, 3)\n");
    requireNear(scene.dynamics.at(0).position, {0, 5, 0});
    requireNear(scene.dynamics.at(1).position, {1, 0, 3});
    // Components not given keep their defaults: Scale (1, 1, 1) becomes (2, 1, 1).
    requireNear(scene.dynamics.at(2).scale, {2, 1, 1});
    CHECK(scene.dynamics.at(2).radius == 1);  // radius defaults to ScaleX / 2
    requireColor(scene.dynamics.at(3).color, 0.8f, 0, 0.8f);
    requireNear(scene.dynamics.at(3).velocity, {1, 2, 3});
}

// ------------------------------------------------------------------ rotation

TEST_CASE("Rotation is in degrees: 90 about Y sends +X to -Z", "[config]") {
    const Scene scene = load("DynamicObject, Rotation=(0, 90, 0)\nDynamicObject, RotationY=90\n");
    for (const DynamicObject& body : scene.dynamics) {
        requireNear(rotate(body.orientation, {1, 0, 0}), {0, 0, -1});
        CHECK(glm::length(body.orientation) == Approx(1));
    }
}

TEST_CASE("Rotation turns about world X, then world Y, then world Z", "[config]") {
    // (0, 1, 0): X by 90 gives (0, 0, 1); then Y by 90 gives (1, 0, 0).
    // The opposite order (Y first) would give (0, 0, 1) instead.
    const Scene scene = load(
        "DynamicObject, Rotation=(90, 90, 0)\n"
        "DynamicObject, Rotation=(0, 90, 90)\n"
        "DynamicObject, RotationZ=90, RotationX=90\n");
    requireNear(rotate(scene.dynamics.at(0).orientation, {0, 1, 0}), {1, 0, 0});
    // (1, 0, 0): Y by 90 gives (0, 0, -1); Z by 90 leaves it.  (Z first would give (0, 1, 0).)
    requireNear(rotate(scene.dynamics.at(1).orientation, {1, 0, 0}), {0, 0, -1});
    // (0, 1, 0): X by 90 gives (0, 0, 1); Z by 90 leaves it. The order of the fields does not matter.
    requireNear(rotate(scene.dynamics.at(2).orientation, {0, 1, 0}), {0, 0, 1});
    // And the quaternion is the documented product q = qz · qy · qx.
    const Quat qx = glm::angleAxis(glm::radians(Real(90)), Vec3(1, 0, 0));
    const Quat qy = glm::angleAxis(glm::radians(Real(90)), Vec3(0, 1, 0));
    const Quat expected = qy * qx;
    const Quat actual = scene.dynamics.at(0).orientation;
    CHECK(std::abs(glm::dot(actual, expected)) == Approx(1));
}

// ------------------------------------------------------------------ defaults and names

TEST_CASE("A DynamicObject with no fields gets every documented default", "[config]") {
    const DynamicObject body = load("DynamicObject\n").dynamics.at(0);
    CHECK(body.shape == Shape::Sphere);
    requireColor(body.color, 0.8f, 0.8f, 0.8f);
    requireNear(body.position, {0, 0, 0});
    requireNear(body.velocity, {0, 0, 0});
    requireNear(body.constantAcceleration, {0, 0, 0});
    requireNear(body.scale, {1, 1, 1});
    CHECK(body.radius == 0.5);
    CHECK(body.mass == 1);
    CHECK(body.inverseMass == 1);
    CHECK(body.elasticity == 0.5);
    CHECK(body.friction == 0.5);
    requireNear(body.angularVelocity, {0, 0, 0});
    CHECK(body.orientation.w == 1);
}

TEST_CASE("A KinematicsObject with no fields is a unit sphere with coefficients 1", "[config]") {
    const KinematicsObject mover = load("KinematicsObject\n").kinematics.at(0);
    CHECK(mover.shape == Shape::Sphere);  // the format's default, not the class's (Box)
    requireColor(mover.color, 0.8f, 0.8f, 0.8f);
    requireNear(mover.position, {0, 0, 0});
    requireNear(mover.scale, {1, 1, 1});
    CHECK(mover.radius == 0.5);
    requireNear(mover.velocity, {0, 0, 0});
    requireNear(mover.angularVelocity, {0, 0, 0});
    CHECK(mover.elasticity == 1);
    CHECK(mover.friction == 1);
    CHECK(mover.orientation.w == 1);
}

TEST_CASE("A CollisionPlane with no fields is the floor y = 0", "[config]") {
    const CollisionPlane plane = load("CollisionPlane\n").planes.at(0);
    requireNear(plane.position, {0, 0, 0});
    requireNear(plane.normal, {0, 1, 0});
    CHECK(plane.elasticity == 1);
    CHECK(plane.friction == 1);
    requireColor(plane.color, 0.8f, 0.8f, 0.8f);
}

TEST_CASE("Without a World record the settings are the defaults", "[config]") {
    const Scene scene = load("DynamicObject\n");
    requireNear(scene.settings.gravity, {0, -9.81, 0});
    CHECK(scene.settings.timeStep == Approx(1.0 / 60));
    CHECK(scene.settings.integrator == IntegratorKind::SymplecticEuler);
    CHECK(scene.settings.duration == 10);
    CHECK(scene.sourcePath == "test.scene");
}

TEST_CASE("An empty file is an empty scene", "[config]") {
    const Scene scene = load("# nothing here\n\n");
    CHECK(scene.dynamics.empty());
    CHECK(scene.kinematics.empty());
    CHECK(scene.planes.empty());
}

TEST_CASE("Default names are the record type and its index within that type", "[config]") {
    const Scene scene = load(
        "CollisionPlane\nDynamicObject\nKinematicsObject\nDynamicObject, Name=Ball\nDynamicObject\n"
        "CollisionPlane\n");
    CHECK(scene.planes.at(0).name == "CollisionPlane0");
    CHECK(scene.planes.at(1).name == "CollisionPlane1");
    CHECK(scene.kinematics.at(0).name == "KinematicsObject0");
    CHECK(scene.dynamics.at(0).name == "DynamicObject0");
    CHECK(scene.dynamics.at(1).name == "Ball");
    CHECK(scene.dynamics.at(2).name == "DynamicObject2");  // the named one still counts
}

TEST_CASE("Cube is a synonym of Box, and dynamic boxes load without a warning", "[config]") {
    // Boxes collide now (src/collision/box_box.cpp, box_plane.cpp): nothing to warn about.
    const Scene scene = load("DynamicObject, Sphere\n\nDynamicObject, Cube, Name=Crate\nKinematicsObject, Box\n");
    CHECK(scene.dynamics.at(1).shape == Shape::Box);
    CHECK(scene.kinematics.at(0).shape == Shape::Box);
    CHECK(scene.warnings.empty());
}

// ------------------------------------------------------------------ layout rules

TEST_CASE("Record names, field names and words ignore case", "[config]") {
    const Scene scene = load(
        "dynamicobject, SPHERE, mass=2, POSITIONy=3\n"
        "WORLD, integrator=VERLET, timestep=0.01\n"
        "CollisionPLANE, NORMAL=(0,1,0)\n");
    CHECK(scene.dynamics.at(0).mass == 2);
    CHECK(scene.dynamics.at(0).position.y == 3);
    CHECK(scene.settings.integrator == IntegratorKind::Verlet);
    CHECK(scene.settings.timeStep == 0.01);
    CHECK(scene.planes.size() == 1);
}

TEST_CASE("Comments, blank lines, spaces, tabs, a trailing comma and CRLF are tolerated", "[config]") {
    const Scene scene = load(
        "# A scene with every layout liberty\r\n"
        "\r\n"
        "   \t  \r\n"
        "DynamicObject ,\tSphere , Mass = 2 ,   # the ball\r\n"
        "  CollisionPlane,0,0,0,0,1,0,\r\n"
        "KinematicsObject, Name=Paddle, Position=( 1 ,2, 3 ) # no newline at the end");
    CHECK(scene.dynamics.at(0).mass == 2);
    requireNear(scene.planes.at(0).normal, {0, 1, 0});
    requireNear(scene.kinematics.at(0).position, {1, 2, 3});
    CHECK(scene.kinematics.at(0).name == "Paddle");
}

TEST_CASE("A UTF-8 byte-order mark at the start of the file is skipped", "[config]") {
    const Scene scene = load("\xEF\xBB\xBF" "DynamicObject, Mass=2\n");
    CHECK(scene.dynamics.at(0).mass == 2);
}

TEST_CASE("Numbers may be decimal, scientific or a fraction p/q", "[config]") {
    const Scene scene = load(
        "World, TimeStep=1/60, Duration=2.5e1\n"
        "DynamicObject, Mass=3/2, Radius=.25, Color=(255/255, 128/255, 0), Position=(-1e-3, +2, 1 / 4)\n");
    CHECK(scene.settings.timeStep == Approx(1.0 / 60));
    CHECK(scene.settings.duration == 25);
    const DynamicObject& body = scene.dynamics.at(0);
    CHECK(body.mass == 1.5);
    CHECK(body.radius == 0.25);
    requireColor(body.color, 1, 128.0f / 255, 0);
    requireNear(body.position, {-0.001, 2, 0.25});
}

// ------------------------------------------------------------------ World

TEST_CASE("The World record sets gravity, time step, integrator and duration", "[config]") {
    const Scene scene = load("World, Gravity=(0, -1.62, 0), TimeStep=0.005, Integrator=Verlet, Duration=3\n");
    requireNear(scene.settings.gravity, {0, -1.62, 0});
    CHECK(scene.settings.timeStep == 0.005);
    CHECK(scene.settings.integrator == IntegratorKind::Verlet);
    CHECK(scene.settings.duration == 3);
}

TEST_CASE("The World record may come anywhere and may set only some fields", "[config]") {
    const Scene scene = load("DynamicObject\nCollisionPlane\nWorld, GravityY=-1.62\n");
    requireNear(scene.settings.gravity, {0, -1.62, 0});
    CHECK(scene.settings.timeStep == Approx(1.0 / 60));
    CHECK(scene.settings.integrator == IntegratorKind::SymplecticEuler);
    CHECK(scene.settings.duration == 10);
}

TEST_CASE("Every integrator spelling maps to its integrator", "[config]") {
    const auto integratorOf = [](const std::string& word) {
        return load("World, Integrator=" + word + "\n").settings.integrator;
    };
    CHECK(integratorOf("Euler") == IntegratorKind::ExplicitEuler);
    CHECK(integratorOf("ExplicitEuler") == IntegratorKind::ExplicitEuler);
    CHECK(integratorOf("SymplecticEuler") == IntegratorKind::SymplecticEuler);
    CHECK(integratorOf("semiimpliciteuler") == IntegratorKind::SymplecticEuler);
    CHECK(integratorOf("Verlet") == IntegratorKind::Verlet);
    CHECK(integratorOf("VelocityVerlet") == IntegratorKind::Verlet);
}

TEST_CASE("The World's Broadphase is Auto by default and takes every broadphase's spelling", "[config][broadphase]") {
    CHECK(load("DynamicObject\n").settings.broadphase == BroadphaseKind::Auto);
    const auto broadphaseOf = [](const std::string& word) {
        return load("World, Broadphase=" + word + "\n").settings.broadphase;
    };
    CHECK(broadphaseOf("Auto") == BroadphaseKind::Auto);
    CHECK(broadphaseOf("BruteForce") == BroadphaseKind::BruteForce);
    CHECK(broadphaseOf("sweepandprune") == BroadphaseKind::SweepAndPrune);
    CHECK(broadphaseOf("SAP") == BroadphaseKind::SweepAndPrune);
    CHECK(broadphaseOf("AabbTree") == BroadphaseKind::AabbTree);
    CHECK(broadphaseOf("DynamicTree") == BroadphaseKind::AabbTree);
    CHECK(broadphaseOf("Grid") == BroadphaseKind::Grid);
    CHECK(broadphaseOf("UniformGrid") == BroadphaseKind::Grid);
    CHECK(broadphaseOf("Octree") == BroadphaseKind::Octree);
    CHECK(broadphaseOf("LooseOctree") == BroadphaseKind::Octree);
}

// ------------------------------------------------------------------ the pieces

TEST_CASE("The record tables give each record the classic positional layout", "[config]") {
    using namespace stepwise::config;
    const auto positionalNames = [](std::string_view recordName) {
        const RecordSpec* record = findRecord(recordName);
        REQUIRE(record != nullptr);
        std::string names;
        for (int i = 0; i < positionalCount(*record); ++i) {
            const FieldRef ref = positionalField(*record, i);
            names += (i > 0 ? "," : "") + fieldName(record->fields[ref.field], ref.component);
        }
        return names;
    };
    CHECK(positionalNames("DynamicObject") ==
          "Shape,ColorR,ColorG,ColorB,PositionX,PositionY,PositionZ,VelocityX,VelocityY,VelocityZ,"
          "AccelerationX,AccelerationY,AccelerationZ,ScaleX,ScaleY,ScaleZ,Radius,Mass,Elasticity");
    CHECK(positionalNames("KinematicsObject") ==
          "Shape,ColorR,ColorG,ColorB,PositionX,PositionY,PositionZ,ScaleX,ScaleY,ScaleZ");
    CHECK(positionalNames("CollisionPlane") == "PositionX,PositionY,PositionZ,NormalX,NormalY,NormalZ");
    CHECK(positionalNames("World").empty());
}

TEST_CASE("Edit distance counts single-letter edits, ignoring case", "[config]") {
    using namespace stepwise::config;
    CHECK(editDistance("", "") == 0);
    CHECK(editDistance("Mass", "mass") == 0);
    CHECK(editDistance("Elastcity", "Elasticity") == 1);  // one insertion
    CHECK(editDistance("Sphear", "Sphere") == 2);         // two substitutions
    CHECK(editDistance("kitten", "sitting") == 3);
    CHECK(closestMatch("Verlat", {"Euler", "Verlet"}) == std::optional<std::string>("Verlet"));
    CHECK_FALSE(closestMatch("Dog", {"Box", "Sphere"}).has_value());
}

TEST_CASE("The tokenizer keeps vectors whole and reports columns", "[config]") {
    using namespace stepwise::config;
    const auto lines = tokenizeScene("# comment\n\nA, b = (1, 2, 3) ,c,\n");
    REQUIRE(lines.size() == 1);
    CHECK(lines[0].number == 3);
    REQUIRE(lines[0].tokens.size() == 3);
    CHECK(lines[0].tokens[1].text == "b = (1, 2, 3)");
    CHECK(lines[0].tokens[1].column == 4);
    CHECK(lines[0].tokens[2].text == "c");
    CHECK(lines[0].tokens[2].column == 19);
    const auto named = splitNamed(lines[0].tokens[1]);
    REQUIRE(named.has_value());
    CHECK(named->name.text == "b");
    CHECK(named->value.text == "(1, 2, 3)");
    CHECK(named->value.column == 8);
}

TEST_CASE("Bodies that will press on each other beyond the solver's mass ratio are warned about", "[config]") {
    // kMaxMassRatio (src/core/limits.hpp) is the ratio the solver holds; the warning names the
    // lighter body, at its line, and the heavier one.
    const std::string base = "CollisionPlane\n"
                             "DynamicObject, Name=light, Shape=Box, Position=(0, 0.5, 0), Mass=1\n";
    const auto warningsOf = [&](const std::string& more) { return parseScene(base + more, "ratio.scene").warnings; };

    SECTION("a box resting on a much lighter one") {
        const std::vector<std::string> warnings =
            warningsOf("DynamicObject, Name=heavy, Shape=Box, Position=(0, 1.5, 0), Mass=1001\n");
        REQUIRE(warnings.size() == 1);
        CHECK_THAT(warnings[0], Catch::Matchers::StartsWith("ratio.scene:2: warning: DynamicObject 'light' (1 kg) "
                                                            "presses on 'heavy' (1001 kg)"));
    }
    SECTION("exactly at the ratio, no warning") {
        CHECK(warningsOf("DynamicObject, Name=heavy, Shape=Box, Position=(0, 1.5, 0), Mass=1000\n").empty());
    }
    SECTION("bodies far apart may differ as much as they like") {
        CHECK(warningsOf("DynamicObject, Name=heavy, Shape=Box, Position=(5, 0.5, 0), Mass=1e6\n").empty());
    }
    SECTION("a joint makes them press on each other wherever they start") {
        const std::vector<std::string> warnings =
            warningsOf("DynamicObject, Name=heavy, Position=(5, 0.5, 0), Mass=1e6\n"
                       "BallJoint, BodyA=light, BodyB=heavy, Anchor=(2.5, 0.5, 0)\n");
        REQUIRE(warnings.size() == 1);
        CHECK_THAT(warnings[0], Catch::Matchers::Contains("'light' (1 kg) presses on 'heavy'"));
    }
}
