// The viewer (src/viewer/, `stepwise view`): its camera, ray, mouse and
// clock maths; real screenshots drawn under Xvfb, checked pixel by pixel
// against where the physics puts the bodies; and the real window driven with
// the mouse by xdotool, its picks and pushes checked against the physics.
// Tag: [viewer] (the ones under Xvfb also [xvfb], the mouse one [xdotool]).
//
// The screenshot tests need xvfb-run (Debian package xvfb, installed by
// scripts/setup.sh) and a program built with STEPWISE_VIEWER=ON, and the
// picking test also xdotool; without them they pass with a WARN saying what
// was skipped.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <array>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <utility>
#include <sstream>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "skip.hpp"
#include "config/scene_loader.hpp"
#include "viewer/camera.hpp"
#include "objects/inertia.hpp"
#include "test_support.hpp"
#include "viewer/fixed_step_clock.hpp"
#include "viewer/mouse_controls.hpp"
#include "viewer/mouse_force.hpp"
#include "viewer/picking.hpp"
#include "viewer/renderer.hpp"
#include "viewer/simulation.hpp"
#include "viewer/space_layout.hpp"
#include "viewer/stage_walkthrough.hpp"

using Catch::Matchers::Contains;
using namespace stepwise;
using namespace stepwise::viewer;

namespace {

const std::string kSourceDir = STEPWISE_SOURCE_DIR;
const std::string kScene = kSourceDir + "/config/viewer_test.scene";

using Result = stepwise::test::CommandResult;
using stepwise::test::shell;

std::string cli() { return std::string("'") + STEPWISE_CLI_PATH + "'"; }

/// Runs @p command (`stepwise view …`, or a script that starts it) in a
/// virtual X display. LeakSanitizer (in the asan preset) is told to ignore
/// leaks inside Mesa's driver, listed in src/viewer/lsan_suppressions.txt;
/// leaks in Stepwise's own code still fail.
///
/// Two things about xvfb-run are worked around here:
/// - `xvfb-run -a` picks the first free display number, but two started at
///   the same moment (CTest runs tests in parallel) can pick the same one,
///   and the loser's server fails to start. That is retried, a few times,
///   after a pause.
/// - xvfb-run's own exit status replaces the command's when its clean-up
///   fails ("problem while cleaning up temporary directory", status 5, seen
///   on a loaded CI machine). So the command's status is printed after it
///   runs, behind a marker, and taken from there.
Result underXvfb(const std::string& command) {
    static const std::string kMarker = "stepwise-test-exit-status=";
    std::string quoted;  // command inside sh -c '…': each ' becomes '\''
    for (char c : command) quoted += (c == '\'' ? std::string("'\\''") : std::string(1, c));
    Result result;
    for (int attempt = 0; attempt < 4; ++attempt) {
        if (attempt > 0) ::usleep(static_cast<useconds_t>(300000 + 400000 * attempt + (::getpid() % 7) * 50000));
        result = shell("LSAN_OPTIONS=print_suppressions=0:suppressions='" + kSourceDir +
                       "/src/viewer/lsan_suppressions.txt' xvfb-run -a sh -c '" + quoted + "; echo " + kMarker +
                       "$?'");
        const std::size_t marker = result.output.rfind(kMarker);
        if (marker != std::string::npos) {  // the command ran: its status, not xvfb-run's
            result.exitCode = std::atoi(result.output.c_str() + marker + kMarker.size());
            result.output.erase(marker, result.output.find('\n', marker) - marker);
        }
        const bool serverClash = result.exitCode != 0 && (result.output.find("Xvfb failed to start") != std::string::npos ||
                                 result.output.find("already active") != std::string::npos ||
                                 result.output.find("cannot open the X display") != std::string::npos ||
                                 result.output.find("failed to open display") != std::string::npos);
        if (!serverClash) break;
    }
    return result;
}

/// Runs `stepwise view ARGS` in a virtual X display (see underXvfb()).
Result viewUnderXvfb(const std::string& args) { return underXvfb(cli() + " view " + args); }

/// Why the screenshot tests cannot run on this build ("" when they can). A program built without
/// the viewer cannot take one: the test is skipped. A missing xvfb-run is not the build's doing:
/// the test fails, saying how to install it.
std::string screenshotsUnavailable() {
    const Result probe = shell("env -u DISPLAY " + cli() + " view '" + kScene + "'");
    if (probe.output.find("was not built") != std::string::npos) {
        return "this stepwise was built without the viewer (STEPWISE_VIEWER=OFF)";
    }
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) {
        FAIL("xvfb-run is not installed (Debian package xvfb; scripts/setup.sh installs it)");
    }
    return "";
}

struct TempFile {
    std::filesystem::path path;
    explicit TempFile(const std::string& name)
        : path(std::filesystem::temp_directory_path() /
               ("stepwise-test-" + std::to_string(::getpid()) + "-" + name)) {}
    ~TempFile() { std::filesystem::remove(path); }
    std::string quoted() const { return "'" + path.string() + "'"; }
};

/// A fresh directory under the temporary directory, removed with everything in it.
struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& name)
        : path(std::filesystem::temp_directory_path() /
               ("stepwise-test-" + std::to_string(::getpid()) + "-" + name)) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
    std::string quoted() const { return "'" + path.string() + "'"; }
};

std::vector<std::uint8_t> readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> lines(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::vector<std::string> all;
    for (std::string line; std::getline(in, line);) all.push_back(line);
    return all;
}

// ---- A PNG decoder for what the viewer writes --------------------------------
// Written independently of src/viewer/png_writer.cpp (bitwise CRC, its own
// parsing), so a bug in the encoder is not mirrored here. It reads 8-bit RGB
// images whose zlib stream uses stored blocks and whose rows use filter 0:
// exactly what the viewer writes; anything else fails the test.

std::uint32_t bigEndian32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

std::uint32_t bitwiseCrc32(const std::uint8_t* p, std::size_t n) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < n; ++i) {
        crc ^= p[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;  // top row first
    const std::uint8_t* at(int x, int y) const {
        return &rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3];
    }
};

Image decodePng(const std::vector<std::uint8_t>& file) {
    const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    REQUIRE(file.size() > 8);
    REQUIRE(std::equal(signature, signature + 8, file.begin()));
    Image image;
    std::vector<std::uint8_t> zlib;
    bool ended = false;
    for (std::size_t at = 8; at + 12 <= file.size() && !ended;) {
        const std::uint32_t length = bigEndian32(&file[at]);
        REQUIRE(at + 12 + length <= file.size());
        const std::string type(file.begin() + static_cast<std::ptrdiff_t>(at + 4),
                               file.begin() + static_cast<std::ptrdiff_t>(at + 8));
        const std::uint8_t* data = &file[at + 8];
        INFO("chunk " << type);
        CHECK(bitwiseCrc32(&file[at + 4], length + 4) == bigEndian32(data + length));
        if (type == "IHDR") {
            image.width = static_cast<int>(bigEndian32(data));
            image.height = static_cast<int>(bigEndian32(data + 4));
            REQUIRE(data[8] == 8);   // bit depth
            REQUIRE(data[9] == 2);   // RGB
            REQUIRE(data[12] == 0);  // not interlaced
        } else if (type == "IDAT") {
            zlib.insert(zlib.end(), data, data + length);
        } else if (type == "IEND") {
            ended = true;
        }
        at += 12 + length;
    }
    REQUIRE(ended);
    REQUIRE(image.width > 0);
    // zlib: CMF/FLG header, stored deflate blocks, Adler-32.
    REQUIRE(zlib.size() >= 6);
    REQUIRE((zlib[0] * 256 + zlib[1]) % 31 == 0);
    std::vector<std::uint8_t> raw;
    std::size_t at = 2;
    for (bool last = false; !last;) {
        REQUIRE(at + 5 <= zlib.size());
        last = (zlib[at] & 1) != 0;
        REQUIRE((zlib[at] >> 1) == 0);  // BTYPE 00: stored
        const unsigned length = zlib[at + 1] | unsigned(zlib[at + 2]) << 8;
        const unsigned complement = zlib[at + 3] | unsigned(zlib[at + 4]) << 8;
        REQUIRE((length ^ 0xFFFFu) == complement);
        REQUIRE(at + 5 + length <= zlib.size());
        raw.insert(raw.end(), zlib.begin() + static_cast<std::ptrdiff_t>(at + 5),
                   zlib.begin() + static_cast<std::ptrdiff_t>(at + 5 + length));
        at += 5 + length;
    }
    REQUIRE(at + 4 == zlib.size());
    std::uint32_t a = 1, b = 0;
    for (std::uint8_t byte : raw) {
        a = (a + byte) % 65521;
        b = (b + a) % 65521;
    }
    CHECK(((b << 16) | a) == bigEndian32(&zlib[at]));
    const std::size_t row = static_cast<std::size_t>(image.width) * 3;
    REQUIRE(raw.size() == (row + 1) * static_cast<std::size_t>(image.height));
    for (int y = 0; y < image.height; ++y) {
        const auto start = raw.begin() + static_cast<std::ptrdiff_t>((row + 1) * static_cast<std::size_t>(y));
        REQUIRE(*start == 0);  // filter "none"
        image.rgb.insert(image.rgb.end(), start + 1, start + 1 + static_cast<std::ptrdiff_t>(row));
    }
    return image;
}

