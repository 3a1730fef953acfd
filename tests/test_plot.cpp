// `stepwise plot`: the picture it draws and the numbers it drew, held to physics,
// and its refusals of bad command lines. Tag: [plot].
//
// The numbers are read back from --data, the same table the picture is drawn
// from (src/io/quantity_table.hpp), and compared with closed-form motion: a
// throw's parabola and explicit Euler's lag, a spring's energy growth, a
// collision's momentum. The picture is checked for what a plot can be checked
// for without looking at it: a PNG of the size asked for.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "command_runner.hpp"
#include "config/scene_loader.hpp"
#include "io/quantity_table.hpp"
#include "world/measurements.hpp"
#include "world/world.hpp"

using Catch::Matchers::Contains;
using namespace stepwise;

namespace {

using Result = stepwise::test::CommandResult;

const std::string kSourceDir = STEPWISE_SOURCE_DIR;

/// Runs `stepwise ARGS` and captures what it prints.
Result runStepwise(const std::string& args) {
    return stepwise::test::shell(std::string("'") + STEPWISE_CLI_PATH + "' " + args);
}

/// A scratch file in the system's temporary folder, removed at scope exit.
struct TempFile {
    std::filesystem::path path;
    explicit TempFile(const std::string& name, const std::string& contents = "")
        : path(std::filesystem::temp_directory_path() / ("stepwise-plot-test-" + name)) {
        std::filesystem::remove(path);
        if (!contents.empty()) std::ofstream(path) << contents;
    }
    ~TempFile() { std::filesystem::remove(path); }
    std::string quoted() const { return "'" + path.string() + "'"; }
};

std::string scene(const std::string& name) { return "'" + kSourceDir + "/config/" + name + "'"; }

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// A --data file: its header's column names and its rows of numbers.
struct DataTable {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;
    /// The index of column @p name; fails the test when there is none.
    std::size_t column(const std::string& name) const {
        for (std::size_t i = 0; i < columns.size(); ++i)
            if (columns[i] == name) return i;
        FAIL("no column " << name);
        return 0;
    }
};

DataTable readData(const std::filesystem::path& path) {
    DataTable table;
    std::ifstream in(path);
    std::string line;
    if (!std::getline(in, line)) return table;
    std::istringstream header(line);
    for (std::string cell; std::getline(header, cell, ',');) table.columns.push_back(cell);
    while (std::getline(in, line)) {
        std::istringstream row(line);
        std::vector<double> values;
        for (std::string cell; std::getline(row, cell, ',');) values.push_back(std::stod(cell));
        table.rows.push_back(values);
    }
    return table;
}

/// Width and height of a PNG file, from its IHDR chunk; {0, 0} when the file is not a PNG.
std::pair<std::uint32_t, std::uint32_t> pngSize(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char head[24] = {};
    in.read(reinterpret_cast<char*>(head), sizeof head);
    const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (in.gcount() != sizeof head || !std::equal(signature, signature + 8, head) ||
        std::string(reinterpret_cast<char*>(head + 12), 4) != "IHDR") {
        return {0, 0};
    }
    const auto bigEndian = [&](int at) {
        return (std::uint32_t(head[at]) << 24) | (std::uint32_t(head[at + 1]) << 16) | (std::uint32_t(head[at + 2]) << 8) |
               std::uint32_t(head[at + 3]);
    };
    return {bigEndian(16), bigEndian(20)};
}

constexpr double kG = 9.81;

}  // namespace

TEST_CASE("plot draws a throw's height, and the numbers it drew are the parabola less explicit Euler's lag", "[plot]") {
    // config/lesson01_explicit_euler.scene: thrown from y0 = 10 m at v0y = 4 m/s, h = 1/60 s, explicit
    // Euler. Lecture 1: y_n = y0 + v0y t - g t^2/2 + g h t/2 exactly, so the error never exceeds g h t / 2.
    TempFile png("throw.png");
    TempFile csv("throw.csv");
    const Result r = runStepwise("plot " + scene("lesson01_explicit_euler.scene") + " --quantity position --component y" +
                                 " --out " + png.quoted() + " --data " + csv.quoted() + " --size 640x400");
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    CHECK_THAT(r.output, Contains("Plot written to"));
    REQUIRE(std::filesystem::exists(png.path));
    CHECK(pngSize(png.path) == std::pair<std::uint32_t, std::uint32_t>(640, 400));

    const DataTable data = readData(csv.path);
    REQUIRE(data.columns == std::vector<std::string>{"time", "ball:y"});
    REQUIRE(data.rows.size() == 121);  // t = 0, then 120 steps of 1/60 s: the scene's 2 s
    const double h = 1.0 / 60;
    for (const std::vector<double>& row : data.rows) {
        const double t = row[0];
        const double exact = 10 + 4 * t - 0.5 * kG * t * t;
        INFO("t = " << t << " s: y = " << row[1] << " m, parabola " << exact << " m");
        CHECK(std::abs(row[1] - exact) <= 0.5 * kG * h * t + 1e-9);         // within the integrator's error
        CHECK(std::abs(row[1] - (exact + 0.5 * kG * h * t)) < 1e-9);         // and it is exactly that lag
    }
    CHECK(std::abs(data.rows.back()[0] - 2.0) < 1e-12);
}

