/// @file space_layout.cpp
/// @brief The spaces' swept boxes and their offsets side by side (the formula is in space_layout.hpp).
#include "viewer/space_layout.hpp"

#include <algorithm>
#include <iterator>
#include <limits>

namespace stepwise::viewer {

namespace {

/// Nine colours far apart in hue, one per key 1–9, bright enough to read as text on the dark background.
constexpr Color kSpaceColors[] = {{0.95f, 0.55f, 0.2f}, {0.35f, 0.85f, 0.4f}, {0.4f, 0.6f, 1.0f},
                                  {0.95f, 0.4f, 0.8f},  {0.95f, 0.9f, 0.3f},  {0.3f, 0.9f, 0.9f},
                                  {0.7f, 0.5f, 1.0f},   {1.0f, 0.4f, 0.4f},   {0.8f, 0.8f, 0.8f}};

void include(Aabb& box, const Aabb& more) {
    box.min = glm::min(box.min, more.min);
    box.max = glm::max(box.max, more.max);
}

}  // namespace

Color spaceColor(std::size_t k) { return kSpaceColors[k % std::size(kSpaceColors)]; }

std::optional<std::size_t> spaceForKey(unsigned char key) {
    if (key < '1' || key > '9') return std::nullopt;
    return static_cast<std::size_t>(key - '1');
}

void SpaceLayout::reset(std::size_t spaces) {
    const Vec3 half(kEmptySpaceSize / 2);
    boxes_.assign(spaces, Aabb{-half, half});
    seen_.assign(spaces, 0);
    offsets_.assign(spaces, 0);
    place();
}

void SpaceLayout::grow(std::size_t space, const World& world) {
    if (space >= boxes_.size()) return;
    Aabb& box = boxes_[space];
    auto add = [&](const Aabb& body) {
        if (!seen_[space]) box = body;
        else include(box, body);
        seen_[space] = 1;
    };
    const Aabb before = box;
    for (const DynamicObject& b : world.dynamics()) add(shapeAabb(b));
    for (const KinematicsObject& b : world.kinematics()) add(shapeAabb(b));
    for (const SoftBody& b : world.softBodies()) {  // every node's small sphere: the surface as it squashes
        for (const Vec3& x : b.nodePositions) add(Aabb{x - Vec3(b.nodeRadius), x + Vec3(b.nodeRadius)});
    }
    // Most steps move the bodies inside the box swept so far: nothing to place again.
    if (box.min != before.min || box.max != before.max) place();
}

void SpaceLayout::place() {
    Real widest = 0;
    for (const Aabb& box : boxes_) widest = std::max(widest, box.max.x - box.min.x);
    gap_ = std::max(kMinSpaceGap, kSpaceGapShare * widest);
    for (std::size_t k = 1; k < boxes_.size(); ++k) {
        offsets_[k] = boxes_[k - 1].max.x + offsets_[k - 1] + gap_ - boxes_[k].min.x;
    }
}

Vec3 SpaceLayout::offset(std::size_t space) const {
    if (arrangement_ == SpaceArrangement::Overlaid || space >= offsets_.size()) return Vec3(0);
    return Vec3(offsets_[space], 0, 0);
}

Aabb SpaceLayout::bounds(std::size_t space) const { return boxes_.at(space); }

std::pair<Real, Real> SpaceLayout::band(std::size_t space) const {
    if (arrangement_ == SpaceArrangement::Overlaid) return {-std::numeric_limits<Real>::infinity(), std::numeric_limits<Real>::infinity()};
    const Aabb& box = boxes_.at(space);
    return {box.min.x - gap_ / 2, box.max.x + gap_ / 2};
}

Aabb SpaceLayout::drawnBox() const {
    if (boxes_.empty()) return Aabb{Vec3(-kEmptySpaceSize / 2), Vec3(kEmptySpaceSize / 2)};
    Aabb all{boxes_[0].min + offset(0), boxes_[0].max + offset(0)};
    for (std::size_t k = 1; k < boxes_.size(); ++k) include(all, Aabb{boxes_[k].min + offset(k), boxes_[k].max + offset(k)});
    return all;
}

}  // namespace stepwise::viewer
