/// @file elastic_gas.cpp
/// @brief The elastic gas scene and its Maxwell–Boltzmann distance (elastic_gas.hpp).
#include "elastic_gas.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "config/scene_generator.hpp"
#include "config/scene_loader.hpp"

namespace stepwise::bench {

namespace {

/// Clearance between the highest sphere's centre and the ceiling, m.
constexpr Real kCeilingClearance = 1;

/// The regularised lower incomplete gamma function P(3/2, x).
double gammaCdfThreeHalves(double x) {
    return std::erf(std::sqrt(x)) - 2 * std::sqrt(x / std::numbers::pi) * std::exp(-x);
}

}  // namespace

void addCeiling(Scene& scene) {
    Real top = 0;
    for (const DynamicObject& b : scene.dynamics) top = std::max(top, b.position.y);
    CollisionPlane ceiling;
    ceiling.name = "ceiling";
    ceiling.position = Vec3(0, top + kCeilingClearance, 0);
    ceiling.normal = Vec3(0, -1, 0);
    scene.planes.push_back(ceiling);
}

Vec3 randomVelocity(std::mt19937_64& random, double speed) {
    // One component per statement: the order of the draws is then fixed, as the seed's scene must be.
    const auto uniform = [&] { return speed * (2 * double(random() >> 11) * 0x1.0p-53 - 1); };
    const double x = uniform();
    const double y = uniform();
    const double z = uniform();
    return Vec3(x, y, z);
}

Scene elasticGasScene(std::size_t count, std::uint64_t seed) {
    GeneratorOptions generate;
    generate.scene = GeneratedScene::SphereRain;
    generate.count = count;
    generate.seed = seed;
    Scene scene = parseScene(generateSceneText(generate), "elastic-gas");
    scene.settings.gravity = Vec3(0);
    scene.settings.sleeping = false;
    addCeiling(scene);
    std::mt19937_64 random(seed);
    for (DynamicObject& b : scene.dynamics) {
        b.elasticity = 1;
        b.friction = 0;
        b.velocity = randomVelocity(random, kGasSpeed);
    }
    for (CollisionPlane& p : scene.planes) p.elasticity = p.friction = 1;
    return scene;
}

double maxwellBoltzmannDistance(const World& world) {
    std::vector<double> energies;
    double total = 0;
    for (const DynamicObject& b : world.dynamics()) {
        energies.push_back(0.5 * double(b.mass) * double(glm::dot(b.velocity, b.velocity)));
        total += energies.back();
    }
    const std::size_t n = energies.size();
    if (n == 0 || total <= 0) return 1;
    const double kT = 2 * total / (3 * double(n));
    std::sort(energies.begin(), energies.end());
    double distance = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double f = gammaCdfThreeHalves(energies[i] / kT);
        distance = std::max({distance, double(i + 1) / double(n) - f, f - double(i) / double(n)});
    }
    return distance;
}

double kolmogorovSmirnovCritical1Percent(std::size_t n) { return 1.628 / std::sqrt(double(n)); }

}  // namespace stepwise::bench
