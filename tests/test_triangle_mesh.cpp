/// @file test_triangle_mesh.cpp
/// @brief Triangle meshes: the checks, the box hierarchy's invariants, and which edges are active.
/// Tags: [mesh].
///
/// The hierarchy is checked by its definition (every triangle in exactly one leaf, leaves of
/// at most kMeshLeafSize, every box holding what is below it), not by its exact shape; the
/// active edges against folds whose kind is known by construction (flat, ridge, valley).
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "config/obj_file.hpp"
#include "mesh_fixtures.hpp"
#include "objects/triangle_mesh.hpp"

using namespace stepwise;

namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

/// A flat n × n grid of unit squares in the y = 0 plane, two triangles each, facing up
/// (test::heightGrid(), mesh_fixtures.hpp).
TriangleMesh grid(std::uint32_t n) {
    return test::heightGrid(n, 1, 0, 0, [](Real, Real) { return Real(0); });
}

/// Two triangles folded along the z axis edge (0,0,0)–(0,0,1), the second's far corner at
/// (1, @p rise, 0.5) against the first's at (-1, 0, 0.5). Both face +y-ish.
TriangleMesh fold(Real rise) {
    const std::vector<Vec3> vertices{Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(-1, 0, Real(0.5)), Vec3(1, rise, Real(0.5))};
    // First: 0 → 2 → 1, counter-clockwise seen from above (normal +y), running the shared
    // edge 1 → 0 as its third edge; the second runs it 0 → 1 as its first edge.
    const Triangles triangles{{0, 2, 1}, {0, 1, 3}};
    return buildTriangleMesh(vertices, triangles);
}

bool inside(const MeshNode& outer, const Vec3& p) {
    return p.x >= outer.lower.x && p.y >= outer.lower.y && p.z >= outer.lower.z && p.x <= outer.upper.x &&
           p.y <= outer.upper.y && p.z <= outer.upper.z;
}

MeshProblem problemOf(const std::vector<Vec3>& vertices, const Triangles& triangles) {
    try {
        (void)buildTriangleMesh(vertices, triangles);
    } catch (const MeshError& error) {
        return error.problem();
    }
    FAIL("no MeshError");
    return MeshProblem::NoTriangles;
}

}  // namespace

TEST_CASE("The hierarchy holds every triangle once, in leaves of at most 4, inside every box above", "[mesh]") {
    const TriangleMesh mesh = grid(10);  // 200 triangles
    REQUIRE(mesh.order.size() == 200);
    std::set<std::uint32_t> seen;
    std::vector<std::pair<std::size_t, std::size_t>> stack{{0, 0}};  // node, its parent (root: itself)
    std::size_t leaves = 0;
    while (!stack.empty()) {
        const auto [index, parent] = stack.back();
        stack.pop_back();
        const MeshNode& node = mesh.nodes.at(index);
        CHECK(inside(mesh.nodes[parent], node.lower));
        CHECK(inside(mesh.nodes[parent], node.upper));
        if (node.count == 0) {
            stack.push_back({node.first, index});
            stack.push_back({node.first + 1, index});
            continue;
        }
        ++leaves;
        CHECK(node.count <= kMeshLeafSize);
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
            const std::uint32_t t = mesh.order.at(k);
            CHECK(seen.insert(t).second);  // in one leaf only
            for (const std::uint32_t v : mesh.triangles[t]) CHECK(inside(node, mesh.vertices[v]));
        }
    }
    CHECK(seen.size() == 200);
    // 200 triangles in leaves of at most 4: at least 50 leaves, and a binary tree of L leaves has 2L - 1 nodes.
    CHECK(leaves >= 50);
    CHECK(mesh.nodes.size() == 2 * leaves - 1);
}

TEST_CASE("On a flat grid only the border edges stay active", "[mesh]") {
    const std::uint32_t n = 4;
    const TriangleMesh mesh = grid(n);
    std::size_t active = 0;
    for (const auto& edges : mesh.activeEdges) {
        for (const bool a : edges) active += a ? 1 : 0;
    }
    CHECK(active == 4 * n);  // the n unit edges along each of the four sides
}

