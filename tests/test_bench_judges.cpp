// The reference problems' judges (bench/reference_problems.cpp): the precision
// benchmark and the Bullet side by side measure every engine's errors with them,
// so each is checked here on motions whose answer is known, fed through a
// stand-in engine. A judge that reads the exact motion must find no error; one
// that reads a wrong motion must find the error the physics says. Tag: [bench].
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

#include "config/scene_loader.hpp"
#include "reference_problems.hpp"

using namespace stepwise;
using namespace stepwise::bench;

namespace {

/// A stand-in engine: one body whose state after step n is whatever `motion(n·h)` says.
struct ScriptedEngine {
    std::function<BodyState(double t)> motion;
    double h = 0;
    std::uint64_t steps = 0;
    void step() { ++steps; }
    void states(std::vector<BodyState>& out) const { out.assign(1, motion(double(steps) * h)); }
};

/// The pendulum of config/reference_pendulum.scene: 1 m, released at 60 degrees, a 1 kg ball of 5 cm.
constexpr const char* kPendulumScene =
    "World, TimeStep=1/60, Integrator=SymplecticEuler, Duration=25, Sleep=false\n"
    "DynamicObject, Name=bob, Position=(0.8660254037844386, 1.5, 0), Mass=1, Radius=0.05\n"
    "DistanceJoint, Name=rod, BodyA=bob, AnchorA=(0.8660254037844386, 1.5, 0), AnchorB=(0, 2, 0)\n";
constexpr double kRod = 1, kGravity = 9.81, kTheta0 = 3.14159265358979323846 / 3;
/// The ball's own moment of inertia, ⅖·m·r², kg·m².
constexpr double kBallInertia = 0.4 * 1 * 0.05 * 0.05;

/// θ(t) of θ¨ = −(g/ℓ)·sin θ from rest at θ₀, by RK4 steps of kFine, tabulated once per run.
class Swing {
public:
    static constexpr double kFine = 1e-4;  // s: RK4's error ∝ kFine⁴, far below the tolerances
    Swing(double length, double duration) {
        double theta = kTheta0, rate = 0;
        const auto accel = [=](double a) { return -kGravity / length * std::sin(a); };
        for (double t = 0; t <= duration + kFine; t += kFine) {
            table_.push_back({theta, rate});
            const double k1a = rate, k1b = accel(theta);
            const double k2a = rate + 0.5 * kFine * k1b, k2b = accel(theta + 0.5 * kFine * k1a);
            const double k3a = rate + 0.5 * kFine * k2b, k3b = accel(theta + 0.5 * kFine * k2a);
            const double k4a = rate + kFine * k3b, k4b = accel(theta + kFine * k3a);
            theta += kFine / 6 * (k1a + 2 * k2a + 2 * k3a + k4a);
            rate += kFine / 6 * (k1b + 2 * k2b + 2 * k3b + k4b);
        }
    }
    /// The bob's state at @p t (a whole number of kFine): on the 1 m rod from (0, 2, 0), turning with it if @p turns.
    BodyState at(double t, bool turns) const {
        const auto [theta, rate] = table_.at(static_cast<std::size_t>(std::llround(t / kFine)));
        BodyState s;
        s.position = Vec3(Real(kRod * std::sin(theta)), Real(2 - kRod * std::cos(theta)), 0);
        s.velocity = Vec3(Real(kRod * rate * std::cos(theta)), Real(kRod * rate * std::sin(theta)), 0);
        if (turns) {
            s.angularVelocity = Vec3(0, 0, Real(rate));
            s.angularMomentum = Vec3(0, 0, Real(kBallInertia * rate));
        }
        return s;
    }

private:
    std::vector<std::pair<double, double>> table_;
};

Measurement judgeSwing(const JudgeMaker& judges, const Swing& swing, bool turns, double h) {
    const Judge judge = judges(h);
    ScriptedEngine engine{[&](double t) { return swing.at(t, turns); }, h};
    return runJudged(engine, judge, h);
}

}  // namespace

TEST_CASE("The pendulum's judges time an exact swing, of the simple pendulum and of the compound one", "[bench]") {
    const Scene scene = parseScene(kPendulumScene, "pendulum");
    const JudgeMaker simple = referenceProblems()[6].prepare(scene);
    const JudgeMaker compound = preparePendulumTurningBob(scene);
    REQUIRE(referenceProblems()[6].name == "pendulum");
    const double h = 1.0 / 60;  // 1/60 is 166⅔ fine steps: round it to a whole number of them
    const double step = std::round(h / Swing::kFine) * Swing::kFine;
    const double duration = double(simple(step).steps) * step + 1;

    // A bob held at its centre swings as a point on a 1 m rod; one that turns with the rod
    // as a point on a rod 1 m + I/(m·L) long: 1 mm longer, a period 0.05 % longer.
    const Swing held(kRod, duration), turning(kRod + kBallInertia / kRod, duration);
    // The crossings are interpolated linearly inside a step, where the swing is nearly
    // straight (θ¨ = 0 under the pivot): 1e-6 of the period bounds that here.
    constexpr double kPeriodTolerance = 1e-6;
    const Measurement exactSimple = judgeSwing(simple, held, false, step);
    const Measurement exactCompound = judgeSwing(compound, turning, true, step);
    REQUIRE(exactSimple.metrics.size() == 3);
    CHECK(exactSimple.metrics[0].value < kPeriodTolerance);
    CHECK(exactCompound.metrics[0].value < kPeriodTolerance);
    // The rod keeps its length and the energy (with the bob's turning ½·ω·L in it) is kept.
    CHECK(exactSimple.metrics[1].value < 1e-9);
    CHECK(exactCompound.metrics[2].value < 1e-6);

    // Judged as the other kind, each is half the length ratio off: ΔT/T = ½·ΔL/L = 5e-4.
    const double expected = 0.5 * kBallInertia / (kRod * kRod);
    CHECK(judgeSwing(simple, turning, true, step).metrics[0].value == Approx(expected).epsilon(0.02));
    CHECK(judgeSwing(compound, held, false, step).metrics[0].value == Approx(expected).epsilon(0.02));
}

TEST_CASE("The projectile's judge finds no error in the exact parabola and 1 m in one shifted by 1 m", "[bench]") {
    const Scene scene = parseScene(
        "World, Gravity=(0, -9.81, 0), TimeStep=1/60, Duration=2, Solver=Impulse\n"
        "DynamicObject, Name=projectile, Position=(0, 10, 0), Velocity=(3, 4, 0), Radius=0.1\n",
        "projectile");
    REQUIRE(referenceProblems()[0].name == "projectile");
    const JudgeMaker judges = referenceProblems()[0].prepare(scene);
    const double h = 1.0 / 60;
    const auto parabola = [](double shift) {
        return [shift](double t) {
            BodyState s;
            s.position = Vec3(Real(3 * t + shift), Real(10 + 4 * t - 0.5 * 9.81 * t * t), 0);
            s.velocity = Vec3(3, Real(4 - 9.81 * t), 0);
            return s;
        };
    };
    ScriptedEngine exact{parabola(0), h}, shifted{parabola(1), h};
    const Measurement good = runJudged(exact, judges(h), h);
    const Measurement off = runJudged(shifted, judges(h), h);
    CHECK(good.steps == 120);
    CHECK(good.metrics[0].value < 1e-12);
    CHECK(off.metrics[0].value == Approx(1).epsilon(1e-12));
    CHECK(off.metrics[1].value < 1e-12);  // the velocity was not shifted
}
