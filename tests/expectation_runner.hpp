// Runs a scene the way `stepwise run` does and checks its Expect records.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "world/expectations.hpp"
#include "world/world.hpp"

namespace stepwise::test {

/// What a scene's Expect records came to.
struct ExpectationOutcome {
    std::vector<Expectation> expectations;  ///< The records checked.
    std::vector<ExpectationResult> results; ///< One verdict each.

    /// @brief How many passed.
    std::size_t passed() const {
        std::size_t count = 0;
        for (const ExpectationResult& r : results) count += r.passed ? 1 : 0;
        return count;
    }
    /// @brief True when every expectation passed (and there was at least one).
    bool allPassed() const { return !results.empty() && passed() == results.size(); }
};

/// Simulates @p scene for its Duration, observing after every step as `stepwise run` does.
inline ExpectationOutcome runExpectations(Scene scene) {
    ExpectationOutcome outcome;
    outcome.expectations = scene.expectations;
    World world(std::move(scene));
    ExpectationMonitor monitor(world, outcome.expectations);
    monitor.observe(world);
    const auto steps = static_cast<std::uint64_t>(std::llround(world.settings().duration / world.settings().timeStep));
    for (std::uint64_t i = 0; i < steps; ++i) {
        world.step();
        monitor.observe(world);
    }
    outcome.results = monitor.results(world);
    return outcome;
}

}  // namespace stepwise::test
