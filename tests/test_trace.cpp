// `stepwise trace` and its TraceObserver: the numbers it prints are those of
// the World, checked against free fall and the impulse law; the output is the
// same bytes every run; the filters and the errors. Tag: [trace].
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "core/errors.hpp"
#include "test_support.hpp"
#include "trace_values.hpp"

using namespace stepwise;
using Catch::Matchers::Contains;

namespace {

constexpr Real kRadius = Real(0.1);     ///< Ball radius, m.
constexpr Real kMass = Real(2);         ///< Ball mass, kg.
constexpr Real kElasticity = Real(0.5); ///< Ball restitution; the floor's is 1, so e = 0.5.
constexpr Real kDropHeight = Real(1);   ///< Height of the ball's lowest point above the floor, m.

/// A frictionless ball whose lowest point is kDropHeight above the floor, at rest.
Scene droppedBall(SolverKind solver, IntegratorKind integrator = IntegratorKind::SymplecticEuler) {
    Scene scene = test::emptyScene(integrator);
    scene.settings.solver = solver;
    scene.dynamics.push_back(
        test::sphere("ball", Vec3(0, kDropHeight + kRadius, 0), Vec3(0), kRadius, kMass, kElasticity, 0));
    scene.planes.push_back(test::ground("floor"));
    return scene;
}

/// The number after "step" in a trace line.
std::uint64_t stepOf(const std::string& line) { return std::stoull(test::words(line).at(1)); }

/// Writes down the step number of every stage event, and stepCount() while the stage runs.
struct StepNumbers : StepObserver {
    std::uint64_t lastEventStep = 0;
    std::uint64_t countDuringStage = 0;
    void beforeStage(const StageEvent& event, const World& world) override {
        lastEventStep = event.step;
        countDuringStage = world.stepCount();
    }
};

/// Per stage of one step: the feature id of each contact index, as World::contacts() holds it.
struct ContactFeatures : StepObserver {
    std::vector<std::uint32_t> features;
    void afterStage(const StageEvent& event, const World& world) override {
        if (event.stage != Stage::Narrowphase) return;
        features.clear();
        for (const Contact& c : world.contacts()) features.push_back(c.featureId);
    }
};

/// Writes down what the broadphase and narrowphase produced.
struct PairCounter : StepObserver {
    std::size_t pairs = 0;
    std::size_t contacts = 0;
    Real depth = -1;
    void afterStage(const StageEvent& event, const World& world) override {
        if (event.stage == Stage::Broadphase) pairs = world.candidatePairs().size();
        if (event.stage == Stage::Narrowphase) {
            contacts = world.contacts().size();
            if (!world.contacts().empty()) depth = world.contacts()[0].depth;
        }
    }
};

}  // namespace

TEST_CASE("The integrate lines show free fall: v = -g*k*h after step k", "[trace]") {
    const Scene scene = droppedBall(SolverKind::Impulse);
    const Real h = scene.settings.timeStep;
    const std::string trace = test::traceOf(scene, {"--steps", "5", "--stage", "integrate", "--digits", "10"});
    for (int k = 1; k <= 5; ++k) {
        const std::string line = test::traceLine(trace, "step " + std::to_string(k) + " integrate ball");
        INFO(trace);
        REQUIRE(!line.empty());
        const std::vector<double> before = test::traceValue(line, "v");
        const std::vector<double> after = test::traceValue(line, "v->");
        REQUIRE(after.size() == 3);
        // Symplectic Euler from rest: v_k = -g*k*h, exact up to rounding (1e-9 m/s at 10 decimals).
        CHECK(before[1] == Approx(-kStandardGravity * h * (k - 1)).margin(1e-9));
        CHECK(after[1] == Approx(-kStandardGravity * h * k).margin(1e-9));
        CHECK(after[0] == 0);
    }
}

