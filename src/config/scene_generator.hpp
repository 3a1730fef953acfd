/// @file scene_generator.hpp
/// @brief Writes large benchmark scenes (sphere rain, box pile, pyramids) as scene-file text.
///
/// Scenes of thousands of bodies are not committed: `stepwise generate`
/// writes them from a name, a count and a seed, and the broadphase benchmark
/// (bench/broadphase) parses the same text, so every program that loads the
/// file (including another engine, for comparison) sees the same bodies.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/world_settings.hpp"

namespace stepwise {

/// @brief The benchmark scenes.
enum class GeneratedScene : std::uint8_t {
    SphereRain,  ///< Spheres of radius 0.08–0.12 m on a jittered lattice, falling into a box of five planes.
    BoxPile,     ///< Randomly turned boxes of 0.16–0.24 m, falling into the same kind of box.
    Pyramids,    ///< Rows of 2D pyramids of 0.5 m cubes, 10 at the base, standing on a floor.
};

/// @brief What to generate.
struct GeneratorOptions {
    GeneratedScene scene = GeneratedScene::SphereRain;  ///< Which scene.
    std::size_t count = 1000;                           ///< Number of dynamic bodies (≥ 1).
    std::uint64_t seed = 1;                             ///< Seed of the jitter, sizes and colours.
    BroadphaseKind broadphase = BroadphaseKind::Auto;   ///< The World record's Broadphase.
};

/// @brief The scene file's text: a comment saying how it was made, a World record, planes, bodies.
///
/// The layout keeps the number of bodies per unit of floor area the same
/// whatever the count (the box grows with it), so a good broadphase costs
/// the same per body at 1k and at 64k bodies. The same options give the
/// same text on every machine (the random numbers are SplitMix64, not a
/// library distribution).
std::string generateSceneText(const GeneratorOptions& options);

/// @brief The command-line name of a scene: "sphere-rain", "box-pile", "pyramids".
const char* toString(GeneratedScene scene);

/// @brief The scene called @p name, or nothing.
std::optional<GeneratedScene> generatedSceneNamed(std::string_view name);

}  // namespace stepwise