/// Which of red, green and blue clearly dominates a pixel ('r', 'g', 'b'), or '-'.
char dominant(const std::uint8_t* p) {
    const int r = p[0], g = p[1], b = p[2];
    if (r > 80 && r > 2 * g && r > 2 * b) return 'r';
    if (g > 80 && g > 2 * r && g > 2 * b) return 'g';
    if (b > 80 && b > 2 * r && b > 2 * g) return 'b';
    return '-';
}

/// The World of the test scene after the same number of steps the viewer takes for `--at seconds`.
World worldAt(double seconds) {
    World world(loadSceneFile(kScene));
    const auto steps = std::llround(seconds / double(world.settings().timeStep));
    for (long long i = 0; i < steps; ++i) world.step();
    return world;
}

}  // namespace

TEST_CASE("The camera's projection and its mouse ray agree", "[viewer]") {
    OrbitCamera camera;
    camera.target = Vec3(1, 0.5, -2);
    camera.distance = 7;
    camera.yaw = Real(0.9);
    camera.pitch = Real(0.4);
    const int width = 640, height = 400;

    // The target is drawn at the centre of the image.
    const Vec3 centre = camera.project(camera.target, width, height);
    CHECK(centre.x == Approx(320).margin(1e-9));
    CHECK(centre.y == Approx(200).margin(1e-9));

    // A point above the target appears higher (smaller y from the top).
    CHECK(camera.project(camera.target + Vec3(0, 1, 0), width, height).y < 200);

    // The ray through a point's pixel passes through the point.
    const Vec3 p(2.5, 1.2, -1);
    const Vec3 pixel = camera.project(p, width, height);
    const Ray ray = camera.rayThroughPixel(pixel.x, pixel.y, width, height);
    const Vec3 toP = p - ray.origin;
    const Vec3 offRay = toP - glm::dot(toP, ray.direction) * ray.direction;
    CHECK(glm::length(offRay) < 1e-9);
    CHECK(glm::length(ray.direction) == Approx(1));
    CHECK(glm::length(camera.eye() - camera.target) == Approx(7));
}

namespace {

/// A World holding only @p body (a dynamic body), for one ray cast.
World worldWith(const DynamicObject& body) {
    Scene scene;
    scene.dynamics = {body};
    return World(scene);
}

/// Where the pick along @p ray meets the World of @p body alone, m along the ray; nothing when it misses.
std::optional<Real> pickDistance(const DynamicObject& body, const Ray& ray) {
    const std::optional<RayHit> hit = pickBody(worldWith(body), ray);
    return hit ? std::optional<Real>(hit->distance) : std::nullopt;
}

DynamicObject boxAt(const Vec3& centre, const Quat& orientation, const Vec3& halfExtents) {
    DynamicObject box;
    box.name = "box";
    box.shape = Shape::Box;
    box.position = centre;
    box.orientation = orientation;
    box.scale = Real(2) * halfExtents;
    return box;
}

}  // namespace

TEST_CASE("Picking through World::raycast hits spheres and turned boxes where the geometry says", "[viewer]") {
    const Ray down{Vec3(0, 10, 0), Vec3(0, -1, 0)};
    const DynamicObject ball = test::sphere("ball", Vec3(0), Vec3(0), 1);
    // A sphere of radius 1 at the origin is entered at y = 1: 9 m down the ray, normal up.
    const std::optional<RayHit> top = pickBody(worldWith(ball), down);
    REQUIRE(top.has_value());
    CHECK(top->distance == Approx(9));
    CHECK(glm::length(top->point - Vec3(0, 1, 0)) < 1e-12);
    CHECK(glm::length(top->normal - Vec3(0, 1, 0)) < 1e-12);
    CHECK_FALSE(pickDistance(test::sphere("beside", Vec3(3, 0, 0), Vec3(0), 1), down).has_value());
    CHECK_FALSE(pickDistance(ball, {Vec3(0, 10, 0), Vec3(0, 1, 0)}).has_value());  // behind the ray
    CHECK(*pickDistance(ball, {Vec3(0.2, 0, 0), Vec3(1, 0, 0)}) == 0);            // starting inside

    // A 2 m cube turned 45° about z has a corner on top at y = √2.
    const Quat turned = glm::angleAxis(kPi / 4, Vec3(0, 0, 1));
    REQUIRE(pickDistance(boxAt(Vec3(0), turned, Vec3(1)), down).has_value());
    CHECK(*pickDistance(boxAt(Vec3(0), turned, Vec3(1)), down) == Approx(10 - std::sqrt(2.0)));
    // Straight, its top face is at y = 1; 1.2 m to the side the ray misses it, turned or not.
    CHECK(*pickDistance(boxAt(Vec3(0), Quat(1, 0, 0, 0), Vec3(1)), down) == Approx(9));
    CHECK_FALSE(pickDistance(boxAt(Vec3(0), turned, Vec3(1)), {Vec3(1.5, 10, 0), Vec3(0, -1, 0)}).has_value());
    CHECK_FALSE(pickDistance(boxAt(Vec3(0), turned, Vec3(1)), {Vec3(0, 10, 1.2), Vec3(0, -1, 0)}).has_value());

    // Of two bodies on the ray, the nearer is picked.
    Scene scene;
    DynamicObject low, high;
    low.name = "low";
    low.position = Vec3(0, 1, 0);
    high.name = "high";
    high.shape = Shape::Box;
    high.position = Vec3(0, 4, 0);
    scene.dynamics = {low, high};
    const World world(scene);
    const std::optional<RayHit> hit = pickBody(world, down);
    REQUIRE(hit.has_value());
    CHECK(hit->body.kind == BodyKind::Dynamic);
    CHECK(hit->body.index == 1);
    CHECK(hit->point.y == Approx(4.5));
}

TEST_CASE("The ray through a cursor pixel meets a sphere, a turned box and a plane at the point drawn there",
          "[viewer]") {
    // Each shape gets a point on its camera-facing side; the ray through the
    // pixel that point is drawn at must enter the shape exactly there.
    OrbitCamera camera;
    camera.target = Vec3(0.2, 0.5, -0.4);
    camera.distance = 9;
    camera.yaw = Real(-0.7);
    camera.pitch = Real(0.45);
    const int width = 640, height = 400;
    const Vec3 eye = camera.eye();
    const Mat4 view = camera.viewMatrix();
    const Vec3 cameraRight(view[0][0], view[1][0], view[2][0]);
    const Vec3 cameraUp(view[0][1], view[1][1], view[2][1]);
    auto rayAt = [&](const Vec3& p) {
        const Vec3 pixel = camera.project(p, width, height);
        return camera.rayThroughPixel(pixel.x, pixel.y, width, height);
    };

    SECTION("sphere: the nearer root of the quadratic") {
        const Vec3 centre(0.5, 1, -0.3);
        const Real radius = Real(0.7);
        // Off the centre, to the right of it and above, still facing the eye.
        const Vec3 normal = glm::normalize(glm::normalize(eye - centre) + Real(0.6) * cameraRight + Real(0.3) * cameraUp);
        REQUIRE(glm::dot(normal, eye - centre) > 0);
        const Vec3 surface = centre + radius * normal;
        const Ray ray = rayAt(surface);
        const std::optional<Real> s = pickDistance(test::sphere("ball", centre, Vec3(0), radius), ray);
        REQUIRE(s.has_value());
        CHECK(glm::length(ray.origin + *s * ray.direction - surface) < 1e-9);
        // The ray enters there and leaves on the far side: the far point is not the hit.
        CHECK(*s < glm::length(centre - ray.origin));
    }
    SECTION("oriented box: the entry point of the slab test, on the face turned to the eye") {
        const Vec3 centre(-0.6, 0.4, 0.8);
        const Quat turn = glm::angleAxis(Real(0.5), glm::normalize(Vec3(1, 1, 0)));
        const Vec3 half(0.5, 0.3, 0.8);
        // The face whose outward normal looks most towards the eye, and a point off its centre.
        int axis = 0;
        Real sign = 1, best = -2;
        for (int i = 0; i < 3; ++i) {
            for (Real side : {Real(-1), Real(1)}) {
                Vec3 local(0);
                local[i] = side;
                const Real facing = glm::dot(glm::normalize(turn * local), glm::normalize(eye - centre));
                if (facing > best) {
                    best = facing;
                    axis = i;
                    sign = side;
                }
            }
        }
        Vec3 local(0);
        local[axis] = sign * half[axis];
        local[(axis + 1) % 3] = Real(0.4) * half[(axis + 1) % 3];
        local[(axis + 2) % 3] = Real(-0.7) * half[(axis + 2) % 3];
        const Vec3 onFace = centre + turn * local;
        const Ray ray = rayAt(onFace);
        const std::optional<Real> s = pickDistance(boxAt(centre, turn, half), ray);
        REQUIRE(s.has_value());
        CHECK(glm::length(ray.origin + *s * ray.direction - onFace) < 1e-9);
        // A pixel beside the box: its ray passes farther from the centre than
        // the box's corners are, so the slab test must find no hit.
        const Ray beside = rayAt(centre + Real(2.5) * glm::length(half) * cameraRight);
        const Vec3 toCentre = centre - beside.origin;
        REQUIRE(glm::length(toCentre - glm::dot(toCentre, beside.direction) * beside.direction) > glm::length(half));
        CHECK_FALSE(pickDistance(boxAt(centre, turn, half), beside).has_value());
    }
    SECTION("plane: s = n·(p0 − o) / n·d") {
        Scene scene;
        CollisionPlane floor;
        floor.name = "floor";
        floor.position = Vec3(0, -1, 0);
        scene.planes = {floor};
        const World world(scene);
        const Vec3 onFloor(1.3, -1, 2.1);
        const Ray ray = rayAt(onFloor);
        const std::optional<RayHit> hit = pickBody(world, ray);
        REQUIRE(hit.has_value());
        CHECK(hit->body.kind == BodyKind::Plane);
        CHECK(glm::length(ray.origin + hit->distance * ray.direction - onFloor) < 1e-9);
        CHECK(glm::length(hit->point - onFloor) < 1e-9);
        // Not a plane the ray runs along or away from ...
        CHECK_FALSE(pickBody(world, {Vec3(0, 2, 0), Vec3(1, 0, 0)}).has_value());
        CHECK_FALSE(pickBody(world, {Vec3(0, 2, 0), Vec3(0, 1, 0)}).has_value());
        // ... and from below, inside the solid, the plane is met at once: nothing behind it can be picked.
        const std::optional<RayHit> below = pickBody(world, {Vec3(0, -3, 0), Vec3(0, 1, 0)});
        REQUIRE(below.has_value());
        CHECK(below->distance == 0);
    }
}

