/// @file finite_state.hpp
/// @brief The check after every stage: is each number a stage wrote into a body still finite?
///
/// A NaN or an infinity, once in a body's state, spreads through every
/// contact and every step that touches it, and ten seconds later the screen
/// is empty. So after each stage the step checks what that stage may have
/// written, and the first non-finite number stops the run with a
/// SimulationError naming the body, the quantity, the stage and the step.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "core/stages.hpp"
#include "objects/game_object.hpp"

namespace stepwise {

/// @brief The parts of a dynamic body's state a stage may write; a check reads only those.
enum StateParts : unsigned {
    kPose = 1u << 0,    ///< position, orientation
    kMotion = 1u << 1,  ///< velocity, angular velocity, angular momentum
    kForces = 1u << 2,  ///< acceleration, torque
    kEverything = kPose | kMotion | kForces,
};

/// @brief Where a check runs, to name it when it fails: the stage, and the step being taken.
struct StageAtStep {
    Stage stage = Stage::Count;  ///< The stage that just ran.
    std::uint64_t step = 0;      ///< The step being taken, from 1: World::stepCount() + 1.
    double time = 0;             ///< Simulated time at the step's start, s.
};

/// @brief Zero exactly when the @p parts of @p body's state are finite (a branch-free sum of
/// zeroIfFinite(), core/types.hpp): cheap enough to take for every body after every stage.
Real finiteProbe(const DynamicObject& body, unsigned parts);

/// @brief Throws SimulationError "non-finite QUANTITY" naming @p object, the stage and the step.
[[noreturn]] void failNonFinite(const std::string& object, const char* quantity, const StageAtStep& where);

/// @brief Throws SimulationError for the first body of @p bodies whose @p parts are not all finite.
void requireFiniteState(std::span<const DynamicObject> bodies, unsigned parts, const StageAtStep& where);

/// @brief The same for the bodies of @p bodies at the indices @p which only.
void requireFiniteState(std::span<const DynamicObject> bodies, std::span<const std::uint32_t> which, unsigned parts,
                        const StageAtStep& where);

/// @brief Throws SimulationError for the first kinematic body whose position or orientation is not finite.
void requireFiniteState(std::span<const KinematicsObject> bodies, const StageAtStep& where);

}  // namespace stepwise
