/// @file fast_path_counts.hpp
/// @brief What the fast path reports: how many steps it ran, and how many waves it split between threads.
#pragma once

#include <cstdint>

namespace stepwise {

/// @brief How many steps took the fast path, and how many of those ran on the packed records (World::fastPathCounts()).
struct FastPathCounts {
    std::uint64_t steps = 0;        ///< Steps whose substeps ran on the fast path.
    std::uint64_t packedSteps = 0;  ///< Of those, the steps whose substeps ran on the packed records.
    std::uint64_t splitWaves = 0;   ///< Waves of a contact pass cut between several threads (parallel_waves.hpp).
    std::uint64_t boxLaneSteps = 0; ///< Of those, the steps whose contacts with stored rows were solved in lanes (box_contact_lanes.hpp).
};

}  // namespace stepwise
