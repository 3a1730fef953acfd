/// @file shape_fixtures.hpp
/// @brief Hulls, meshes, compounds and bodies of the new shapes, made by hand for tests.
///
/// Each fixture is written out corner by corner, so a test's expected value
/// comes from the geometry on the page and not from a builder under test:
/// a cube hull (8 vertices, 6 quad faces counter-clockwise seen from outside,
/// 12 edges), a square of two triangles with its hierarchy, and a compound of
/// two boxes. Any test may include this header.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "objects/game_object.hpp"

namespace stepwise::test {

/// @brief A box hull of half extents @p half about the origin.
///
/// Vertex i has coordinate +half on axis k when bit k of i is set, −half
/// otherwise: vertex 0 is (−,−,−), 7 is (+,+,+). Each face's loop runs
/// counter-clockwise seen from outside, so (v₁ − v₀) × (v₂ − v₀) points
/// along its normal ("[raycast]" checks this, as a builder's hull must).
inline std::shared_ptr<const ConvexHull> cubeHull(Vec3 half = Vec3(Real(0.5))) {
    auto hull = std::make_shared<ConvexHull>();
    for (std::uint32_t i = 0; i < 8; ++i) {
        hull->vertices.emplace_back((i & 1u) ? half.x : -half.x, (i & 2u) ? half.y : -half.y,
                                    (i & 4u) ? half.z : -half.z);
    }
    struct FaceLoop {
        Vec3 normal;
        Real offset;
        std::array<std::uint32_t, 4> loop;
    };
    const FaceLoop faces[6] = {
        {{1, 0, 0}, half.x, {1, 3, 7, 5}},  {{-1, 0, 0}, half.x, {0, 4, 6, 2}},
        {{0, 1, 0}, half.y, {2, 6, 7, 3}},  {{0, -1, 0}, half.y, {0, 1, 5, 4}},
        {{0, 0, 1}, half.z, {4, 5, 7, 6}},  {{0, 0, -1}, half.z, {0, 2, 3, 1}},
    };
    for (const FaceLoop& f : faces) {
        HullFace face;
        face.normal = f.normal;
        face.offset = f.offset;
        face.firstIndex = static_cast<std::uint32_t>(hull->faceIndices.size());
        face.indexCount = 4;
        hull->faceIndices.insert(hull->faceIndices.end(), f.loop.begin(), f.loop.end());
        hull->faces.push_back(face);
    }
    // The 12 edges join vertices that differ in one coordinate (one bit).
    for (std::uint32_t i = 0; i < 8; ++i) {
        for (std::uint32_t bit : {1u, 2u, 4u}) {
            if ((i & bit) == 0) hull->edges.push_back({i, i | bit});
        }
    }
    hull->volume = 8 * half.x * half.y * half.z;
    hull->boundingRadius = glm::length(half);
    return hull;
}

/// @brief A square of side 2·@p half in the plane y = 0, two triangles facing +y.
///
/// Vertices 0 (−h, 0, −h), 1 (h, 0, −h), 2 (h, 0, h), 3 (−h, 0, h);
/// triangles (0, 3, 2) and (0, 2, 1), counter-clockwise seen from above.
/// With @p twoLeaves false the hierarchy is one leaf holding both; with it
/// true a root over two leaves of one triangle each (the x < z and x > z
/// halves), so a ray must choose a child. The diagonal 0–2 is shared and
/// flat, so it is inactive in both triangles.
inline std::shared_ptr<const TriangleMesh> squareMesh(Real half = 1, bool twoLeaves = false) {
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->vertices = {{-half, 0, -half}, {half, 0, -half}, {half, 0, half}, {-half, 0, half}};
    mesh->triangles = {{0, 3, 2}, {0, 2, 1}};
    mesh->order = {0, 1};
    mesh->activeEdges = {{true, true, false}, {false, true, true}};
    const Vec3 lower(-half, 0, -half), upper(half, 0, half);
    if (!twoLeaves) {
        mesh->nodes = {MeshNode{lower, upper, 0, 2}};
    } else {
        mesh->nodes = {MeshNode{lower, upper, 1, 0},   // inner: children 1 and 2
                       MeshNode{lower, upper, 0, 1},   // triangle 0: x ≤ z
                       MeshNode{lower, upper, 1, 1}};  // triangle 1: x ≥ z
    }
    return mesh;
}

/// @brief Two boxes of @p size side by side along x, touching at x = 0: together a 2s × s × s bar.
inline std::shared_ptr<const CompoundShape> twoBoxCompound(Real size = 1) {
    auto compound = std::make_shared<CompoundShape>();
    for (const Real side : {Real(-1), Real(1)}) {
        CompoundPart part;
        part.shape = Shape::Box;
        part.position = Vec3(side * size / 2, 0, 0);
        part.scale = Vec3(size);
        part.mass = 1;
        compound->parts.push_back(part);
    }
    compound->boundingRadius = glm::length(Vec3(size, size / 2, size / 2));
    return compound;
}

/// @brief A dynamic body of @p shape at @p position: radius, height, hull and compound as given.
inline DynamicObject shapedBody(const std::string& name, Shape shape, Vec3 position, Quat orientation = Quat(1, 0, 0, 0),
                                Real radius = Real(0.5), Real height = 1) {
    DynamicObject body;
    body.name = name;
    body.shape = shape;
    body.position = position;
    body.orientation = orientation;
    body.radius = radius;
    body.height = height;
    body.scale = Vec3(2 * radius);
    return body;
}

}  // namespace stepwise::test
