/// @file soft_mesh.hpp
/// @brief The surfaces soft bodies are made of: an icosphere and a subdivided cube, closed and wound outward.
///
/// Both meshes are *watertight*: every edge is shared by exactly two
/// triangles, which run along it in opposite directions. That is what the
/// pressure model needs: the divergence theorem gives the enclosed volume
/// only for a closed surface, and only an outward winding makes it
/// positive. A closed surface of genus 0 also has Euler characteristic
/// V − E + F = 2, a quick check that no node is doubled.
///
/// | shape | made by | nodes V | edges E | faces F |
/// |---|---|---|---|---|
/// | `Sphere`, subdivisions s | the 20 triangles of an icosahedron, each cut into 4 s times, every new node pushed out onto the sphere | 10·4ˢ + 2 | 30·4ˢ | 20·4ˢ |
/// | `Box`, n cells per edge | each face of the cube cut into n × n squares, each square into 2 triangles; corner and edge nodes shared | 6n² + 2 | 18n² | 12n² |
///
/// The icosphere's triangles are nearly equal (its springs nearly the same
/// length), with no pole where many springs meet, as a latitude–longitude
/// sphere has.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/types.hpp"
#include "objects/soft_body.hpp"

namespace stepwise {

/// Most icosphere subdivisions a scene may ask for: 5 gives 10 242 nodes.
inline constexpr int kMaxIcosphereSubdivisions = 5;
/// Most cells along a cube's edge a scene may ask for: 32 gives 6 146 nodes.
inline constexpr int kMaxCubeCells = 32;
/// A node collides as a sphere of this fraction of the mean edge length: big enough that a rigid
/// edge or corner is caught before it slips between two nodes' spheres, small enough that the
/// ball rests visibly on its surface (the gap to a floor is the node radius).
inline constexpr Real kNodeRadiusPerEdge = Real(0.2);

/// @brief A closed triangle mesh: points and outward-wound triangles.
struct SurfaceMesh {
    std::vector<Vec3> points;      ///< Vertices.
    std::vector<SoftFace> faces;   ///< Triangles, counter-clockwise seen from outside.
};

/// @brief The icosphere of radius 1 about the origin after @p subdivisions (0 to kMaxIcosphereSubdivisions).
SurfaceMesh makeIcosphere(int subdivisions);

/// @brief The surface of the cube [−1, 1]³ with @p cells squares along each edge (1 to kMaxCubeCells).
SurfaceMesh makeSubdividedCube(int cells);

/// @brief One edge of a mesh, with the two triangles that share it.
struct MeshEdge {
    std::uint32_t a = 0;              ///< Smaller node index.
    std::uint32_t b = 0;              ///< Larger node index.
    std::uint32_t opposite[2] = {0, 0};  ///< The corner facing the edge in each of its triangles (the first two found).
    int faceCount = 0;                ///< How many triangles use it: 2 on a closed surface.
    bool consistent = true;           ///< Its triangles run along it in opposite directions (a consistent winding).
};

/// @brief Every edge of @p faces once, sorted by (a, b).
std::vector<MeshEdge> meshEdges(std::span<const SoftFace> faces);

/// @brief Everything a SoftBody record asks for, in SI units.
struct SoftBodyMaking {
    Shape shape = Shape::Sphere;     ///< Sphere or Box.
    int resolution = 2;              ///< Icosphere subdivisions, or cells along a cube's edge.
    Vec3 position{0, 0, 0};          ///< Centre, m.
    Vec3 velocity{0, 0, 0};          ///< Velocity of every node at the start, m/s.
    Vec3 angularVelocity{0, 0, 0};   ///< Spin about the centre, rad/s: node i starts at v + ω × r_i.
    Real radius = Real(0.5);         ///< Sphere: radius, m.
    Vec3 halfExtents{0.5, 0.5, 0.5}; ///< Box: half edge lengths, m.
    Real mass = 1;                   ///< Total, kg, spread evenly over the nodes.
    Real stiffness = 0;              ///< Edge springs' k, N/m.
    Real damping = 0;                ///< Every spring's c, N·s/m.
    Real bendStiffness = 0;          ///< Bending springs' k, N/m (0: none).
    Real nRT = 0;                    ///< The gas's n·R·T, J.
};

/// @brief Builds @p body's nodes, springs and faces from @p making (its name, colour and
/// materials are the caller's). Each spring starts at its rest length, so the body starts
/// without tension and the gas inflates it from there.
///
/// The edge springs run along every mesh edge. A bending spring joins the two corners that
/// face an edge across its two triangles: it resists folding the surface along that edge,
/// which the edge springs alone do not (a hinge of two triangles folds freely).
void buildSoftBody(const SoftBodyMaking& making, SoftBody& body);

}  // namespace stepwise
