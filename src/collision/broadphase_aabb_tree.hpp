/// @file broadphase_aabb_tree.hpp
/// @brief Broadphase with a dynamic bounding-volume tree of fattened boxes.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "collision/broadphase_proxies.hpp"

namespace stepwise {

/// @brief A dynamic AABB tree (Goldsmith and Salmon 1987; Catto, "Dynamic BVH", GDC 2019; Ericson, RTCD §6.5).
///
/// A binary tree whose leaves are the proxies and whose every internal node
/// holds a box around its two children. Two nodes whose boxes are apart
/// cannot hold an overlapping pair of leaves, so the pairs are found by
/// descending the tree against itself, dropping every pair of subtrees that
/// are apart (findOverlappingLeaves()).
///
/// **Fat boxes.** A leaf stores its proxy's box grown by a margin, a fraction
/// kTreeMarginFraction of its size. A body that stays inside its fat box is
/// not touched: resting and slow bodies stay where they are in the tree for
/// many steps. Only a body that leaves its fat box (or whose fat box has
/// become much larger than it needs) is removed and inserted again.
///
/// **Insertion by the surface-area heuristic.** The expected cost of a query
/// grows with the sum of the internal nodes' surface areas (the chance that a
/// random box overlaps a node grows with its area), so a new leaf goes where
/// it adds the least area: descending from the root, at node N it compares
///
///   - making a new parent of N and the leaf L: new area SA(N ∪ L);
///   - going on into child C: N grows by SA(N ∪ L) − SA(N), and then at least
///     SA(C ∪ L) (C a leaf: a new parent there) or SA(C ∪ L) − SA(C) (C grows),
///
/// and stops where making the parent is cheapest. (The ancestors of N grow in
/// every case alike, so they do not enter the comparison.)
///
/// **Rotations.** This greedy descent decides with what it sees at each level
/// and can leave a poor tree behind, above all when bodies arrive in an
/// orderly sequence (a lattice, row by row). So on the way back up, each node
/// A tries swapping one of its children with a grandchild under its other
/// child (Kopta et al. 2012, "Fast, effective BVH updates for animated
/// scenes"): the leaves below A stay the same, only the child that changes
/// changes its box, and the swap is made when that box's area shrinks. In
/// the sphere rain of 16 384 bodies (docs/broadphase.md) they cut the node
/// tests by a third and the height from 105 to 21 (log₂ n = 14); unlike an
/// AVL tree's, though, the height has no guaranteed bound.
///
/// **Memory.** All nodes live in one array and refer to each other by index;
/// removed nodes go on a free list that later insertions take from, so a
/// running tree allocates nothing.
class AabbTree {
public:
    /// @brief Updates the tree to this step's boxes, then appends every
    /// overlapping pair of proxies (not kinematic–kinematic) to @p pairs.
    void findOverlaps(const ProxySet& proxies, std::vector<ProxyPair>& pairs, BroadphaseCounters& counters);

    /// @brief Appends to @p hits every proxy whose box in @p boxes overlaps @p box, in the tree's order.
    ///
    /// Descends from the root into every node whose box overlaps @p box (a
    /// leaf's fat box holds its proxy's box, an inner node's both children),
    /// and tests the proxies' own boxes at the leaves. Without a stack: from a
    /// node it goes down to its first child, and when a subtree is done it
    /// climbs the parent links to the first ancestor whose second child is
    /// still to visit. @p boxes must be the boxes of the last findOverlaps().
    void query(const Aabb& box, std::span<const Aabb> boxes, std::vector<std::uint32_t>& hits,
               BroadphaseCounters& counters) const;

    /// @brief Height of the tree: 0 for a single leaf, −1 when empty.
    int height() const;

    /// @brief Checks every invariant (for tests): parent and child links agree,
    /// each node's box holds its children's, heights are right, and every
    /// proxy of @p proxies has one leaf whose fat box holds its box.
    bool isConsistent(const ProxySet& proxies) const;

private:
    static constexpr std::int32_t kNull = -1;  ///< "No node".

    /// One node. A leaf has child1 == kNull; a free node has height −1 and
    /// `parent` holds the next free node.
    struct Node {
        Aabb box;                     ///< Fat box (leaf) or the box around both children (internal node).
        std::int32_t parent = kNull;  ///< Parent node, kNull for the root; next free node when free.
        std::int32_t child1 = kNull;  ///< First child, kNull for a leaf.
        std::int32_t child2 = kNull;  ///< Second child, kNull for a leaf.
        std::int32_t height = 0;      ///< 0 for a leaf, 1 + the taller child's for an internal node, −1 when free.
        std::uint32_t proxy = 0;      ///< The proxy of a leaf.
        bool isLeaf() const { return child1 == kNull; }
    };

    void rebuild(const ProxySet& proxies);
    void findOverlappingLeaves(const ProxySet& proxies, std::vector<ProxyPair>& pairs, BroadphaseCounters& counters);
    static Aabb fatBox(const Aabb& tight);
    std::int32_t allocateNode();
    void freeNode(std::int32_t node);
    void insertLeaf(std::int32_t leaf);
    void removeLeaf(std::int32_t leaf);
    void refitUpwards(std::int32_t node);
    void rotate(std::int32_t node);

    std::vector<Node> nodes_;                ///< Every node, in use or free.
    std::int32_t root_ = kNull;              ///< Root node, kNull when empty.
    std::int32_t freeList_ = kNull;          ///< First free node, kNull when none.
    std::vector<std::int32_t> leafOfProxy_;  ///< The leaf of each proxy.
    std::vector<std::pair<std::int32_t, std::int32_t>> stack_;  ///< Node pairs still to visit, kept to avoid allocating.
    std::uint32_t dynamicCount_ = 0;         ///< dynamicCount of the proxies the tree was built for.
};

/// Margin of a fat box on every side, as a fraction of the body's longest
/// box side. Resting bodies jiggle by micrometres as contacts settle; a
/// margin of a tenth of their size absorbs that for good. Larger margins
/// spare falling bodies a few reinsertions but make every query meet more
/// fat boxes; in the sphere rain 0.1 beat 0.05 and 0.2, and stretching the
/// box along the body's velocity (as Box2D does) cost more than it saved.
inline constexpr Real kTreeMarginFraction = Real(0.1);
/// A leaf whose fat box no longer fits in its body's box grown by this many
/// margins is reinserted with a fresh fat box: a box that was fitted to a
/// body rotated another way, long ago, must not stay loose for ever.
inline constexpr Real kTreeLooseMargins = Real(4);

}  // namespace stepwise
