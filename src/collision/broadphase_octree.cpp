/// @file broadphase_octree.cpp
/// @brief Stage 4, loose octree: each body at the depth of its size and the cell of its centre,
/// moved only when it leaves its node's loose box; one descent per body finds its partners.
#include "collision/broadphase_octree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stepwise {

namespace {

/// Most nodes a depth-first descent keeps waiting: each node taken off adds at most
/// 8 children, and a path holds at most kOctreeMaxDepth + 1 nodes, so 7 per level
/// wait beside the path, plus the 8 children of the deepest node.
constexpr int kStackSize = 8 * (kOctreeMaxDepth + 1);
/// Most jobs the pair search keeps waiting. Taking off a job adds at most 45 (a node within
/// itself: its own bodies against 8 children, 8 children within, 28 pairs of children) or 9
/// (two subtrees: own bodies and 8 children against the other); along one chain of jobs each
/// step goes one level deeper on one side or ends, at most 3 (kOctreeMaxDepth + 1) steps.
constexpr int kJobStackSize = 45 * 3 * (kOctreeMaxDepth + 1);

/// The octant of @p point in a cell of centre @p centre: bit 0 set for x ≥ centre.x, bit 1 for y, bit 2 for z.
int octantOf(const Vec3& point, const Vec3& centre) {
    return int(point.x >= centre.x) | (int(point.y >= centre.y) << 1) | (int(point.z >= centre.z) << 2);
}

/// Centre of the child cell in @p octant of a cell of centre @p centre and half side @p half:
/// a quarter of the parent's side away on each axis.
Vec3 childCentre(const Vec3& centre, Real half, int octant) {
    const Real quarter = Real(0.5) * half;
    return {centre.x + ((octant & 1) ? quarter : -quarter), centre.y + ((octant & 2) ? quarter : -quarter),
            centre.z + ((octant & 4) ? quarter : -quarter)};
}

/// The loose box of a cell of centre @p centre and half side @p half: the cell grown by half
/// its side (= @p half) on every side, so it reaches 2·half from the centre.
Aabb looseBox(const Vec3& centre, Real half) {
    const Vec3 reach(Real(2) * half);
    return {centre - reach, centre + reach};
}

}  // namespace

std::int32_t LooseOctree::allocateNode(std::int32_t parent, int octant) {
    std::int32_t index;
    if (freeList_ == kNull) {
        nodes_.push_back(Node{});  // grows only while the octree grows, never in a running scene
        index = static_cast<std::int32_t>(nodes_.size() - 1);
    } else {
        index = freeList_;
        freeList_ = nodes_[index].parent;
        --freeCount_;
        nodes_[index] = Node{};
    }
    Node& node = nodes_[index];
    const Node& up = nodes_[parent];
    node.parent = parent;
    node.level = up.level + 1;
    node.half = Real(0.5) * up.half;
    node.centre = childCentre(up.centre, up.half, octant);
    node.loose = looseBox(node.centre, node.half);
    nodes_[parent].child[octant] = index;
    return index;
}

void LooseOctree::fitRoot(const ProxySet& proxies) {
    // The cube around every box, kOctreeRootPadding times as wide, centred on it.
    Vec3 low(std::numeric_limits<Real>::max());
    Vec3 high(std::numeric_limits<Real>::lowest());
    for (const Aabb& box : proxies.boxes) {
        low = glm::min(low, box.min);
        high = glm::max(high, box.max);
    }
    Aabb around{low, high};
    Node root;
    root.centre = around.centre();
    root.half = Real(0.5) * kOctreeRootPadding * around.longestSide();
    root.loose = looseBox(root.centre, root.half);
    nodes_.clear();
    nodes_.push_back(root);
    freeList_ = kNull;
    freeCount_ = 0;
    ++fits_;
}

bool LooseOctree::staysPut(std::uint32_t p, const Aabb& box) const {
    const Node& node = nodes_[nodeOf_[p]];
    // The root holds anything; a body there is tried again for a deeper place each step.
    if (node.level == 0) return false;
    if (!node.loose.contains(box)) return false;
    return Real(2) * node.half < kOctreeStayRatio * box.longestSide() || node.level == kOctreeMaxDepth;
}

