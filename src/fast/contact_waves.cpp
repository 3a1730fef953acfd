/// @file contact_waves.cpp
/// @brief The waves of a pass list: its colours, or its list schedule (the why is in contact_waves.hpp).
#include "fast/contact_waves.hpp"

#include <algorithm>
#include <cstddef>

#include "dynamics/contact_colours.hpp"
#include "dynamics/contact_solver.hpp"
#include "fast/fast_workspace.hpp"

namespace stepwise {

ContactWaves contactWaves(const SolverWorkspace& solver, const std::vector<std::uint32_t>& list,
                          const std::vector<std::uint32_t>& colourEnds, FastWorkspace& fast) {
    // colourEnds: one entry per colour, then the list's size. kColourCount + 1 colours: the last
    // is the group that found no colour, which is not a wave.
    const bool coloured = !colourEnds.empty() && colourEnds.back() == list.size() && colourEnds.size() <= kColourCount + 1;
    if (coloured) {
        fast.waves = static_cast<std::uint32_t>(colourEnds.size() - 1);
        return {list, std::span(colourEnds).first(fast.waves)};
    }
    scheduleWaves(solver, list, fast.schedule);
    fast.waves = fast.schedule.waves;
    return {fast.schedule.order, std::span(fast.schedule.ends).first(fast.waves)};
}

}  // namespace stepwise