TEST_CASE("plot --every K samples every K-th step, and --data alone draws nothing", "[plot]") {
    TempFile csv("every.csv");
    const Result r = runStepwise("plot " + scene("lesson02_verlet.scene") + " --quantity velocity --every 4 --data " +
                                 csv.quoted());
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    CHECK_THAT(r.output, !Contains("Plot written"));
    const DataTable data = readData(csv.path);
    REQUIRE(data.columns == std::vector<std::string>{"time", "ball:x", "ball:y", "ball:z"});
    REQUIRE(data.rows.size() == 31);  // steps 0, 4, …, 120
    // Velocity Verlet's velocity under constant g is exact: v = v0 + g t at every sample.
    for (const std::vector<double>& row : data.rows) {
        INFO("t = " << row[0]);
        CHECK(std::abs(row[0] - double(&row - &data.rows[0]) * 4 / 60) < 1e-12);
        CHECK(std::abs(row[1] - 3) < 1e-12);
        CHECK(std::abs(row[2] - (4 - kG * row[0])) < 1e-9);
        CHECK(row[3] == 0);
    }
}

TEST_CASE("plot --quantity energy: explicit Euler's spring gains the factor 1 + h^2 w^2 every step", "[plot]") {
    // config/reference_spring.scene: k = 100 N/m, m = 1 kg (w = 10 rad/s), stretched 0.1 m, at rest:
    // E0 = k 0.1^2 / 2 = 0.5 J. Lecture 1: one explicit Euler step multiplies the energy by
    // 1 + h^2 w^2, whatever the state. Symplectic Euler keeps v^2 + w^2 x^2 + h w^2 x v constant, so
    // its E/E0 stays between 1/(1 + hw/2) and 1/(1 - hw/2): bounded, O(hw) (lecture 2).
    const std::string text = readText(kSourceDir + "/config/reference_spring.scene");
    const std::string integrator = "Integrator=SymplecticEuler";
    REQUIRE(text.find(integrator) != std::string::npos);
    std::string euler = text;
    euler.replace(euler.find(integrator), integrator.size(), "Integrator=Euler");
    TempFile eulerScene("spring-euler.scene", euler);
    TempFile eulerCsv("spring-euler.csv");
    TempFile symplecticCsv("spring-symplectic.csv");
    TempFile png("spring-energy.png");

    const Result r = runStepwise("plot " + eulerScene.quoted() + " --quantity energy --duration 2 --data " +
                                 eulerCsv.quoted() + " --out " + png.quoted());
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    CHECK(pngSize(png.path) == std::pair<std::uint32_t, std::uint32_t>(800, 600));  // the default --size
    const DataTable data = readData(eulerCsv.path);
    REQUIRE(data.columns == std::vector<std::string>{"time", "mass:kinetic", "mass:potential", "mass:total"});
    const double h = 1.0 / 60, w = 10, e0 = 0.5;
    REQUIRE(data.rows.size() == 121);
    for (std::size_t n = 0; n < data.rows.size(); ++n) {
        const double expected = e0 * std::pow(1 + h * h * w * w, double(n));
        INFO("step " << n << ": E = " << data.rows[n][3] << " J, expected " << expected << " J");
        CHECK(std::abs(data.rows[n][3] - expected) < 1e-9 * expected);
        CHECK(std::abs(data.rows[n][1] + data.rows[n][2] - data.rows[n][3]) < 1e-12 * expected);
    }

    const Result s = runStepwise("plot " + scene("reference_spring.scene") + " --quantity energy --component total --data " +
                                 symplecticCsv.quoted());
    INFO(s.output);
    REQUIRE(s.exitCode == 0);
    const DataTable symplectic = readData(symplecticCsv.path);
    REQUIRE(symplectic.columns == std::vector<std::string>{"time", "mass:total"});
    double largest = 0;
    for (const std::vector<double>& row : symplectic.rows) largest = std::max(largest, std::abs(row[1] - e0));
    const double bound = e0 * (1 / (1 - 0.5 * h * w) - 1);
    CHECK(largest <= bound * (1 + 1e-9));  // bounded,
    CHECK(largest >= bound * 0.95);        // and the swing reaches the bound: it is not merely small
}

