/// @file continuous_candidates.hpp
/// @brief Which bodies a fast body's path may touch: a sort of the bodies' boxes along one axis, local to the continuous stage.
///
/// The continuous stage (continuous.hpp) tests a fast body's swept box (its
/// box at the start of the step merged with its box at the end) against the
/// other bodies. Against every one of them that costs O(n) per fast body;
/// this index answers "which boxes overlap this one?" in O(log n + k).
///
/// **Why not the broadphase's structure.** The continuous stage runs after
/// the bodies have moved and before the broadphase of the next narrowphase
/// (World::step: after move-kinematics in the impulse pipeline, after the
/// last substep in the sequential-impulse one). The broadphase's tree, grid
/// or sweep order was last brought up to date at the poses of the step's
/// start (or of the previous step), without the swept boxes, and with
/// `Broadphase=BruteForce` there is no structure at all. Querying it would
/// need every one of the five broadphases to prove it still bounds every
/// body: a stale box misses a body that moved in, and the stage must find a
/// superset of the true touches to give the same result. So the stage keeps
/// its own, rebuilt from the current boxes in each step that has a fast body.
///
/// **The index: sort and sweep on one axis, queried by binary search.**
/// Every body gets a box: a slow or kinematic body its box now; a fast
/// body the box of its whole path, start ∪ end, since the stage may move it
/// back anywhere along that path before another fast body asks. Each box is
/// grown by candidateSlack() so that rounding cannot hide a touch. The
/// boxes are sorted by their lowest coordinate along the axis on which the
/// box centres spread most (largest variance). A query box Q overlaps box B
/// along that axis only if
///
///   B.min ≤ Q.max  and  B.max ≥ Q.min,  so  Q.min − w_B ≤ B.min ≤ Q.max,
///
/// with w_B the width of B along the axis. With W the largest width, two
/// binary searches bound the range of sorted boxes to look at: those with
/// B.min in [Q.min − W, Q.max]; each is then tested on all three axes. A
/// few very wide boxes (a floor slab, a wall, a fast body's long path) would
/// make W, and every range, long: boxes wider than kCandidateOversizeRatio ×
/// the median width are *oversize*, left out of W, and tested against every
/// query directly (the grid broadphase does the same, broadphase_grid.hpp).
///
/// **Cost per step** (only in steps with a fast body): O(n) to compute the
/// boxes, the axis and the median; the sort is an insertion sort of last
/// step's order, O(n) when the bodies keep their order (Baraff's
/// observation for sweep and prune: coherence between steps), a full
/// O(n log n) sort only in a step after one without a fast body or when the
/// axis changes. Per fast body: O(log n + s + m), s the boxes in the range
/// (the bodies in a slab of width |Q| + W across the scene) and m the
/// oversize boxes. The stage's old loop cost O(n) per fast body.
///
/// The order of the candidates does not matter to the stage: it keeps the
/// earliest time of impact, a minimum, and each candidate's time of impact
/// does not depend on the others. The index only has to return a superset of
/// the bodies whose box overlaps the query; the stage then applies the same
/// exact box test as before, so the result is bit for bit the brute force's
/// (tested in "[ccd]": stopFastBodiesAtImpactBruteForce()).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "collision/aabb.hpp"
#include "collision/narrowphase.hpp"
#include "objects/body_set.hpp"

namespace stepwise {

/// Boxes wider along the sorted axis than this many times the median width
/// are tested against every query instead of widening every query's range.
/// A ball pile lands with fast balls whose paths are up to a few diameters
/// long; a ratio of 4 keeps those in the sorted range and leaves out floor
/// slabs, walls and the long path of a bullet.
inline constexpr Real kCandidateOversizeRatio = Real(4);

/// Round-off allowance of a candidate box, in units of Real's epsilon times
/// the box's largest coordinate: a body put back at start + t·Δ lands a few
/// roundings from the segment's box, never 16 ulps away.
inline constexpr Real kCandidateRoundingUlps = Real(16);

/// @brief The bounding box of a shape where it is now (geometryAabb(): infinite for a plane or a compound's Geometry).
Aabb geometryBounds(const Geometry& shape);

/// @brief How much a candidate box is grown on every side, m: the touching tolerance,
/// plus kCandidateRoundingUlps ulps of its largest coordinate (round-off in single precision).
Real candidateSlack(const Aabb& box);

/// @brief The bodies' boxes, sorted along one axis, for the continuous stage's queries.
///
/// Proxies follow the broadphase's numbering (broadphase_proxies.hpp): dynamic
/// body i is proxy i, kinematic body k is proxy dynamics.size() + k. Every
/// array keeps its capacity from step to step: a running scene allocates nothing.
class SweptBoxIndex {
public:
    /// @brief Computes every body's box (the whole path's for a fast one) and sorts them.
    /// @param bodies          the world's bodies, at the end of the step's motion
    /// @param startPositions  each dynamic body's centre at the start of the step, m
    /// @param fast            1 for each dynamic body that is fast this step (continuous.hpp)
    void build(const BodySet& bodies, std::span<const Vec3> startPositions, std::span<const std::uint8_t> fast);

    /// @brief Forgets the order (the stage ran no query this step): the next build sorts from scratch.
    void markStale() { sortedLastStep_ = false; }

    /// @brief Appends to @p out every proxy except @p self whose box overlaps @p query
    /// (@p out is cleared first). A superset of the bodies whose current box overlaps it.
    void query(const Aabb& query, std::uint32_t self, std::vector<std::uint32_t>& out) const;

    /// @brief The axis the boxes were sorted along in the last build (0: x, 1: y, 2: z).
    int axis() const { return axis_; }
    /// @brief Number of oversize boxes in the last build (tested against every query).
    std::size_t oversizeCount() const { return oversize_.size(); }

private:
    /// One box in the sorted order: its lowest coordinate along the axis, and whose it is.
    struct Entry {
        Real key = 0;             ///< boxes_[proxy].min[axis_], m.
        std::uint32_t proxy = 0;  ///< Which body.
    };
    void sortEntries();

    std::vector<Aabb> boxes_;             ///< One per proxy: grown current box, or grown path box for a fast body.
    std::vector<Entry> entries_;          ///< Every proxy, by key then proxy (a total order: deterministic).
    std::vector<std::uint8_t> isOversize_;///< 1 for a proxy tested directly rather than through the range.
    std::vector<std::uint32_t> oversize_; ///< The oversize proxies, in index order.
    std::vector<Real> widths_;            ///< Scratch: each box's width along the axis (for the median).
    Real maxWidth_ = 0;                   ///< W: the largest width along the axis of a box that is not oversize, m.
    int axis_ = 0;                        ///< Axis of the sort.
    bool sortedLastStep_ = false;         ///< entries_ holds last step's order: an insertion sort suffices.
};

}  // namespace stepwise
