// The benchmark's meters (bench/scenario_metrics.cpp) and its sphere-rain scene
// (bench/sphere_rain_scene.cpp): the figures of docs/benchmarks.md's Scaling and
// Bullet sections come from them, for both engines, so each is checked here
// against geometry or physics worked out by hand. Tag: [bench].
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "config/scene_loader.hpp"
#include "scenario_metrics.hpp"
#include "sphere_rain_scene.hpp"

using namespace stepwise;
using namespace stepwise::bench;

namespace {

constexpr Real kTight = Real(1e-9);  // exact arithmetic on a few doubles

CollisionPlane plane(const Vec3& position, const Vec3& normal) {
    CollisionPlane p;
    p.position = position;
    p.normal = normal;
    return p;
}

BodyState at(const Vec3& position) {
    BodyState s;
    s.position = position;
    return s;
}

}  // namespace

TEST_CASE("RainMeter finds the deepest sphere-sphere and sphere-plane overlap, and the escaped spheres", "[bench]") {
    const Real r = Real(0.5);
    RainMeter meter({plane({0, 0, 0}, {0, 1, 0}), plane({0, 0, 0}, {1, 0, 0})}, r);

    // A 20 x 20 layer of spheres exactly touching (centres 2r apart, 1 m above the
    // floor's touching height): no overlap anywhere...
    std::vector<BodyState> bodies;
    for (int i = 0; i < 20; ++i) {
        for (int k = 0; k < 20; ++k) bodies.push_back(at({1 + Real(i), 2, Real(k)}));
    }
    meter.observe(bodies);
    CHECK(meter.worstOverlap() == Approx(0).margin(kTight));

    // ...then one pair 3 mm closer than touching, far from the first sphere:
    // 2r − |d| = 1 − 0.997 = 3 mm, found through the grid's neighbouring cells.
    bodies.push_back(at({Real(30.2), 2, 5}));
    bodies.push_back(at({Real(30.2) + Real(0.997), 2, 5}));
    meter.observe(bodies);
    CHECK(meter.worstOverlap() == Approx(0.003).margin(kTight));

    // A sphere 4 mm into the floor: r − y = 0.5 − 0.496.
    bodies.push_back(at({50, Real(0.496), 50}));
    meter.observe(bodies);
    CHECK(meter.worstOverlap() == Approx(0.004).margin(kTight));

    // Escaped: centre behind a plane (x < 0), not merely overlapping it.
    CHECK(meter.escaped(bodies) == 0);
    bodies.push_back(at({Real(-0.1), 3, 3}));
    CHECK(meter.escaped(bodies) == 1);
}

TEST_CASE("BounceMeter reads the apexes e^(2n) h0 from an exactly bouncing ball, to within g h^2/8", "[bench]") {
    // The exact motion: dropped from rest with its lowest point h0 above the floor,
    // each bounce returns e times the impact speed, so the n-th apex is e^(2n)·h0.
    const double g = 9.81, e = 0.8, h0 = 1.0, radius = 0.1, h = 1.0 / 60;
    BounceMeter meter(0, Real(radius));
    double t0 = 0, y0 = h0, v0 = 0;  // start of the current flight
    for (int step = 1; step <= 240; ++step) {
        const double t = step * h;
        double tau = t - t0;
        double land = (v0 + std::sqrt(v0 * v0 + 2 * g * y0)) / g;  // time to reach y = 0
        while (tau > land) {
            const double impact = v0 - g * land;
            t0 += land;
            y0 = 0;
            v0 = -e * impact;
            tau = t - t0;
            land = 2 * v0 / g;
        }
        BodyState ball;
        ball.position = {0, Real(y0 + v0 * tau - 0.5 * g * tau * tau + radius), 0};
        ball.velocity = {0, Real(v0 - g * tau), 0};
        meter.observe(ball);
    }
    REQUIRE(meter.apexes().size() >= 4);
    const double sampling = g * h * h / 8;  // the top of a parabola falls at most this far between samples
    for (int n = 1; n <= 4; ++n) {
        INFO("apex " << n);
        CHECK(double(meter.apexes()[std::size_t(n - 1)]) == Approx(std::pow(e, 2 * n) * h0).margin(sampling + 1e-6));
    }
}