TEST_CASE("Picking takes the nearest hit along the cursor's ray, and the floor hides what is below it", "[viewer]") {
    OrbitCamera camera;
    camera.distance = 12;
    const int width = 640, height = 400;
    const Vec3 towardsEye = glm::normalize(camera.eye() - camera.target);

    Scene scene;
    DynamicObject front = test::sphere("front", camera.target + Real(2) * towardsEye, Vec3(0), Real(0.5));
    DynamicObject back = test::sphere("back", camera.target - Real(2) * towardsEye, Vec3(0), Real(0.5));
    DynamicObject buried = test::sphere("buried", Vec3(4, -3, 0), Vec3(0), Real(0.5));
    KinematicsObject slab;
    slab.name = "slab";
    slab.shape = Shape::Box;
    slab.position = Vec3(-4, 1, 0);
    slab.scale = Vec3(2, 0.4, 2);
    scene.dynamics = {back, front, buried};  // the farther one first: the order must not matter
    scene.kinematics = {slab};
    scene.planes = {test::ground("floor")};
    const World world(scene);
    auto pickAtPointOf = [&](const Vec3& p) {
        const Vec3 pixel = camera.project(p, width, height);
        return pickBody(world, camera.rayThroughPixel(pixel.x, pixel.y, width, height));
    };

    // Front and back lie on one line of sight: the front one is picked, at its near surface.
    const std::optional<RayHit> hit = pickAtPointOf(world.dynamics()[0].position);
    REQUIRE(hit.has_value());
    CHECK(hit->body.kind == BodyKind::Dynamic);
    CHECK(hit->body.index == 1);
    CHECK(glm::length(hit->point - (world.dynamics()[1].position + Real(0.5) * towardsEye)) < 1e-9);
    CHECK(glm::length(hit->normal - towardsEye) < 1e-9);  // the sphere's outward normal faces the eye

    // A kinematic body is picked (to be named; the viewer does not push it).
    const std::optional<RayHit> onSlab = pickAtPointOf(slab.position + Vec3(0, 0.2, 0));
    REQUIRE(onSlab.has_value());
    CHECK(onSlab->body.kind == BodyKind::Kinematic);
    CHECK(onSlab->point.y == Approx(1.2));

    // The ball under the floor is behind the floor from the eye: the floor is hit, at y = 0.
    const std::optional<RayHit> onFloor = pickAtPointOf(world.dynamics()[2].position);
    REQUIRE(onFloor.has_value());
    CHECK(onFloor->body.kind == BodyKind::Plane);
    CHECK(onFloor->point.y == Approx(0).margin(1e-9));

    // Straight up into the sky nothing is hit.
    CHECK_FALSE(pickBody(world, Ray{camera.eye(), Vec3(0, 1, 0)}).has_value());
}

TEST_CASE("A push acts at the picked point: the body moves along the ray and turns about r x F", "[viewer]") {
    // A ball of 2 kg and radius 1 m at the camera's target, no gravity: the
    // grab's acceleration is 20 m/s^2 and I = 2/5 m R^2 = 0.8 kg m^2.
    const Real mass = 2, radius = 1, h = Real(1) / 60;
    const Vec3 noGravity(0);
    const Real inertia = Real(0.4) * mass * radius * radius;
    OrbitCamera camera;
    camera.distance = 6;
    const int width = 640, height = 400;
    const Mat4 view = camera.viewMatrix();
    const Vec3 cameraRight(view[0][0], view[1][0], view[2][0]);
    const Vec3 cameraUp(view[0][1], view[1][1], view[2][1]);

    auto pushOnce = [&](Real pixelsRightOfCentre, bool pull) {
        DynamicObject ball = test::sphere("ball", camera.target, Vec3(0), radius, mass);
        initialiseMassProperties(ball);
        const Ray ray = camera.rayThroughPixel(Real(width) / 2 + pixelsRightOfCentre, Real(height) / 2, width, height);
        const std::optional<RayHit> picked = pickBody(worldWith(ball), ray);
        REQUIRE(picked.has_value());
        const Vec3 hit = picked->point;
        const Grab grab = grabAt(ball, 0, hit, ray.direction, pull);
        CHECK(glm::length(grabPoint(ball, grab) - hit) < 1e-12);
        applyGrab(ball, grab, noGravity, h);

        // Linear: dv = F h / m = 20 m/s^2 * h along the ray (against it for a pull).
        const Vec3 force = (pull ? -1 : 1) * mass * Real(20) * ray.direction;
        CHECK(glm::length(ball.velocity - force * h / mass) < 1e-12);
        // Angular: dL = r x F h, and for a ball w = L / I about any axis.
        const Vec3 r = hit - ball.position;
        CHECK(glm::length(ball.angularVelocity - glm::cross(r, force) * h / inertia) < 1e-12);
        return ball;
    };

    SECTION("through the centre it only moves") {
        const DynamicObject ball = pushOnce(0, false);
        CHECK(glm::length(ball.angularVelocity) < 1e-9);
        CHECK(glm::dot(ball.velocity, camera.target - camera.eye()) > 0);  // away from the eye
    }
    SECTION("right of the centre it turns about the camera's up axis, its right side going away") {
        const DynamicObject ball = pushOnce(60, false);
        CHECK(glm::dot(ball.angularVelocity, cameraUp) > 0);
        CHECK(std::abs(glm::dot(glm::normalize(ball.angularVelocity), cameraUp)) > 0.99);
        // The pushed point gains more speed along the push than the centre:
        // an off-centre push spends part of the impulse on turning, not less on the point.
        const Vec3 rightSide = ball.position + radius * cameraRight;
        CHECK(glm::dot(velocityAt(ball, rightSide), camera.target - camera.eye()) >
              glm::dot(ball.velocity, camera.target - camera.eye()));
    }
    SECTION("left of the centre, or pulled, it turns the other way") {
        CHECK(glm::dot(pushOnce(-60, false).angularVelocity, cameraUp) < 0);
        const DynamicObject pulled = pushOnce(60, true);
        CHECK(glm::dot(pulled.angularVelocity, cameraUp) < 0);
        CHECK(glm::dot(pulled.velocity, camera.target - camera.eye()) < 0);  // towards the eye
    }
    SECTION("the held point turns with the body; with gravity the force is 2 m |g|") {
        DynamicObject ball = test::sphere("ball", Vec3(0), Vec3(0), radius, mass);
        const Grab grab = grabAt(ball, 0, Vec3(radius, 0, 0), Vec3(0, 0, -1), false);
        ball.orientation = glm::angleAxis(kPi / 2, Vec3(0, 1, 0));  // a quarter turn about +y takes +x to -z
        ball.position = Vec3(0, 5, 0);
        CHECK(glm::length(grabPoint(ball, grab) - Vec3(0, 5, -radius)) < 1e-12);
        CHECK(grabAcceleration(Vec3(0, -9.81, 0)) == Approx(2 * 9.81));
        CHECK(glm::length(grabForce(ball, grab, Vec3(0, -9.81, 0)) - Vec3(0, 0, -mass * 2 * 9.81)) < 1e-12);
    }
}

