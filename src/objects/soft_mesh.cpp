/// @file soft_mesh.cpp
/// @brief The icosphere, the subdivided cube, their edges, and a soft body built on them.
#include "objects/soft_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace stepwise {

namespace {

/// The key of the edge between nodes @p a and @p b, the same whichever way it is walked.
std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    const std::uint64_t low = std::min(a, b);
    const std::uint64_t high = std::max(a, b);
    return (high << 32) | low;
}

/// Turns every triangle of a convex mesh about the origin so that (b − a) × (c − a) points away
/// from the origin: outward. The icosahedron's faces are found as point triples, in no order.
void windOutward(SurfaceMesh& mesh) {
    for (SoftFace& face : mesh.faces) {
        const Vec3& a = mesh.points[face.a];
        const Vec3& b = mesh.points[face.b];
        const Vec3& c = mesh.points[face.c];
        if (glm::dot(glm::cross(b - a, c - a), a + b + c) < 0) std::swap(face.b, face.c);
    }
}

/// The regular icosahedron with edge length 2: its 12 vertices are the cyclic permutations of
/// (0, ±1, ±φ), φ = (1 + √5)/2, and its 20 faces are the triples of vertices 2 apart from each other.
SurfaceMesh icosahedron() {
    const Real phi = (1 + std::sqrt(Real(5))) / 2;
    SurfaceMesh mesh;
    for (const Real s : {Real(-1), Real(1)}) {
        for (const Real t : {-phi, phi}) {
            mesh.points.emplace_back(0, s, t);
            mesh.points.emplace_back(s, t, 0);
            mesh.points.emplace_back(t, 0, s);
        }
    }
    const auto adjacent = [&](std::size_t i, std::size_t j) {
        return std::abs(glm::length(mesh.points[i] - mesh.points[j]) - 2) < Real(1e-9);
    };
    const std::uint32_t n = static_cast<std::uint32_t>(mesh.points.size());
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = i + 1; j < n; ++j) {
            for (std::uint32_t k = j + 1; k < n; ++k) {
                if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k)) mesh.faces.push_back({i, j, k});
            }
        }
    }
    windOutward(mesh);
    return mesh;
}

/// Cuts every triangle into four by its edges' midpoints (shared between the two triangles of an
/// edge), keeping the winding: (a, b, c) → (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca).
void subdivide(SurfaceMesh& mesh) {
    std::map<std::uint64_t, std::uint32_t> midpoints;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        const auto [at, inserted] = midpoints.try_emplace(edgeKey(a, b), static_cast<std::uint32_t>(mesh.points.size()));
        if (inserted) mesh.points.push_back(Real(0.5) * (mesh.points[a] + mesh.points[b]));
        return at->second;
    };
    std::vector<SoftFace> faces;
    faces.reserve(4 * mesh.faces.size());
    for (const SoftFace& f : mesh.faces) {
        const std::uint32_t ab = midpoint(f.a, f.b);
        const std::uint32_t bc = midpoint(f.b, f.c);
        const std::uint32_t ca = midpoint(f.c, f.a);
        faces.push_back({f.a, ab, ca});
        faces.push_back({ab, f.b, bc});
        faces.push_back({ca, bc, f.c});
        faces.push_back({ab, bc, ca});
    }
    mesh.faces = std::move(faces);
}

}  // namespace

SurfaceMesh makeIcosphere(int subdivisions) {
    if (subdivisions < 0 || subdivisions > kMaxIcosphereSubdivisions) {
        throw std::invalid_argument("icosphere subdivisions must be from 0 to " + std::to_string(kMaxIcosphereSubdivisions));
    }
    SurfaceMesh mesh = icosahedron();
    for (int i = 0; i < subdivisions; ++i) subdivide(mesh);
    for (Vec3& p : mesh.points) p = glm::normalize(p);  // onto the unit sphere: a projection keeps the winding
    return mesh;
}

