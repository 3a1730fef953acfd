/// @file contact_colours.cpp
/// @brief Greedy colouring of the contacts and the pass order it gives (the why is in contact_colours.hpp).
#include "dynamics/contact_colours.hpp"

#include <bit>
#include <cstddef>

#include "dynamics/contact_solver.hpp"

namespace stepwise {

std::uint32_t orderByColour(SolverWorkspace& workspace, std::vector<std::uint32_t>& list) {
    if (list.size() < 2) return static_cast<std::uint32_t>(list.size());
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
    s.colourStart.assign(colours + 1, 0);
    for (const std::uint32_t colour : s.colourOf) ++s.colourStart[colour + 1];
    for (std::uint32_t colour = 0; colour < colours; ++colour) s.colourStart[colour + 1] += s.colourStart[colour];
    s.ordered.resize(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) s.ordered[s.colourStart[s.colourOf[k]]++] = list[k];
    list.swap(s.ordered);
    return colours;
}

}  // namespace stepwise
