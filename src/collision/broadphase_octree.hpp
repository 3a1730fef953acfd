/// @file broadphase_octree.hpp
/// @brief Broadphase with a loose octree: each body filed at the depth its size fixes, in the cell of its centre.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "collision/broadphase_proxies.hpp"

namespace stepwise {

/// Deepest level of the octree (the root is level 0). A body smaller than the
/// cells of this level stays at this level with its neighbours: with a root
/// cube a hundred metres wide, cells of 100 m / 2²⁴ ≈ 6 µm, far below any body.
inline constexpr int kOctreeMaxDepth = 24;
/// A body stays in its node while the node's cell is less than this many times
/// its size (one level shallower than a fresh insertion would put it) and its box
/// stays inside the node's loose box. Without this slack, a falling body whose swept
/// box grows and shrinks around a power of two would change level every step.
inline constexpr Real kOctreeStayRatio = Real(4);
/// The root cube is the cube around every box, this many times as wide: bodies that
/// fall, spread or bounce away from where they started stay inside it for a while.
inline constexpr Real kOctreeRootPadding = Real(2);
/// When more than one body in this many sits in the root only because its centre left
/// the root cube, the root cube is fitted again and every body filed again.
inline constexpr std::uint32_t kOctreeRefitShare = 8;

/// @brief A loose octree (Ulrich, "Loose Octrees", Game Programming Gems 1, §4.11, 2000).
///
/// **The octree.** A cube around the scene (the root, level 0) is cut into 8
/// cubes of half its side (level 1), each of those into 8 (level 2), and so
/// on: the cell of level d has side \f$ L_d = W / 2^d \f$. Nodes exist only
/// where bodies are: a node with no body below it is given back.
///
/// **Why loose.** In a plain octree a body goes in the smallest cell that
/// holds all of it, so a small body lying across the centre plane of the
/// root (the floor of a pile is full of them) is stuck in the root, and is
/// tested against everything. A loose octree gives each cell a *loose box*:
/// the cell grown by half its side on every side, twice as wide
/// (looseness k = 2). A body of size s (its box's longest side) whose centre
/// lies in a cell of side L with s ≤ L always fits the cell's loose box: its
/// centre is inside the cell, and it reaches s/2 ≤ L/2 beyond the centre.
/// So where a body goes follows from two numbers, not a search:
///
/// - its depth: the deepest level whose cells are still as large as the body,
///   \f$ d = \lfloor \log_2 (W / s) \rfloor \f$, so \f$ s \le L_d < 2s \f$;
/// - its cell: the one that holds its centre, \f$ \lfloor (c - o) / L_d \rfloor \f$
///   on each axis (o: the root's lowest corner).
///
/// The insertion walks down from the root by the octant of the centre at each
/// level (d steps: O(1) for a given scene, with no splitting rule nor balance to
/// keep), and a body that does not fit a child's loose box (its centre outside
/// the root cube, or a rounding at a cell's edge) stays in the parent, so every
/// body's box lies inside the loose box of its node and of every ancestor.
///
/// **Queries.** A box Q can overlap a body only if it overlaps the loose box
/// of every node on the way to the body's node. So a query descends from the
/// root into the children whose loose boxes Q overlaps, and tests the exact
/// boxes of the bodies in each node it enters (query()). The price of the
/// looseness: a node's loose box is 8 times its cell's volume, so a query
/// meets more nodes than in a tight octree; a body costs one descent, never
/// more than the few cells its size allows.
///
/// **Pairs.** Found by descending pairs of subtrees, as the AABB tree descends
/// itself (Ericson, RTCD §6.5.1), never one body at a time from the root. The
/// pairs within the subtree of node X are those among X's own bodies, those
/// of X's own bodies with each child's subtree, those within each child's
/// subtree, and those between two children's subtrees; the pairs between two
/// subtrees X and Y apart in the tree are X's own bodies against Y, plus each
/// child of X against Y (X the shallower). Each pair of bodies falls in
/// exactly one of these, and two subtrees whose loose boxes are apart hold no
/// overlapping pair (every body lies in the loose box of its node and of its
/// ancestors), so such a pair of subtrees is dropped whole. A node's own bodies
/// against a subtree descend it one body at a time, pruned by each body's box.
/// Far parts of the scene are so dropped once, near the root, where a descent
/// per body would test their loose boxes again for every body.
///
/// **From step to step.** A body stays where it is while its box is still
/// inside its node's loose box and its node is not too coarse for it
/// (kOctreeStayRatio): the looseness lets it move up to a quarter of its cell's
/// side past the cell's edge before it changes node, and then it is removed and
/// inserted again (each O(d)). The loose boxes never change, so nothing is refitted.
///
/// **Memory.** The nodes live in one array and refer to each other by index;
/// the bodies of a node form a doubly linked list through per-body arrays, so
/// moving a body is O(1) at either end; freed nodes go on a free list that later
/// insertions reuse. A running octree allocates nothing.
class LooseOctree {
public:
    /// @brief Files the proxies of this step (only those that moved out of their node change node),
    /// then appends every overlapping pair of proxies (not kinematic–kinematic) to @p pairs.
    void findOverlaps(const ProxySet& proxies, std::vector<ProxyPair>& pairs, BroadphaseCounters& counters);

