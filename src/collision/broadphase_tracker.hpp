/// @file broadphase_tracker.hpp
/// @brief Runs every broadphase on the same bodies, checks each against brute force, and measures them.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "collision/broadphase.hpp"

namespace stepwise {

/// @brief The five broadphases, brute force (the reference) first.
inline constexpr std::array<BroadphaseKind, 5> kAllBroadphases = {
    BroadphaseKind::BruteForce, BroadphaseKind::SweepAndPrune, BroadphaseKind::AabbTree, BroadphaseKind::Grid,
    BroadphaseKind::Octree};

/// @brief One broadphase's totals over the steps the tracker watched.
struct TrackedBroadphase {
    BroadphaseKind kind = BroadphaseKind::BruteForce;  ///< Which broadphase.
    std::uint64_t steps = 0;            ///< Steps it ran.
    double seconds = 0;                 ///< Wall-clock time of those runs, s.
    std::uint64_t pairTests = 0;        ///< Σ body pairs whose boxes it compared (BroadphaseCounters::pairTests).
    std::uint64_t structureTests = 0;   ///< Σ other box tests (tree nodes).
    std::uint64_t reinsertions = 0;     ///< Σ tree leaves moved.
    std::uint64_t candidatePairs = 0;   ///< Σ pairs it returned.
    std::uint64_t contactPairs = 0;     ///< Σ pairs the narrowphase found touching, over the same steps.
    std::uint64_t missedContacts = 0;   ///< Pairs it missed that the narrowphase finds touching: errors.
    std::uint64_t otherDifferences = 0; ///< Other differences from brute force: missed pairs not touching, extra pairs, order.

    /// @brief Mean time per step, s.
    double secondsPerStep() const { return steps ? seconds / double(steps) : 0.0; }
    /// @brief True contacts per tested pair: the share of its work that found something.
    double efficiency() const { return pairTests ? double(contactPairs) / double(pairTests) : 0.0; }
};

/// @brief One pair on which a broadphase and brute force disagree.
struct BroadphaseDifference {
    std::uint64_t step = 0;                            ///< Step number (as passed to observe()).
    BroadphaseKind kind = BroadphaseKind::BruteForce;  ///< The broadphase that differs.
    CandidatePair pair;                                ///< The pair.
    bool missing = false;   ///< True: brute force has it, the broadphase not; false: the broadphase has it extra.
    bool touching = false;  ///< The narrowphase finds the pair touching (a missed touching pair is a lost contact).
    bool orderOnly = false; ///< Same pairs, different order (pair is the first out of place).
};

/// Differences kept for the report; further ones are only counted.
inline constexpr std::size_t kMaxKeptDifferences = 20;

/// @brief The broadphase tracker behind `stepwise bench broadphase`.
///
/// Call observe() once per step with the World's bodies. Every broadphase
/// keeps its own state (its tree, grid, sort order) from step to step, as it
/// would inside a World, and is timed on its own. On checked steps, brute
/// force runs too and every other broadphase's pairs must equal its pairs,
/// in the same order; each difference is recorded with the step and the pair,
/// and a missed pair the narrowphase would have found touching is an error.
class BroadphaseTracker {
public:
    /// @brief Tracks the broadphases @p kinds (brute force is always added, as the reference).
    explicit BroadphaseTracker(std::span<const BroadphaseKind> kinds = kAllBroadphases);

    /// @brief Runs every broadphase on @p bodies; compares them with brute force when @p check.
    void observe(const BodySet& bodies, std::uint64_t step, bool check = true);

    /// @brief Totals per broadphase, brute force first.
    const std::vector<TrackedBroadphase>& results() const { return results_; }
    /// @brief The totals sorted by time per step, fastest first.
    std::vector<TrackedBroadphase> ranked() const;
    /// @brief The first kMaxKeptDifferences differences.
    const std::vector<BroadphaseDifference>& differences() const { return differences_; }
    /// @brief Steps observed, and steps checked against brute force.
    std::uint64_t steps() const { return steps_; }
    /// @brief Steps on which the broadphases were compared with brute force.
    std::uint64_t checkedSteps() const { return checkedSteps_; }
    /// @brief True when no broadphase differed from brute force on any checked step.
    bool agrees() const;

private:
    std::vector<TrackedBroadphase> results_;
    std::vector<Broadphase> broadphases_;               ///< One per result, each with its own state.
    std::vector<std::vector<CandidatePair>> outputs_;   ///< Last output of each.
    std::vector<Contact> contacts_;                     ///< Scratch for counting touching pairs.
    std::vector<BroadphaseDifference> differences_;
    std::uint64_t steps_ = 0;
    std::uint64_t checkedSteps_ = 0;
};

/// @brief Compares a broadphase's pairs with brute force's, adding each difference to @p totals and
/// the first ones to @p kept (what BroadphaseTracker::observe() does for each broadphase).
/// @param reference brute force's pairs, in its order
/// @param candidate the pairs to check
void compareWithReference(const BodySet& bodies, std::span<const CandidatePair> reference,
                          std::span<const CandidatePair> candidate, std::uint64_t step, TrackedBroadphase& totals,
                          std::vector<BroadphaseDifference>& kept);

/// @brief True when the narrowphase finds the two bodies of @p pair touching (or within its speculative distance).
bool pairTouches(const BodySet& bodies, const CandidatePair& pair);

/// @brief "ball3" for a body of @p bodies.
const std::string& bodyName(const BodySet& bodies, const BodyRef& body);

}  // namespace stepwise