void LooseOctree::insert(std::uint32_t p, const Aabb& box) {
    // Down from the root by the octant of the centre, while the child's cells are still as large as
    // the body (side = the parent's half side ≥ s) and its loose box holds the body's box.
    const Real size = box.longestSide();
    const Vec3 centre = box.centre();
    std::int32_t index = 0;
    while (nodes_[index].level < kOctreeMaxDepth && size <= nodes_[index].half) {
        const Node& node = nodes_[index];
        const int octant = octantOf(centre, node.centre);
        std::int32_t child = node.child[octant];
        if (child == kNull) {
            // Test before making the node: a body that does not fit leaves no empty node behind.
            if (!looseBox(childCentre(node.centre, node.half, octant), Real(0.5) * node.half).contains(box)) break;
            child = allocateNode(index, octant);  // may move nodes_: `node` is not used after this
        } else if (!nodes_[child].loose.contains(box)) {
            break;
        }
        index = child;
    }
    // At the head of the node's list, and counted in it and every ancestor.
    Node& node = nodes_[index];
    nodeOf_[p] = index;
    previous_[p] = kNull;
    next_[p] = node.first;
    if (node.first != kNull) previous_[node.first] = static_cast<std::int32_t>(p);
    node.first = static_cast<std::int32_t>(p);
    for (std::int32_t up = index; up != kNull; up = nodes_[up].parent) ++nodes_[up].below;
}

void LooseOctree::remove(std::uint32_t p) {
    const std::int32_t index = nodeOf_[p];
    if (previous_[p] != kNull) {
        next_[previous_[p]] = next_[p];
    } else {
        nodes_[index].first = next_[p];
    }
    if (next_[p] != kNull) previous_[next_[p]] = previous_[p];
    // Uncount it on the way up; a node left with nothing below it is given back (the root stays).
    std::int32_t up = index;
    while (up != kNull) {
        Node& node = nodes_[up];
        const std::int32_t parent = node.parent;
        if (--node.below == 0 && parent != kNull) {
            std::int32_t* slot = std::find(nodes_[parent].child, nodes_[parent].child + 8, up);
            *slot = kNull;
            node.level = -1;
            node.parent = freeList_;
            freeList_ = up;
            ++freeCount_;
        }
        up = parent;
    }
}

std::uint32_t LooseOctree::strandedCount(const ProxySet& proxies) const {
    // In the root although small enough for level 1: its centre is outside the root cube.
    std::uint32_t count = 0;
    for (std::int32_t p = nodes_[0].first; p != kNull; p = next_[p]) {
        if (proxies.boxes[p].longestSide() <= nodes_[0].half) ++count;
    }
    return count;
}

void LooseOctree::findOverlaps(const ProxySet& proxies, std::vector<ProxyPair>& pairs, BroadphaseCounters& counters) {
    const std::uint32_t n = proxies.size();
    if (n == 0) {
        nodes_.clear();
        nodeOf_.clear();
        freeList_ = kNull;
        freeCount_ = 0;
        return;
    }
    bool refile = nodes_.empty() || nodeOf_.size() != n || dynamicCount_ != proxies.dynamicCount;
    if (!refile) {
        for (std::uint32_t p = 0; p < n; ++p) {
            if (staysPut(p, proxies.boxes[p])) continue;
            remove(p);
            insert(p, proxies.boxes[p]);
            ++counters.reinsertions;
        }
        refile = strandedCount(proxies) * kOctreeRefitShare > n;
    }
    if (refile) {
        fitRoot(proxies);
        dynamicCount_ = proxies.dynamicCount;
        nodeOf_.resize(n);
        next_.resize(n);
        previous_.resize(n);
        for (std::uint32_t p = 0; p < n; ++p) insert(p, proxies.boxes[p]);
        counters.reinsertions += n;
    }

    // The pairs of the whole tree: pairs of subtrees whose loose boxes meet, split until
    // one side is a node's own bodies (see the class comment).
    enum class Task : std::uint8_t { Within, Between, OwnAgainst };
    struct Job {
        std::int32_t x, y;
        Task task;
    };
    Job jobs[kJobStackSize];
    int top = 0;
    jobs[top++] = {0, 0, Task::Within};
    const auto test = [&](std::uint32_t a, std::uint32_t b) {
        if (proxies.isKinematic(a) && proxies.isKinematic(b)) return;  // neither can be pushed
        ++counters.pairTests;
        if (proxies.boxes[a].overlaps(proxies.boxes[b])) pairs.push_back(orderedPair(a, b));
    };
    const auto looseMeet = [&](std::int32_t x, std::int32_t y) {
        ++counters.structureTests;
        return nodes_[x].loose.overlaps(nodes_[y].loose);
    };
    std::int32_t stack[kStackSize];
    while (top > 0) {
        const Job job = jobs[--top];
        const Node& x = nodes_[job.x];
        if (job.task == Task::Within) {
            // Own × own, each pair once; own × each child's subtree; each child within; children two by two.
            for (std::int32_t p = x.first; p != kNull; p = next_[p]) {
                for (std::int32_t q = next_[p]; q != kNull; q = next_[q]) test(std::uint32_t(p), std::uint32_t(q));
            }
            for (int i = 0; i < 8; ++i) {
                const std::int32_t ci = x.child[i];
                if (ci == kNull) continue;
                if (x.first != kNull) jobs[top++] = {job.x, ci, Task::OwnAgainst};
                jobs[top++] = {ci, ci, Task::Within};
                for (int j = i + 1; j < 8; ++j) {
                    const std::int32_t cj = x.child[j];
                    if (cj != kNull && looseMeet(ci, cj)) jobs[top++] = {ci, cj, Task::Between};
                }
            }
        } else if (job.task == Task::Between) {
            // Two subtrees apart in the tree: split the shallower one into its own bodies and its children.
            const bool splitX = x.level <= nodes_[job.y].level;
            const std::int32_t split = splitX ? job.x : job.y;
            const std::int32_t other = splitX ? job.y : job.x;
            const Node& node = nodes_[split];
            if (node.first != kNull) jobs[top++] = {split, other, Task::OwnAgainst};
            for (const std::int32_t child : node.child) {
                if (child != kNull && looseMeet(child, other)) jobs[top++] = {child, other, Task::Between};
            }
        } else {
            // A node's own bodies against a subtree: each body descends it with its own box.
            for (std::int32_t p = x.first; p != kNull; p = next_[p]) {
                const auto a = static_cast<std::uint32_t>(p);
                const Aabb& box = proxies.boxes[a];
                int depth = 0;
                ++counters.structureTests;
                if (nodes_[job.y].loose.overlaps(box)) stack[depth++] = job.y;
                while (depth > 0) {
                    const Node& node = nodes_[stack[--depth]];
                    for (std::int32_t q = node.first; q != kNull; q = next_[q]) test(a, std::uint32_t(q));
                    for (const std::int32_t child : node.child) {
                        if (child == kNull) continue;
                        ++counters.structureTests;
                        if (nodes_[child].loose.overlaps(box)) stack[depth++] = child;
                    }
                }
            }
        }
    }
}

