/// @file broadphase_static.hpp
/// @brief The kinematic bodies' own broadphase structure: a tree built once, queried by the dynamic bodies.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "collision/aabb.hpp"
#include "collision/broadphase_proxies.hpp"

namespace stepwise {

/// Most kinematic bodies in one leaf of the static tree. Below about this
/// many, testing every box of a leaf costs less than descending one more
/// level (each level is a box test too, and a branch the processor may guess
/// wrong); a level of five static boxes is then a root and two leaves.
inline constexpr std::uint32_t kStaticLeafSize = 4;

/// @brief The kinematic bodies (floors, walls, a level of static boxes) in a tree of their own.
///
/// A kinematic body is never pushed: no contact or joint moves it, so two of
/// them never make a pair, and one at rest (KinematicsObject::atRest()) keeps
/// its bounding box step after step. So they are kept apart from the dynamic
/// bodies' structure (sweep and prune, tree or grid), which then sees only
/// the bodies that move. Each dynamic body asks this tree for the kinematic
/// bodies its box overlaps, as it asks each plane whether its box touches it:
/// static geometry costs a query per body, like a plane, and is never
/// re-inserted or tested against other static geometry.
///
/// **The tree.** Built top down (Ericson, RTCD §6.2.1): a node's bodies are
/// split in two halves at the median of their box centres along the longest
/// side of the node's box, until at most kStaticLeafSize remain in a leaf.
/// The nodes sit in one array, each node's left child right after it (a
/// pre-order layout), so a query walks the array mostly forward. The tree is
/// balanced, ⌈log₂(k / kStaticLeafSize)⌉ levels for k bodies.
///
/// **When it is rebuilt.** update() compares each kinematic body's box with
/// the one it was built from: while every body is at rest, nothing changes
/// and nothing is rebuilt; a step in which one moved rebuilds the tree,
/// O(k log k). Rebuilding reuses the arrays, so it allocates nothing once
/// they have grown to the scene's size.
class StaticTree {
public:
    /// @brief Brings the tree up to date with the kinematic bodies' boxes @p boxes (one per body, in order);
    /// rebuilds it only if a box differs from the one it was built from.
    /// @return true if it was rebuilt
    bool update(std::span<const Aabb> boxes);

    /// @brief Appends to @p hits the index of every kinematic body whose box overlaps @p box
    /// (Aabb::overlaps, the test brute force makes), in increasing order.
    void query(const Aabb& box, std::vector<std::uint32_t>& hits, BroadphaseCounters& counters) const;

    /// @brief Number of kinematic bodies in the tree.
    std::uint32_t size() const { return static_cast<std::uint32_t>(boxes_.size()); }
    /// @brief Number of times the tree was built (the first time included).
    std::uint64_t builds() const { return builds_; }
    /// @brief True when every node's box holds its children's (or its bodies') boxes
    /// and every body is in exactly one leaf: the invariants a query relies on.
    bool isConsistent() const;

private:
    /// One node: an inner node's children are the next node and `right`; a leaf's bodies are
    /// order_[first, first + count).
    struct Node {
        Aabb box;                   ///< Holds the boxes of every body below.
        std::uint32_t first = 0;    ///< Leaf: first of its bodies in order_.
        std::uint32_t count = 0;    ///< Leaf: how many bodies (0 for an inner node).
        std::uint32_t right = 0;    ///< Inner node: index of its right child (the left one is the next node).
    };

    std::uint32_t build(std::uint32_t first, std::uint32_t count);

    std::vector<Aabb> boxes_;            ///< Each kinematic body's box, as the tree was built from them.
    std::vector<std::uint32_t> order_;   ///< The bodies, leaf after leaf.
    std::vector<Node> nodes_;            ///< Pre-order: the root first.
    std::uint64_t builds_ = 0;
};

/// Deepest the static tree gets: a balanced tree this deep holds 2^kStaticMaxDepth leaves,
/// more kinematic bodies than memory does; the query's stack is a fixed array of this size.
inline constexpr int kStaticMaxDepth = 48;

}  // namespace stepwise