TEST_CASE("Mouse drags move the camera as their formulas say", "[viewer]") {
    OrbitCamera start;
    start.target = Vec3(1, 2, 3);
    start.distance = 8;
    start.yaw = Real(0.3);
    start.pitch = Real(0.2);
    const int width = 800, height = 500;

    SECTION("a button press picks the drag: grab on a dynamic body, else orbit, zoom or pan") {
        const Modifiers none, shift{true, false}, ctrl{false, true};
        CHECK(dragForPress(MouseButton::Left, none, true) == Drag::Grab);
        CHECK(dragForPress(MouseButton::Right, none, true) == Drag::Grab);
        CHECK(dragForPress(MouseButton::Left, none, false) == Drag::Orbit);
        CHECK(dragForPress(MouseButton::Right, none, false) == Drag::Zoom);
        CHECK(dragForPress(MouseButton::Middle, none, true) == Drag::Pan);
        CHECK(dragForPress(MouseButton::Left, shift, true) == Drag::Pan);
        CHECK(dragForPress(MouseButton::Left, ctrl, true) == Drag::Zoom);
        CHECK(dragForPress(MouseButton::WheelUp, none, true) == Drag::None);
    }
    SECTION("orbit: the angles change by 0.008 rad per pixel; target and distance stay") {
        OrbitCamera camera = start;
        dragCamera(camera, Drag::Orbit, 100, -50, height);
        CHECK(camera.yaw == Approx(0.3 - 0.8));
        CHECK(camera.pitch == Approx(0.2 - 0.4));
        CHECK(glm::length(camera.eye() - camera.target) == Approx(8));
        CHECK(glm::length(camera.target - start.target) == 0);
        // Dragging far down stops short of looking straight down (the view would flip).
        dragCamera(camera, Drag::Orbit, 0, 10000, height);
        CHECK(camera.pitch == Approx(1.5));
    }
    SECTION("zoom: the distance is multiplied by exp(0.01 dy), or 0.9 per wheel click; the eye stays on its line") {
        OrbitCamera camera = start;
        dragCamera(camera, Drag::Zoom, 37, 30, height);  // sideways motion does not zoom
        CHECK(camera.distance == Approx(8 * std::exp(0.3)));
        const Vec3 line = glm::normalize(start.eye() - start.target);
        CHECK(glm::length(glm::normalize(camera.eye() - camera.target) - line) < 1e-12);
        camera = start;
        wheelZoom(camera, MouseButton::WheelUp);
        CHECK(camera.distance == Approx(7.2));
        wheelZoom(camera, MouseButton::WheelDown);
        CHECK(camera.distance == Approx(8));
    }
    SECTION("pan: the scene at the target's depth follows the cursor pixel for pixel") {
        OrbitCamera camera = start;
        const Vec3 before = camera.project(start.target, width, height);
        dragCamera(camera, Drag::Pan, 40, -25, height);
        const Vec3 after = camera.project(start.target, width, height);
        CHECK(after.x - before.x == Approx(40).margin(1e-6));
        CHECK(after.y - before.y == Approx(-25).margin(1e-6));
        CHECK(glm::length((camera.eye() - camera.target) - (start.eye() - start.target)) < 1e-12);
    }
    SECTION("a grab leaves the camera alone") {
        OrbitCamera camera = start;
        dragCamera(camera, Drag::Grab, 40, 40, height);
        CHECK(glm::length(camera.eye() - start.eye()) == 0);
    }
}

TEST_CASE("The fixed-step clock turns any frame rate into the same whole steps", "[viewer]") {
    const double h = 1.0 / 240;
    SECTION("60 frames a second for 2 s give 480 steps of 1/240 s") {
        FixedStepClock clock(h);
        std::uint64_t steps = 0;
        for (int i = 0; i < 120; ++i) steps += clock.advance(1.0 / 60);
        CHECK(steps == 480);
    }
    SECTION("uneven frames give floor(total / h) steps, the remainder waits") {
        FixedStepClock clock(h);
        std::uint64_t steps = 0;
        double total = 0;
        for (int i = 0; i < 1000; ++i) {
            const double frame = 0.001 + 0.03 * ((i * 7919) % 101) / 100.0;  // 1 to 31 ms
            total += frame;
            steps += clock.advance(frame);
        }
        CHECK(steps == static_cast<std::uint64_t>(std::floor(total / h + 1e-6)));
        CHECK(clock.accumulator() < h);
    }
    SECTION("paused, nothing is stepped; half speed steps half as often") {
        FixedStepClock clock(h);
        clock.setPaused(true);
        CHECK(clock.advance(1.0) == 0);
        clock.setPaused(false);
        clock.setScale(0.5);
        std::uint64_t steps = 0;
        for (int i = 0; i < 60; ++i) steps += clock.advance(1.0 / 60);
        CHECK(steps == 120);
    }
    SECTION("a stalled frame counts as at most a quarter of a second") {
        FixedStepClock clock(h);
        CHECK(clock.advance(5.0) == 60);
    }
}

namespace {

/// Lesson 3's ball (radius 0.1 m, lowest point 1 m above the floor, e = 0.8,
/// Verlet, h = 1/60 s, Solver=Impulse). It touches at t = sqrt(2 / g) = 0.4515 s,
/// inside step 28: after 27 steps (t = 0.45 s) the next step sinks it into the floor.
const std::string kBounceScene = kSourceDir + "/config/lesson03_bounce.scene";
constexpr double kBeforeImpact = 0.45;

/// Presses S until the walk-through shows @p stage; returns the snapshot index.
std::size_t pressSUntil(Simulation& sim, Stage stage) {
    for (int press = 0; press < 1000; ++press) {
        sim.stepStage();
        REQUIRE(sim.shownStage().has_value());
        if (sim.walkthrough().snapshot(*sim.shownStage()).event.stage == stage) return *sim.shownStage();
    }
    FAIL("S never showed " << stageName(stage));
    return 0;
}

}  // namespace

TEST_CASE("S shows the ball where each stage left it: in the floor after integrate, on it after correct-positions",
          "[viewer]") {
    Simulation sim(kBounceScene);
    sim.stepTo(kBeforeImpact);
    const World& world = sim.world();
    REQUIRE(world.settings().solver == SolverKind::Impulse);
    const DynamicObject& ball = world.dynamics()[0];
    const CollisionPlane& floor = world.planes()[0];
    const Real r = ball.radius, e = ball.elasticity, g = glm::length(world.settings().gravity);
    const Real dropHeight = floor.signedDistance(ball.position) - r + Real(0.5) * glm::dot(ball.velocity, ball.velocity) / g;
    auto height = [&](const Vec3& centre) { return floor.signedDistance(centre) - r; };  // of the lowest point, m

    const std::size_t integrate = pressSUntil(sim, Stage::Integrate);
    const StageWalkthrough& walk = sim.walkthrough();
    REQUIRE(walk.snapshot(integrate).event.step == 28);
    // The World already is at the end of step 28; the snapshot is not.
    const BodySnapshot& sunk = walk.body(integrate, 0);
    INFO("after integrate the lowest point is at " << height(sunk.position) << " m");
    CHECK(height(sunk.position) < 0);  // below the floor's surface
    CHECK(sim.view().dynamics[0].position == sunk.position);  // what the renderer draws
    CHECK(height(world.dynamics()[0].position) >= -kTouchTolerance);
    // Verlet is exact under constant gravity: the depth is g t²/2 − 1 m at t = 28 h.
    const Real t = Real(28) * world.settings().timeStep;
    CHECK(-height(sunk.position) == Approx(Real(0.5) * g * t * t - dropHeight).epsilon(1e-9));

    // The narrowphase reports the contact that deep, at the floor.
    const std::size_t narrow = pressSUntil(sim, Stage::Narrowphase);
    const SceneView atNarrow = sim.view();
    REQUIRE(atNarrow.contacts.size() == 1);
    CHECK(atNarrow.contacts[0].depth == Approx(-height(walk.body(narrow, 0).position)).epsilon(1e-9));
    CHECK(walk.snapshot(narrow).description.find("1 contact") != std::string::npos);

    // Resolve-impulses turns the velocity up: e times the speed at touch, sqrt(2 g · 1 m).
    const std::size_t resolve = pressSUntil(sim, Stage::ResolveImpulses);
    const BodySnapshot& bounced = walk.body(resolve, 0);
    CHECK(bounced.velocity.y > 0);
    CHECK(bounced.velocity.y == Approx(e * std::sqrt(2 * g * dropHeight)).epsilon(0.01));
    CHECK(bounced.position == sunk.position);  // impulses change velocities only

    // Correct-positions puts it back on the surface.
    const std::size_t correct = pressSUntil(sim, Stage::CorrectPositions);
    CHECK(height(walk.body(correct, 0).position) >= -kTouchTolerance);
    CHECK(correct + 1 == walk.size());  // the last stage of the step
    CHECK(walk.body(correct, 0).position == world.dynamics()[0].position);
}

