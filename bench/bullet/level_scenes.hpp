/// @file level_scenes.hpp
/// @brief The side-by-side scenes of issue #33: levels built of static boxes, and jointed bodies.
///
/// Four scenes as users build them (default solver settings, default
/// substeps), each run in Stepwise and in Bullet from the same Scene, each
/// with a figure of its accuracy beside its speed:
///
/// | scene      | what                                                       | accuracy (smaller is better) |
/// |------------|------------------------------------------------------------|------------------------------|
/// | wall rain  | spheres into a box of static boxes (wall_rain_scene.hpp)   | worst overlap, sphere–sphere and sphere–wall; escapes |
/// | box pile   | 1000 boxes into a box of static boxes (box_pile_scene.hpp) | worst overlap, box–box and box–wall; escapes; speed at the end |
/// | chain      | config/bench_chain.scene: 100 links on BallJoints          | worst gap between a joint's anchors; stretch; energy |
/// | ragdoll    | config/bench_ragdoll.scene: 20 boxes, Ball and Hinge joints | worst anchor gap, hinge-axis angle, floor overlap; speed at the end |
///
/// and the threads table: the same scene with `Threads=1` and `Threads=2`,
/// stepped in turn in one process, so the machine's load falls on both.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "side_by_side_table.hpp"

namespace stepwise::bench {

/// @brief One scene's speed and its main accuracy figure in both engines (for the verdicts and the CSV).
struct SceneFigure {
    std::string scene;         ///< "wall rain 1000", "chain", …
    double ourCpu = 0;         ///< Stepwise's CPU s per step (median).
    double theirCpu = 0;       ///< Bullet's CPU s per step (median).
    std::string accuracy;      ///< The accuracy figure's name and unit, e.g. "worst overlap (mm)".
    double ours = 0;           ///< Stepwise's accuracy figure, in that unit (smaller is better).
    double theirs = 0;         ///< Bullet's.
    std::string whereTimeGoes; ///< For a missed speed target: whereTheStepGoes(); empty when met.
};

/// @brief Stepwise at least this many times Bullet's speed (issues #7 and #33).
inline constexpr double kSpeedTarget = 2;

/// @brief Why a scene misses the speed target, in figures of this run: the three largest stages'
/// shares of Stepwise's step over @p steps steps of @p scene on one thread, timed stage by stage
/// (World::timeStages()), and the Gauss–Seidel passes a step against Bullet's @p bulletIterations.
/// Empty when Bullet's @p theirCpu ÷ Stepwise's @p ourCpu meets kSpeedTarget (nothing is run then).
std::string whereTheStepGoes(const Scene& scene, int steps, double ourCpu, double theirCpu, int bulletIterations);

/// @brief Wall-clock time per step of one scene on one thread and on two, stepped in turn.
struct ThreadFigure {
    std::string scene;      ///< Which scene.
    double oneThread = 0;   ///< Median wall s per step, `Threads=1`.
    double twoThreads = 0;  ///< Median wall s per step, `Threads=2`.
};

/// @brief The wall rain of @p count spheres for @p steps steps (kQuickSteps when @p quick).
Table wallRain(std::size_t count, int steps, bool quick, std::vector<SceneFigure>& figures);

/// @brief The box pile of @p count boxes, for its scene's duration (kQuickSteps when @p quick).
Table boxPile(std::size_t count, bool quick, std::vector<SceneFigure>& figures);

/// @brief The chain of @p path (config/bench_chain.scene).
Table chain(const std::string& path, bool quick, std::vector<SceneFigure>& figures);

/// @brief The ragdoll of @p path (config/bench_ragdoll.scene).
Table ragdoll(const std::string& path, bool quick, std::vector<SceneFigure>& figures);

/// @brief Stepwise alone: each of @p scenes (name, scene) with one thread and with two, @p steps steps.
Table threadScaling(const std::vector<std::pair<std::string, Scene>>& scenes, int steps,
                    std::vector<ThreadFigure>& figures);

/// @brief The wall rain's scene of @p count spheres (seed 1, as the tables run it).
Scene wallRainScene(std::size_t count);
/// @brief The box pile's scene of @p count boxes (seed 1, as the tables run it).
Scene boxPileScene(std::size_t count);

}  // namespace stepwise::bench
