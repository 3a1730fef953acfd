/// @file broadphase_tracker.cpp
/// @brief The broadphase tracker: every broadphase on the same bodies, timed, and checked against brute force.
#include "collision/broadphase_tracker.hpp"

#include <algorithm>
#include <chrono>
#include <tuple>

#include "collision/narrowphase.hpp"

namespace stepwise {

namespace {

/// The canonical order of candidate pairs: by body A, then B's kind, then B's index.
auto orderKey(const CandidatePair& p) { return std::tuple(p.a, p.b.kind, p.b.index); }

bool before(const CandidatePair& p, const CandidatePair& q) { return orderKey(p) < orderKey(q); }

bool same(const CandidatePair& p, const CandidatePair& q) { return orderKey(p) == orderKey(q); }

/// Pairs in @p contacts with at least one contact point (contacts of one pair are consecutive).
std::uint64_t countTouchingPairs(const std::vector<Contact>& contacts) {
    std::uint64_t count = 0;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        if (i == 0 || contacts[i].a != contacts[i - 1].a || contacts[i].b.kind != contacts[i - 1].b.kind ||
            contacts[i].b.index != contacts[i - 1].b.index) {
            ++count;
        }
    }
    return count;
}

}  // namespace

bool pairTouches(const BodySet& bodies, const CandidatePair& pair) {
    const Geometry a = geometryOf(bodies.dynamics[pair.a]);
    const Geometry b = geometryOf(bodies, pair.b);
    const PairTest test = pairTestFor(a.type, b.type);
    ContactManifold manifold;
    return test != nullptr && test(a, b, manifold) && manifold.pointCount > 0;
}

const std::string& bodyName(const BodySet& bodies, const BodyRef& body) {
    switch (body.kind) {
        case BodyKind::Dynamic: return bodies.dynamics[body.index].name;
        case BodyKind::Kinematic: return bodies.kinematics[body.index].name;
        case BodyKind::Plane: break;
    }
    return bodies.planes[body.index].name;
}

void compareWithReference(const BodySet& bodies, std::span<const CandidatePair> reference,
                          std::span<const CandidatePair> candidate, std::uint64_t step, TrackedBroadphase& totals,
                          std::vector<BroadphaseDifference>& kept) {
    const auto record = [&](const BroadphaseDifference& difference) {
        if (difference.missing && difference.touching) {
            ++totals.missedContacts;
        } else {
            ++totals.otherDifferences;
        }
        if (kept.size() < kMaxKeptDifferences) kept.push_back(difference);
    };
    if (std::equal(reference.begin(), reference.end(), candidate.begin(), candidate.end(), same)) return;

    // Out of order? Report the first pair out of place, then compare the sets.
    std::vector<CandidatePair> sorted(candidate.begin(), candidate.end());
    const auto unsorted = std::is_sorted_until(sorted.begin(), sorted.end(), before);
    if (unsorted != sorted.end()) {
        record({step, totals.kind, *unsorted, false, false, true});
        std::sort(sorted.begin(), sorted.end(), before);
    }

    // Both sorted now: walk them side by side, as in a merge.
    std::size_t i = 0, j = 0;
    while (i < reference.size() || j < sorted.size()) {
        if (j == sorted.size() || (i < reference.size() && before(reference[i], sorted[j]))) {
            record({step, totals.kind, reference[i], true, pairTouches(bodies, reference[i]), false});
            ++i;
        } else if (i == reference.size() || before(sorted[j], reference[i])) {
            record({step, totals.kind, sorted[j], false, pairTouches(bodies, sorted[j]), false});
            ++j;
        } else {
            ++i;
            ++j;
        }
    }
}

BroadphaseTracker::BroadphaseTracker(std::span<const BroadphaseKind> kinds) {
    results_.push_back({});  // brute force, the reference
    for (const BroadphaseKind kind : kinds) {
        if (kind == BroadphaseKind::BruteForce || kind == BroadphaseKind::Auto) continue;
        TrackedBroadphase tracked;
        tracked.kind = kind;
        results_.push_back(tracked);
    }
    broadphases_.resize(results_.size());
    outputs_.resize(results_.size());
}

void BroadphaseTracker::observe(const BodySet& bodies, std::uint64_t step, bool check) {
    using Clock = std::chrono::steady_clock;
    ++steps_;
    if (check) ++checkedSteps_;
    // Brute force runs only on checked steps: on a large scene it is by far the slowest.
    const std::size_t first = check ? 0 : 1;
    for (std::size_t k = first; k < results_.size(); ++k) {
        TrackedBroadphase& tracked = results_[k];
        const auto start = Clock::now();
        broadphases_[k].findPairs(tracked.kind, bodies, outputs_[k]);
        tracked.seconds += std::chrono::duration<double>(Clock::now() - start).count();
        tracked.steps += 1;
        const BroadphaseCounters& counters = broadphases_[k].counters();
        tracked.pairTests += counters.pairTests;
        tracked.structureTests += counters.structureTests;
        tracked.reinsertions += counters.reinsertions;
        tracked.candidatePairs += outputs_[k].size();
    }
    if (first >= results_.size()) return;

    // True contacts: the pairs of the reference (or, unchecked, of the first
    // broadphase) that the narrowphase finds touching.
    findContacts(bodies, outputs_[first], contacts_);
    const std::uint64_t touching = countTouchingPairs(contacts_);
    for (std::size_t k = first; k < results_.size(); ++k) {
        const std::uint64_t missedBefore = results_[k].missedContacts;
        if (check && k > 0) {
            compareWithReference(bodies, outputs_[0], outputs_[k], step, results_[k], differences_);
        }
        results_[k].contactPairs += touching - (results_[k].missedContacts - missedBefore);
    }
}

std::vector<TrackedBroadphase> BroadphaseTracker::ranked() const {
    std::vector<TrackedBroadphase> sorted = results_;
    std::stable_sort(sorted.begin(), sorted.end(), [](const TrackedBroadphase& p, const TrackedBroadphase& q) {
        return p.secondsPerStep() < q.secondsPerStep();
    });
    return sorted;
}

bool BroadphaseTracker::agrees() const {
    return std::all_of(results_.begin(), results_.end(), [](const TrackedBroadphase& tracked) {
        return tracked.missedContacts == 0 && tracked.otherDifferences == 0;
    });
}

}  // namespace stepwise