TEST_CASE("The walk-through has one snapshot per stage run, and leaving it keeps the trajectory of stepwise run",
          "[viewer]") {
    // viewer_test.scene runs the default sequential-impulse solver, 16 substeps.
    Simulation sim(kScene);
    sim.stepTo(0.5);
    const World& world = sim.world();
    REQUIRE(world.settings().solver == SolverKind::SequentialImpulse);
    const int substeps = world.settings().substeps;
    std::array<std::uint64_t, kStageCount> runsBefore{};
    for (std::size_t i = 0; i < kStageCount; ++i) runsBefore[i] = world.stageRecords()[i].runs;

    sim.stepStage();
    const StageWalkthrough& walk = sim.walkthrough();
    std::uint64_t runs = 0;
    for (std::size_t i = 0; i < kStageCount; ++i) runs += world.stageRecords()[i].runs - runsBefore[i];
    CHECK(walk.size() == runs);
    // Every substep runs integrate, move-kinematics, solve and relax; apply-forces again from the
    // second when springs or attractors make the forces follow the bodies (step_plan.hpp).
    const int forcesAgain = world.plan().substepForces.runs ? substeps - 1 : 0;
    CHECK(walk.size() >= std::size_t(4 * substeps + forcesAgain));
    std::vector<Stage> order;
    for (std::size_t k = 0; k < walk.size(); ++k) {
        const StageEvent& event = walk.snapshot(k).event;
        CHECK(event.step == world.stepCount());
        if (event.stage == Stage::SolveConstraints) {
            CHECK(event.substep == static_cast<int>(std::count(order.begin(), order.end(), Stage::SolveConstraints)));
            CHECK(walk.snapshot(k).description.rfind("substep " + std::to_string(event.substep + 1) + "/" +
                                                         std::to_string(substeps) + ": solve-constraints",
                                                     0) == 0);
        }
        order.push_back(event.stage);
    }

    SECTION("S visits every snapshot in order; Shift+S only the first and last substep's") {
        std::size_t plain = 1;
        while (sim.shownStage() && *sim.shownStage() + 1 < walk.size()) {
            sim.stepStage();
            ++plain;
        }
        CHECK(plain == walk.size());
        Simulation skipping(kScene);
        skipping.stepTo(0.5);
        std::size_t presses = 0;
        std::vector<int> substepsSeen;
        do {
            skipping.stepStage(true);
            ++presses;
            const int substep = skipping.walkthrough().snapshot(*skipping.shownStage()).event.substep;
            if (substep >= 0 && (substepsSeen.empty() || substepsSeen.back() != substep)) substepsSeen.push_back(substep);
        } while (*skipping.shownStage() + 1 < skipping.walkthrough().size());
        CHECK(substepsSeen == std::vector<int>{0, substeps - 1});
        CHECK(presses < walk.size() / 4);
    }
    SECTION("N leaves at the end of the step; the state is that of the same steps without the walk-through") {
        sim.stepStage();
        sim.stepStage(true);
        sim.stepOnce();  // leaves the walk-through: no step
        CHECK_FALSE(sim.shownStage().has_value());
        CHECK(world.stepCount() == 31);
        sim.stepStage();  // a second recorded step
        sim.stepOnce();
        sim.stepOnce();  // and one plain step
        World plain(loadSceneFile(kScene));
        for (int i = 0; i < 33; ++i) plain.step();
        REQUIRE(world.stepCount() == 33);
        for (std::size_t i = 0; i < plain.dynamics().size(); ++i) {
            CHECK(world.dynamics()[i].position == plain.dynamics()[i].position);
            CHECK(world.dynamics()[i].velocity == plain.dynamics()[i].velocity);
            CHECK(world.dynamics()[i].orientation == plain.dynamics()[i].orientation);
        }
    }
}

TEST_CASE("The walk-through's arrays stop growing after the first recorded step", "[viewer]") {
    // The bouncing ball has at most one pair and one contact in any step, and
    // every step has the same seven stage runs (the foundation's seven and
    // continuous, less move-kinematics, which the step plan skips: no kinematic bodies): after the step with the
    // contact, no recording needs more room.
    Simulation sim(kBounceScene);
    sim.stepTo(kBeforeImpact);
    sim.showStageRun(0);
    REQUIRE(sim.walkthrough().size() == 7);
    const std::size_t first = sim.walkthrough().memoryBytes();
    CHECK(first > 0);
    for (int step = 0; step < 20; ++step) {
        sim.stepOnce();
        sim.showStageRun(0);
        CHECK(sim.walkthrough().memoryBytes() == first);
    }
}

TEST_CASE("Without a display, stepwise view says why and how to run headless", "[viewer]") {
    const Result r = shell("env -u DISPLAY " + cli() + " view '" + kScene + "'");
    CHECK(r.exitCode == 2);
    if (r.output.find("was not built") != std::string::npos) {
        CHECK_THAT(r.output, Contains("STEPWISE_VIEWER"));
        return;
    }
    CHECK_THAT(r.output, Contains("DISPLAY is not set") && Contains("xvfb-run -a") && Contains("--screenshot"));
}

TEST_CASE("stepwise view rejects malformed options with exit code 2", "[viewer]") {
    if (shell("env -u DISPLAY " + cli() + " view '" + kScene + "'").output.find("was not built") !=
        std::string::npos) {
        STEPWISE_SKIP("this stepwise was built without the viewer (STEPWISE_VIEWER=OFF)");
    }
    CHECK(shell(cli() + " view --at 1").exitCode == 2);  // --at without --screenshot
    CHECK_THAT(shell(cli() + " view --screenshot x.png --size 10x10").output, Contains("--size expects"));
    CHECK(shell(cli() + " view --screenshot x.png --at -1").exitCode == 2);
    CHECK(shell(cli() + " view --zoom 3").exitCode == 2);
    CHECK_THAT(shell(cli() + " view --screenshot x.png --log-events y.log").output, Contains("--log-events"));
    CHECK(shell(cli() + " view /no/such.scene").exitCode == 2);
}

TEST_CASE("A screenshot shows the bodies where the physics puts them, and drawing changes nothing",
          "[viewer][xvfb]") {
    if (const std::string why = screenshotsUnavailable(); !why.empty()) STEPWISE_SKIP(why);
    const double t = 0.5;
    const int width = 320, height = 240;
    const TempFile png("viewer.png"), state("viewer-state.csv"), csv("viewer-run.csv");

    // O hides the text overlay, so every pixel is the 3D scene.
    const Result shot = viewUnderXvfb("'" + kScene + "' --screenshot " + png.quoted() + " --at 0.5 --size 320x240" +
                                      " --keys O --dump-state " + state.quoted());
    INFO(shot.output);
    REQUIRE(shot.exitCode == 0);
    CHECK_THAT(shot.output, Contains("t = 0.5 s (step 30)"));
    const Image image = decodePng(readBytes(png.path));
    REQUIRE(image.width == width);
    REQUIRE(image.height == height);

    {  // The image is a picture, not a blank.
        std::vector<std::uint32_t> colours;
        for (int y = 0; y < height; y += 2) {
            for (int x = 0; x < width; x += 2) {
                const std::uint8_t* p = image.at(x, y);
                colours.push_back(std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2]);
            }
        }
        std::sort(colours.begin(), colours.end());
        const auto distinct = std::unique(colours.begin(), colours.end()) - colours.begin();
        CHECK(distinct > 50);
    }

    {  // Each body's colour is at its projected centre; the ball has left its start.
        // The viewer frames the scene as loaded (t = 0), then simulates to t.
        const OrbitCamera camera = cameraForScene(World(loadSceneFile(kScene)));
        const World world = worldAt(t);
        auto colourAt = [&](const Vec3& p) {
            const Vec3 pixel = camera.project(p, width, height);
            INFO("projected to (" << pixel.x << ", " << pixel.y << ")");
            REQUIRE(pixel.x >= 0);
            REQUIRE(pixel.x < width);
            REQUIRE(pixel.y >= 0);
            REQUIRE(pixel.y < height);
            return dominant(image.at(static_cast<int>(pixel.x), static_cast<int>(pixel.y)));
        };
        const DynamicObject& red = *world.findDynamic("red");
        CHECK(red.position.y < Real(1.8));  // it fell about 1.2 m
        CHECK(colourAt(red.position) == 'r');
        CHECK(colourAt(Vec3(0, 3, 0)) == '-');  // where it started: floor or sky now
        CHECK(colourAt(world.findDynamic("green")->position) == 'g');
        CHECK(colourAt(world.kinematics()[0].position) == 'b');  // moved 0.5 m since t = 0
    }

    {  // The state drawn is the state `stepwise run` reaches, to the last bit.
        const Result run = shell(cli() + " run '" + kScene + "' --duration 0.5 --csv " + csv.quoted());
        REQUIRE(run.exitCode == 0);
        const std::vector<std::string> drawn = lines(state.path);
        const std::vector<std::string> ran = lines(csv.path);
        REQUIRE(drawn.size() == 4);  // header and three objects
        REQUIRE(ran.size() > 4);
        CHECK(drawn[0] == ran[0]);
        for (std::size_t i = 1; i < drawn.size(); ++i) CHECK(drawn[i] == ran[ran.size() - 4 + i]);
    }
}