void LooseOctree::query(const Aabb& box, std::span<const Aabb> boxes, std::vector<std::uint32_t>& hits,
                        BroadphaseCounters& counters) const {
    if (nodes_.empty()) return;
    std::int32_t stack[kStackSize];
    int top = 0;
    stack[top++] = 0;  // the root is entered whatever its loose box: it also holds the bodies outside it
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        for (std::int32_t p = node.first; p != kNull; p = next_[p]) {
            ++counters.pairTests;
            if (box.overlaps(boxes[p])) hits.push_back(static_cast<std::uint32_t>(p));
        }
        for (const std::int32_t child : node.child) {
            if (child == kNull) continue;
            ++counters.structureTests;
            if (nodes_[child].loose.overlaps(box)) stack[top++] = child;
        }
    }
}

int LooseOctree::depth() const {
    int deepest = -1;
    for (const Node& node : nodes_) {
        if (node.level >= 0 && node.first != kNull) deepest = std::max(deepest, node.level);
    }
    return deepest;
}

bool LooseOctree::isConsistent(const ProxySet& proxies) const {
    if (nodes_.empty()) return proxies.size() == 0;
    if (nodeOf_.size() != proxies.size()) return false;
    std::vector<int> listed(proxies.size(), 0);
    std::size_t free = 0;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        const Node& node = nodes_[i];
        if (node.level < 0) {
            ++free;
            continue;
        }
        const auto index = static_cast<std::int32_t>(i);
        std::uint32_t below = 0;
        for (std::int32_t p = node.first, last = kNull; p != kNull; last = p, p = next_[p]) {
            if (p < 0 || std::size_t(p) >= proxies.size() || nodeOf_[p] != index || previous_[p] != last) return false;
            ++listed[p];
            ++below;
        }
        for (int octant = 0; octant < 8; ++octant) {
            const std::int32_t c = node.child[octant];
            if (c == kNull) continue;
            const Node& child = nodes_[c];
            if (child.parent != index || child.level != node.level + 1 || child.half != Real(0.5) * node.half) return false;
            if (octantOf(child.centre, node.centre) != octant || !node.loose.contains(child.loose)) return false;
            below += child.below;
        }
        if (below != node.below || (index != 0 && below == 0)) return false;
    }
    if (free != freeCount_) return false;
    for (std::uint32_t p = 0; p < proxies.size(); ++p) {
        if (listed[p] != 1) return false;
        // Inside the loose box of its node and every ancestor but the root (which holds anything).
        for (std::int32_t up = nodeOf_[p]; up != 0; up = nodes_[up].parent) {
            if (!nodes_[up].loose.contains(proxies.boxes[p])) return false;
        }
    }
    return true;
}

}  // namespace stepwise
