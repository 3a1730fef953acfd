/// @file contact_colours.cpp
/// @brief Greedy colouring of the contacts and the pass order it gives (the why is in contact_colours.hpp).
#include "dynamics/contact_colours.hpp"

#include <algorithm>
#include <bit>
#include <cstddef>

#include "core/counting_sort.hpp"
#include "dynamics/contact_solver.hpp"

namespace stepwise {

std::uint32_t orderByColour(SolverWorkspace& workspace, std::vector<std::uint32_t>& list,
                            std::vector<std::uint32_t>& colourEnds) {
    if (list.size() < 2) {  // no contact or one: colour 0 at most, nothing to move
        colourEnds.assign(list.size() + 1, static_cast<std::uint32_t>(list.size()));
        return static_cast<std::uint32_t>(list.size());
    }
    ContactColouring& s = workspace.colouring;
    // 1. Each contact's colour: the lowest bit free in both bodies' masks (the static record 0
    //    never takes one: nothing moves it, any number of contacts may share it).
    s.usedColours.assign(workspace.bodies.size(), 0);
    s.colourOf.resize(list.size());
    std::uint32_t colours = 0;
    for (std::size_t k = 0; k < list.size(); ++k) {
        const SolverContact& c = workspace.contacts[list[k]];
        const bool bothDynamic = c.bodyB != kStaticSolverBody;
        const std::uint64_t used = s.usedColours[c.bodyA] | (bothDynamic ? s.usedColours[c.bodyB] : 0);
        const std::uint32_t colour = static_cast<std::uint32_t>(std::countr_one(used));  // kColourCount: none free
        s.colourOf[k] = colour;
        if (colour < kColourCount) {
            const std::uint64_t bit = std::uint64_t(1) << colour;
            s.usedColours[c.bodyA] |= bit;
            if (bothDynamic) s.usedColours[c.bodyB] |= bit;
        }
        if (colour + 1 > colours) colours = colour + 1;
    }
    // 2. Counting sort by colour, each colour's contacts in the list's order.
    countingSort<std::uint32_t>(list, s.colourOf, colours, colourEnds, s.ordered);
    list.swap(s.ordered);
    return colours;
}

void scheduleWaves(const SolverWorkspace& workspace, const std::vector<std::uint32_t>& list,
                   ContactWaveSchedule& schedule) {
    ContactWaveSchedule& s = schedule;
    // 1. Each contact's wave, walking them in order: one after the last wave of an earlier
    //    contact on either of its bodies.
    s.nextWave.assign(workspace.bodies.size(), 0);
    s.waveOf.resize(list.size());
    s.waves = 0;
    for (std::size_t k = 0; k < list.size(); ++k) {
        const SolverContact& c = workspace.contacts[list[k]];
        const bool bothDynamic = c.bodyB != kStaticSolverBody;  // nothing moves the static record: no wait
        const std::uint32_t wave = std::max(s.nextWave[c.bodyA], bothDynamic ? s.nextWave[c.bodyB] : 0);
        s.waveOf[k] = wave;
        s.nextWave[c.bodyA] = wave + 1;
        if (bothDynamic) s.nextWave[c.bodyB] = wave + 1;
        s.waves = std::max(s.waves, wave + 1);
    }
    // 2. Counting sort by wave, the contact order kept within a wave.
    countingSort<std::uint32_t>(list, s.waveOf, s.waves, s.ends, s.order);
}

}  // namespace stepwise