TEST_CASE("A screenshot draws capsules, hulls, cylinders and compounds where their bodies are", "[viewer][xvfb]") {
    // No gravity: each body stays where the scene puts it. A pixel at each body's projected centre
    // of mass must show that body's own colour (the floor and sky are grey), so each new shape
    // is drawn, and drawn where the physics has it (a hull's and a compound's position is its
    // centre of mass, which lies inside these convex shapes).
    if (const std::string why = screenshotsUnavailable(); !why.empty()) STEPWISE_SKIP(why);
    const int width = 320, height = 240;
    const TempFile png("shapes.png"), scenePath("shapes.scene");
    std::ofstream(scenePath.path) << "World, Gravity=(0, 0, 0)\n"
                                     "CollisionPlane, Name=floor\n"
                                     "DynamicObject, Name=pill, Shape=Capsule, Radius=0.3, Height=1, Position=(-1.5, 1, 0), "
                                     "Rotation=(0, 0, 90), Color=(0.9, 0.1, 0.1)\n"
                                     "DynamicObject, Name=gem, Shape=Hull, Vertices=(0, -0.5, 0), (0, 0.5, 0), (0.5, 0, 0), "
                                     "(-0.5, 0, 0), (0, 0, 0.5), (0, 0, -0.5), Position=(0, 1, 0), Color=(0.1, 0.9, 0.1)\n"
                                     "DynamicObject, Name=can, Shape=Cylinder, Radius=0.4, Height=0.8, Position=(1.5, 1, 0), "
                                     "Color=(0.1, 0.1, 0.9)\n"
                                     "DynamicObject, Name=pair, Shape=Compound, Position=(0, 2.5, 0), Color=(0.9, 0.1, 0.1)\n"
                                     "Part, Body=pair, Shape=Box, Scale=(0.8, 0.8, 0.8), Position=(-0.3, 0, 0)\n"
                                     "Part, Body=pair, Shape=Sphere, Radius=0.45, Position=(0.3, 0, 0)\n";
    const Result shot = viewUnderXvfb(scenePath.quoted() + " --screenshot " + png.quoted() + " --at 0.1 --size 320x240 --keys O");
    INFO(shot.output);
    REQUIRE(shot.exitCode == 0);
    const Image image = decodePng(readBytes(png.path));
    const World world(loadSceneFile(scenePath.path.string()));
    const OrbitCamera camera = cameraForScene(world);
    auto colourAt = [&](const Vec3& p) {
        const Vec3 pixel = camera.project(p, width, height);
        REQUIRE(pixel.x >= 0);
        REQUIRE(pixel.x < width);
        REQUIRE(pixel.y >= 0);
        REQUIRE(pixel.y < height);
        return dominant(image.at(static_cast<int>(pixel.x), static_cast<int>(pixel.y)));
    };
    CHECK(colourAt(world.findDynamic("pill")->position) == 'r');
    CHECK(colourAt(world.findDynamic("gem")->position) == 'g');
    CHECK(colourAt(world.findDynamic("can")->position) == 'b');
    CHECK(colourAt(world.findDynamic("pair")->position) == 'r');
    CHECK(colourAt(Vec3(0, 1.8, 0)) == '-');  // between the gem and the pair: nothing drawn
}

TEST_CASE("A screenshot with the overlays shows the heads-up display's text", "[viewer][xvfb]") {
    if (const std::string why = screenshotsUnavailable(); !why.empty()) STEPWISE_SKIP(why);
    const TempFile png("viewer-hud.png");
    const Result shot =
        viewUnderXvfb("'" + kScene + "' --screenshot " + png.quoted() + " --at 1 --size 640x400 --keys HCVBSS");
    INFO(shot.output);
    REQUIRE(shot.exitCode == 0);
    const Image image = decodePng(readBytes(png.path));
    // The text is near-white (0.95); nothing in the lit scene is that bright.
    int white = 0;
    for (int y = 0; y < 100; ++y) {
        for (int x = 0; x < 320; ++x) {
            const std::uint8_t* p = image.at(x, y);
            if (p[0] > 225 && p[1] > 225 && p[2] > 225) ++white;
        }
    }
    CHECK(white > 200);
}

TEST_CASE("The option --stage K draws the bodies where the K-th stage run of the step left them", "[viewer][xvfb]") {
    // Lesson 3's ball in step 28: after integrate (stage run 2) its centre is
    // 68 mm below its radius, the ball half in the floor; after
    // correct-positions (run 7: continuous runs, move-kinematics is skipped) it rests on the floor, centre at y = r. A
    // point r/2 above the resting centre is inside the resting ball but above
    // the sunken one: red only in the second picture.
    if (const std::string why = screenshotsUnavailable(); !why.empty()) STEPWISE_SKIP(why);
    const int width = 640, height = 480;
    World world(loadSceneFile(kBounceScene));
    while (world.stepCount() < 27) world.step();
    const OrbitCamera camera = cameraForScene(world);  // F frames the World as it is at t = 0.45 s
    const Real r = world.dynamics()[0].radius;
    const Vec3 probe = camera.project(Vec3(0, r + r / 2, 0), width, height);
    auto shoot = [&](int stage) {
        const TempFile png("stage-" + std::to_string(stage) + ".png");
        const Result shot = viewUnderXvfb("'" + kBounceScene + "' --screenshot " + png.quoted() +
                                          " --at 0.45 --size 640x480 --keys OF --stage " + std::to_string(stage));
        INFO(shot.output);
        REQUIRE(shot.exitCode == 0);
        CHECK_THAT(shot.output, Contains("(step 28)"));
        const Image image = decodePng(readBytes(png.path));
        return dominant(image.at(static_cast<int>(probe.x), static_cast<int>(probe.y)));
    };
    CHECK(shoot(2) != 'r');
    CHECK(shoot(7) == 'r');
    const TempFile unused("stage-8.png");
    const Result tooFar = viewUnderXvfb("'" + kBounceScene + "' --screenshot " + unused.quoted() + " --at 0.45 --stage 8");
    CHECK(tooFar.exitCode == 2);
    CHECK_THAT(tooFar.output, Contains("7 stage runs"));
}

TEST_CASE("In the window, the mouse picks, highlights, pushes and pulls the body under the cursor",
          "[viewer][xvfb][xdotool]") {
    // The real window under Xvfb, driven by xdotool (Debian package xdotool,
    // installed by scripts/setup.sh): point at the ball right of its centre,
    // take a picture (P) with and without the pointer on it, hold the left
    // button for exactly three steps (paused, N steps once), then the right
    // button for two. The viewer's --log-events file says what it picked and
    // pushed; every number is checked against the camera and the physics.
    if (const std::string why = screenshotsUnavailable(); !why.empty()) STEPWISE_SKIP(why);
    if (std::system("command -v xdotool >/dev/null 2>&1") != 0) {
        FAIL("xdotool is not installed (Debian package xdotool; scripts/setup.sh installs it)");
    }
    const std::string scene = kSourceDir + "/config/viewer_pick.scene";
    const int width = 320, height = 240;
    const TempDir dir("viewer-pick");

    // The ball (R = 1 m, 2 kg, at the origin, no gravity) and the camera the viewer starts with.
    const World world(loadSceneFile(scene));
    REQUIRE(world.dynamics().size() == 1);
    const DynamicObject& ball = world.dynamics()[0];
    const Real radius = ball.radius, mass = ball.mass, h = world.settings().timeStep;
    REQUIRE(glm::length(world.settings().gravity) == 0);
    const OrbitCamera camera = cameraForScene(world);
    const Mat4 view = camera.viewMatrix();
    const Vec3 cameraRight(view[0][0], view[1][0], view[2][0]);
    const Vec3 cameraUp(view[0][1], view[1][1], view[2][1]);
    const Vec3 aim = camera.project(ball.position + Real(0.5) * radius * cameraRight, width, height);
    const int px = static_cast<int>(aim.x), py = static_cast<int>(aim.y);

    const std::string script =
        "cd " + dir.quoted() + " || exit 3\n" + cli() + " view '" + scene + "' --size " + std::to_string(width) +
        "x" + std::to_string(height) + " --log-events events.log &\n" +
        "viewer=$!\n"
        "window=$(timeout 60 xdotool search --sync --onlyvisible --name 'stepwise view' | head -n 1)\n"
        "if [ -z \"$window\" ]; then echo 'test: no viewer window'; kill $viewer; exit 3; fi\n"
        // O hides the text, Space pauses, P takes a picture with the pointer off the ball.
        "xdotool mousemove --window $window 2 2 key o space p\n"
        "xdotool mousemove --window $window " + std::to_string(px) + " " + std::to_string(py) + " key p\n" +
        "xdotool mousedown 1 key n key n key n mouseup 1\n"
        "xdotool mousedown 3 key n key n mouseup 3\n"
        "xdotool key Escape\n"
        "wait $viewer\n";
    {
        std::ofstream out(dir.path / "drive.sh");
        out << script;
    }
    const Result run = underXvfb("timeout 180 bash '" + (dir.path / "drive.sh").string() + "'");
    INFO(run.output);
    REQUIRE(run.exitCode == 0);

    // The log, line by line.
    std::vector<std::vector<std::string>> events;
    for (const std::string& line : lines(dir.path / "events.log")) {
        std::istringstream words(line);
        events.emplace_back(std::istream_iterator<std::string>(words), std::istream_iterator<std::string>());
    }
    auto all = [&](const std::string& kind) {
        std::vector<std::vector<std::string>> found;
        for (const auto& e : events) {
            if (!e.empty() && e[0] == kind) found.push_back(e);
        }
        return found;
    };
    auto vecAt = [](const std::vector<std::string>& e, std::size_t i) {
        REQUIRE(e.size() >= i + 3);
        return Vec3(std::stod(e[i]), std::stod(e[i + 1]), std::stod(e[i + 2]));
    };
    const auto picks = all("pick"), pushes = all("push"), pulls = all("pull"), releases = all("release"),
               pictures = all("picture"), highlights = all("highlight");
    REQUIRE(picks.size() == 2);
    REQUIRE(releases.size() == 2);
    REQUIRE(pictures.size() == 2);
    CHECK(pushes.size() == 3);  // one per N while the left button was down
    CHECK(pulls.size() == 2);
    REQUIRE_FALSE(highlights.empty());
    CHECK(highlights[0][1] == "ball");

    // The ray through the pixel's centre, and where it meets the ball: the
    // nearer root of |o + s d - c|^2 = R^2, solved here on its own.
    const Ray ray = camera.rayThroughPixel(Real(px) + Real(0.5), Real(py) + Real(0.5), width, height);
    auto entry = [&](const Vec3& centre) {
        const Vec3 m = ray.origin - centre;
        const Real b = glm::dot(m, ray.direction), c = glm::dot(m, m) - radius * radius;
        REQUIRE(b * b - c > 0);
        return ray.origin + (-b - std::sqrt(b * b - c)) * ray.direction;
    };
    const Real a = 20;  // m/s^2, the grab's acceleration without gravity
    const Vec3 force = mass * a * ray.direction;

    // Left button: the ball at rest at the origin, hit right of its centre.
    for (const auto& pick : picks) {
        REQUIRE(pick.size() == 10);  // pick NAME pixel PX PY hit X Y Z KIND
        CHECK(pick[1] == "ball");
        CHECK(pick[3] == std::to_string(px));
        CHECK(pick[4] == std::to_string(py));
        CHECK(pick[9] == "dynamic");
    }
    const Vec3 hit = vecAt(picks[0], 6);
    CHECK(glm::length(hit - entry(ball.position)) < 1e-6);
    Vec3 centre = ball.position, velocity(0);
    for (const auto& push : pushes) {
        REQUIRE(push.size() == 12);  // push NAME step N at X Y Z force FX FY FZ
        // The force is F = m a along the ray, at a point on the ball's surface
        // (the held point turns with the ball, so it stays there).
        CHECK(glm::length(vecAt(push, 9) - force) < 1e-6 * glm::length(force));
        CHECK(glm::length(vecAt(push, 5) - centre) == Approx(radius).epsilon(1e-6));
        velocity += force * h / mass;  // symplectic Euler, no other force: v += (F/m) h, then x += v h
        centre += velocity * h;
    }
    CHECK(glm::length(vecAt(pushes[0], 5) - hit) < 1e-6);
    const Vec3 v1 = vecAt(releases[0], 3), w1 = vecAt(releases[0], 7);  // release NAME v VX VY VZ w WX WY WZ
    CHECK(glm::length(v1 - Real(3) * a * h * ray.direction) < 1e-6);  // 3 steps of a h = 1/3 m/s
    // It turns about r x F: for a ball the axis stays put while r turns
    // towards F, so only the size drifts (a few per cent over three steps).
    const Vec3 torqueAxis = glm::normalize(glm::cross(hit - ball.position, force));
    CHECK(glm::dot(glm::normalize(w1), torqueAxis) > 0.9999);
    const Real inertia = Real(0.4) * mass * radius * radius;
    CHECK(glm::length(w1) == Approx(3 * h * glm::length(glm::cross(hit - ball.position, force)) / inertia)
                                 .epsilon(0.05));
    CHECK(glm::dot(w1, cameraUp) > 0);  // right of the centre, pushed away: its right side goes away

    // Right button at the same pixel: the ball has moved on a little; the pull is against the ray.
    const Vec3 pullHit = vecAt(picks[1], 6);
    CHECK(glm::length(pullHit - entry(centre)) < 1e-6);
    for (const auto& pull : pulls) CHECK(glm::length(vecAt(pull, 9) + force) < 1e-6 * glm::length(force));
    CHECK(glm::length(vecAt(releases[1], 3) - a * h * ray.direction) < 1e-6);  // 3 - 2 steps' worth

    // The pictures: no yellow outline with the pointer off the ball, a clear one on it.
    auto yellowPixels = [&](const std::string& name) {
        const Image image = decodePng(readBytes(dir.path / name));
        REQUIRE(image.width == width);
        REQUIRE(image.height == height);
        int count = 0;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const std::uint8_t* p = image.at(x, y);
                if (p[0] > 200 && p[1] > 200 && p[2] < 100) ++count;
            }
        }
        return count;
    };
    const int offBall = yellowPixels(pictures[0][1]);
    const int onBall = yellowPixels(pictures[1][1]);
    INFO("yellow pixels: " << offBall << " with the pointer off the ball, " << onBall << " on it");
    CHECK(offBall < 10);
    CHECK(onBall > 300);
}