TEST_CASE("The first impact's line shows v_c = sqrt(2gH), m_eff = m and j = (1+e)*m*v", "[trace]") {
    const Scene scene = droppedBall(SolverKind::Impulse);
    const Real g = kStandardGravity;
    const Real h = scene.settings.timeStep;
    const std::string trace = test::traceOf(scene, {"--steps", "40", "--stage", "resolve-impulses", "--digits", "9"});
    const std::vector<std::string> impacts = test::linesWith(trace, "ball|floor");
    REQUIRE(!impacts.empty());
    const std::string& line = impacts.front();
    INFO(line);
    // Symplectic Euler from rest has fallen g*h^2*k(k+1)/2 after k steps (v_k = -g*k*h, x_k = x_{k-1} + h*v_k):
    // the first contact is found in the first step k where that reaches H (k = 27 at h = 1/60 s).
    std::uint64_t firstStep = 1;
    while (g * h * h * Real(firstStep * (firstStep + 1)) / 2 < kDropHeight) ++firstStep;
    CHECK(stepOf(line) == firstStep);
    // Impact speed sqrt(2gH) = 4.429 m/s; the reconstruction at touch is good to within one step's g*h.
    const Real impactSpeed = std::sqrt(2 * g * kDropHeight);
    const double vc = test::traceValue(line, "v_c").at(0);
    CHECK(std::abs(vc - impactSpeed) < g * h);
    // A sphere on an immovable plane: r x n = 0, so the effective mass is the mass.
    CHECK(test::traceValue(line, "m_eff").at(0) == Approx(kMass).epsilon(1e-9));
    CHECK(test::traceValue(line, "e").at(0) == Approx(kElasticity).epsilon(1e-9));
    // The impulse takes v_n from -v (sunk in by at most one step) to +e*v_c: j = m*(e*v_c + v),
    // (1+e)*m*sqrt(2gH) within the mass times (1+e) steps' g*h.
    const double vn = test::traceValue(line, "v_n").at(0);
    CHECK(vn < -vc + g * h);
    CHECK(test::traceValue(line, "v_n->").at(0) == Approx(kElasticity * vc).margin(1e-8));
    CHECK(std::abs(test::traceValue(line, "j").at(0) - (1 + kElasticity) * kMass * impactSpeed) <
          (2 + kElasticity) * kMass * g * h);
    CHECK_THAT(line, Contains("clamped no") && Contains("(impact)"));
}

TEST_CASE("A trace is the same bytes every run", "[trace]") {
    Scene scene = droppedBall(SolverKind::SequentialImpulse);
    scene.dynamics.push_back(test::sphere("other", Vec3(0.15, 2, 0.05), Vec3(0.3, 0, 0), 0.2, 1, 0.3, 0.4));
    const std::vector<std::string> args = {"--steps", "60", "--substeps", "all"};
    const std::string first = test::traceOf(scene, args);
    const std::string second = test::traceOf(scene, args);
    CHECK(first.size() > 1000);
    CHECK(first == second);
    // Every sequential-impulse stage reported something, substeps numbered from 1.
    for (const char* stage : {"apply-forces", "integrate", "broadphase", "narrowphase", "prepare-constraints",
                              "solve-constraints", "relax-constraints", "restitution", "sleep"}) {
        INFO(stage);
        CHECK(!test::linesWith(first, stage).empty());
    }
    const std::string last = std::to_string(scene.settings.substeps);
    CHECK_THAT(first, Contains("step 1 [" + last + "/" + last + "]  integrate  ball"));
}

TEST_CASE("Trace filters: --from and --steps, --stage, --object, --substeps", "[trace]") {
    Scene scene = droppedBall(SolverKind::SequentialImpulse);
    scene.dynamics.push_back(test::sphere("other", Vec3(3, 2, 0)));
    SECTION("--from 3 --steps 2 prints steps 3 and 4 only") {
        const std::string trace = test::traceOf(scene, {"--from", "3", "--steps", "2"});
        std::vector<std::uint64_t> steps;
        for (const std::string& line : test::textLines(trace)) steps.push_back(stepOf(line));
        REQUIRE(!steps.empty());
        CHECK(steps.front() == 3);
        CHECK(steps.back() == 4);
        for (std::uint64_t s : steps) CHECK((s == 3 || s == 4));
    }
    SECTION("--stage keeps that stage's lines (and each step's time line)") {
        const std::string trace = test::traceOf(scene, {"--steps", "3", "--stage", "integrate,sleep"});
        for (const std::string& line : test::textLines(trace)) {
            const std::vector<std::string> w = test::words(line);
            const bool wanted = w[2] == "t" || w[2] == "integrate" || w[3] == "integrate" || w[2] == "sleep";
            INFO(line);
            CHECK(wanted);
        }
        CHECK(test::linesWith(trace, "sleep").size() == 6);  // 2 bodies x 3 steps
    }
    SECTION("--object keeps the lines about that body") {
        const std::string trace = test::traceOf(scene, {"--steps", "2", "--object", "other"});
        CHECK(test::linesWith(trace, "ball").empty());
        CHECK(!test::linesWith(trace, "other").empty());
    }
    SECTION("Only the first substep unless --substeps all") {
        const int substeps = scene.settings.substeps;
        REQUIRE(substeps > 1);
        const std::vector<std::string> args = {"--stage", "integrate", "--object", "ball"};
        CHECK(test::linesWith(test::traceOf(scene, args), "integrate").size() == 1);
        std::vector<std::string> all = args;
        all.insert(all.end(), {"--substeps", "all"});
        CHECK(test::linesWith(test::traceOf(scene, all), "integrate").size() == std::size_t(substeps));
    }
}

