/// @file materials.cpp
/// @brief The pair table of ContactMaterials: built once, searched per contact only when needed.
#include "objects/materials.hpp"

#include <algorithm>

namespace stepwise {

ContactMaterials::ContactMaterials(const WorldSettings& settings, std::size_t materialCount,
                                   std::span<const MaterialPair> pairs)
    : frictionRule_(settings.frictionCombine), elasticityRule_(settings.elasticityCombine) {
    for (const MaterialPair& pair : pairs) {
        if (pair.a >= materialCount || pair.b >= materialCount) continue;  // the loader never gives such a pair
        Entry entry{keyOf(pair.a, pair.b), pair.friction, pair.elasticity};
        // A later record for the same pair fills in or replaces what an earlier one gave.
        const auto same = std::find_if(pairs_.begin(), pairs_.end(), [&](const Entry& e) { return e.key == entry.key; });
        if (same == pairs_.end()) {
            pairs_.push_back(entry);
        } else {
            if (entry.friction) same->friction = entry.friction;
            if (entry.elasticity) same->elasticity = entry.elasticity;
        }
    }
    std::sort(pairs_.begin(), pairs_.end(), [](const Entry& x, const Entry& y) { return x.key < y.key; });
    plain_ = frictionRule_ == CombineRule::Product && elasticityRule_ == CombineRule::Product && pairs_.empty();
}

std::uint64_t ContactMaterials::keyOf(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t low = std::min(a, b);
    const std::uint32_t high = std::max(a, b);
    return (std::uint64_t(low) << 32) | high;
}

ContactCoefficients ContactMaterials::mix(std::uint32_t materialA, Real frictionA, Real elasticityA,
                                          std::uint32_t materialB, Real frictionB, Real elasticityB) const {
    ContactCoefficients c{combine(frictionRule_, frictionA, frictionB),
                          combine(elasticityRule_, elasticityA, elasticityB)};
    if (pairs_.empty() || materialA == kNoMaterial || materialB == kNoMaterial) return c;
    const std::uint64_t key = keyOf(materialA, materialB);
    const auto found = std::lower_bound(pairs_.begin(), pairs_.end(), key,
                                        [](const Entry& e, std::uint64_t k) { return e.key < k; });
    if (found == pairs_.end() || found->key != key) return c;
    if (found->friction) c.friction = *found->friction;
    if (found->elasticity) c.elasticity = *found->elasticity;
    return c;
}

}  // namespace stepwise