TEST_CASE("plot --quantity momentum draws each ball and the whole scene, which only the kinematic wall changes", "[plot]") {
    // config/lesson03_collisions.scene: the balls' momentum, 2.5 kg m/s along x, is conserved by
    // their collisions; the wall (moving at u = +1 m/s) turns ball's -2 m/s into 2u - v = +4 m/s
    // at t = 0.75 s, adding 6 kg m/s: 8.5 from then on.
    TempFile csv("momentum.csv");
    const Result r = runStepwise("plot " + scene("lesson03_collisions.scene") + " --quantity momentum --component x --data " +
                                 csv.quoted());
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    const DataTable data = readData(csv.path);
    REQUIRE(data.columns ==
            std::vector<std::string>{"time", "left:x", "right:x", "small:x", "big:x", "ball:x", "(all):x"});
    const std::size_t all = data.column("(all):x");
    const std::size_t ball = data.column("ball:x");
    int before = 0, after = 0;
    for (const std::vector<double>& row : data.rows) {
        INFO("t = " << row[0]);
        if (row[0] < 0.74) {
            CHECK(std::abs(row[all] - 2.5) < 1e-9);
            ++before;
        } else if (row[0] > 0.76) {
            CHECK(std::abs(row[all] - 8.5) < 1e-9);
            CHECK(std::abs(row[ball] - 4) < 1e-9);
            ++after;
        }
    }
    CHECK(before > 80);
    CHECK(after > 200);
}

TEST_CASE("plot draws a run that blows up, up to its last whole step, and exits with code 1", "[plot]") {
    // config/stress_spring_past.scene: k = 16000 N/m, m = 1 kg, h = 1/60 s, so h w = 2.108, past
    // symplectic Euler's limit of 2 (lecture 9). Once the swing dwarfs the 1 m rest length the
    // step is linear again and multiplies it by lambda = -(c + sqrt(c^2 - 1)), c = (h w)^2/2 - 1,
    // every step, until the numbers overflow and the run stops.
    TempFile png("blow-up.png");
    TempFile csv("blow-up.csv");
    const Result r = runStepwise("plot " + scene("stress_spring_past.scene") + " --quantity position --component x" +
                                 " --duration 20 --out " + png.quoted() + " --data " + csv.quoted());
    INFO(r.output);
    CHECK(r.exitCode == 1);
    CHECK_THAT(r.output, Contains("simulation failed") && Contains("Plot written to"));
    CHECK(pngSize(png.path) == std::pair<std::uint32_t, std::uint32_t>(800, 600));
    const DataTable data = readData(csv.path);
    REQUIRE(data.rows.size() > 100);
    CHECK(data.rows.back()[0] < 20);  // it stopped early
    const double hw = std::sqrt(16000.0) / 60, c = hw * hw / 2 - 1;
    const double lambda = -(c + std::sqrt(c * c - 1));
    for (std::size_t n = data.rows.size() - 10; n < data.rows.size(); ++n) {
        INFO("step " << n << ": x = " << data.rows[n][1]);
        CHECK(std::isfinite(data.rows[n][1]));
        CHECK(std::abs(data.rows[n][1] / data.rows[n - 1][1] - lambda) < 1e-6 * std::abs(lambda));
    }
}

TEST_CASE("energyOfBody keeps a spring between two bodies out, energyOf(world) counts it", "[plot]") {
    // Two 1 kg balls at rest, no gravity, a spring of k = 100 N/m stretched 0.1 m between them:
    // no body has energy of its own, the pair holds k 0.1^2 / 2 = 0.5 J. A spring fixed in the
    // world (stretched 0.2 m, k = 50) belongs to its one body: 50 * 0.2^2 / 2 = 1 J.
    const Scene scene = parseScene("World, Gravity=(0, 0, 0), Solver=Impulse\n"
                                   "DynamicObject, Name=a, Position=(0, 0, 0), Radius=0.1, Mass=1\n"
                                   "DynamicObject, Name=b, Position=(1.1, 0, 0), Radius=0.1, Mass=1\n"
                                   "Spring, BodyA=a, BodyB=b, Stiffness=100, RestLength=1\n"
                                   "Spring, BodyA=b, AnchorB=(1.1, 1.2, 0), Stiffness=50, RestLength=1\n",
                                   "two-springs");
    const World world(scene);
    CHECK(std::abs(double(energyOfBody(world, 0).total())) < 1e-12);
    CHECK(std::abs(double(energyOfBody(world, 1).total()) - 1.0) < 1e-12);
    CHECK(std::abs(double(energyOf(world).total()) - 1.5) < 1e-12);
    const QuantityTable table(world, PlotQuantity::Energy, {}, {"potential"});
    CHECK(table.columnNames() == std::vector<std::string>{"a:potential", "b:potential", "(all):potential"});
}

