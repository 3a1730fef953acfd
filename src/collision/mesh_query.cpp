/// @file mesh_query.cpp
/// @brief The descent of a mesh's box hierarchy for a query box (mesh_query.hpp).
#include "collision/mesh_query.hpp"

#include <cmath>

namespace stepwise {

namespace {

bool overlaps(const Aabb& box, const Vec3& lower, const Vec3& upper) {
    return box.min.x <= upper.x && lower.x <= box.max.x && box.min.y <= upper.y && lower.y <= box.max.y &&
           box.min.z <= upper.z && lower.z <= box.max.z;
}

}  // namespace

Aabb meshFrameBox(const Aabb& worldBox, const Vec3& meshCentre, const Quat& meshOrientation) {
    const Mat3 toMesh = glm::transpose(glm::mat3_cast(meshOrientation));  // world → mesh frame: Rᵀ
    const Vec3 centre = toMesh * (worldBox.centre() - meshCentre);
    const Vec3 half = Real(0.5) * (worldBox.max - worldBox.min);
    Vec3 reach(0);
    for (int column = 0; column < 3; ++column) {
        for (int row = 0; row < 3; ++row) reach[row] += std::abs(toMesh[column][row]) * half[column];
    }
    return {centre - reach, centre + reach};
}

TrianglesInBox::TrianglesInBox(const TriangleMesh& mesh, const Aabb& box) : mesh_(mesh), box_(box) {
    if (mesh.nodes.empty()) {
        byIndex_ = true;
        end_ = static_cast<std::uint32_t>(mesh.triangles.size());
        return;
    }
    stack_[top_++] = 0;  // the root
}

bool TrianglesInBox::triangleOverlaps(std::uint32_t index) const {
    if (index >= mesh_.triangles.size()) return false;
    const std::array<std::uint32_t, 3>& t = mesh_.triangles[index];
    const std::size_t vertices = mesh_.vertices.size();
    if (t[0] >= vertices || t[1] >= vertices || t[2] >= vertices) return false;
    const Vec3& a = mesh_.vertices[t[0]];
    const Vec3& b = mesh_.vertices[t[1]];
    const Vec3& c = mesh_.vertices[t[2]];
    return overlaps(box_, glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)));
}

void TrianglesInBox::subtreeRun(std::uint32_t node, std::uint32_t& first, std::uint32_t& end) const {
    // Down the first children to the leftmost leaf, down the second children to the rightmost.
    // Each step goes to a node of larger index (children come after their parent), so a
    // malformed hierarchy cannot loop: the walk stops after at most nodes.size() steps.
    const std::size_t count = mesh_.nodes.size();
    std::uint32_t left = node;
    for (std::size_t step = 0; step < count && mesh_.nodes[left].count == 0; ++step) {
        const std::uint32_t child = mesh_.nodes[left].first;
        if (child <= left || child >= count) break;
        left = child;
    }
    std::uint32_t right = node;
    for (std::size_t step = 0; step < count && mesh_.nodes[right].count == 0; ++step) {
        const std::uint32_t child = mesh_.nodes[right].first + 1;
        if (child <= right || child >= count) break;
        right = child;
    }
    first = mesh_.nodes[left].count > 0 ? mesh_.nodes[left].first : 0;
    end = mesh_.nodes[right].count > 0 ? mesh_.nodes[right].first + mesh_.nodes[right].count
                                       : static_cast<std::uint32_t>(mesh_.order.size());
}

bool TrianglesInBox::next(std::uint32_t& triangle) {
    for (;;) {
        // 1. The run being read: a leaf's triangles, or a subtree the stack had no room for.
        while (cursor_ < end_) {
            const std::uint32_t entry = cursor_++;
            if (byIndex_) {
                if (triangleOverlaps(entry)) {
                    triangle = entry;
                    return true;
                }
                continue;
            }
            if (entry < mesh_.order.size() && triangleOverlaps(mesh_.order[entry])) {
                triangle = mesh_.order[entry];
                return true;
            }
        }
        // 2. The next node waiting.
        if (top_ == 0) return false;
        const std::uint32_t index = stack_[static_cast<std::size_t>(--top_)];
        if (index >= mesh_.nodes.size()) continue;
        const MeshNode& node = mesh_.nodes[index];
        ++nodesVisited_;
        if (!overlaps(box_, node.lower, node.upper)) continue;
        if (node.count > 0) {  // a leaf: read its triangles
            cursor_ = node.first;
            end_ = node.first + node.count;
        } else if (top_ + 2 <= kMeshQueryStack) {  // an inner node: both children wait, the first on top
            stack_[static_cast<std::size_t>(top_++)] = node.first + 1;
            stack_[static_cast<std::size_t>(top_++)] = node.first;
        } else {  // no room: read the whole subtree's run, triangle by triangle
            subtreeRun(index, cursor_, end_);
        }
    }
}

}  // namespace stepwise
