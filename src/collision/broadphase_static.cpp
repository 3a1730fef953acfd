/// @file broadphase_static.cpp
/// @brief The kinematic bodies' tree: built top down at the median, rebuilt only when one of them moved.
#include "collision/broadphase_static.hpp"

#include <algorithm>

namespace stepwise {

bool StaticTree::update(std::span<const Aabb> boxes) {
    const bool same = boxes.size() == boxes_.size() &&
                      std::equal(boxes.begin(), boxes.end(), boxes_.begin(), [](const Aabb& p, const Aabb& q) {
                          return p.min == q.min && p.max == q.max;
                      });
    if (same && builds_ > 0) return false;
    boxes_.assign(boxes.begin(), boxes.end());
    order_.resize(boxes_.size());
    for (std::uint32_t k = 0; k < order_.size(); ++k) order_[k] = k;
    nodes_.clear();
    if (!boxes_.empty()) build(0, size());
    ++builds_;
    return true;
}

std::uint32_t StaticTree::build(std::uint32_t first, std::uint32_t count) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    Aabb box = boxes_[order_[first]];
    for (std::uint32_t i = first + 1; i < first + count; ++i) box = merged(box, boxes_[order_[i]]);
    nodes_[index].box = box;
    if (count <= kStaticLeafSize) {
        nodes_[index].first = first;
        nodes_[index].count = count;
        return index;
    }
    // Split at the median centre along the node's longest side: two halves of equal count,
    // so the tree is balanced whatever the sizes (a floor beside pebbles still splits evenly).
    const Vec3 extent = box.max - box.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const std::uint32_t half = count / 2;
    const auto begin = order_.begin() + first;
    std::nth_element(begin, begin + half, begin + count, [&](std::uint32_t p, std::uint32_t q) {
        const Real cp = boxes_[p].min[axis] + boxes_[p].max[axis];  // twice the centre: the order is the same
        const Real cq = boxes_[q].min[axis] + boxes_[q].max[axis];
        return cp < cq || (cp == cq && p < q);  // ties by index: the same tree on every machine
    });
    build(first, half);  // the left child is the next node
    const std::uint32_t right = build(first + half, count - half);
    nodes_[index].right = right;
    return index;
}

void StaticTree::query(const Aabb& box, std::vector<std::uint32_t>& hits, BroadphaseCounters& counters) const {
    if (nodes_.empty()) return;
    const auto start = hits.size();
    std::uint32_t stack[kStaticMaxDepth];
    int top = 0;
    std::uint32_t node = 0;
    while (true) {
        const Node& n = nodes_[node];
        if (n.count > 0) {
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                ++counters.pairTests;
                if (box.overlaps(boxes_[order_[i]])) hits.push_back(order_[i]);
            }
        } else {
            // An inner node: go on into the children whose boxes overlap, the left one first.
            const Node& left = nodes_[node + 1];
            const Node& right = nodes_[n.right];
            counters.structureTests += 2;
            const bool intoLeft = box.overlaps(left.box);
            const bool intoRight = box.overlaps(right.box);
            if (intoLeft && intoRight) {
                stack[top++] = n.right;
                node = node + 1;
                continue;
            }
            if (intoLeft || intoRight) {
                node = intoLeft ? node + 1 : n.right;
                continue;
            }
        }
        if (top == 0) break;
        node = stack[--top];
    }
    // The leaves hold the bodies in the tree's order; the pairs are wanted in index order.
    // A box meets a few static bodies, so an insertion sort of those few, in place.
    for (auto i = start + 1; i < hits.size(); ++i) {
        const std::uint32_t value = hits[i];
        auto j = i;
        for (; j > start && hits[j - 1] > value; --j) hits[j] = hits[j - 1];
        hits[j] = value;
    }
}

bool StaticTree::isConsistent() const {
    if (nodes_.empty()) return boxes_.empty();
    std::vector<int> seen(boxes_.size(), 0);
    // Walk every node; each child's box (or body's box) must lie inside its parent's.
    for (std::uint32_t index = 0; index < nodes_.size(); ++index) {
        const Node& n = nodes_[index];
        if (n.count > 0) {
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                if (!n.box.contains(boxes_[order_[i]])) return false;
                ++seen[order_[i]];
            }
        } else {
            if (index + 1 >= nodes_.size() || n.right >= nodes_.size() || n.right <= index + 1) return false;
            if (!n.box.contains(nodes_[index + 1].box) || !n.box.contains(nodes_[n.right].box)) return false;
        }
    }
    return std::all_of(seen.begin(), seen.end(), [](int count) { return count == 1; });
}

}  // namespace stepwise
