/// @file triangle_mesh.cpp
/// @brief Mesh checks, the top-down SAH build of the box hierarchy, and the active-edge flags.
#include "objects/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace stepwise {

namespace {

/// A triangle whose area is below this fraction of its longest edge squared has corners on
/// one line (or coinciding) up to round-off: its normal would be noise.
constexpr Real kDegenerateAreaFraction = Real(1e-12);

struct Box {
    Vec3 lower{std::numeric_limits<Real>::max()};
    Vec3 upper{std::numeric_limits<Real>::lowest()};
    void grow(const Vec3& p) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    void grow(const Box& b) {
        lower = glm::min(lower, b.lower);
        upper = glm::max(upper, b.upper);
    }
    /// Surface area 2(ab + bc + ca): proportional to the chance a random ray or box meets it.
    Real area() const {
        const Vec3 d = upper - lower;
        return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
};

void checkTriangles(const std::vector<Vec3>& vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles) {
    if (triangles.empty()) throw MeshError(MeshProblem::NoTriangles, "the mesh has no triangles");
    if (triangles.size() > kMaxMeshTriangles) {
        throw MeshError(MeshProblem::TooManyTriangles, "a mesh takes at most " + std::to_string(kMaxMeshTriangles) +
                                                           " triangles, got " + std::to_string(triangles.size()));
    }
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vec3& p = vertices[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw MeshError(MeshProblem::NotFinite,
                            "vertex " + std::to_string(i + 1) + " has a coordinate that is NaN or infinite");
        }
    }
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (const std::uint32_t index : triangles[t]) {
            if (index >= vertices.size()) {
                throw MeshError(MeshProblem::IndexOutOfRange,
                                "triangle " + std::to_string(t + 1) + " uses vertex " + std::to_string(index + 1) +
                                    ", but there are " + std::to_string(vertices.size()) + " vertices");
            }
        }
        const Vec3& a = vertices[triangles[t][0]];
        const Vec3& b = vertices[triangles[t][1]];
        const Vec3& c = vertices[triangles[t][2]];
        const Real twiceArea = glm::length(glm::cross(b - a, c - a));
        const Real longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
        if (!(twiceArea > 2 * kDegenerateAreaFraction * longest * longest)) {
            throw MeshError(MeshProblem::ZeroArea, "triangle " + std::to_string(t + 1) +
                                                       " has zero area (its corners coincide or lie on one line)");
        }
    }
}

/// The hierarchy, built top down from a stack of (node, range of `order`) still to split.
void buildHierarchy(TriangleMesh& mesh) {
    const std::size_t n = mesh.triangles.size();
    std::vector<Box> boxes(n);
    std::vector<Vec3> centres(n);
    for (std::size_t t = 0; t < n; ++t) {
        for (const std::uint32_t i : mesh.triangles[t]) boxes[t].grow(mesh.vertices[i]);
        centres[t] = (boxes[t].lower + boxes[t].upper) / Real(2);
    }
    mesh.order.resize(n);
    for (std::size_t t = 0; t < n; ++t) mesh.order[t] = std::uint32_t(t);
    mesh.nodes.assign(1, MeshNode{});

    struct Pending {
        std::size_t node;
        std::uint32_t begin;
        std::uint32_t end;
    };
    std::vector<Pending> stack{{0, 0, std::uint32_t(n)}};
    std::vector<Real> rightArea(n);  // scratch: area of the box of triangles [k, end) along the sweep
    while (!stack.empty()) {
        const Pending job = stack.back();
        stack.pop_back();
        Box bounds;
        for (std::uint32_t k = job.begin; k < job.end; ++k) bounds.grow(boxes[mesh.order[k]]);
        MeshNode& node = mesh.nodes[job.node];
        node.lower = bounds.lower;
        node.upper = bounds.upper;
        const std::uint32_t count = job.end - job.begin;
        if (count <= kMeshLeafSize) {
            node.first = job.begin;
            node.count = count;
            continue;
        }
        // Try every axis: sort the triangles by centre along it, sweep from both ends for
        // the boxes' areas, and keep the split of least cost A_left·n_left + A_right·n_right.
        Real bestCost = std::numeric_limits<Real>::max();
        int bestAxis = 0;
        std::uint32_t bestSplit = count / 2;
        const auto first = mesh.order.begin() + job.begin;
        const auto last = mesh.order.begin() + job.end;
        for (int axis = 0; axis < 3; ++axis) {
            std::stable_sort(first, last, [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; });
            Box right;
            for (std::uint32_t k = count; k-- > 0;) {
                right.grow(boxes[mesh.order[job.begin + k]]);
                rightArea[k] = right.area();
            }
            Box left;
            for (std::uint32_t k = 1; k < count; ++k) {  // left: [0, k), right: [k, count)
                left.grow(boxes[mesh.order[job.begin + k - 1]]);
                const Real cost = left.area() * Real(k) + rightArea[k] * Real(count - k);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestSplit = k;
                }
            }
        }
        std::stable_sort(first, last,
                         [&](std::uint32_t a, std::uint32_t b) { return centres[a][bestAxis] < centres[b][bestAxis]; });
        const std::size_t children = mesh.nodes.size();
        mesh.nodes[job.node].first = std::uint32_t(children);  // `node` may dangle after the push_backs
        mesh.nodes[job.node].count = 0;
        mesh.nodes.push_back(MeshNode{});
        mesh.nodes.push_back(MeshNode{});
        stack.push_back({children, job.begin, job.begin + bestSplit});
        stack.push_back({children + 1, job.begin + bestSplit, job.end});
    }
}

