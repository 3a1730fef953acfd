/// @file continuous_candidates.cpp
/// @brief The continuous stage's candidate index: boxes sorted along their widest-spread axis.
///
/// The reasoning (why a local index, why the range [Q.min − W, Q.max] holds
/// every overlapping box) is in continuous_candidates.hpp.
#include "collision/continuous_candidates.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/insertion_sort.hpp"

namespace stepwise {

Aabb geometryBounds(const Geometry& shape) { return geometryAabb(shape); }

Real candidateSlack(const Aabb& box) {
    const Vec3 magnitude = glm::max(glm::abs(box.min), glm::abs(box.max));
    const Real largest = glm::max(magnitude.x, glm::max(magnitude.y, magnitude.z));
    return kTouchTolerance + kCandidateRoundingUlps * std::numeric_limits<Real>::epsilon() * largest;
}

namespace {

Aabb grown(Aabb box) {
    const Real slack = candidateSlack(box);
    box.min -= Vec3(slack);
    box.max += Vec3(slack);
    return box;
}

}  // namespace

void SweptBoxIndex::build(const BodySet& bodies, std::span<const Vec3> startPositions,
                          std::span<const std::uint8_t> fast) {
    const std::size_t dynamicCount = bodies.dynamics.size();
    const std::size_t count = dynamicCount + bodies.kinematics.size();
    boxes_.resize(count);  // allocates only when bodies are added
    for (std::size_t i = 0; i < dynamicCount; ++i) {
        // The body's own box (a compound's holds all its parts, which its Geometry does not carry)
        const DynamicObject& body = bodies.dynamics[i];
        Aabb box = shapeAabb(body);
        if (fast[i]) {
            // It may be put back anywhere on start + t·Δ before another fast body asks.
            box = merged(shapeAabb(body, startPositions[i]), box);
        }
        boxes_[i] = grown(box);
    }
    for (std::size_t k = 0; k < bodies.kinematics.size(); ++k) {
        boxes_[dynamicCount + k] = grown(shapeAabb(bodies.kinematics[k]));
    }

    // The axis along which the centres spread most: the variance Σc²/n − (Σc/n)² per axis.
    Vec3 sum(0), sumOfSquares(0);
    for (const Aabb& box : boxes_) {
        const Vec3 c = box.centre();
        sum += c;
        sumOfSquares += c * c;
    }
    const Real n = Real(count > 0 ? count : 1);
    const Vec3 variance = sumOfSquares / n - (sum / n) * (sum / n);
    int axis = 0;
    if (variance.y > variance[axis]) axis = 1;
    if (variance.z > variance[axis]) axis = 2;
    if (axis != axis_) sortedLastStep_ = false;  // last step's order is along another axis
    axis_ = axis;

    // Oversize: wider than kCandidateOversizeRatio × the median width along the axis.
    widths_.resize(count);
    for (std::size_t p = 0; p < count; ++p) widths_[p] = boxes_[p].max[axis_] - boxes_[p].min[axis_];
    Real limit = std::numeric_limits<Real>::infinity();
    if (count > 0) {
        const auto middle = widths_.begin() + static_cast<std::ptrdiff_t>(count / 2);
        std::nth_element(widths_.begin(), middle, widths_.end());  // the value is the median whatever the algorithm
        limit = kCandidateOversizeRatio * *middle;
    }
    isOversize_.resize(count);
    oversize_.clear();
    maxWidth_ = 0;
    for (std::size_t p = 0; p < count; ++p) {
        const Real width = boxes_[p].max[axis_] - boxes_[p].min[axis_];
        isOversize_[p] = width > limit ? 1 : 0;
        if (isOversize_[p]) {
            oversize_.push_back(static_cast<std::uint32_t>(p));
        } else {
            maxWidth_ = glm::max(maxWidth_, width);
        }
    }

    if (entries_.size() != count) {  // bodies were added: start the order again
        entries_.resize(count);
        for (std::size_t p = 0; p < count; ++p) entries_[p].proxy = static_cast<std::uint32_t>(p);
        sortedLastStep_ = false;
    }
    for (Entry& entry : entries_) entry.key = boxes_[entry.proxy].min[axis_];
    sortEntries();
    sortedLastStep_ = true;
}

void SweptBoxIndex::sortEntries() {
    // By key, then proxy: a total order, so the same boxes give the same order whichever sort runs.
    const auto before = [](const Entry& a, const Entry& b) {
        return a.key < b.key || (a.key == b.key && a.proxy < b.proxy);
    };
    if (!sortedLastStep_) {
        std::sort(entries_.begin(), entries_.end(), before);
        return;
    }
    // The bodies rarely pass each other in one step: last step's order is nearly sorted.
    insertionSort(std::span<Entry>(entries_), before);
}

void SweptBoxIndex::query(const Aabb& query, std::uint32_t self, std::vector<std::uint32_t>& out) const {
    out.clear();
    // Every box that is not oversize and overlaps Q along the axis has min in [Q.min − W, Q.max].
    const Real low = query.min[axis_] - maxWidth_;
    const Real high = query.max[axis_];
    auto entry = std::lower_bound(entries_.begin(), entries_.end(), low,
                                  [](const Entry& e, Real key) { return e.key < key; });
    for (; entry != entries_.end() && entry->key <= high; ++entry) {
        const std::uint32_t p = entry->proxy;
        if (p != self && !isOversize_[p] && boxes_[p].overlaps(query)) out.push_back(p);
    }
    for (const std::uint32_t p : oversize_) {
        if (p != self && boxes_[p].overlaps(query)) out.push_back(p);
    }
}

}  // namespace stepwise