TEST_CASE("FreeBodyMeter measures the relative drift of L and of the kinetic energy", "[bench]") {
    BodyState start;
    start.angularVelocity = {0, 5, 0};
    start.angularMomentum = {0, 10, 0};  // T = ½·ω·L = 25 J
    FreeBodyMeter meter(start);
    meter.observe(start);
    CHECK(meter.worstMomentumDrift() == Approx(0).margin(kTight));
    BodyState later = start;
    later.angularMomentum = {Real(0.1), 10, 0};  // |ΔL|/|L| = 0.1/10; T = ½·5·10 unchanged
    later.angularVelocity = {0, Real(4.9), 0};   // T = ½·4.9·10 = 24.5 J: −2 %
    meter.observe(later);
    CHECK(meter.worstMomentumDrift() == Approx(0.01).epsilon(1e-6));
    CHECK(meter.finalEnergyDrift() == Approx(-0.02).epsilon(1e-6));
    CHECK(meter.worstEnergyDrift() == Approx(0.02).epsilon(1e-6));
}

TEST_CASE("inclineAcceleration: rolling 5/7 and 3/5 g sin(theta), sliding g (sin - mu cos), sticking 0", "[bench]") {
    // A 30° slope: normal (sin 30°, cos 30°, 0), gravity 9.81 m/s² down.
    const CollisionPlane slope = plane({0, 0, 0}, {Real(0.5), Real(std::sqrt(3.0) / 2), 0});
    const Vec3 gravity{0, Real(-9.81), 0};
    const double g = 9.81, s = 0.5, c = std::sqrt(3.0) / 2;
    DynamicObject ball;
    ball.shape = Shape::Sphere;
    ball.friction = Real(0.5);
    CHECK(double(inclineAcceleration(ball, slope, gravity)) == Approx(5.0 / 7 * g * s));
    ball.hollow = true;
    CHECK(double(inclineAcceleration(ball, slope, gravity)) == Approx(3.0 / 5 * g * s));
    ball.hollow = false;
    ball.friction = Real(0.1);  // below 2/7·tan30° = 0.165: it slips
    CHECK(double(inclineAcceleration(ball, slope, gravity)) == Approx(g * (s - 0.1 * c)));
    DynamicObject box;
    box.shape = Shape::Box;
    box.friction = Real(0.3);
    CHECK(double(inclineAcceleration(box, slope, gravity)) == Approx(g * (s - 0.3 * c)));
    box.friction = Real(0.8);  // above tan30° = 0.577
    CHECK(double(inclineAcceleration(box, slope, gravity)) == 0);
    const Vec3 down = downSlope(slope, gravity);
    CHECK(double(down.x) == Approx(c));
    CHECK(double(down.y) == Approx(-s));
}

TEST_CASE("The sphere-rain scene: N spheres of radius 0.5 m, apart, inside a five-plane box", "[bench]") {
    constexpr std::size_t kCount = 1000;
    const Scene scene = parseScene(sphereRainSceneText(kCount, 1), "rain");
    REQUIRE(scene.dynamics.size() == kCount);
    CHECK(scene.planes.size() == 5);
    CHECK(double(scene.settings.timeStep) == Approx(1.0 / 60));
    std::vector<BodyState> bodies;
    for (const DynamicObject& b : scene.dynamics) {
        CHECK(b.radius == Real(0.5));
        bodies.push_back(at(b.position));
    }
    RainMeter meter(scene.planes, kRainRadius);
    meter.observe(bodies);
    CHECK(meter.worstOverlap() == 0);  // nothing starts touching: the jitter is under half the gap
    CHECK(meter.escaped(bodies) == 0);
    // The same seed writes the same text (SplitMix64, not a library distribution).
    CHECK(sphereRainSceneText(kCount, 1) == sphereRainSceneText(kCount, 1));
    CHECK(sphereRainSceneText(kCount, 1) != sphereRainSceneText(kCount, 2));
}

// [slow]: a second of 4000 bodies; the sanitizer build skips it and steps the same stages in the
// smaller rains. The Release tests run it.
TEST_CASE("The 4000-sphere rain's spheres never overlap by 5 mm while they land", "[bench][narrowphase][slow]") {
    // Issue #7's target for the rain, worst overlap under 5 mm, over the first second, when the
    // spheres land and strike each other hardest. At step 57 of this seed a ball sliding down a
    // wall is struck from above at about 4 m/s and carried 78 mm towards a ball 58 mm away: with
    // contacts looked for only as far as each body's own motion reaches, it ends 19.5 mm inside
    // (World::widenSweepsByKnocks() says why the reach now covers the knock).
    constexpr int kSteps = 60;
    World world(onOneThread(parseScene(sphereRainSceneText(4000, 1), "rain")));
    RainMeter meter(world.planes(), kRainRadius);
    std::vector<BodyState> states;
    for (int step = 0; step < kSteps; ++step) {
        world.step();
        statesOf(world, states);
        meter.observe(states);
    }
    INFO("worst overlap " << meter.worstOverlap() * 1000 << " mm");
    CHECK(meter.worstOverlap() < Real(0.005));
    CHECK(meter.escaped(states) == 0);
}
