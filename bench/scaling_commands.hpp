/// @file scaling_commands.hpp
/// @brief The command lines of `stepwise-bench scaling`, `stage-costs`, `bullet`, `rain-scene` and `pile-scene` (bench/main.cpp dispatches).
#pragma once

#include <string>
#include <vector>

namespace stepwise::bench {

/// @brief `stepwise-bench scaling [--quick] [--sizes LIST] [--pile-sizes LIST] [--steps N] [--large-steps N]
/// [--pile-steps N] [--seed S] [--markdown PATH]`; @p args start after the subcommand. Returns the exit code.
int scalingCommand(const std::vector<std::string>& args);

/// @brief `stepwise-bench stage-costs [--quick] [--sizes LIST] [--settle N] [--rounds N] [--seed S] [--markdown PATH]`.
int stageCostsCommand(const std::vector<std::string>& args);

/// @brief `stepwise-bench bullet [--quick] [--sizes LIST] [--markdown PATH] [--config DIR]`; exit code 2 with
/// a message when the program was built without Bullet.
int bulletCommand(const std::vector<std::string>& args);

/// @brief `stepwise-bench rain-scene --count N [--seed S] --out FILE`: writes the sphere-rain scene.
int rainSceneCommand(const std::vector<std::string>& args);

/// @brief `stepwise-bench pile-scene --count N [--seed S] --out FILE`: writes the box pile (box_pile_scene.hpp).
int pileSceneCommand(const std::vector<std::string>& args);

/// @brief Usage of these commands, for `stepwise-bench --help`.
extern const char* const kScalingUsage;

}  // namespace stepwise::bench
