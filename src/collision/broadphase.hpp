/// @file broadphase.hpp
/// @brief Stage 4 of the step: find the pairs worth an exact test, with one of five broadphases.
///
/// | broadphase      | file                               | per step                  | good for |
/// |-----------------|------------------------------------|---------------------------|----------|
/// | `BruteForce`    | broadphase_brute_force.cpp         | O(n²) box tests           | a handful of bodies; the reference |
/// | `SweepAndPrune` | broadphase_sweep_and_prune.cpp     | O(n + k) after a near-sorted insertion sort | bodies spread out along one axis |
/// | `AabbTree`      | broadphase_aabb_tree.cpp           | O(n log n) queries, few reinsertions | any mix of sizes, resting bodies |
/// | `Grid`          | broadphase_grid.cpp                | O(n) rebuild and queries  | many bodies of similar size |
/// | `Octree`        | broadphase_octree.cpp              | O(n · depth) queries, a body moves only when it leaves its loose cell | sizes spread over a few powers of two |
///
/// All five return exactly the same pairs, in the same order, so a scene's
/// trajectory does not depend on which one runs: only the time does.
#pragma once

#include <string>
#include <vector>

#include "collision/aabb.hpp"
#include "collision/broadphase_aabb_tree.hpp"
#include "collision/broadphase_grid.hpp"
#include "collision/broadphase_octree.hpp"
#include "collision/broadphase_proxies.hpp"
#include "collision/broadphase_static.hpp"
#include "collision/broadphase_sweep_and_prune.hpp"
#include "collision/contact.hpp"
#include "objects/body_set.hpp"
#include "core/world_settings.hpp"

namespace stepwise {

/// @brief The brute-force broadphase: test every dynamic body against every other object.
///
/// O(n²) bounding-box tests: the reference every faster broadphase must
/// agree with. Pairs come out in a fixed order (dynamic–dynamic by index,
/// then dynamic–kinematic, then dynamic–plane), so runs are repeatable.
/// @param bodies the world's objects
/// @param boxes  scratch array of bounding boxes, reused between steps (no allocation once sized)
/// @param pairs  output, cleared first
void findPairsBruteForce(const BodySet& bodies, std::vector<Aabb>& boxes, std::vector<CandidatePair>& pairs);

/// @brief Which broadphase `Auto` runs for a scene, and why.
struct BroadphaseChoice {
    BroadphaseKind kind = BroadphaseKind::BruteForce;  ///< Never Auto.
    std::string reason;                                ///< One sentence, for the run summary.
};

/// Below this many dynamic bodies `Auto` uses brute force. Up to about 64
/// bodies its n²/2 box tests cost a few hundredths of a millisecond more than
/// sweep and prune, a few per cent of the step (docs/broadphase.md has the
/// measurements): little to win, and brute force is the reference, the
/// easiest to follow in a debugger, and what the lecture scenes run. Beyond,
/// its n² tests cost more and more.
inline constexpr std::size_t kAutoBruteForceBelow = 64;
/// Below this many bodies `Auto` prefers sweep and prune to the grid for
/// bodies of similar size. Measured (docs/broadphase.md), the two cost about
/// the same up to a few hundred bodies, and beyond the grid is the faster:
/// the wider the floor the bodies spread over, the more of them each sweep
/// interval crosses (sweep and prune's cost per body grows as √n), while the
/// dense grid's stays flat. Structures at
/// rest (the pyramids) need no rule of their own: there the grid, rebuilt
/// every step, still costs less than the AABB tree's descent (whose leaves
/// stay put), and sweep and prune as little as the tree below 512 bodies.
inline constexpr std::size_t kAutoSweepBelow = 512;
/// `Auto` picks the grid when at most this many bodies are oversize for it
/// (larger than kGridOversizeRatio × the median size). Each oversize body is
/// tested against every other one, n tests each, so a handful of them cost
/// about what the grid itself costs; more, and the tree is the better choice.
inline constexpr std::size_t kAutoGridMaxOversize = 8;

/// @brief What `Auto` chooses for these bodies, with the reason in words.
///
/// - fewer than kAutoBruteForceBelow dynamic bodies: brute force;
/// - bodies of similar size (at most kAutoGridMaxOversize larger than
///   kGridOversizeRatio × the median): sweep and prune below kAutoSweepBelow
///   bodies, the grid from there on, whose cost per body stays flat;
/// - otherwise: the AABB tree, which does not care about sizes.
///
/// Only the dynamic bodies are weighed: the kinematic ones never enter the
/// structure chosen here (they are in the static tree, StaticTree).
BroadphaseChoice chooseBroadphase(const BodySet& bodies);

/// @brief The World's broadphase: the structure it keeps between steps, and the dispatcher.
///
/// Holds the sweep-and-prune order, the tree, the grid and the octree from one step to
/// the next (only the one in use is kept up to date), which hold the dynamic
/// bodies; the static tree of the kinematic bodies (StaticTree), which all four
/// query and which is rebuilt only when a kinematic body moved; and the scratch arrays
/// of the common part: the bounding boxes, the raw pairs, and the sort that
/// puts them in the canonical order. A running scene allocates nothing.
class Broadphase {
public:
    /// @brief Finds the candidate pairs with broadphase @p kind (Auto: see chooseBroadphase()).
    ///
    /// Whatever the kind, @p pairs ends up exactly as findPairsBruteForce()
    /// would leave it: sorted by dynamic body A, then kinematic/dynamic/plane
    /// B in the brute force's order.
    /// @param pairs output, cleared first
    void findPairs(BroadphaseKind kind, const BodySet& bodies, std::vector<CandidatePair>& pairs);