TEST_CASE("A resting ball's sleep lines say when it falls asleep and why not before", "[trace]") {
    Scene scene = test::emptyScene();
    scene.settings.solver = SolverKind::SequentialImpulse;
    scene.dynamics.push_back(test::sphere("ball", Vec3(0, 0.5, 0)));  // touching the floor, at rest
    scene.planes.push_back(test::ground("floor"));
    const Real h = scene.settings.timeStep;
    const std::string trace = test::traceOf(scene, {"--steps", "120", "--stage", "sleep"});
    const std::vector<std::string> falls = test::linesWith(trace, "falls");
    REQUIRE(falls.size() == 1);
    // Still from the first step: asleep once it has been still for timeToSleep, not earlier.
    CHECK(Real(stepOf(falls[0])) * h >= scene.settings.timeToSleep - h / 2);
    CHECK(Real(stepOf(falls[0]) - 1) * h < scene.settings.timeToSleep + h);
    CHECK_THAT(test::traceLine(trace, "step 1 sleep ball"), Contains("awake") && Contains("still"));
}

TEST_CASE("The observer sees the broadphase's pairs and the narrowphase's depth", "[trace]") {
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60, Vec3(0));
    scene.settings.solver = SolverKind::Impulse;
    // Centres 0.8 m apart with radii 0.5 m: overlap 2r - d = 0.2 m. The third is 10 m away.
    scene.dynamics.push_back(test::sphere("a", Vec3(0, 0, 0)));
    scene.dynamics.push_back(test::sphere("b", Vec3(0.8, 0, 0)));
    scene.dynamics.push_back(test::sphere("c", Vec3(10, 0, 0)));
    World world(scene);
    PairCounter counter;
    world.setObserver(&counter);
    world.step();
    CHECK(counter.pairs == 1);
    CHECK(counter.contacts == 1);
    CHECK(counter.depth == Approx(0.2).margin(1e-12));
    // The trace prints the same counts.
    const std::string trace = test::traceOf(scene, {"--stage", "broadphase,narrowphase", "--digits", "6"});
    CHECK_THAT(trace, Contains("broadphase  all  pairs 1") && Contains("narrowphase  all  contacts 1"));
    CHECK(test::traceValue(test::traceLine(trace, "step 1 narrowphase a|b"), "depth").at(0) ==
          Approx(0.2).margin(1e-6));
}

