/// @file triangle_mesh.hpp
/// @brief A static triangle mesh: its checks, its box hierarchy (SAH), and which edges may push.
///
/// Level geometry (a ramp, a terrain) is a list of triangles. Two things
/// make it usable by the collision stages, and both are built once, here:
///
/// **A bounding-volume hierarchy.** A body touches a handful of a mesh's
/// thousands of triangles; a tree of boxes finds them in O(log n). The tree
/// is built top down: each node's triangles are split in two where the
/// *surface-area heuristic* says a ray or a box is least likely to have to
/// visit both halves (MacDonald and Booth, 1990; Ericson, *Real-Time Collision
/// Detection*, §6.2): the expected cost of a split is proportional to
/// \f[ C = A_\text{left}\,n_\text{left} + A_\text{right}\,n_\text{right}, \f]
/// with A the surface area of each half's box and n its number of triangles.
/// A node of at most kMeshLeafSize triangles is a leaf.
///
/// **Active edges.** A ball rolling across a flat floor of many triangles
/// meets the edges between them. Tested against one triangle alone, a point
/// near such an edge may be pushed out *sideways*, along the edge's outward
/// direction, and the ball snags on a floor that is perfectly flat. An edge
/// shared with a neighbour in a flat or concave fold can never be the place
/// a body should be pushed off, so it is marked inactive: the contact stage
/// then uses the triangle's face normal there instead. Only a convex fold
/// sharper than kFlatFoldDegrees, or an edge with no neighbour, stays active.
/// (The same no-snagging rule as Box2D's chain shapes and Jolt's "active
/// edges", written here from the geometry.)
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

#include "objects/shapes.hpp"

namespace stepwise {

/// @brief Most triangles a leaf of the hierarchy holds.
inline constexpr std::uint32_t kMeshLeafSize = 4;

/// @brief Folds flatter than this (the angle between the two triangles' normals, degrees)
/// count as flat: their shared edge is inactive. A smooth surface exported from a modelling
/// tool folds by a few degrees per triangle; a push along such an edge would only snag.
inline constexpr double kFlatFoldDegrees = 5;

/// @brief Most triangles buildTriangleMesh() accepts (a level, not a film set).
inline constexpr std::size_t kMaxMeshTriangles = 1000000;

/// @brief Why a list of triangles is not a usable mesh.
enum class MeshProblem : std::uint8_t {
    NoTriangles,      ///< Nothing to collide with.
    TooManyTriangles, ///< More than kMaxMeshTriangles.
    IndexOutOfRange,  ///< A triangle names a vertex that does not exist.
    NotFinite,        ///< A vertex coordinate is NaN or infinite.
    ZeroArea,         ///< A triangle's corners coincide or lie on one line: it has no normal.
};

/// @brief Thrown by buildTriangleMesh(); the scene loader turns it into file:line:column.
class MeshError : public std::runtime_error {
public:
    /// @brief An error of kind @p problem, with @p what saying it in words.
    MeshError(MeshProblem problem, const std::string& what) : std::runtime_error(what), problem_(problem) {}
    /// @brief Which way the mesh failed.
    MeshProblem problem() const { return problem_; }

private:
    MeshProblem problem_;
};

/// @brief Checks @p triangles over @p vertices and builds the hierarchy and the active edges.
///
/// Triangles are counter-clockwise seen from the side a body should stay on
/// (the outward side of a solid; the top of a floor).
/// @throws MeshError when there are no triangles, too many, a bad index, a
///         non-finite vertex, or a triangle of zero area (each named by its number, from 1).
TriangleMesh buildTriangleMesh(std::vector<Vec3> vertices, std::vector<std::array<std::uint32_t, 3>> triangles);

}  // namespace stepwise