    /// @brief The dynamic bodies whose boxes of the last findPairs() meet @p box, ascending (out cleared first).
    /// @brief The dynamic bodies (indices into BodySet::dynamics) whose box of the last findPairs()
    /// overlaps @p box (Aabb::overlaps, with the boxes broadphaseBounds() gave), sorted ascending.
    ///
    /// Asks the structure lastKind() used, so a region costs what a body's own
    /// search costs, not a loop over every body: brute force loops over the
    /// boxes; sweep and prune walks its sorted axis from a binary search; the
    /// tree and the octree descend from their roots; the grid reads the cells
    /// the box covers. The answer is the same whichever ran (the tests check
    /// it against a loop over the boxes). Bodies added or moved since the last
    /// findPairs() are seen where they were then.
    /// @param out output, cleared first; no allocation once it has grown to the answer's size
    void dynamicBodiesOverlapping(const Aabb& box, std::vector<std::uint32_t>& out) const;

    /// @brief The broadphase that ran last (Auto resolved), BruteForce before the first call.
    BroadphaseKind lastKind() const { return lastKind_; }
    /// @brief What Auto chose, once it has run; an empty reason before that.
    const BroadphaseChoice& autoChoice() const { return autoChoice_; }
    /// @brief The work done by the last call.
    const BroadphaseCounters& counters() const { return counters_; }

    /// @brief The tree (for tests and the tracker).
    const AabbTree& tree() const { return tree_; }
    /// @brief The grid (for tests and the tracker).
    const UniformGrid& grid() const { return grid_; }
    /// @brief The sweep and prune state (for tests and the tracker).
    const SweepAndPrune& sweepAndPrune() const { return sweepAndPrune_; }
    /// @brief The octree (for tests and the tracker).
    const LooseOctree& octree() const { return octree_; }
    /// @brief The kinematic bodies' tree, which every broadphase but brute force queries (for tests).
    const StaticTree& staticTree() const { return staticTree_; }

private:
    void sortIntoCanonicalOrder(const BodySet& bodies, std::vector<CandidatePair>& pairs);

    std::vector<Aabb> boxes_;                ///< One per dynamic body: the structure's proxies.
    std::vector<Aabb> staticBoxes_;          ///< One per kinematic body, for the static tree.
    std::vector<std::uint32_t> staticHits_;  ///< Scratch: the kinematic partners of one dynamic body.
    std::vector<ProxyPair> rawPairs_;        ///< What the structure found, in its own order.
    std::vector<std::uint32_t> pairStart_;   ///< Counting sort: where each dynamic body's pairs start.
    std::vector<std::uint32_t> partners_;    ///< Counting sort: each body's partners, grouped by body.
    SweepAndPrune sweepAndPrune_;
    StaticTree staticTree_;
    AabbTree tree_;
    UniformGrid grid_;
    LooseOctree octree_;
    BroadphaseKind lastKind_ = BroadphaseKind::BruteForce;
    std::uint32_t lastDynamicCount_ = 0;     ///< Dynamic bodies in the last call: boxes_ holds theirs first.
    BroadphaseChoice autoChoice_;
    bool autoChosen_ = false;
    BroadphaseCounters counters_;
};

}  // namespace stepwise
