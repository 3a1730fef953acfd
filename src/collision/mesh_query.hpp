/// @file mesh_query.hpp
/// @brief The triangles of a mesh whose boxes overlap a given box: a descent of the mesh's box hierarchy.
///
/// A body on a terrain touches a handful of its thousands of triangles. The
/// mesh's hierarchy (TriangleMesh::nodes, built by buildTriangleMesh()) finds
/// them in about log₂ n box tests (Ericson, *Real-Time Collision Detection*,
/// §6.3.2 "descent rules"): start at the root; a node whose box misses the
/// query box is skipped with everything below it; an inner node's two
/// children are visited in turn; a leaf's triangles are checked one by one
/// against the query box (each triangle's own box, from its three corners).
///
/// **In the mesh's frame.** The hierarchy's boxes are in the mesh body's own
/// frame, and the mesh may be moved and turned (a kinematic object). The
/// query box is therefore taken into that frame (meshFrameBox()): a box
/// turned by R is held by the axis-aligned box of half widths |Rᵀ|·e about
/// its turned centre (the same rule as boxAabb(), Ericson §4.2.6). That box
/// is larger than the turned one when the turn is not a multiple of 90°,
/// which only means a few more triangles are handed to the exact test.
///
/// **No allocation.** The nodes still to visit live in a fixed stack of
/// kMeshQueryStack entries inside TrianglesInBox, and triangles come out one
/// at a time from next(), so a query in the step costs no memory at all.
/// A hierarchy too deep for the stack (a badly unbalanced one; a halving
/// build of a million triangles is about 20 deep) loses no triangle: the
/// subtree that does not fit is searched triangle by triangle instead. That
/// works because buildTriangleMesh() gives every node a contiguous run of
/// TriangleMesh::order (its first child the front of it, its second the
/// back), so a subtree's triangles run from its leftmost leaf's first to its
/// rightmost leaf's last.
#pragma once

#include <array>
#include <cstdint>

#include "collision/aabb.hpp"
#include "objects/shapes.hpp"

namespace stepwise {

/// Nodes TrianglesInBox keeps waiting: one per level of the hierarchy plus one (the sibling
/// of each node on the way down waits while the other is searched).
inline constexpr int kMeshQueryStack = 64;

/// @brief A box in the mesh body's frame that holds @p worldBox, for a mesh at @p meshCentre turned by @p meshOrientation.
///
/// With c and e the box's centre and half widths and R the mesh's rotation,
/// the box in the mesh frame is centred on Rᵀ(c − t) with half widths
/// |Rᵀ|·e (|·| element by element): exact when R turns the axes onto axes,
/// larger otherwise, never smaller.
Aabb meshFrameBox(const Aabb& worldBox, const Vec3& meshCentre, const Quat& meshOrientation);

/// @brief The triangles of @p mesh whose boxes overlap a box in the mesh's frame, one at a time.
///
/// ```cpp
/// for (TrianglesInBox query(mesh, box); query.next(triangle);) test(triangle);
/// ```
/// Each such triangle comes out exactly once, in the hierarchy's order. A
/// mesh without a hierarchy (no nodes) is searched triangle by triangle.
/// Node and triangle indices out of range (a hand-made mesh gone wrong) are
/// skipped, never followed.
class TrianglesInBox {
public:
    /// @brief Starts a query of @p mesh for @p box (mesh frame, meshFrameBox()). The mesh must outlive the query.
    TrianglesInBox(const TriangleMesh& mesh, const Aabb& box);

    /// @brief The next triangle whose box overlaps the query box, as its index in TriangleMesh::triangles.
    /// @return false when there is none left (@p triangle is then unchanged)
    bool next(std::uint32_t& triangle);

    /// @brief Nodes whose boxes were tested so far (for the tests and the lecture: about log₂ n per triangle found).
    int nodesVisited() const { return nodesVisited_; }

private:
    /// Does triangle @p index exist and overlap the query box?
    bool triangleOverlaps(std::uint32_t index) const;
    /// The run of TriangleMesh::order below node @p node: [first, end).
    void subtreeRun(std::uint32_t node, std::uint32_t& first, std::uint32_t& end) const;

    const TriangleMesh& mesh_;
    Aabb box_;
    std::array<std::uint32_t, kMeshQueryStack> stack_{};  ///< Nodes still to visit.
    int top_ = 0;                                         ///< How many of stack_ are waiting.
    std::uint32_t cursor_ = 0;   ///< Next entry of the run being read (of order, or of triangles when byIndex_).
    std::uint32_t end_ = 0;      ///< One past the run's last entry.
    bool byIndex_ = false;       ///< No hierarchy: the run is of triangle indices themselves.
    int nodesVisited_ = 0;
};

}  // namespace stepwise
