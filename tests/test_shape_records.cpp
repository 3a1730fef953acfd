/// @file test_shape_records.cpp
/// @brief The scene records of the larger shapes: Shape=Capsule|Cylinder|Hull|Compound|Mesh,
/// Height, Vertices, File, Part, World's Narrowphase. Each record loads what it says; each
/// mistake is one error at its file:line:column with what was expected and what was found.
/// Tags: [config].
///
/// OBJ files are written into a scratch folder of their own, so a relative File= is read
/// next to the scene that names it, as the loader promises.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "config/scene_loader.hpp"

using namespace stepwise;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using Catch::Matchers::WithinAbs;
namespace fs = std::filesystem;

namespace {

/// Positions after moving a body to its centre of mass are sums of a few products: round-off.
constexpr double kRoundOff = 1e-12;

/// The one problem loading @p text reports.
ConfigDiagnostic theProblemIn(const std::string& text, const std::string& source = "test.scene") {
    try {
        (void)parseScene(text, source);
    } catch (const ConfigError& error) {
        INFO(error.what());
        REQUIRE(error.diagnostics().size() == 1);
        return error.diagnostics().front();
    }
    FAIL("the scene loaded:\n" << text);
    return {};
}

/// A scratch folder holding a scene and its models; removed when it goes out of scope.
class Folder {
public:
    explicit Folder(const std::string& name) : path_(fs::temp_directory_path() / ("stepwise_shapes_" + name)) {
        fs::remove_all(path_);
        fs::create_directories(path_ / "models");
    }
    ~Folder() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    Folder(const Folder&) = delete;
    Folder& operator=(const Folder&) = delete;