SurfaceMesh makeSubdividedCube(int cells) {
    if (cells < 1 || cells > kMaxCubeCells) {
        throw std::invalid_argument("cube cells must be from 1 to " + std::to_string(kMaxCubeCells));
    }
    // The surface nodes of the (n + 1)³ grid, numbered once each: a corner or edge node is shared
    // by the faces that meet there, which is what makes the surface closed.
    const int n = cells;
    const int side = n + 1;
    std::vector<std::int64_t> index(static_cast<std::size_t>(side * side * side), -1);
    const auto at = [&](int i, int j, int k) -> std::int64_t& {
        return index[static_cast<std::size_t>((i * side + j) * side + k)];
    };
    SurfaceMesh mesh;
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            for (int k = 0; k <= n; ++k) {
                const bool onSurface = i == 0 || i == n || j == 0 || j == n || k == 0 || k == n;
                if (!onSurface) continue;
                at(i, j, k) = static_cast<std::int64_t>(mesh.points.size());
                const auto coordinate = [&](int g) { return Real(-1) + Real(2) * Real(g) / Real(n); };
                mesh.points.emplace_back(coordinate(i), coordinate(j), coordinate(k));
            }
        }
    }
    // Face a = s of the cube (axis a, s = 0 or n), with u, v the next two axes in cyclic order, so
    // that e_u × e_v = e_a: a square (p, q) → (p + 1, q + 1) is wound outward as (00, 10, 11), (00, 11, 01)
    // on the positive side, and the other way round on the negative side.
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3;
        const int v = (axis + 2) % 3;
        for (const int s : {0, n}) {
            const auto node = [&](int p, int q) {
                int g[3];
                g[axis] = s;
                g[u] = p;
                g[v] = q;
                return static_cast<std::uint32_t>(at(g[0], g[1], g[2]));
            };
            for (int p = 0; p < n; ++p) {
                for (int q = 0; q < n; ++q) {
                    const std::uint32_t q00 = node(p, q), q10 = node(p + 1, q), q11 = node(p + 1, q + 1),
                                        q01 = node(p, q + 1);
                    if (s == n) {
                        mesh.faces.push_back({q00, q10, q11});
                        mesh.faces.push_back({q00, q11, q01});
                    } else {
                        mesh.faces.push_back({q00, q11, q10});
                        mesh.faces.push_back({q00, q01, q11});
                    }
                }
            }
        }
    }
    return mesh;
}

std::vector<MeshEdge> meshEdges(std::span<const SoftFace> faces) {
    // Each triangle's three directed edges with the corner facing them, sorted so that the uses of
    // one edge lie side by side.
    struct Use {
        std::uint64_t key;
        std::uint32_t from, to, opposite;
    };
    std::vector<Use> uses;
    uses.reserve(3 * faces.size());
    for (const SoftFace& f : faces) {
        uses.push_back({edgeKey(f.a, f.b), f.a, f.b, f.c});
        uses.push_back({edgeKey(f.b, f.c), f.b, f.c, f.a});
        uses.push_back({edgeKey(f.c, f.a), f.c, f.a, f.b});
    }
    std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) { return x.key < y.key; });
    std::vector<MeshEdge> edges;
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i;
        MeshEdge edge;
        edge.a = std::min(uses[i].from, uses[i].to);
        edge.b = std::max(uses[i].from, uses[i].to);
        int forward = 0;  // uses from a to b, less those from b to a: 0 when they pair up
        for (; j < uses.size() && uses[j].key == uses[i].key; ++j) {
            if (edge.faceCount < 2) edge.opposite[edge.faceCount] = uses[j].opposite;
            ++edge.faceCount;
            forward += uses[j].from == edge.a ? 1 : -1;
        }
        edge.consistent = forward == 0;
        edges.push_back(edge);
        i = j;
    }
    return edges;
}

void buildSoftBody(const SoftBodyMaking& making, SoftBody& body) {
    SurfaceMesh mesh = making.shape == Shape::Box ? makeSubdividedCube(making.resolution) : makeIcosphere(making.resolution);
    const Vec3 size = making.shape == Shape::Box ? making.halfExtents : Vec3(making.radius);
    const std::size_t n = mesh.points.size();
    body.shape = making.shape;
    body.resolution = making.resolution;
    body.mass = making.mass;
    body.nRT = making.nRT;
    body.nodePositions.resize(n);
    body.nodeVelocities.resize(n);
    body.nodeForces.assign(n, Vec3(0));
    body.nodeInverseMasses.assign(n, Real(n) / making.mass);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 r = mesh.points[i] * size;  // from the centre, m
        body.nodePositions[i] = making.position + r;
        body.nodeVelocities[i] = making.velocity + glm::cross(making.angularVelocity, r);
    }
    body.faces = std::move(mesh.faces);

    const std::vector<MeshEdge> edges = meshEdges(body.faces);
    const auto length = [&](std::uint32_t a, std::uint32_t b) {
        return glm::length(body.nodePositions[b] - body.nodePositions[a]);
    };
    body.springs.clear();
    Real edgeLengths = 0;
    for (const MeshEdge& e : edges) {
        body.springs.push_back({e.a, e.b, length(e.a, e.b), making.stiffness, making.damping});
        edgeLengths += length(e.a, e.b);
    }
    body.edgeSprings = static_cast<std::uint32_t>(body.springs.size());
    if (making.bendStiffness > 0) {
        for (const MeshEdge& e : edges) {
            const std::uint32_t c = e.opposite[0], d = e.opposite[1];
            body.springs.push_back({c, d, length(c, d), making.bendStiffness, making.damping});
        }
    }
    body.nodeRadius = kNodeRadiusPerEdge * edgeLengths / Real(edges.size());

    // Every mesh is symmetric about its centre and the masses are equal: the centre of mass is
    // the centre, and ω × r averages to zero, so the centre moves at v.
    body.position = making.position;
    body.velocity = making.velocity;
    body.orientation = Quat(1, 0, 0, 0);
}

}  // namespace stepwise
