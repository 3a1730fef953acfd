/// @file contact_waves.cpp
/// @brief List scheduling of contacts into waves (the why and the formula are in contact_waves.hpp).
#include "fast/contact_waves.hpp"

#include <algorithm>
#include <cstddef>

#include "dynamics/contact_solver.hpp"
#include "fast/fast_workspace.hpp"

namespace stepwise {

void scheduleWaves(const SolverWorkspace& solver, const std::vector<std::uint32_t>& list, FastWorkspace& fast) {
    // Each contact's wave, walking them in order: one after the last wave of an earlier
    // contact on either of its bodies.
    fast.nextWave.assign(solver.bodies.size(), 0);  // per record: the wave its next contact may take
    fast.waveOf.resize(list.size());
    fast.waves = 0;
    for (std::size_t k = 0; k < list.size(); ++k) {
        const SolverContact& c = solver.contacts[list[k]];
        const bool bothDynamic = c.bodyB != kStaticSolverBody;  // nothing moves the static record: no wait
        const std::uint32_t wave = std::max(fast.nextWave[c.bodyA], bothDynamic ? fast.nextWave[c.bodyB] : 0);
        fast.waveOf[k] = wave;
        fast.nextWave[c.bodyA] = wave + 1;
        if (bothDynamic) fast.nextWave[c.bodyB] = wave + 1;
        fast.waves = std::max(fast.waves, wave + 1);
    }
    // Counting sort by wave, the contact order kept within a wave.
    const std::uint32_t waves = fast.waves;
    fast.waveStart.assign(waves + 1, 0);
    for (const std::uint32_t wave : fast.waveOf) ++fast.waveStart[wave + 1];
    for (std::uint32_t wave = 0; wave < waves; ++wave) fast.waveStart[wave + 1] += fast.waveStart[wave];
    fast.waveOrder.resize(list.size());
    // Placing moves each wave's start to its end.
    for (std::size_t k = 0; k < list.size(); ++k) fast.waveOrder[fast.waveStart[fast.waveOf[k]]++] = list[k];
}

}  // namespace stepwise
