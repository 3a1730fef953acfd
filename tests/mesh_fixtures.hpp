/// @file mesh_fixtures.hpp
/// @brief Triangle meshes built in code for the mesh tests: a grid over a height field.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "objects/triangle_mesh.hpp"

namespace stepwise::test {

/// @brief A grid of n × n square cells of side @p cell over y = height(x, z), its first corner at
/// (@p x0, ·, @p z0) and running towards +x and +z, each cell two triangles counter-clockwise seen
/// from above (+y): 2n² triangles.
///
/// Seen from above, x then z runs clockwise, so (x, z) → (x, z + 1) → (x + 1, z) is counter-clockwise.
template <class Height>
TriangleMesh heightGrid(std::uint32_t n, Real cell, Real x0, Real z0, Height height) {
    std::vector<Vec3> vertices;
    for (std::uint32_t i = 0; i <= n; ++i) {
        for (std::uint32_t k = 0; k <= n; ++k) {
            const Real x = x0 + Real(i) * cell;
            const Real z = z0 + Real(k) * cell;
            vertices.emplace_back(x, height(x, z), z);
        }
    }
    std::vector<std::array<std::uint32_t, 3>> triangles;
    const auto at = [n](std::uint32_t i, std::uint32_t k) { return i * (n + 1) + k; };
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t k = 0; k < n; ++k) {
            triangles.push_back({at(i, k), at(i, k + 1), at(i + 1, k)});
            triangles.push_back({at(i + 1, k), at(i, k + 1), at(i + 1, k + 1)});
        }
    }
    return buildTriangleMesh(vertices, triangles);
}

}  // namespace stepwise::test