    /// @brief Appends to @p hits every proxy whose box in @p boxes overlaps @p box (Aabb::overlaps),
    /// in the tree's order; @p boxes must be the boxes of the last findOverlaps().
    void query(const Aabb& box, std::span<const Aabb> boxes, std::vector<std::uint32_t>& hits,
               BroadphaseCounters& counters) const;

    /// @brief Number of nodes in use (the root included); 0 before the first call.
    std::size_t nodeCount() const { return nodes_.size() - freeCount_; }
    /// @brief Deepest level that holds a body in the last call (0: every body in the root), −1 when empty.
    int depth() const;
    /// @brief Level of the node that holds proxy @p p.
    int levelOf(std::uint32_t p) const { return nodes_[nodeOf_[p]].level; }
    /// @brief Side W of the root cube, m (0 before the first call); the cells of level d have side W / 2^d.
    Real rootSide() const { return nodes_.empty() ? 0 : Real(2) * nodes_[0].half; }
    /// @brief How many times the root cube was fitted (the first call included).
    std::uint64_t fits() const { return fits_; }
    /// @brief Checks every invariant (for tests): each proxy of @p proxies is in the list of one node,
    /// and its box lies inside the loose box of that node and of every ancestor; every node's loose
    /// box lies at the octant of its parent the node is filed under; no node is empty below.
    bool isConsistent(const ProxySet& proxies) const;

private:
    static constexpr std::int32_t kNull = -1;  ///< "No node", "no proxy".

    /// One cell of the octree.
    struct Node {
        Aabb loose;                     ///< The cell grown by half its side on every side: where its bodies lie.
        Vec3 centre{0, 0, 0};           ///< Centre of the cell, m.
        Real half = 0;                  ///< Half the side of the cell, m (a quarter of the loose box's side).
        std::int32_t parent = kNull;    ///< Parent node, kNull for the root; next free node when free.
        std::int32_t child[8] = {kNull, kNull, kNull, kNull, kNull, kNull, kNull, kNull};  ///< By octant: bit 0 x, 1 y, 2 z.
        std::int32_t first = kNull;     ///< First proxy of the node's list.
        std::uint32_t below = 0;        ///< Proxies in this node and all below it.
        std::int32_t level = 0;         ///< 0 for the root; −1 when free.
    };

    void fitRoot(const ProxySet& proxies);
    std::int32_t allocateNode(std::int32_t parent, int octant);
    void insert(std::uint32_t p, const Aabb& box);
    void remove(std::uint32_t p);
    bool staysPut(std::uint32_t p, const Aabb& box) const;
    std::uint32_t strandedCount(const ProxySet& proxies) const;

    std::vector<Node> nodes_;               ///< Every node, in use or free; the root is node 0.
    std::int32_t freeList_ = kNull;         ///< First free node.
    std::size_t freeCount_ = 0;             ///< Nodes on the free list.
    std::vector<std::int32_t> nodeOf_;      ///< Node of each proxy.
    std::vector<std::int32_t> next_;        ///< Next proxy in the same node, kNull at the end.
    std::vector<std::int32_t> previous_;    ///< Previous proxy in the same node, kNull at the start.
    std::uint32_t dynamicCount_ = 0;        ///< dynamicCount of the proxies the tree was filed for.
    std::uint64_t fits_ = 0;
};

}  // namespace stepwise
