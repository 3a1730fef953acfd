/// @file kill_region.cpp
/// @brief Effect=Kill: which bodies leave the world (the World removes them).
#include "forces/kill_region.hpp"

#include <algorithm>

namespace stepwise {

bool anyKillRegion(std::span<const Region> regions) {
    return std::any_of(regions.begin(), regions.end(), [](const Region& r) { return r.effect == RegionEffect::Kill; });
}

}  // namespace stepwise
