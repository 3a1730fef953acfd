/// @file convex_fixtures.hpp
/// @brief Small convex hulls built by hand (a tetrahedron; the cube is shape_fixtures.hpp's) and geometry makers for the convex tests.
///
/// The hull builder of the scene loader comes from another stage; these
/// hulls are written out vertex by vertex and face by face, so a test of
/// GJK, EPA or the manifolds depends on nothing but the data it states.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "collision/narrowphase.hpp"
#include "objects/shapes.hpp"
#include "shape_fixtures.hpp"

namespace stepwise::test {

/// A hull from its vertices and its faces' vertex loops (any winding: each
/// loop is turned counter-clockwise seen from outside, the centroid of the
/// vertices taken as inside).
inline std::shared_ptr<ConvexHull> hullOf(const std::vector<Vec3>& vertices,
                                          const std::vector<std::vector<std::uint32_t>>& loops) {
    auto hull = std::make_shared<ConvexHull>();
    hull->vertices = vertices;
    Vec3 centroid(0);
    for (const Vec3& v : vertices) centroid += v;
    centroid /= Real(vertices.size());
    for (std::vector<std::uint32_t> loop : loops) {
        Vec3 n = glm::cross(vertices[loop[1]] - vertices[loop[0]], vertices[loop[2]] - vertices[loop[0]]);
        if (glm::dot(n, vertices[loop[0]] - centroid) < 0) {
            std::reverse(loop.begin(), loop.end());
            n = -n;
        }
        HullFace face;
        face.normal = glm::normalize(n);
        face.offset = glm::dot(face.normal, vertices[loop[0]]);
        face.firstIndex = static_cast<std::uint32_t>(hull->faceIndices.size());
        face.indexCount = static_cast<std::uint32_t>(loop.size());
        hull->faces.push_back(face);
        for (std::size_t i = 0; i < loop.size(); ++i) {
            hull->faceIndices.push_back(loop[i]);
            std::array<std::uint32_t, 2> edge{loop[i], loop[(i + 1) % loop.size()]};
            if (edge[0] > edge[1]) std::swap(edge[0], edge[1]);
            if (std::find(hull->edges.begin(), hull->edges.end(), edge) == hull->edges.end()) hull->edges.push_back(edge);
        }
    }
    for (const Vec3& v : vertices) hull->boundingRadius = std::max(hull->boundingRadius, glm::length(v));
    return hull;
}

// A cube: cubeHull() of shape_fixtures.hpp, the one written out face by face.

/// The tetrahedron with corners (0,0,0), (s,0,0), (0,s,0), (0,0,s), moved so its centroid is the origin.
inline std::shared_ptr<ConvexHull> tetrahedronHull(Real s) {
    const Vec3 centroid(s / 4, s / 4, s / 4);
    std::vector<Vec3> v = {Vec3(0) - centroid, Vec3(s, 0, 0) - centroid, Vec3(0, s, 0) - centroid, Vec3(0, 0, s) - centroid};
    auto hull = hullOf(v, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}});
    hull->volume = s * s * s / 6;
    return hull;
}

inline Geometry sphereAt(const Vec3& centre, Real radius) {
    Geometry g;
    g.type = GeometryType::Sphere;
    g.centre = centre;
    g.radius = radius;
    return g;
}

inline Geometry boxAt(const Vec3& centre, const Vec3& halfExtents, const Quat& orientation = Quat(1, 0, 0, 0)) {
    Geometry g;
    g.type = GeometryType::Box;
    g.centre = centre;
    g.halfExtents = halfExtents;
    g.orientation = orientation;
    return g;
}

/// A capsule or cylinder along its local y axis.
inline Geometry roundAt(GeometryType type, const Vec3& centre, Real radius, Real halfHeight,
                        const Quat& orientation = Quat(1, 0, 0, 0)) {
    Geometry g;
    g.type = type;
    g.centre = centre;
    g.radius = radius;
    g.halfHeight = halfHeight;
    g.orientation = orientation;
    return g;
}

inline Geometry hullAt(const ConvexHull& hull, const Vec3& centre, const Quat& orientation = Quat(1, 0, 0, 0)) {
    Geometry g;
    g.type = GeometryType::Hull;
    g.centre = centre;
    g.orientation = orientation;
    g.hull = &hull;
    return g;
}

inline Geometry planeAt(const Vec3& point, const Vec3& normal) {
    Geometry g;
    g.type = GeometryType::Plane;
    g.centre = point;
    g.normal = normal;
    return g;
}

}  // namespace stepwise::test