TEST_CASE("A ridge's shared edge is active, and a valley's and a flat fold's are not", "[mesh]") {
    // The shared edge is edge 2 of the first triangle and edge 0 of the second.
    // rise < 0: the second triangle bends down, a ridge (convex). rise > 0: a valley (concave).
    const TriangleMesh ridge = fold(Real(-0.5));
    CHECK(ridge.activeEdges[0][2]);
    CHECK(ridge.activeEdges[1][0]);
    const TriangleMesh valley = fold(Real(0.5));
    CHECK_FALSE(valley.activeEdges[0][2]);
    CHECK_FALSE(valley.activeEdges[1][0]);
    // A ridge of 2 degrees is flatter than kFlatFoldDegrees (5): inactive, so nothing snags on it.
    const TriangleMesh gentle = fold(-std::tan(glm::radians(Real(2))));
    CHECK_FALSE(gentle.activeEdges[0][2]);
    // 10 degrees is a real edge.
    const TriangleMesh sharp = fold(-std::tan(glm::radians(Real(10))));
    CHECK(sharp.activeEdges[0][2]);
    // The unshared edges are on the border: active.
    CHECK(ridge.activeEdges[0][0]);
    CHECK(ridge.activeEdges[0][1]);
}

TEST_CASE("A mesh refuses no triangles, bad indices, zero-area triangles and NaN", "[mesh]") {
    const std::vector<Vec3> square{Vec3(0), Vec3(0, 0, 1), Vec3(1, 0, 0)};
    CHECK(problemOf(square, {}) == MeshProblem::NoTriangles);
    CHECK(problemOf(square, {{0, 1, 3}}) == MeshProblem::IndexOutOfRange);
    CHECK(problemOf({Vec3(0), Vec3(1, 0, 0), Vec3(2, 0, 0)}, {{0, 1, 2}}) == MeshProblem::ZeroArea);
    CHECK(problemOf({Vec3(0), Vec3(0), Vec3(1, 0, 0)}, {{0, 1, 2}}) == MeshProblem::ZeroArea);
    CHECK(problemOf({Vec3(0), Vec3(0, 0, 1), Vec3(std::nan(""), 0, 0)}, {{0, 1, 2}}) == MeshProblem::NotFinite);
    try {
        (void)buildTriangleMesh(square, {{0, 1, 2}, {0, 1, 7}});
    } catch (const MeshError& error) {
        CHECK(std::string(error.what()) == "triangle 2 uses vertex 8, but there are 3 vertices");
    }
}

TEST_CASE("The shipped ramp is a mesh of 32 triangles whose inner edges are all inactive", "[mesh]") {
    // config/models/ramp.obj: 8 x 2 squares on a flat 20-degree slope, so every shared edge is a
    // flat fold and only the 2 (8 + 2) unit-length pieces of its border stay active.
    ObjModel model = readObjFile(STEPWISE_SOURCE_DIR "/config/models/ramp.obj");
    const TriangleMesh mesh = buildTriangleMesh(std::move(model.vertices), std::move(model.triangles));
    std::size_t active = 0;
    for (const auto& edges : mesh.activeEdges) {
        for (const bool a : edges) active += a ? 1 : 0;
    }
    CHECK(mesh.triangles.size() == 32);
    CHECK(active == 2 * (8 + 2));
    // Every triangle faces up the slope's outside: normal (-sin 20°, cos 20°, 0).
    const Vec3 up(-std::sin(glm::radians(Real(20))), std::cos(glm::radians(Real(20))), 0);
    for (const auto& t : mesh.triangles) {
        const Vec3 n = glm::normalize(glm::cross(mesh.vertices[t[1]] - mesh.vertices[t[0]], mesh.vertices[t[2]] - mesh.vertices[t[0]]));
        CHECK(glm::dot(n, up) > 1 - 1e-6);  // the file's 6 decimals tilt a normal by at most ~1e-6
    }
}