Vec3 unitNormal(const TriangleMesh& mesh, const std::array<std::uint32_t, 3>& t) {
    const Vec3& a = mesh.vertices[t[0]];
    return glm::normalize(glm::cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a));
}

/// Marks each edge shared by two triangles in a flat or concave fold inactive.
///
/// Triangles t and u share the edge a→b (u runs it b→a when both wind the same way).
/// The fold is convex, a ridge, when u's third corner lies below t's plane:
/// dot(n_t, c_u − a) < 0. It is flat when the normals differ by less than
/// kFlatFoldDegrees: dot(n_t, n_u) > cos(kFlatFoldDegrees).
void markActiveEdges(TriangleMesh& mesh) {
    const std::size_t n = mesh.triangles.size();
    mesh.activeEdges.assign(n, {true, true, true});
    // Undirected edge (smaller vertex, larger) → the (triangle, edge) pairs that use it.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::pair<std::uint32_t, int>>> users;
    for (std::uint32_t t = 0; t < n; ++t) {
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = mesh.triangles[t][std::size_t(e)];
            const std::uint32_t b = mesh.triangles[t][std::size_t((e + 1) % 3)];
            users[{std::min(a, b), std::max(a, b)}].emplace_back(t, e);
        }
    }
    const Real flatCosine = std::cos(glm::radians(Real(kFlatFoldDegrees)));
    for (const auto& [edge, list] : users) {
        // An edge on the mesh's border, or one where three or more triangles meet: keep it
        // active, the safe choice (a push along it is then a real possibility).
        if (list.size() != 2) continue;
        const auto [t, e] = list[0];
        const auto [u, f] = list[1];
        const auto& tt = mesh.triangles[t];
        const auto& uu = mesh.triangles[u];
        // Opposite windings along the shared edge mean both normals face the same side.
        const bool consistent = tt[std::size_t(e)] == uu[std::size_t((f + 1) % 3)];
        if (!consistent) continue;
        const Vec3 nt = unitNormal(mesh, tt);
        const Vec3 nu = unitNormal(mesh, uu);
        const Vec3& onEdge = mesh.vertices[tt[std::size_t(e)]];
        const Vec3& uThird = mesh.vertices[uu[std::size_t((f + 2) % 3)]];
        const bool flat = glm::dot(nt, nu) > flatCosine;
        const bool convex = glm::dot(nt, uThird - onEdge) < 0;
        if (flat || !convex) {
            mesh.activeEdges[t][std::size_t(e)] = false;
            mesh.activeEdges[u][std::size_t(f)] = false;
        }
    }
}

}  // namespace

TriangleMesh buildTriangleMesh(std::vector<Vec3> vertices, std::vector<std::array<std::uint32_t, 3>> triangles) {
    checkTriangles(vertices, triangles);
    TriangleMesh mesh;
    mesh.vertices = std::move(vertices);
    mesh.triangles = std::move(triangles);
    buildHierarchy(mesh);
    markActiveEdges(mesh);
    return mesh;
}

}  // namespace stepwise
