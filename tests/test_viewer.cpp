// The viewer (src/viewer/, `stepwise view`): its camera and ray maths, its
// fixed-step clock, and real screenshots drawn under Xvfb, checked pixel by
// pixel against where the physics puts the bodies. Tag: [viewer].
//
// The screenshot tests need xvfb-run (Debian package xvfb, installed by
// scripts/setup.sh) and a program built with STEPWISE_VIEWER=ON; without
// either they pass with a WARN saying what was skipped.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "config/scene_loader.hpp"
#include "viewer/camera.hpp"
#include "viewer/fixed_step_clock.hpp"
#include "viewer/picking.hpp"

using Catch::Matchers::Contains;
using namespace stepwise;
using namespace stepwise::viewer;

namespace {

const std::string kSourceDir = STEPWISE_SOURCE_DIR;
const std::string kScene = kSourceDir + "/config/viewer_test.scene";

using Result = stepwise::test::CommandResult;
using stepwise::test::shell;

std::string cli() { return std::string("'") + STEPWISE_CLI_PATH + "'"; }

/// Runs `stepwise view ARGS` in a virtual X display. LeakSanitizer (in the
/// asan preset) is told to ignore leaks inside Mesa's driver, listed in
/// src/viewer/lsan_suppressions.txt; leaks in Stepwise's own code still fail.
///
/// `xvfb-run -a` picks the first free display number, but two started at
/// the same moment (CTest runs tests in parallel) can pick the same one, and
/// the loser's server fails to start. That is retried, a few times, after a
/// pause; any other failure is returned as it is.
Result viewUnderXvfb(const std::string& args) {
    Result result;
    for (int attempt = 0; attempt < 4; ++attempt) {
        if (attempt > 0) ::usleep(static_cast<useconds_t>(300000 + 400000 * attempt + (::getpid() % 7) * 50000));
        result = shell("LSAN_OPTIONS=print_suppressions=0:suppressions='" + kSourceDir +
                       "/src/viewer/lsan_suppressions.txt' xvfb-run -a " + cli() + " view " + args);
        const bool serverClash = result.exitCode != 0 &&
                                 (result.output.find("Xvfb failed to start") != std::string::npos ||
                                  result.output.find("already active") != std::string::npos ||
                                  result.output.find("cannot open the X display") != std::string::npos ||
                                  result.output.find("failed to open display") != std::string::npos);
        if (!serverClash) break;
    }
    return result;
}

/// True when the screenshot tests can run here; otherwise WARNs why not.
bool canTakeScreenshots() {
    const Result probe = shell("env -u DISPLAY " + cli() + " view '" + kScene + "'");
    if (probe.output.find("was not built") != std::string::npos) {
        WARN("skipped: this stepwise was built without the viewer (STEPWISE_VIEWER=OFF)");
        return false;
    }
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) {
        WARN("skipped: xvfb-run is not installed (Debian package xvfb; scripts/setup.sh installs it)");
        return false;
    }
    return true;
}

struct TempFile {
    std::filesystem::path path;
    explicit TempFile(const std::string& name)
        : path(std::filesystem::temp_directory_path() /
               ("stepwise-test-" + std::to_string(::getpid()) + "-" + name)) {}
    ~TempFile() { std::filesystem::remove(path); }
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

TEST_CASE("Ray casts hit spheres and turned boxes where the geometry says", "[viewer]") {
    const Ray down{Vec3(0, 10, 0), Vec3(0, -1, 0)};
    // A sphere of radius 1 at the origin is entered at y = 1: 9 m down the ray.
    REQUIRE(raySphere(down, Vec3(0), 1).has_value());
    CHECK(*raySphere(down, Vec3(0), 1) == Approx(9));
    CHECK_FALSE(raySphere(down, Vec3(3, 0, 0), 1).has_value());                     // beside the ray
    CHECK_FALSE(raySphere({Vec3(0, 10, 0), Vec3(0, 1, 0)}, Vec3(0), 1).has_value()); // behind it
    CHECK(*raySphere({Vec3(0.2, 0, 0), Vec3(1, 0, 0)}, Vec3(0), 1) == 0); // starting inside

    // A 2 m cube turned 45° about z has a corner on top at y = √2.
    const Quat turned = glm::angleAxis(kPi / 4, Vec3(0, 0, 1));
    REQUIRE(rayBox(down, Vec3(0), turned, Vec3(1)).has_value());
    CHECK(*rayBox(down, Vec3(0), turned, Vec3(1)) == Approx(10 - std::sqrt(2.0)));
    // Straight, its top face is at y = 1; 1.2 m to the side the ray misses it, turned or not.
    CHECK(*rayBox(down, Vec3(0), Quat(1, 0, 0, 0), Vec3(1)) == Approx(9));
    CHECK_FALSE(rayBox({Vec3(1.5, 10, 0), Vec3(0, -1, 0)}, Vec3(0), turned, Vec3(1)).has_value());
    CHECK_FALSE(rayBox({Vec3(0, 10, 1.2), Vec3(0, -1, 0)}, Vec3(0), turned, Vec3(1)).has_value());

    // pickBody returns the nearest body along the ray.
    Scene scene;
    DynamicObject low, high;
    low.name = "low";
    low.position = Vec3(0, 1, 0);
    high.name = "high";
    high.shape = Shape::Box;
    high.position = Vec3(0, 4, 0);
    scene.dynamics = {low, high};
    const World world(scene);
    const std::optional<PickHit> hit = pickBody(world, down);
    REQUIRE(hit.has_value());
    CHECK(hit->index == 1);
    CHECK(hit->point.y == Approx(4.5));
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
        WARN("skipped: this stepwise was built without the viewer");
        return;
    }
    CHECK(shell(cli() + " view --at 1").exitCode == 2);  // --at without --screenshot
    CHECK_THAT(shell(cli() + " view --screenshot x.png --size 10x10").output, Contains("--size expects"));
    CHECK(shell(cli() + " view --screenshot x.png --at -1").exitCode == 2);
    CHECK(shell(cli() + " view --zoom 3").exitCode == 2);
    CHECK(shell(cli() + " view /no/such.scene").exitCode == 2);
}

TEST_CASE("A screenshot shows the bodies where the physics puts them, and drawing changes nothing",
          "[viewer][xvfb]") {
    if (!canTakeScreenshots()) return;
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

TEST_CASE("A screenshot with the overlays shows the heads-up display's text", "[viewer][xvfb]") {
    if (!canTakeScreenshots()) return;
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