TEST_CASE("I shows sleeping bodies in the sleeping colour instead of their own", "[viewer][xvfb][sleep]") {
    // The 100:1 stack with Sleep=true settles and then sleeps, once it has been at rest and
    // in equilibrium for TimeToSleep (islands.hpp); half a second after that the heavy box,
    // red in the scene, must be drawn in kSleepingColor (blue above red) with I, and in its red without.
    if (const std::string why = screenshotsUnavailable(); !why.empty()) STEPWISE_SKIP(why);
    const TempFile scene("sleeping.scene");
    {
        std::ifstream in(kSourceDir + "/config/lesson08_heavy_on_light.scene");
        std::ostringstream text;
        text << in.rdbuf();
        std::string contents = text.str();
        const std::string off = "Sleep=false";
        contents.replace(contents.find(off), off.size(), "Sleep=true");
        std::ofstream(scene.path) << contents;
    }
    // When the heavy box falls asleep (within 20 s), and half a second later, in whole steps.
    const Real at = [&] {
        World w(loadSceneFile(scene.path.string()));
        while (!w.findDynamic("heavy")->asleep && w.time() < 20) w.step();
        return std::ceil((w.time() + Real(0.5)) * 10) / 10;
    }();
    const World world = [&] {
        World w(loadSceneFile(scene.path.string()));
        while (w.time() < at - 1e-9) w.step();
        return w;
    }();
    const DynamicObject& heavy = *world.findDynamic("heavy");
    REQUIRE(heavy.asleep);
    const OrbitCamera camera = cameraForScene(World(loadSceneFile(scene.path.string())));
    const Vec3 pixel = camera.project(heavy.position, 320, 240);
    auto shoot = [&](const std::string& keys) {
        const TempFile png("sleep-" + keys + ".png");
        const Result shot = viewUnderXvfb(scene.quoted() + " --screenshot " + png.quoted() +
                                          " --at " + std::to_string(at) + " --size 320x240 --keys " + keys);
        INFO(shot.output);
        REQUIRE(shot.exitCode == 0);
        const Image image = decodePng(readBytes(png.path));
        const std::uint8_t* p = image.at(static_cast<int>(pixel.x), static_cast<int>(pixel.y));
        return std::array<int, 3>{p[0], p[1], p[2]};
    };
    const auto own = shoot("O");
    const auto sleeping = shoot("OI");
    CHECK(own[0] > own[2]);            // red: the scene's colour (0.8, 0.3, 0.2)
    CHECK(sleeping[2] > sleeping[0]);  // kSleepingColor (0.55, 0.6, 0.7)
}

// ---- Spaces: side by side or overlaid, paused one by one -------------------------------------

namespace {

const std::string kSpacesScenes[] = {kSourceDir + "/config/spaces_integrators.scene",
                                     kSourceDir + "/config/spaces_timesteps.scene",
                                     kSourceDir + "/config/spaces_solvers.scene"};

/// The x range that space @p k's bodies cover now, as drawn (moved by the layout's offset),
/// computed from the bodies' own boxes, not from the layout's swept boxes.
std::pair<Real, Real> drawnExtent(const Simulation& sim, std::size_t k) {
    Real low = std::numeric_limits<Real>::infinity();
    Real high = -low;
    const World& world = sim.worldAt(k);
    for (const DynamicObject& b : world.dynamics()) {
        const Aabb box = shapeAabb(b);
        low = std::min(low, box.min.x);
        high = std::max(high, box.max.x);
    }
    for (const KinematicsObject& b : world.kinematics()) {
        const Aabb box = shapeAabb(b);
        low = std::min(low, box.min.x);
        high = std::max(high, box.max.x);
    }
    const Real offset = sim.layout().offset(k).x;
    return {low + offset, high + offset};
}

}  // namespace

TEST_CASE("Side by side, the spaces of each shipped scene never overlap, and the layout stays put for the run",
          "[viewer][spaces]") {
    for (const std::string& path : kSpacesScenes) {
        INFO(path);
        Simulation sim(path);
        REQUIRE(sim.hasSpaces());
        REQUIRE(sim.worldCount() >= 2);
        REQUIRE(sim.layout().arrangement() == SpaceArrangement::SideBySide);
        std::vector<Real> offsetsAtStart;
        for (std::size_t k = 0; k < sim.worldCount(); ++k) offsetsAtStart.push_back(sim.layout().offset(k).x);
        const double duration = double(sim.world().settings().duration);
        auto disjoint = [&](double t) {
            INFO("t = " << t << " s");
            for (std::size_t i = 0; i < sim.worldCount(); ++i) {
                const auto a = drawnExtent(sim, i);
                for (std::size_t j = i + 1; j < sim.worldCount(); ++j) {
                    const auto b = drawnExtent(sim, j);
                    INFO("spaces " << i << " [" << a.first << ", " << a.second << "] and " << j << " [" << b.first
                                   << ", " << b.second << "]");
                    // Left to right in file order, with room between.
                    CHECK(a.second < b.first);
                }
            }
        };
        disjoint(0);
        for (int tenth = 1; tenth <= static_cast<int>(std::lround(duration * 10)); ++tenth) {
            sim.stepTo(tenth / 10.0);
            disjoint(tenth / 10.0);
        }
        // The copy run ahead at load swept every box of the run: no space had to move since.
        for (std::size_t k = 0; k < sim.worldCount(); ++k) CHECK(sim.layout().offset(k).x == offsetsAtStart[k]);

        sim.layout().arrange(SpaceArrangement::Overlaid);  // L: every space at its own coordinates
        for (std::size_t k = 0; k < sim.worldCount(); ++k) CHECK(sim.layout().offset(k) == Vec3(0));
    }
}