TEST_CASE("Bad trace arguments say what is wrong", "[trace]") {
    const auto messageOf = [](const std::vector<std::string>& args) {
        std::vector<std::string> line{"scene.scene"};
        line.insert(line.end(), args.begin(), args.end());
        try {
            cli::parseTraceOptions(line);
        } catch (const cli::UsageError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    CHECK_THAT(messageOf({"--stage", "integrat"}),
               Contains("unknown stage 'integrat'") && Contains("integrate") && Contains("sleep"));
    CHECK_THAT(messageOf({"--steps", "0"}), Contains("--steps"));
    CHECK_THAT(messageOf({"--digits", "40"}), Contains("--digits"));
    CHECK_THAT(messageOf({"--substeps", "some"}), Contains("'all'"));
    CHECK_THAT(messageOf({"--fast"}), Contains("unknown option '--fast'"));
    const Scene scene = droppedBall(SolverKind::Impulse);
    TraceOptions options;
    options.objects = {"bal"};
    CHECK_THROWS_WITH(checkTraceObjects(options, scene), Contains("no object named 'bal'") && Contains("ball"));
}

TEST_CASE("stepwise trace on the command line", "[trace]") {
    const std::string cli = std::string("'") + STEPWISE_CLI_PATH + "' trace ";
    const std::string scene = std::string("'") + STEPWISE_SOURCE_DIR + "/config/lesson03_bounce.scene' ";
    const test::CommandResult ok = test::shell(cli + scene + "--from 28 --stage resolve-impulses");
    CHECK(ok.exitCode == 0);
    CHECK_THAT(ok.output, Contains("step 28  resolve-impulses  ball|floor  contact 0  feature 0  m_eff"));
    const test::CommandResult stage = test::shell(cli + scene + "--stage bounce");
    CHECK(stage.exitCode == 2);
    CHECK_THAT(stage.output, Contains("unknown stage 'bounce'") && Contains("resolve-impulses"));
    const test::CommandResult object = test::shell(cli + scene + "--object bal");
    CHECK(object.exitCode == 2);
    CHECK_THAT(object.output, Contains("no object named 'bal'"));
    CHECK(test::shell(cli).exitCode == 2);
    CHECK(test::shell(cli + scene + "--steps").exitCode == 2);
}

TEST_CASE("The trace, a SimulationError and stepCount() number the same step", "[trace]") {
    // One convention: step 1 is the first step, from t = 0 to h; step N runs from (N - 1)h to Nh,
    // and while it runs World::stepCount() (gdb's stepCount_) is N - 1, the steps completed.
    // A NaN planted just before step N is found in step N: the trace's "step N", the error's
    // "step N" and the observer's StageEvent::step must all say N.
    const Scene scene = droppedBall(SolverKind::Impulse);
    const Real h = scene.settings.timeStep;
    for (const std::uint64_t n : {std::uint64_t(1), std::uint64_t(5)}) {
        INFO("step " << n);
        const std::string trace = test::traceOf(scene, {"--from", std::to_string(n), "--stage", "integrate", "--digits", "12"});
        const std::vector<std::string> timeLine = test::words(test::textLines(trace).at(0));
        REQUIRE(timeLine.size() >= 4);
        CHECK(timeLine[0] == "step");
        CHECK(stepOf(test::textLines(trace).at(0)) == n);
        CHECK(std::stod(timeLine[3]) == Approx(double(n - 1) * double(h)).margin(1e-12));  // "step N  t T0 s -> ..."

        World world(scene);
        while (world.stepCount() < n - 1) world.step();
        StepNumbers seen;
        world.setObserver(&seen);
        world.dynamics()[0].velocity = Vec3(std::numeric_limits<Real>::quiet_NaN(), 0, 0);
        try {
            world.step();
            FAIL("no SimulationError");
        } catch (const SimulationError& error) {
            CHECK(error.step() == n);
            CHECK_THAT(error.what(), Contains("step " + std::to_string(n) + " (t = ") && Contains("'ball'"));
        }
        CHECK(seen.lastEventStep == n);
        CHECK(seen.countDuringStage == n - 1);
    }
}

TEST_CASE("Each contact line names its index in the step's contacts and its feature id", "[trace]") {
    // A 100 kg box on a 1 kg box on the ground: four corners of each face touch, so eight contacts,
    // four of them light|heavy. Without an index and a feature id their lines would look alike.
    Scene scene = test::emptyScene();
    scene.planes.push_back(test::ground());
    scene.dynamics.push_back(test::dynamicBox("light", Vec3(0, 0.5, 0), Vec3(1), 1, 0.6));
    scene.dynamics.push_back(test::dynamicBox("heavy", Vec3(0, 1.5, 0), Vec3(1), 100, 0.6));
    World world(scene);
    ContactFeatures features;
    world.setObserver(&features);
    world.step();
    REQUIRE(features.features.size() == 8);
    const std::string trace = test::traceOf(scene, {});
    for (const char* stage : {"narrowphase", "prepare-constraints", "solve-constraints", "relax-constraints",
                              "restitution"}) {
        INFO(stage);
        std::vector<std::string> rows;
        for (const std::string& line : test::linesWith(trace, stage)) {
            if (line.find("|") != std::string::npos) rows.push_back(line);
        }
        REQUIRE(rows.size() == features.features.size());
        std::set<std::string> distinct;
        for (std::size_t i = 0; i < rows.size(); ++i) {
            INFO(rows[i]);
            // The rows come in the contacts' order, each with its own index and the World's feature id.
            CHECK(test::traceValue(rows[i], "contact") == std::vector<double>{double(i)});
            CHECK(test::traceValue(rows[i], "feature") == std::vector<double>{double(features.features[i])});
            for (const std::string& word : test::words(rows[i])) {
                if (word.find('|') != std::string::npos) distinct.insert(word + " " + std::to_string(features.features[i]));
            }
        }
        // A corner's feature id is unique among the contacts of its pair: two boxes, four corners each.
        CHECK(distinct.size() == rows.size());
    }
}
