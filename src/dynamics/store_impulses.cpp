/// @file store_impulses.cpp
/// @brief The end of the step: each contact's impulses kept, by key, for the next step's warm start.
#include "dynamics/contact_solver.hpp"

#include <span>

#include "core/insertion_sort.hpp"

#include "objects/inertia.hpp"

namespace stepwise {

void storeContactImpulses(std::span<const Contact> contacts, SolverWorkspace& workspace,
                          std::span<ImpulseReport> reports) {
    workspace.currentImpulses.clear();
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const SolverContact& c = workspace.contacts[i];
        const ContactStart& start = workspace.starts[i];
        const Vec3 friction = c.tangentImpulse[0] * c.tangent[0] + c.tangentImpulse[1] * c.tangent[1];
        workspace.currentImpulses.push_back({keyOf(contacts[i]), c.normalImpulse, friction});
        if (!reports.empty()) {
            reports[i] = {start.approachAtTouch, start.approachAtTouch, start.restitution, c.normalImpulse,
                          glm::length(friction)};
        }
    }
    // In key order for next step's lookups. The narrowphase's order is the keys' order but for
    // the points of one pair, whose feature ids need not ascend (a box's manifold): each entry is
    // at most a pair's few points from its place, so insertion sort puts them right in O(n).
    const auto byKey = [](const CachedImpulse& x, const CachedImpulse& y) { return x.key < y.key; };
    insertionSort(std::span(workspace.currentImpulses), byKey);
    std::swap(workspace.previousImpulses, workspace.currentImpulses);
    // ω was updated alongside L with the step's fixed I⁻¹; make them agree exactly again.
    // Once per body in a contact: the result depends only on L and the orientation.
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) updateAngularVelocity(workspace.dynamics[workspace.recordBody[i]]);
}

}  // namespace stepwise