TEST_CASE("Keys 1-9 pause one space while the others step on the shared clock", "[viewer][spaces]") {
    CHECK(spaceForKey('1') == std::optional<std::size_t>(0));
    CHECK(spaceForKey('9') == std::optional<std::size_t>(8));
    CHECK_FALSE(spaceForKey('0'));
    CHECK_FALSE(spaceForKey('a'));
    CHECK_FALSE(spaceForKey(' '));

    // Space 1 steps at h = 1/30 s, space 2 at 1/240 s; the clock ticks every 1/240 s.
    Simulation sim(kSourceDir + "/config/spaces_timesteps.scene");
    REQUIRE(sim.worldCount() == 2);
    const World& coarse = sim.worldAt(0);
    const World& fine = sim.worldAt(1);
    CHECK(sim.clock().timeStep() == Approx(1.0 / 240).epsilon(1e-12));
    CHECK_FALSE(sim.toggleSpacePause(2));  // key 3: no such space
    REQUIRE(sim.toggleSpacePause(0));      // key 1
    const Vec3 held = coarse.dynamics()[0].position;
    for (int frame = 0; frame < 4; ++frame) sim.advanceFrame(0.25);  // 1 s of the clock
    CHECK(coarse.stepCount() == 0);
    CHECK(coarse.dynamics()[0].position == held);
    CHECK(fine.stepCount() == 240);  // 1 s / (1/240 s)
    REQUIRE(sim.toggleSpacePause(0));  // resumed: it goes on from where it stopped
    for (int frame = 0; frame < 4; ++frame) sim.advanceFrame(0.25);
    CHECK(coarse.stepCount() == 30);  // 1 s of running / (1/30 s)
    CHECK(fine.stepCount() == 480);

    // N: ticks until a running space steps; with every space paused nothing can, and it says so.
    CHECK(sim.stepOnce());
    CHECK(fine.stepCount() == 481);
    REQUIRE(sim.toggleSpacePause(0));
    REQUIRE(sim.toggleSpacePause(1));
    CHECK_FALSE(sim.stepOnce());
    CHECK(fine.stepCount() == 481);

    // The walk-through follows one World: with spaces it runs nothing.
    sim.stepStage();
    CHECK_FALSE(sim.shownStage());
    CHECK_FALSE(sim.showStageRun(0));
}

TEST_CASE("With spaces, picking finds the body or floor of the space drawn under the cursor, and pushes it there",
          "[viewer][spaces]") {
    SECTION("three balls thrown from one point, drawn side by side") {
        Simulation sim(kSourceDir + "/config/spaces_integrators.scene");
        for (std::size_t k = 0; k < sim.worldCount(); ++k) {
            const DynamicObject& ball = sim.worldAt(k).dynamics()[0];
            const Vec3 drawn = ball.position + sim.layout().offset(k);
            const std::optional<SpaceHit> hit = pickInSimulation(sim, Ray{drawn + Vec3(0, 5, 0), Vec3(0, -1, 0)});
            REQUIRE(hit);
            CHECK(hit->space == k);
            CHECK(hit->hit.body.kind == BodyKind::Dynamic);
            CHECK(hit->hit.point.y == Approx(double(ball.position.y + ball.radius)).margin(1e-9));  // own coordinates
        }
    }
    SECTION("two floors at the same place: the one of the band under the cursor") {
        Simulation sim(kSourceDir + "/config/spaces_timesteps.scene");
        for (std::size_t k = 0; k < sim.worldCount(); ++k) {
            const auto [low, high] = sim.layout().band(k);
            const Vec3 above((low + high) / 2 + sim.layout().offset(k).x, 5, 3);  // z = 3 m: beside the ball
            const std::optional<SpaceHit> hit = pickInSimulation(sim, Ray{above, Vec3(0, -1, 0)});
            REQUIRE(hit);
            CHECK(hit->space == k);
            CHECK(hit->hit.body.kind == BodyKind::Plane);
        }
    }
    SECTION("a push acts on the held body's space only, one step's impulse F h before its step") {
        Simulation sim(kSourceDir + "/config/spaces_timesteps.scene");
        const DynamicObject& fineBall = sim.worldAt(1).dynamics()[0];
        const DynamicObject& coarseBall = sim.worldAt(0).dynamics()[0];
        sim.grab(0, fineBall.position, Vec3(1, 0, 0), false, 1);
        REQUIRE(sim.grabbedSpace() == 1);
        REQUIRE(sim.stepOnce());  // one tick: the fine space's first step, the coarse one waits
        CHECK(sim.worldAt(1).stepCount() == 1);
        CHECK(sim.worldAt(0).stepCount() == 0);
        // F = 2 m |g| along x, for h = 1/240 s: Δv = 2 |g| h.
        CHECK(double(fineBall.velocity.x) == Approx(2 * 9.81 / 240).epsilon(1e-12));
        CHECK(coarseBall.velocity.x == 0);
        sim.release();
    }
}

TEST_CASE("A screenshot of spaces shows them in separate bands side by side, and together overlaid",
          "[viewer][xvfb][spaces]") {
    // Three balls thrown from the origin under three integrators. Side by side, each space has a
    // band of x of its own: the columns of the picture that hold anything drawn form three groups
    // with background between, each ball in its own, left to right. Overlaid (L), the three balls
    // are at x = 10 m (every integrator moves x exactly at constant velocity): one group.
    if (const std::string why = screenshotsUnavailable(); !why.empty()) STEPWISE_SKIP(why);
    const std::string scene = kSourceDir + "/config/spaces_integrators.scene";
    const int width = 640, height = 400;
    const double t = 2;  // the scene's Duration, when its Expect record is checked
    const TempFile side("spaces-side.png"), over("spaces-over.png"), state("spaces-state.csv"),
        csv("spaces-run.csv");

    // The groups of columns that hold a pixel other than the background, as [first, last] column.
    const auto groups = [&](const Image& image) {
        std::vector<std::pair<int, int>> found;
        for (int x = 0; x < image.width; ++x) {
            bool drawn = false;
            for (int y = 0; y < image.height && !drawn; ++y) {
                const std::uint8_t* p = image.at(x, y);
                for (int c = 0; c < 3; ++c) {
                    if (std::abs(int(p[c]) - int(std::lround(255 * kBackground[c]))) > 12) drawn = true;
                }
            }
            if (!drawn) continue;
            if (!found.empty() && x - found.back().second <= 3) found.back().second = x;  // a gap of a pixel or two: one group
            else found.emplace_back(x, x);
        }
        return found;
    };

    {  // Side by side, with O: no text, only the balls.
        const Result shot = viewUnderXvfb("'" + scene + "' --screenshot " + side.quoted() + " --at 2 --size 640x400" +
                                          " --keys O --dump-state " + state.quoted());
        INFO(shot.output);
        REQUIRE(shot.exitCode == 0);
        CHECK_THAT(shot.output, Contains("t = 2 s on the spaces' clock (3 spaces)"));
        const Image image = decodePng(readBytes(side.path));
        REQUIRE(image.width == width);
        const std::vector<std::pair<int, int>> bands = groups(image);
        INFO(bands.size() << " groups of drawn columns");
        REQUIRE(bands.size() == 3);
        // Where each ball must be drawn: the viewer frames the layout as loaded, then steps to t.
        const OrbitCamera camera = cameraForSpaces(Simulation(scene).layout(), Real(width) / Real(height));
        Simulation sim(scene);
        sim.stepTo(t);
        for (std::size_t k = 0; k < 3; ++k) {
            const Vec3 pixel = camera.project(sim.worldAt(k).dynamics()[0].position + sim.layout().offset(k), width, height);
            INFO("space " << k << " ball drawn at (" << pixel.x << ", " << pixel.y << ")");
            CHECK(pixel.x >= bands[k].first - 2);
            CHECK(pixel.x <= bands[k].second + 3);
        }
    }
    {  // The state drawn is what `stepwise run` reaches on the same clock, every space's row.
        const Result run = shell(cli() + " run '" + scene + "' --duration 2 --csv " + csv.quoted());
        REQUIRE(run.exitCode == 0);
        const std::vector<std::string> drawn = lines(state.path);
        const std::vector<std::string> ran = lines(csv.path);
        REQUIRE(drawn.size() == 4);  // header and three balls, one per space
        REQUIRE(ran.size() > 4);
        CHECK(drawn[0] == ran[0]);
        for (std::size_t i = 1; i < drawn.size(); ++i) CHECK(drawn[i] == ran[ran.size() - 4 + i]);
    }
    {  // Overlaid: one group.
        const Result shot =
            viewUnderXvfb("'" + scene + "' --screenshot " + over.quoted() + " --at 2 --size 640x400 --keys OL");
        INFO(shot.output);
        REQUIRE(shot.exitCode == 0);
        CHECK(groups(decodePng(readBytes(over.path))).size() == 1);
    }
    {  // The walk-through follows one World: --stage is refused, saying why.
        const Result shot = viewUnderXvfb("'" + scene + "' --screenshot " + over.quoted() + " --stage 1");
        CHECK(shot.exitCode == 2);
        CHECK_THAT(shot.output, Contains("this scene has spaces"));
    }
}
