/// @file run_watch.hpp
/// @brief What a run must tell its user although nothing failed: a body pushed through a plane,
/// and two bodies in contact whose masses differ more than the solver can hold.
///
/// Neither stops a run. A body whose centre is behind a CollisionPlane has gone through the
/// surface: the solver was asked for more than it can give (a mass ratio beyond kMaxMassRatio
/// pressing it down, or a speed too high for the step with ContinuousCollision off), and the
/// numbers that follow are not physics. Saying so, with the names and the step, is better than a
/// summary that looks right. `stepwise run` prints these warnings as they happen.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_set>
#include <vector>

#include "world/world.hpp"

namespace stepwise {

/// @brief Looks at the World after each step and says, once per body or pair, what went wrong.
class RunWatch {
public:
    /// @brief Prepares to watch @p world (its bodies and planes must not be added to afterwards).
    explicit RunWatch(const World& world);

    /// @brief The new warnings after the step just taken, each one line ("step 12 (t = 0.2 s): ...").
    std::vector<std::string> observe(const World& world);

    /// @brief How many warnings were given in all, including those no longer printed.
    std::size_t count() const { return count_; }

private:
    std::vector<std::uint8_t> throughPlane_;  ///< Per dynamic body: already reported behind a plane.
    std::unordered_set<std::uint64_t> unequalPairs_;  ///< Pairs (a, b), a < b, already reported, as a·n + b.
    std::size_t count_ = 0;
};

}  // namespace stepwise
