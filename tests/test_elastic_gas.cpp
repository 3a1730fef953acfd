// The elastic gas held to the physics of an ideal gas (issue 34): 1000 spheres with e = 1 and no
// friction in a closed box without gravity, at the default settings. Its kinetic energy must stay
// what it was (perfectly elastic collisions keep it, simultaneous ones too by Poisson's law:
// applyRestitution() in src/dynamics/contact_solver.hpp), and collisions must spread the start's
// velocities, uniform in a cube, into Maxwell–Boltzmann's distribution.
// Tags: [solver][slow] (10 s of a 1000-body scene is too long for the sanitizer build).
#include <catch2/catch.hpp>

#include <algorithm>

#include "elastic_gas.hpp"
#include "world/measurements.hpp"

using namespace stepwise;

TEST_CASE("An elastic gas keeps its energy within 2 % over 10 s, and its speeds become Maxwell-Boltzmann's",
          "[solver][slow]") {
    World world(bench::elasticGasScene(1000, 1));
    const double critical = bench::kolmogorovSmirnovCritical1Percent(world.dynamics().size());
    // The start is far from equilibrium: velocity components uniform in [-2, 2) m/s, whose
    // energies a Kolmogorov–Smirnov test at 1 % tells apart from Maxwell–Boltzmann's. (If it did
    // not, the check at the end would prove nothing.)
    CHECK(bench::maxwellBoltzmannDistance(world) > critical);

    const double start = double(energyOf(world).total());
    double lowest = start, highest = start;
    while (world.time() < 10) {
        world.step();
        const double e = double(energyOf(world).total());
        lowest = std::min(lowest, e);
        highest = std::max(highest, e);
    }
    INFO("energy from " << 100 * (lowest / start - 1) << " % to " << 100 * (highest / start - 1) << " % of its start");
    CHECK(lowest >= 0.98 * start);
    CHECK(highest <= 1.02 * start);
    // After 10 s (hundreds of collisions a ball) the energies pass the same test at 1 %: the
    // hypothesis "Maxwell–Boltzmann at the gas's own temperature" is not rejected.
    const double distance = bench::maxwellBoltzmannDistance(world);
    INFO("Kolmogorov-Smirnov distance " << distance << ", critical at 1 % " << critical);
    CHECK(distance < critical);
}

TEST_CASE("The Maxwell-Boltzmann distance tells Maxwell-Boltzmann's own energies from others", "[solver]") {
    // Energies placed at the quantiles of the gamma(3/2) distribution itself are at distance about
    // 1/(2n); all equal (every ball at one speed) they are far.
    Scene scene;
    scene.settings.gravity = Vec3(0);
    for (int i = 0; i < 200; ++i) {
        DynamicObject b;
        b.name = "b" + std::to_string(i);
        b.setMass(1);
        b.velocity = Vec3(1, 0, 0);
        b.position = Vec3(Real(3 * i), 0, 0);
        scene.dynamics.push_back(b);
    }
    World same(scene);
    CHECK(bench::maxwellBoltzmannDistance(same) > 0.3);
    // The quantiles: solve P(3/2, x) = (i + 1/2)/n for x by bisection; speed √(2 x kT) with kT = 1.
    const auto cdf = [](double x) { return std::erf(std::sqrt(x)) - 2 * std::sqrt(x / 3.141592653589793) * std::exp(-x); };
    for (int i = 0; i < 200; ++i) {
        double low = 0, high = 50;
        for (int k = 0; k < 100; ++k) (cdf(0.5 * (low + high)) < (i + 0.5) / 200 ? low : high) = 0.5 * (low + high);
        scene.dynamics[std::size_t(i)].velocity = Vec3(Real(std::sqrt(2 * 0.5 * (low + high))), 0, 0);
    }
    World quantiles(scene);
    CHECK(bench::maxwellBoltzmannDistance(quantiles) < 0.02);
}