TEST_CASE("plot refuses a bad command line with exit code 2 and names the cause", "[plot][cli]") {
    TempFile png("refused.png");
    const std::string out = " --out " + png.quoted();
    const std::string bounce = scene("lesson03_bounce.scene");
    const std::pair<std::string, std::string> cases[] = {
        {"plot " + bounce + out, "'plot' needs --quantity Q"},
        {"plot " + bounce + " --quantity speed" + out, "--quantity expects one of position, velocity"},
        {"plot " + bounce + " --quantity energy", "'plot' needs --out FILE.png"},
        {"plot " + bounce + " --quantity energy --out e.svg", "--out expects the name of a .png file"},
        {"plot " + bounce + " --quantity energy --quantity momentum" + out, "--quantity is given twice"},
        {"plot " + bounce + " --quantity position --object nobody" + out, "the scene has no body named 'nobody'"},
        {"plot " + bounce + " --quantity position --object floor" + out, "'floor' is a collision plane"},
        {"plot " + bounce + " --quantity position --object ball,ball" + out, "'ball' is named twice"},
        {"plot " + bounce + " --quantity position --object ball," + out, "--object expects a name"},
        {"plot " + scene("lesson03_collisions.scene") + " --quantity energy --object wall" + out,
         "'wall' is a kinematic body: it has no mass"},
        {"plot " + bounce + " --quantity energy --component y" + out, "energy has no component 'y'"},
        {"plot " + bounce + " --quantity velocity --component x,x" + out, "component 'x' is asked for twice"},
        {"plot " + scene("bench_sphere_rain_1k.scene") + " --quantity position" + out, "choose up to 8 with --object"},
        {"plot " + bounce + " --quantity position --size 5x5" + out, "--size expects WIDTHxHEIGHT"},
        {"plot " + bounce + " --quantity position --every 0" + out, "--every expects a whole number from 1 to"},
        {"plot " + bounce + " --quantity position --duration 1 --steps 3" + out, "give --duration or --steps"},
        {"plot " + bounce + " --quantity position --out a.png --data a.png", "name the same file"},
        {"plot " + bounce + " --quantity position --colour red" + out, "unknown option '--colour' for 'plot'"},
        {"plot " + bounce + " " + bounce + " --quantity position" + out, "'plot' takes one scene file"},
        {"plot /nonexistent/x.scene --quantity position" + out, "nothing was loaded"},
        {"plot " + bounce + " --quantity position --out /nonexistent/folder/x.png", "cannot write '/nonexistent/folder/x.png'"},
    };
    for (const auto& [command, message] : cases) {
        INFO("stepwise " << command);
        const Result r = runStepwise(command);
        INFO(r.output);
        CHECK(r.exitCode == 2);
        CHECK_THAT(r.output, Contains(message));
    }
}

TEST_CASE("plot without gnuplot says how to get it, with exit code 1", "[plot][cli]") {
    TempFile png("no-gnuplot.png");
    const std::string args = "plot " + scene("lesson03_bounce.scene") + " --quantity position --out " + png.quoted();
    const Result missing =
        stepwise::test::shell("STEPWISE_GNUPLOT=/nonexistent/gnuplot '" + std::string(STEPWISE_CLI_PATH) + "' " + args);
    INFO(missing.output);
    CHECK(missing.exitCode == 1);
    CHECK_THAT(missing.output, Contains("cannot run '/nonexistent/gnuplot'") && Contains("gnuplot-nox"));
    const Result failing = stepwise::test::shell("STEPWISE_GNUPLOT=false '" + std::string(STEPWISE_CLI_PATH) + "' " + args);
    INFO(failing.output);
    CHECK(failing.exitCode == 1);
    CHECK_THAT(failing.output, Contains("'false' failed (exit status 1"));
}