    /// Writes @p text to @p relative inside the folder; returns its full path.
    std::string write(const std::string& relative, const std::string& text) const {
        std::ofstream out(path_ / relative, std::ios::binary);
        out << text;
        return (path_ / relative).string();
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

const std::string kTetrahedronObj = "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";
/// Two triangles making the unit square in the y = 0 plane, facing up.
const std::string kSquareObj = "v 0 0 0\nv 0 0 1\nv 1 0 0\nv 1 0 1\nf 1 2 3\nf 3 2 4\n";

}  // namespace

TEST_CASE("Shape takes Capsule, Cylinder, Hull, Compound and Mesh, in any case", "[config]") {
    const Scene scene = parseScene("DynamicObject, Name=c, Shape=capsule, Radius=0.2, Height=1\n"
                                   "DynamicObject, Name=y, Shape=CYLINDER, Radius=0.3, Height=0.5\n"
                                   "KinematicsObject, Name=k, Shape=Cylinder, Radius=1, Height=0.1\n",
                                   "test.scene");
    CHECK(scene.dynamics[0].shape == Shape::Capsule);
    CHECK(scene.dynamics[0].height == Approx(1));
    CHECK(scene.dynamics[1].shape == Shape::Cylinder);
    CHECK(scene.dynamics[1].radius == Approx(0.3));
    CHECK(scene.kinematics[0].shape == Shape::Cylinder);
    CHECK(scene.kinematics[0].height == Approx(0.1));
}

TEST_CASE("Height defaults to ScaleY", "[config]") {
    const Scene scene = parseScene("DynamicObject, Shape=Cylinder, Scale=(1, 3, 1)\n", "test.scene");
    CHECK(scene.dynamics[0].height == Approx(3));
}

TEST_CASE("A hull from Vertices: the points wrapped, the frame at the centre of mass", "[config]") {
    const Scene scene = parseScene("DynamicObject, Name=t, Shape=Hull, Position=(0, 2, 0), "
                                   "Vertices=(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1), (0, 0, 0)\n",
                                   "test.scene");
    const DynamicObject& body = scene.dynamics.front();
    REQUIRE(body.hull);
    CHECK(body.hull->vertices.size() == 4);  // the centre point is inside
    CHECK(body.hull->faces.size() == 4);
    CHECK_THAT(body.hull->volume, WithinAbs(8.0 / 3.0, kRoundOff));
    CHECK_THAT(glm::length(body.position - Vec3(0, 2, 0)), WithinAbs(0.0, kRoundOff));
}

TEST_CASE("Scale stretches a hull's points, and the body's own scale is then 1", "[config]") {
    const Scene scene = parseScene("DynamicObject, Shape=Hull, Scale=(2, 1, 1), "
                                   "Vertices=(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)\n",
                                   "test.scene");
    CHECK_THAT(scene.dynamics[0].hull->volume, WithinAbs(16.0 / 3.0, kRoundOff));
    CHECK(scene.dynamics[0].scale == Vec3(1));
}

TEST_CASE("A hull and a mesh from OBJ files, relative to the scene's folder", "[config]") {
    const Folder folder("obj");
    folder.write("models/tetra.obj", kTetrahedronObj);
    folder.write("models/square.obj", kSquareObj);
    const std::string scene = folder.write("scene.scene",
                                           "DynamicObject, Name=t, Shape=Hull, File=models/tetra.obj, Mass=2\n"
                                           "KinematicsObject, Name=floor, Shape=Mesh, File=models/square.obj, Scale=(3, 1, 3)\n");
    const Scene loaded = loadSceneFile(scene);
    REQUIRE(loaded.dynamics[0].hull);
    CHECK(loaded.dynamics[0].hull->faces.size() == 4);
    const KinematicsObject& floor = loaded.kinematics[0];
    REQUIRE(floor.mesh);
    CHECK(floor.mesh->triangles.size() == 2);
    CHECK(floor.mesh->vertices[3] == Vec3(3, 0, 3));  // Scale multiplies the points
    CHECK(floor.mesh->nodes.size() == 1);            // two triangles: one leaf
    // The square's diagonal is a flat fold between its two triangles: inactive on both.
    int inactive = 0;
    for (const auto& edges : floor.mesh->activeEdges) {
        for (const bool active : edges) inactive += active ? 0 : 1;
    }
    CHECK(inactive == 2);
}

TEST_CASE("A compound's parts: positions and rotations in the body's scene frame", "[config]") {
    // An L of two boxes, the body turned 90° about z: its parts' world centres are the
    // scene's Position plus the turned part Positions, before and after the move to the centre.
    const Scene scene = parseScene("DynamicObject, Name=L, Shape=Compound, Mass=3, Position=(5, 0, 0), Rotation=(0, 0, 90)\n"
                                   "Part, Name=foot, Body=L, Shape=Box, Position=(1, 0, 0), Scale=(2, 1, 1)\n"
                                   "Part, Name=leg, Body=L, Shape=Box, Position=(0, 1.5, 0), Scale=(1, 2, 1), Rotation=(0, 0, 0)\n",
                                   "test.scene");
    const DynamicObject& body = scene.dynamics.front();
    REQUIRE(body.compound);
    REQUIRE(body.compound->parts.size() == 2);
    // Volumes 2 and 2: masses 1.5 and 1.5; centre (0.5, 0.75, 0) in the scene frame,
    // turned 90° about z: (-0.75, 0.5, 0).
    CHECK_THAT(body.compound->parts[0].mass, WithinAbs(1.5, kRoundOff));
    CHECK_THAT(glm::length(body.position - Vec3(5 - 0.75, 0.5, 0)), WithinAbs(0.0, kRoundOff));
    const Vec3 footWorld = body.position + body.orientation * body.compound->parts[0].position;
    CHECK_THAT(glm::length(footWorld - Vec3(5, 1, 0)), WithinAbs(0.0, kRoundOff));
    const Vec3 legWorld = body.position + body.orientation * body.compound->parts[1].position;
    CHECK_THAT(glm::length(legWorld - Vec3(5 - 1.5, 0, 0)), WithinAbs(0.0, kRoundOff));
}

TEST_CASE("A Part may come before its body, and a kinematic compound needs no mass", "[config]") {
    const Scene scene = parseScene("Part, Body=gate, Shape=Box, Scale=(0.1, 2, 0.1)\n"
                                   "Part, Body=gate, Shape=Box, Position=(1, 0, 0), Scale=(0.1, 2, 0.1)\n"
                                   "KinematicsObject, Name=gate, Shape=Compound\n",
                                   "test.scene");
    REQUIRE(scene.kinematics[0].compound);
    CHECK_THAT(glm::length(scene.kinematics[0].position - Vec3(0.5, 0, 0)), WithinAbs(0.0, kRoundOff));
}

TEST_CASE("World, Narrowphase=Auto|GjkEpa|Mpr", "[config]") {
    CHECK(parseScene("World\n", "t").settings.narrowphase == NarrowphaseKind::Auto);
    CHECK(parseScene("World, Narrowphase=GjkEpa\n", "t").settings.narrowphase == NarrowphaseKind::GjkEpa);
    CHECK(parseScene("World, Narrowphase=mpr\n", "t").settings.narrowphase == NarrowphaseKind::Mpr);
    const ConfigDiagnostic d = theProblemIn("World, Narrowphase=GjkEp\n");
    CHECK(d.message() == "test.scene:1:20: error: Narrowphase: expected one of Auto, GjkEpa, Mpr, found 'GjkEp'; "
                         "did you mean 'GjkEpa'?");
}

TEST_CASE("A hull of fewer than 4 points, or of coplanar points, is an error at Vertices", "[config]") {
    const ConfigDiagnostic few = theProblemIn("DynamicObject, Shape=Hull, Vertices=(0, 0, 0), (1, 0, 0), (0, 1, 0)\n");
    CHECK(few.message() == "test.scene:1:37: error: Vertices: expected at least 4 points that are not coplanar "
                           "(a hull with volume), found '3 points'; a hull needs at least 4 points that are not "
                           "coplanar, got 3");
    const ConfigDiagnostic flat =
        theProblemIn("DynamicObject, Shape=Hull, Vertices=(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)\n");
    CHECK(flat.line == 1);
    CHECK(flat.column == 37);
    CHECK(flat.field == "Vertices");
    CHECK(flat.found == "4 points");
    CHECK_THAT(flat.hint, Contains("coplanar, collinear or coincident"));
}

TEST_CASE("A bad point of Vertices is reported at its own column", "[config]") {
    const ConfigDiagnostic two = theProblemIn("DynamicObject, Shape=Hull, Vertices=(0, 0, 0), (1, 0)\n");
    CHECK(two.message() == "test.scene:1:48: error: Vertices: expected a point (x, y, z) (point 2 of Vertices), "
                           "found '(1, 0)'; 3 components are needed, this has 2");
    const ConfigDiagnostic word = theProblemIn("DynamicObject, Shape=Hull, Vertices=(0, 0, 0), (1, a, 0)\n");
    CHECK(word.message() == "test.scene:1:52: error: Vertices: expected a number, found 'a'");
}

TEST_CASE("A Hull needs Vertices or File, not both, and they belong to hulls and meshes only", "[config]") {
    CHECK(theProblemIn("DynamicObject, Shape=Hull\n").message() ==
          "test.scene:1:22: error: Shape: expected Vertices=(x, y, z), ... or File=model.obj with a Hull, found "
          "'Hull'; a hull is the convex solid around at least 4 points that are not coplanar, e.g. "
          "Vertices=(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)");
    CHECK(theProblemIn("DynamicObject, Shape=Box, Vertices=(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)\n").message() ==
          "test.scene:1:36: error: Vertices: expected no Vertices for a Box, found '(0, 0, 0), (1, 0, 0), (0, 1, 0), "
          "(0, 0, 1)'; Vertices are the points a Shape=Hull wraps");
    CHECK(theProblemIn("DynamicObject, Shape=Sphere, File=ball.obj\n").message() ==
          "test.scene:1:35: error: File: expected no File for a Sphere, found 'ball.obj'; File=model.obj gives a "
          "Shape=Hull its points or a Shape=Mesh its triangles");
    const ConfigDiagnostic both =
        theProblemIn("DynamicObject, Shape=Hull, File=a.obj, Vertices=(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)\n");
    CHECK(both.field == "File");
    CHECK(both.expected == "either Vertices or File for a Hull, not both");
}

TEST_CASE("Height on a shape without one is an error, and a Cylinder's must be a size", "[config]") {
    CHECK(theProblemIn("DynamicObject, Shape=Sphere, Height=2\n").message() ==
          "test.scene:1:37: error: Height: expected no Height for a Sphere, found '2'; Height is a Capsule's "
          "segment between its two ball centres or a Cylinder's full length");
    CHECK(theProblemIn("DynamicObject, Shape=Capsule, Height=-1\n").message() ==
          "test.scene:1:38: error: Height: expected a length from 0 to 1e6 m, found '-1'; Height is a capsule's "
          "segment between its two ball centres, or a cylinder's full length, in metres");
    const ConfigDiagnostic flat = theProblemIn("DynamicObject, Shape=Cylinder, Height=0\n");
    CHECK(flat.column == 39);
    CHECK(flat.expected == "a size from 1e-6 to 1e6 m for a Cylinder");
}

TEST_CASE("Shape=Mesh on a DynamicObject is an error, and a Mesh needs a File with faces", "[config]") {
    CHECK(theProblemIn("DynamicObject, Shape=Mesh, File=ramp.obj\n").message() ==
          "test.scene:1:22: error: Shape: expected a shape with an inside (Sphere, Box, Capsule, Cylinder, Hull or "
          "Compound) for a DynamicObject, found 'Mesh'; a triangle mesh is a surface with no volume, so no mass: "
          "use it on a KinematicsObject, or Shape=Hull for a convex solid read from the same OBJ file");
    const Folder folder("mesh_errors");
    folder.write("models/points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    folder.write("models/sliver.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\n");
    const std::string noFaces = folder.write("a.scene", "KinematicsObject, Shape=Mesh, File=models/points.obj\n");
    try {
        (void)loadSceneFile(noFaces);
        FAIL("loaded");
    } catch (const ConfigError& error) {
        CHECK(std::string(error.what()) ==
              noFaces + ":1:36: error: File: expected an OBJ file with faces (f lines) for a Mesh, found "
                        "'models/points.obj'; it has 3 vertices but no faces");
    }
    const std::string sliver = folder.write("b.scene", "KinematicsObject, Shape=Mesh, File=models/sliver.obj\n");
    try {
        (void)loadSceneFile(sliver);
        FAIL("loaded");
    } catch (const ConfigError& error) {
        CHECK(std::string(error.what()) ==
              sliver + ":1:36: error: File: expected a mesh of triangles that each have an area, found "
                       "'models/sliver.obj'; triangle 1 has zero area (its corners coincide or lie on one line)");
    }
}

TEST_CASE("A missing, empty or special OBJ file is an error naming the path and the reason", "[config]") {
    const Folder folder("obj_errors");
    const std::string missing = folder.write("a.scene", "DynamicObject, Shape=Hull, File=models/none.obj\n");
    try {
        (void)loadSceneFile(missing);
        FAIL("loaded");
    } catch (const ConfigError& error) {
        const std::string resolved = (folder.path() / "models/none.obj").string();
        CHECK(std::string(error.what()) == missing + ":1:33: error: File: expected a readable OBJ file with vertices, "
                                                     "found 'models/none.obj'; cannot read " +
                                               resolved + ": no such file");
    }
    folder.write("models/empty.obj", "# nothing\n");
    const std::string empty = folder.write("b.scene", "DynamicObject, Shape=Hull, File=models/empty.obj\n");
    try {
        (void)loadSceneFile(empty);
        FAIL("loaded");
    } catch (const ConfigError& error) {
        CHECK_THAT(std::string(error.what()), Contains("no vertices"));
    }
    // A FIFO would block the read for ever: refused before it is opened.
    const fs::path fifo = folder.path() / "models/pipe.obj";
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::string piped = folder.write("c.scene", "DynamicObject, Shape=Hull, File=models/pipe.obj\n");
    try {
        (void)loadSceneFile(piped);
        FAIL("loaded");
    } catch (const ConfigError& error) {
        CHECK_THAT(std::string(error.what()), Contains("it is a FIFO, not a regular file"));
    }
}

TEST_CASE("With readFiles off, File= is an error and nothing is opened", "[config]") {
    try {
        (void)parseScene("DynamicObject, Shape=Hull, File=/dev/zero\n", "fuzz.scene", SceneReadOptions{.readFiles = false});
        FAIL("loaded");
    } catch (const ConfigError& error) {
        CHECK_THAT(std::string(error.what()), StartsWith("fuzz.scene:1:33: error: File: expected no File (this loader "
                                                         "reads no files), found '/dev/zero'"));
    }
}

TEST_CASE("A compound with no parts, and a Part naming an unknown or plain body, are errors", "[config]") {
    CHECK(theProblemIn("DynamicObject, Name=robot, Shape=Compound\n").message() ==
          "test.scene:1:34: error: Shape: expected at least one Part record with Body=robot, found 'Compound'; a "
          "compound body is made of its parts, e.g. Part, Body=robot, Shape=Box, Position=(0, 0, 0), Scale=(1, 1, 1)");
    try {
        (void)parseScene("DynamicObject, Name=robot, Shape=Compound\nPart, Body=robott\n", "test.scene");
        FAIL("loaded");
    } catch (const ConfigError& error) {
        // Two problems: the misspelt Body, and so a compound left without parts.
        REQUIRE(error.diagnostics().size() == 2);
        CHECK(error.diagnostics()[1].message() == "test.scene:2:12: error: Body: expected the Name of a "
                                                  "Shape=Compound object, found 'robott'; did you mean 'robot'?");
    }
    const std::string plain = "DynamicObject, Name=ball\nPart, Body=ball, Shape=Box\n";
    CHECK(theProblemIn(plain).message() ==
          "test.scene:2:12: error: Body: expected the Name of a Shape=Compound object, found 'ball'; 'ball' is the "
          "DynamicObject on line 1, not a Shape=Compound object; parts belong to compounds");
    CHECK(theProblemIn("Part, Shape=Box\n").message() ==
          "test.scene:1:1: error: Body: expected the Name of a Shape=Compound object, found 'Part, Shape=Box'; every "
          "Part names the compound it belongs to, e.g. Part, Body=robot, Shape=Box");
}

TEST_CASE("Part masses: all or none, and the body's Mass only when the parts give none", "[config]") {
    const ConfigDiagnostic mixed = theProblemIn("DynamicObject, Name=d, Shape=Compound\n"
                                                "Part, Body=d, Shape=Sphere, Mass=1\n"
                                                "Part, Body=d, Shape=Sphere, Position=(1, 0, 0)\n");
    CHECK(mixed.message() == "test.scene:3:1: error: Mass: expected a Mass on every Part of 'd' or on none, found "
                             "'Part, Body=d, Shape=Sphere, Position=(1, 0, 0)'; give each part of a compound its "
                             "Mass, or give none and the body's Mass is shared by volume (uniform density)");
    const ConfigDiagnostic twice = theProblemIn("DynamicObject, Name=d, Shape=Compound, Mass=5\n"
                                                "Part, Body=d, Shape=Sphere, Mass=1\n");
    CHECK(twice.message() == "test.scene:1:45: error: Mass: expected no Mass on a compound whose parts give theirs, "
                             "found '5'; the body's mass is the sum of its parts' Mass; leave one out");
    const ConfigDiagnostic kinematic = theProblemIn("KinematicsObject, Name=k, Shape=Compound\n"
                                                    "Part, Body=k, Shape=Box, Mass=2\n");
    CHECK(kinematic.line == 2);
    CHECK(kinematic.expected == "no Mass for a part of a KinematicsObject");
}

TEST_CASE("A Part's shape is convex: no Compound or Mesh parts, no Height on a Box part", "[config]") {
    const ConfigDiagnostic nested =
        theProblemIn("DynamicObject, Name=d, Shape=Compound\nPart, Body=d, Shape=Compound\n");
    CHECK(nested.line == 2);
    CHECK(nested.column == 21);
    CHECK(nested.expected == "a convex part (Sphere, Box, Capsule, Cylinder or Hull)");
    const ConfigDiagnostic height =
        theProblemIn("DynamicObject, Name=d, Shape=Compound\nPart, Body=d, Shape=Box, Height=1\n");
    CHECK(height.message() == "test.scene:2:33: error: Height: expected no Height for a Box, found '1'; Height is a "
                              "Capsule's segment between its two ball centres or a Cylinder's full length");
}

TEST_CASE("Nothing is half-loaded: one bad Part fails the whole scene", "[config]") {
    CHECK_THROWS_AS(parseScene("DynamicObject, Name=a\nDynamicObject, Name=d, Shape=Compound\n"
                               "Part, Body=d, Shape=Hull, Vertices=(0, 0, 0), (1, 0, 0), (0, 1, 0)\n",
                               "test.scene"),
                    ConfigError);
}

TEST_CASE("A spring's anchor on a hull stays on the same material point", "[config]") {
    // The hull's frame moves to its centre (1, 1, 1); the anchor written at the scene frame's
    // corner (2, 2, 2) is (1, 1, 1) from the centre, in the body frame.
    const Scene scene = parseScene("DynamicObject, Name=h, Shape=Hull, Vertices=(0, 0, 0), (2, 0, 0), (0, 2, 0), (2, 2, 0), "
                                   "(0, 0, 2), (2, 0, 2), (0, 2, 2), (2, 2, 2)\n"
                                   "Spring, BodyA=h, AnchorA=(2, 2, 2), AnchorB=(0, 10, 0), Stiffness=10\n",
                                   "test.scene");
    CHECK_THAT(glm::length(scene.springs[0].anchorA - Vec3(1, 1, 1)), WithinAbs(0.0, kRoundOff));
}
