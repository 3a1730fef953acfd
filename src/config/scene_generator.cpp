/// @file scene_generator.cpp
/// @brief The benchmark scenes, written as scene-file text.
#include "config/scene_generator.hpp"

#include <cmath>
#include <cstdio>

#include "config/scene_writing.hpp"

namespace stepwise {

namespace {

using namespace scene_writing;

// Sphere rain and box pile: bodies on a lattice (scene_writing.hpp).
constexpr double kLatticeGap = 0.05;       ///< Free space between neighbouring lattice sites, m.
constexpr double kDensity = 1000;          ///< Density of every body, kg/m³ (water).
constexpr double kRainRadiusMin = 0.08;    ///< Sphere radii, m.
constexpr double kRainRadiusMax = 0.12;
constexpr double kPileEdgeMin = 0.16;      ///< Box edge lengths, m.
constexpr double kPileEdgeMax = 0.24;
constexpr double kElasticity = 0.3;        ///< A little bounce, so impacts settle.
constexpr double kFriction = 0.5;

// Pyramids: Box2D's "many pyramids" benchmark, in 3D rows.
constexpr int kPyramidBase = 10;           ///< Cubes in the bottom row of a pyramid.
constexpr double kCubeEdge = 0.5;          ///< Cube edge, m.
constexpr double kCubeGap = 0.02;          ///< Gap between neighbours in a row, m (they start apart).
constexpr double kPyramidSpacing = 1.0;    ///< Free space between neighbouring pyramids, m.
constexpr double kPyramidMass = 1;         ///< Mass of each cube, kg.

constexpr double kPi = 3.14159265358979323846;

void appendHeader(std::string& text, const GeneratorOptions& options) {
    append(text, "# %s: %zu bodies, seed %llu.\n", toString(options.scene), options.count,
           static_cast<unsigned long long>(options.seed));
    append(text, "# Written by: stepwise generate %s --count %zu --seed %llu (src/config/scene_generator.cpp)\n",
           toString(options.scene), options.count, static_cast<unsigned long long>(options.seed));
    append(text, "World, TimeStep=1/60, Integrator=SymplecticEuler, Duration=5, Broadphase=%s\n",
           toString(options.broadphase));
}

/// The open box, then the lattice of `options.count` bodies (scene_writing.hpp).
void appendBoxedLattice(std::string& text, const GeneratorOptions& options, SplitMix64& random, double pitch,
                   double jitter, auto&& body) {
    appendContainer(text, double(latticeColumns(options.count)) * pitch);
    scene_writing::appendLattice(options.count, random, pitch, jitter, body);
}

/// Three draws in turn: the order of a call's arguments is unspecified in C++,
/// so random numbers are never drawn inside an argument list.
Vec3 uniformTriple(SplitMix64& random, double lo, double hi) {
    const double x = random.uniform(lo, hi);
    const double y = random.uniform(lo, hi);
    const double z = random.uniform(lo, hi);
    return {x, y, z};
}

void appendColor(std::string& text, SplitMix64& random) {
    const Vec3 c = uniformTriple(random, 0.2, 1);
    append(text, ", Color=(%.2f, %.2f, %.2f)", double(c.x), double(c.y), double(c.z));
}

void sphereRain(std::string& text, const GeneratorOptions& options, SplitMix64& random) {
    const double pitch = 2 * kRainRadiusMax + kLatticeGap;
    appendBoxedLattice(text, options, random, pitch, kLatticeGap / 2,
                  [&](std::size_t n, double x, double y, double z, double vx, double vz) {
                      const double r = random.uniform(kRainRadiusMin, kRainRadiusMax);
                      const double mass = kDensity * 4.0 / 3.0 * kPi * r * r * r;
                      append(text, "DynamicObject, Name=s%zu, Shape=Sphere, Position=(%.4f, %.4f, %.4f), "
                                   "Velocity=(%.3f, 0, %.3f), Radius=%.4f, Mass=%.4f, Elasticity=%.2f, Friction=%.2f",
                             n, x, y, z, vx, vz, r, mass, kElasticity, kFriction);
                      appendColor(text, random);
                      text += '\n';
                  });
}

void boxPile(std::string& text, const GeneratorOptions& options, SplitMix64& random) {
    // A box turned any way fits in a sphere of its half-diagonal, √3·e/2 at most.
    const double pitch = std::sqrt(3.0) * kPileEdgeMax + kLatticeGap;
    appendBoxedLattice(text, options, random, pitch, kLatticeGap / 2,
                  [&](std::size_t n, double x, double y, double z, double vx, double vz) {
                      const Vec3 edge = uniformTriple(random, kPileEdgeMin, kPileEdgeMax);
                      const Vec3 degrees = uniformTriple(random, 0, 360);
                      const double mass = kDensity * double(edge.x * edge.y * edge.z);
                      append(text, "DynamicObject, Name=b%zu, Shape=Box, Position=(%.4f, %.4f, %.4f), "
                                   "Velocity=(%.3f, 0, %.3f), Scale=(%.4f, %.4f, %.4f), Mass=%.4f, "
                                   "Rotation=(%.1f, %.1f, %.1f), Elasticity=%.2f, Friction=%.2f",
                             n, x, y, z, vx, vz, double(edge.x), double(edge.y), double(edge.z), mass,
                             double(degrees.x), double(degrees.y), double(degrees.z), kElasticity, kFriction);
                      appendColor(text, random);
                      text += '\n';
                  });
}

void pyramids(std::string& text, const GeneratorOptions& options, SplitMix64& random) {
    append(text, "CollisionPlane, Name=floor, Position=(0, 0, 0), Normal=(0, 1, 0), Color=(0.5, 0.5, 0.5)\n");
    constexpr std::size_t kPerPyramid = kPyramidBase * (kPyramidBase + 1) / 2;
    const std::size_t pyramidCount = (options.count + kPerPyramid - 1) / kPerPyramid;
    // Pyramids on a square grid, each in the x–y plane, rows of them along z.
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(double(pyramidCount))));
    const double pitch = kCubeEdge + kCubeGap;
    const double width = kPyramidBase * pitch + kPyramidSpacing;
    const double depth = kCubeEdge + kPyramidSpacing;
    std::size_t n = 0;
    for (std::size_t p = 0; p < pyramidCount; ++p) {
        const double x0 = double(p % side) * width;
        const double z = double(p / side) * depth;
        for (int row = 0; row < kPyramidBase && n < options.count; ++row) {
            for (int k = 0; k < kPyramidBase - row && n < options.count; ++k, ++n) {
                const double x = x0 + (double(k) + 0.5 * double(row) + 0.5) * pitch;
                const double y = (double(row) + 0.5) * kCubeEdge;
                append(text, "DynamicObject, Name=c%zu, Shape=Box, Position=(%.4f, %.4f, %.4f), "
                             "Scale=(%.2f, %.2f, %.2f), Mass=%.2f, Elasticity=0, Friction=%.2f",
                       n, x, y, z, kCubeEdge, kCubeEdge, kCubeEdge, kPyramidMass, kFriction);
                appendColor(text, random);
                text += '\n';
            }
        }
    }
}

}  // namespace

const char* toString(GeneratedScene scene) {
    switch (scene) {
        case GeneratedScene::SphereRain: return "sphere-rain";
        case GeneratedScene::BoxPile: return "box-pile";
        case GeneratedScene::Pyramids: return "pyramids";
    }
    return "?";
}

std::optional<GeneratedScene> generatedSceneNamed(std::string_view name) {
    for (const GeneratedScene scene : {GeneratedScene::SphereRain, GeneratedScene::BoxPile, GeneratedScene::Pyramids}) {
        if (name == toString(scene)) return scene;
    }
    return std::nullopt;
}

std::string generateSceneText(const GeneratorOptions& options) {
    std::string text;
    SplitMix64 random(options.seed);
    appendHeader(text, options);
    switch (options.scene) {
        case GeneratedScene::SphereRain: sphereRain(text, options, random); break;
        case GeneratedScene::BoxPile: boxPile(text, options, random); break;
        case GeneratedScene::Pyramids: pyramids(text, options, random); break;
    }
    return text;
}

}  // namespace stepwise
