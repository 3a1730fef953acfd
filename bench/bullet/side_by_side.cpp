/// @file side_by_side.cpp
/// @brief `stepwise-bench bullet`: Stepwise and Bullet 3 on the same scene files, one table per scenario.
///
/// Each scenario loads one scene file (or the generated sphere rain), builds
/// a Stepwise World and a BulletWorld from the same Scene, steps each the
/// same number of times with the same h, and measures both with the same
/// meters (scenario_metrics.hpp) from their body states. Only the steps are
/// timed (the median of the per-step times: the machine is shared). The
/// last column is Bullet's figure divided by Stepwise's for figures where
/// smaller is better (time, overlap, drift, error): above 1, Stepwise does better.
#include "side_by_side.hpp"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <memory>
#include <optional>
#include <utility>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>

#include "../reference_problems.hpp"
#include "../scenario_metrics.hpp"
#include "../sphere_rain_scene.hpp"
#include "bullet_world.hpp"
#include "level_scenes.hpp"
#include "side_by_side_table.hpp"
#include "config/scene_loader.hpp"
#include "world/world.hpp"

namespace stepwise::bench {

namespace {

constexpr std::size_t kQuickRain = 300;     ///< Spheres of the --quick rain.
constexpr std::size_t kPileBoxes = 1000;    ///< Boxes of the box pile (issue #33).
constexpr std::size_t kQuickPile = 100;     ///< Boxes of the --quick box pile.
constexpr Real kFineTimeStep = Real(1) / Real(240);  ///< The bounce's second time step, s.
constexpr Real kInclineTime = 2;            ///< Incline: accelerations measured over the first 2 s.
constexpr int kApexesCompared = 4;          ///< Bounce: the first four apexes, e^(2n)·h₀, n = 1…4.

/// @brief What one run measured of the targets of issue #7, filled in by the scenarios that ran.
///
/// The verdicts are computed here, from the figures of the same run, so the
/// page that prints them cannot disagree with the tables above it.
struct Targets {
    struct Rain {
        std::size_t count = 0;
        double ourCpu = 0, theirCpu = 0;  ///< CPU s per step (medians).
        double ourOverlap = 0;            ///< Worst overlap, m.
        std::size_t escaped = 0;          ///< Stepwise's spheres out of the box at the end.
        // The same rain with Substeps=kRainFewerSubsteps (sphereRain()).
        double fewerCpu = 0;              ///< CPU s per step (median).
        double fewerOverlap = 0;          ///< Worst overlap, m.
        std::size_t fewerEscaped = 0;     ///< Spheres out of the box at the end.
    };
    std::vector<Rain> rains;
    std::vector<std::pair<std::string, bool>> stacks;  ///< Scene, and whether Stepwise's stands.
    std::optional<double> momentumDrift;               ///< Free box: worst ‖L − L0‖/‖L0‖.
    std::vector<std::pair<int, double>> bounces;       ///< 1/h, and the worst relative apex error.
    /// Every other timed scene: its name, and Stepwise's and Bullet's time per step (s).
    /// No target covers them; the table lists those where Bullet is the faster.
    struct Timed {
        std::string scene;
        double ours = 0, theirs = 0;
    };
    std::vector<Timed> others;
    /// Issue #33: every scene's speed and main accuracy figure in both engines.
    std::vector<SceneFigure> scenes;
    /// Issue #33: the wall rain and box pile on one thread and on two.
    std::vector<ThreadFigure> threads;
};

/// The rain is also run with this many substeps instead of the default 16: the
/// fewest of the 1k sweep (rainSweep()) whose worst overlap stays clearly under
/// the 5 mm target (3.0 mm at 1k). The default keeps four more for stacks at rest
/// (a heavy box on a light one), not for the rain.
constexpr int kRainFewerSubsteps = 12;
constexpr double kOverlapTarget = 5e-3;            ///< Worst sphere overlap under 5 mm, m.
constexpr double kMomentumTarget = 1e-6;           ///< A free body's |L| kept to 1e-6 (relative).
constexpr double kBounceTarget = 0.02;             ///< Bounce apexes within 2 % of e^(2n)·h.
/// "Flat" cost per body: the largest rain's µs per sphere within 25 % of the
/// smallest's. (The issue asks for flat; 25 % is the tolerance this table
/// states for it, over 16 times the bodies.)
constexpr double kFlatCostTolerance = 0.25;
constexpr double kPercent = 100;  ///< Per cent in one.

/// The table of verdicts: one row per target, with the figure measured and "yes" or "no".
void printTargets(std::FILE* out, const Targets& t, bool markdown) {
    std::vector<std::array<std::string, 3>> rows;
    const auto verdict = [](bool met) { return std::string(met ? "yes" : "no"); };
    for (const Targets::Rain& r : t.rains) {
        const double speed = r.theirCpu / r.ourCpu;
        rows.push_back({"rain " + std::to_string(r.count) + ": at least 2× Bullet's speed",
                        format("%.2f", kMs * r.ourCpu) + " against " + format("%.2f", kMs * r.theirCpu) +
                            " ms CPU: " + (speed >= 1 ? format("%.2f× faster", speed) : format("%.2f× slower", 1 / speed)),
                        verdict(speed >= kSpeedTarget)});
        rows.push_back({"rain " + std::to_string(r.count) + ": worst overlap under 5 mm, none escapes",
                        format("%.1f mm", kMs * r.ourOverlap) + ", " + std::to_string(r.escaped) + " escaped",
                        verdict(r.ourOverlap < kOverlapTarget && r.escaped == 0)});
    }
    for (const Targets::Rain& r : t.rains) {
        const double speed = r.theirCpu / r.fewerCpu;
        rows.push_back({"rain " + std::to_string(r.count) + " with `Substeps=" + std::to_string(kRainFewerSubsteps) +
                            "` (not the default): 2× Bullet's speed and worst overlap under 5 mm, none escapes",
                        format("%.2f", kMs * r.fewerCpu) + " against " + format("%.2f", kMs * r.theirCpu) + " ms CPU (" +
                            format("%.2f×", speed) + "), " + format("%.1f mm", kMs * r.fewerOverlap) + ", " +
                            std::to_string(r.fewerEscaped) + " escaped",
                        verdict(speed >= kSpeedTarget && r.fewerOverlap < kOverlapTarget && r.fewerEscaped == 0)});
    }
    if (t.rains.size() >= 2) {
        const Targets::Rain& small = t.rains.front();
        const Targets::Rain& large = t.rains.back();
        const double perSmall = small.ourCpu / double(small.count), perLarge = large.ourCpu / double(large.count);
        const double growth = perLarge / perSmall - 1;
        const double bulletGrowth = (large.theirCpu / double(large.count)) / (small.theirCpu / double(small.count)) - 1;
        // The issue asks for flat up to 64 000 bodies; this table has only the sizes Bullet runs too,
        // each in its own run (the machine's mood differs between them), and says where the firmer
        // figure is: the sizes stepped in turn, settled (bench/stage_costs.cpp).
        rows.push_back({"cost per sphere flat (within " + format("%.0f %%", kPercent * kFlatCostTolerance) + ") from " +
                            std::to_string(small.count) + " to " + std::to_string(large.count) +
                            ", each size in its own run (to 64000, sizes stepped in turn: Scaling, stage by stage)",
                        format("%.1f", 1e6 * perSmall) + " → " + format("%.1f", 1e6 * perLarge) + " µs (" +
                            format("%+.0f %%", kPercent * growth) + "; Bullet " + format("%+.0f %%", kPercent * bulletGrowth) + ")",
                        verdict(std::abs(growth) <= kFlatCostTolerance)});
    }
    for (const auto& [scene, stands] : t.stacks) {
        rows.push_back({scene + " stands", stands ? "stands" : "falls", verdict(stands)});
    }
    if (t.momentumDrift) {
        // Stepwise integrates L itself (ω = I⁻¹·L is derived), so with no torque
        // nothing but rounding could change it: the target is met by the design.
        rows.push_back({"free body: angular momentum kept to 1e-6",
                        format("%.2e", *t.momentumDrift) + " (L is the state Stepwise integrates)",
                        verdict(*t.momentumDrift <= kMomentumTarget)});
    }
    for (const auto& [inverseH, error] : t.bounces) {
        rows.push_back({"bounce apexes within 2 % at h = 1/" + std::to_string(inverseH),
                        std::isfinite(error) ? format("%.2f %%", kPercent * error) : std::string("no bounce"),
                        verdict(error <= kBounceTarget)});
    }
    // No target covers the other scenes' speed; where Bullet is faster, the table says so too.
    std::string slower;
    for (const Targets::Timed& timed : t.others) {
        if (timed.ours <= timed.theirs) continue;
        slower += (slower.empty() ? "" : ", ") + timed.scene + " " + format("%.1f×", timed.ours / timed.theirs);
    }
    if (rows.empty()) return;
    if (markdown) {
        std::fprintf(out, "\n**Against the targets of issue #7** (computed from the tables above, same run)\n\n"
                          "| target for Stepwise | measured | met? |\n|---|---|---|\n");
        for (const auto& r : rows) std::fprintf(out, "| %s | %s | %s |\n", r[0].c_str(), r[1].c_str(), r[2].c_str());
        if (!slower.empty()) {
            std::fprintf(out, "\nWhere Bullet is faster in this run (Stepwise's time per step ÷ Bullet's, from the "
                              "tables above; no target covers these): %s.\n", slower.c_str());
        }
        return;
    }
    std::fprintf(out, "\nAgainst the targets of issue #7\n");
    for (const auto& r : rows) std::fprintf(out, "  %-52s %-56s %s\n", r[0].c_str(), r[1].c_str(), r[2].c_str());
    if (!slower.empty()) std::fprintf(out, "  Where Bullet is faster (Stepwise's time ÷ Bullet's): %s\n", slower.c_str());
}

/// Issue #33: two threads at least this much faster than one on the wall rain and the pile.
constexpr double kThreadTarget = 1.7;

/// @brief The table of verdicts of issue #33, a row per scene: its speed against
/// Bullet's (at least 2×?) and its main accuracy figure against Bullet's (better?);
/// then a row per threaded scene (two threads at least 1.7× one?). All from this run.
void printIssue33Targets(std::FILE* out, const Targets& t, bool markdown) {
    if (t.scenes.empty() && t.threads.empty()) return;
    const auto verdict = [](bool met) { return std::string(met ? "yes" : "no"); };
    std::vector<std::array<std::string, 7>> rows;
    for (const SceneFigure& f : t.scenes) {
        const double speed = f.theirCpu / f.ourCpu;
        // Better: a smaller figure; both at zero (nothing to improve on) counts as met.
        // A figure a run could not measure (NaN: too few steps for a period) has no verdict.
        const bool better = f.ours < f.theirs || (f.ours == 0 && f.theirs == 0);
        const bool measured = !std::isnan(f.ours) && !std::isnan(f.theirs);
        // "unmeasured", not "nan": the scene's own table gives the reason in its note row
        const auto figure = [](double value) { return std::isnan(value) ? std::string("unmeasured") : format("%.3g", value); };
        rows.push_back({f.scene,
                        format("%.3f", kMs * f.ourCpu) + " / " + format("%.3f", kMs * f.theirCpu) + " ms (" +
                            format("%.2f×", speed) + ")",
                        verdict(speed >= kSpeedTarget), f.accuracy,
                        figure(f.ours) + " / " + figure(f.theirs), measured ? verdict(better) : "—",
                        f.whereTimeGoes});
    }
    if (markdown) {
        std::fprintf(out, "\n**Against the targets of issue #33** (same run; Stepwise / Bullet, CPU medians, the "
                          "pendulum's whole-run wall-clock medians; speed-up = Bullet's time ÷ Stepwise's). Where "
                          "the speed is missed, the last column says where Stepwise's step goes: the three largest "
                          "stages' shares of a run of the scene timed stage by stage, and the passes a step "
                          "against Bullet's iterations\n\n"
                          "| scene | time per step | ≥ 2× Bullet? | accuracy figure | Stepwise / Bullet | better? | where the step goes |\n"
                          "|---|---|---|---|---|---|---|\n");
        for (const auto& r : rows) {
            std::fprintf(out, "| %s | %s | %s | %s | %s | %s | %s |\n", r[0].c_str(), r[1].c_str(), r[2].c_str(),
                         r[3].c_str(), r[4].c_str(), r[5].c_str(), r[6].c_str());
        }
    } else {
        std::fprintf(out, "\nAgainst the targets of issue #33 (Stepwise / Bullet)\n  %-28s %-34s %-6s %-44s %-22s %s\n",
                     "scene", "time per step (speed-up)", "≥ 2×?", "accuracy figure", "Stepwise / Bullet", "better?");
        for (const auto& r : rows) {
            std::fprintf(out, "  %-28s %-34s %-6s %-44s %-22s %s\n", r[0].c_str(), r[1].c_str(), r[2].c_str(),
                         r[3].c_str(), r[4].c_str(), r[5].c_str());
            if (!r[6].empty()) std::fprintf(out, "  %-28s where the step goes: %s\n", "", r[6].c_str());
        }
    }
    for (const ThreadFigure& f : t.threads) {
        const double speedUp = f.oneThread / f.twoThreads;
        const std::string measured = format("%.2f", kMs * f.oneThread) + " → " + format("%.2f", kMs * f.twoThreads) +
                                     " ms wall (" + format("%.2f×", speedUp) + ")";
        if (markdown) {
            // A paragraph each: Markdown would join lines that end without a blank one.
            std::fprintf(out, "\n%s: 2 threads at least 1.7× faster than 1: %s: **%s**.\n", f.scene.c_str(),
                         measured.c_str(), verdict(speedUp >= kThreadTarget).c_str());
        } else {
            std::fprintf(out, "  %s: 2 threads at least 1.7× faster than 1: %s: %s\n", f.scene.c_str(), measured.c_str(),
                         verdict(speedUp >= kThreadTarget).c_str());
        }
    }
}

/// @brief The per-scene ratios as CSV, one row a scene (for a figure in the lectures).
void writeRatiosCsv(std::FILE* csv, const Targets& t) {
    std::fprintf(csv, "scene,stepwise_ms,bullet_ms,speed_ratio,accuracy,stepwise_accuracy,bullet_accuracy\n");
    for (const SceneFigure& f : t.scenes) {
        std::fprintf(csv, "\"%s\",%.4f,%.4f,%.3f,\"%s\",%.6g,%.6g\n", f.scene.c_str(), kMs * f.ourCpu, kMs * f.theirCpu,
                     f.theirCpu / f.ourCpu, f.accuracy.c_str(), f.ours, f.theirs);
    }
}

int stepsOf(const Scene& scene, bool quick) {
    const int steps = static_cast<int>(std::lround(scene.settings.duration / scene.settings.timeStep));
    return quick ? std::min(steps, kQuickSteps) : steps;
}

Table sphereRain(std::size_t count, int rainSteps, bool quick, Targets& targets) {
    const Scene scene = parseScene(sphereRainSceneText(count, 1), "sphere-rain");
    const int steps = quick ? kQuickSteps : rainSteps;
    const Real h = scene.settings.timeStep;
    Table table{"Sphere rain, " + std::to_string(count) + " spheres of r = 0.5 m, " + std::to_string(steps) +
                " steps of 1/60 s", {}};

    StepwiseEngine ours{World(onOneThread(scene))};
    RainMeter ourMeter(scene.planes, kRainRadius);
    const Timing ourSeconds = runSteps(ours, steps, h, [&](const auto& s, Real) { ourMeter.observe(s); });
    std::vector<BodyState> ourEnd;
    ours.states(ourEnd);

    BulletWorld theirs(scene);
    RainMeter theirMeter(scene.planes, kRainRadius);
    const Timing theirSeconds = runSteps(theirs, steps, h, [&](const auto& s, Real) { theirMeter.observe(s); });
    std::vector<BodyState> theirEnd;
    theirs.states(theirEnd);

    // The same rain with fewer substeps (kRainFewerSubsteps), against the same Bullet run.
    Scene fewerScene = scene;
    fewerScene.settings.substeps = kRainFewerSubsteps;
    StepwiseEngine fewer{World(onOneThread(fewerScene))};
    RainMeter fewerMeter(scene.planes, kRainRadius);
    const Timing fewerSeconds = runSteps(fewer, steps, h, [&](const auto& s, Real) { fewerMeter.observe(s); });
    std::vector<BodyState> fewerEnd;
    fewer.states(fewerEnd);

    table.add("CPU ms/step (median)", "%.2f", kMs * ourSeconds.cpu, kMs * theirSeconds.cpu);
    table.add("wall ms/step (median)", "%.2f", kMs * ourSeconds.wall, kMs * theirSeconds.wall);
    table.add("worst overlap, any step (mm)", "%.1f", kMs * double(ourMeter.worstOverlap()),
              kMs * double(theirMeter.worstOverlap()));
    table.add("spheres out of the box at the end", "%.0f", double(ourMeter.escaped(ourEnd)),
              double(theirMeter.escaped(theirEnd)));
    std::size_t ourAsleep = 0;
    for (const DynamicObject& b : ours.world.dynamics()) ourAsleep += b.asleep ? 1 : 0;
    table.addText("asleep at the end", std::to_string(ourAsleep), std::to_string(theirs.sleepingCount()));
    const std::string fewerLabel = "Substeps=" + std::to_string(kRainFewerSubsteps) + ": ";
    table.add(fewerLabel + "CPU ms/step (median)", "%.2f", kMs * fewerSeconds.cpu, kMs * theirSeconds.cpu);
    table.add(fewerLabel + "worst overlap, any step (mm)", "%.1f", kMs * double(fewerMeter.worstOverlap()),
              kMs * double(theirMeter.worstOverlap()));
    table.add(fewerLabel + "spheres out of the box", "%.0f", double(fewerMeter.escaped(fewerEnd)),
              double(theirMeter.escaped(theirEnd)));
    targets.scenes.push_back({"rain " + std::to_string(count), ourSeconds.cpu, theirSeconds.cpu, "worst overlap (mm)",
                              kMs * double(ourMeter.worstOverlap()), kMs * double(theirMeter.worstOverlap()),
                              whereTheStepGoes(scene, steps, ourSeconds.cpu, theirSeconds.cpu, theirs.solverIterations())});
    targets.rains.push_back({count, ourSeconds.cpu, theirSeconds.cpu, double(ourMeter.worstOverlap()),
                             ourMeter.escaped(ourEnd), fewerSeconds.cpu, double(fewerMeter.worstOverlap()),
                             fewerMeter.escaped(fewerEnd)});
    return table;
}

/// @brief One run of the rain sweep: an engine at one setting, its cost and its accuracy.
struct SweepRun {
    std::string engine;    ///< "Stepwise" or "Bullet".
    std::string setting;   ///< "Substeps=4", "iterations=20".
    double cpu = 0;        ///< CPU s per step (median).
    double overlap = 0;    ///< Worst overlap, m.
    bool isDefault = false;
};

constexpr int kSweepSubsteps[] = {1, 2, 4, 8, 10, 12, 16};  ///< Stepwise: 16 is the default (world_settings.hpp); 10 and 12 bracket 5 mm.
constexpr int kSweepIterations[] = {5, 10, 20, 40};     ///< Bullet: 10 is its default.
constexpr int kBulletDefaultIterations = 10;
constexpr std::size_t kSweepRain = 1000;                ///< The sweep's rain, spheres.

/// Run time against error for the rain: the worst overlap is the error, and
/// each engine's knob that buys accuracy with time (Stepwise's substeps,
/// Bullet's iterations) is swept, so each engine's curve shows what its
/// accuracy costs, and a default can be compared with the other engine at
/// equal accuracy or equal time.
Table rainSweep(int rainSteps, bool quick, std::vector<SweepRun>& runs) {
    const std::size_t count = quick ? kQuickRain : kSweepRain;
    const Scene scene = parseScene(sphereRainSceneText(count, 1), "sphere-rain");
    const int steps = quick ? kQuickSteps : rainSteps;
    const Real h = scene.settings.timeStep;
    Table table{"Sphere rain, " + std::to_string(count) + " spheres, " + std::to_string(steps) +
                    " steps: run time against worst overlap, each engine's accuracy knob swept",
                {}};
    for (const int substeps : kSweepSubsteps) {
        Scene ours = scene;
        ours.settings.substeps = substeps;
        StepwiseEngine engine{World(onOneThread(ours))};
        RainMeter meter(scene.planes, kRainRadius);
        const Timing t = runSteps(engine, steps, h, [&](const auto& s, Real) { meter.observe(s); });
        runs.push_back({"Stepwise", "Substeps=" + std::to_string(substeps), t.cpu, double(meter.worstOverlap()),
                        substeps == kDefaultSubsteps});
    }
    for (const int iterations : kSweepIterations) {
        BulletWorld engine(scene);
        engine.setSolverIterations(iterations);
        RainMeter meter(scene.planes, kRainRadius);
        const Timing t = runSteps(engine, steps, h, [&](const auto& s, Real) { meter.observe(s); });
        runs.push_back({"Bullet", "iterations=" + std::to_string(iterations), t.cpu, double(meter.worstOverlap()),
                        iterations == kBulletDefaultIterations});
    }
    for (const SweepRun& r : runs) {
        table.rows.push_back({r.engine + ", " + r.setting + (r.isDefault ? " (default)" : ""),
                              format("%.2f", kMs * r.cpu), format("%.1f mm", kMs * r.overlap), ""});
    }
    return table;
}

Table stack(const std::string& path, const std::string& title, bool quick, Targets& targets) {
    const Scene scene = loadSceneFile(path);
    const int steps = stepsOf(scene, quick);
    const Real h = scene.settings.timeStep;
    Table table{title + " (" + path.substr(path.find_last_of('/') + 1) + "), " + std::to_string(steps) +
                " steps, Sleep=" + (scene.settings.sleeping ? "true" : "false"), {}};
    StepwiseEngine ours{World(onOneThread(scene))};
    std::vector<BodyState> initial;
    ours.states(initial);
    StackMeter ourMeter(initial);
    const Timing ourSeconds = runSteps(ours, steps, h, [&](const auto& s, Real t) { ourMeter.observe(s, t); });
    BulletWorld theirs(scene);
    StackMeter theirMeter(initial);
    const Timing theirSeconds = runSteps(theirs, steps, h, [&](const auto& s, Real t) { theirMeter.observe(s, t); });

    table.add("CPU ms/step (median)", "%.3f", kMs * ourSeconds.cpu, kMs * theirSeconds.cpu);
    table.add("wall ms/step (median)", "%.3f", kMs * ourSeconds.wall, kMs * theirSeconds.wall);
    table.add("largest displacement of a box (mm)", "%.1f", kMs * double(ourMeter.worstDrift()),
              kMs * double(theirMeter.worstDrift()));
    const auto fall = [](const StackMeter& m) {
        return m.fallTime() ? format("%.2f s", double(*m.fallTime())) : std::string("stands");
    };
    table.addText("falls (a box moves > 0.5 m) at", fall(ourMeter), fall(theirMeter));
    targets.stacks.emplace_back(title, !ourMeter.fallTime());
    targets.others.push_back({title, ourSeconds.cpu, theirSeconds.cpu});
    targets.scenes.push_back({title, ourSeconds.cpu, theirSeconds.cpu, "largest displacement of a box (mm)",
                              kMs * double(ourMeter.worstDrift()), kMs * double(theirMeter.worstDrift()),
                              whereTheStepGoes(scene, steps, ourSeconds.cpu, theirSeconds.cpu, theirs.solverIterations())});
    return table;
}

/// Run time against error for the 210-box pyramid, as rainSweep() does for the rain: the largest
/// displacement of a box is the error, Stepwise's substeps and Bullet's iterations are swept. It
/// answers "at equal accuracy, which engine is faster?" where the default settings differ in
/// accuracy by two orders of magnitude (issue #33's verdicts use the defaults).
Table pyramidSweep(const std::string& path, bool quick) {
    const Scene scene = loadSceneFile(path);
    const int steps = stepsOf(scene, quick);
    const Real h = scene.settings.timeStep;
    Table table{"Pyramid of 210 boxes (" + path.substr(path.find_last_of('/') + 1) + "), " + std::to_string(steps) +
                    " steps: run time against the largest displacement, each engine's accuracy knob swept",
                {}};
    table.header = {"engine, setting", "CPU ms/step (median)", "largest displacement of a box", ""};
    StepwiseEngine probe{World(onOneThread(scene))};
    std::vector<BodyState> initial;
    probe.states(initial);
    const auto row = [&](const std::string& setting, const Timing& t, const StackMeter& m) {
        table.rows.push_back({setting, format("%.3f", kMs * t.cpu), format("%.1f mm", kMs * double(m.worstDrift())), ""});
    };
    for (const int substeps : {2, 4, 8, 16}) {
        Scene ours = scene;
        ours.settings.substeps = substeps;
        StepwiseEngine engine{World(onOneThread(ours))};
        StackMeter meter(initial);
        const Timing t = runSteps(engine, steps, h, [&](const auto& s, Real time) { meter.observe(s, time); });
        row("Stepwise, Substeps=" + std::to_string(substeps) + (substeps == kDefaultSubsteps ? " (default)" : ""), t, meter);
    }
    for (const int iterations : kSweepIterations) {
        BulletWorld engine(scene);
        engine.setSolverIterations(iterations);
        StackMeter meter(initial);
        const Timing t = runSteps(engine, steps, h, [&](const auto& s, Real time) { meter.observe(s, time); });
        row("Bullet, iterations=" + std::to_string(iterations) + (iterations == kBulletDefaultIterations ? " (default)" : ""),
            t, meter);
    }
    return table;
}

Table freeBox(const std::string& path, bool quick, Targets& targets) {
    const Scene scene = loadSceneFile(path);
    const int steps = stepsOf(scene, quick);
    const Real h = scene.settings.timeStep;
    Table table{"Free box (reference_free_box.scene): torque-free tumbling, " + std::to_string(steps) + " steps of " +
                format("%.4f", double(h)) + " s", {}};
    StepwiseEngine ours{World(onOneThread(scene))};
    std::vector<BodyState> initial;
    ours.states(initial);
    FreeBodyMeter ourMeter(initial[0]);
    runSteps(ours, steps, h, [&](const auto& s, Real) { ourMeter.observe(s[0]); });
    BulletWorld theirs(scene);
    FreeBodyMeter theirMeter(initial[0]);
    runSteps(theirs, steps, h, [&](const auto& s, Real) { theirMeter.observe(s[0]); });

    table.add("worst ‖L − L0‖ / ‖L0‖", "%.2e", ourMeter.worstMomentumDrift(), theirMeter.worstMomentumDrift());
    table.add("‖L − L0‖ / ‖L0‖ at the end", "%.2e", ourMeter.finalMomentumDrift(), theirMeter.finalMomentumDrift());
    table.add("worst abs(T − T0) / T0", "%.2e", ourMeter.worstEnergyDrift(), theirMeter.worstEnergyDrift());
    table.addText("(T - T0) / T0 at the end", format("%+.2e", ourMeter.finalEnergyDrift()),
                  format("%+.2e", theirMeter.finalEnergyDrift()));
    targets.momentumDrift = ourMeter.worstMomentumDrift();
    return table;
}

Table bounce(const std::string& path, Real h, Targets& targets) {
    Scene scene = loadSceneFile(path);
    scene.settings.timeStep = h;
    const int steps = stepsOf(scene, false);
    const DynamicObject& ball = scene.dynamics.at(0);
    const CollisionPlane& floor = scene.planes.at(0);
    const Real floorY = floor.position.y;
    const double e = double(ball.elasticity * floor.elasticity);  // the product rule, on both sides
    const double drop = double(ball.position.y - ball.radius - floorY);
    Table table{"Bounce (reference_bounce.scene), e = " + format("%.2f", e) + ", h = 1/" +
                std::to_string(std::lround(1 / double(h))) + " s: apex heights against e^(2n)·" +
                format("%.2f", drop) + " m", {}};
    StepwiseEngine ours{World(onOneThread(scene))};
    BounceMeter ourMeter(floorY, ball.radius);
    runSteps(ours, steps, h, [&](const auto& s, Real) { ourMeter.observe(s[0]); });
    BulletWorld theirs(scene);
    BounceMeter theirMeter(floorY, ball.radius);
    runSteps(theirs, steps, h, [&](const auto& s, Real) { theirMeter.observe(s[0]); });

    double ourWorst = 0, theirWorst = 0;
    for (int n = 1; n <= kApexesCompared; ++n) {
        const double expected = std::pow(e, 2 * n) * drop;
        const auto apex = [&](const BounceMeter& m, double& worst) {
            if (m.apexes().size() < std::size_t(n)) {
                worst = INFINITY;
                return std::string("no bounce");
            }
            const double got = double(m.apexes()[std::size_t(n - 1)]);
            worst = std::max(worst, std::abs(got - expected) / expected);
            return format("%.4f m", got);
        };
        table.addText("apex " + std::to_string(n) + " (exact " + format("%.4f", expected) + " m)",
                      apex(ourMeter, ourWorst), apex(theirMeter, theirWorst));
    }
    const auto percent = [](double v) { return std::isfinite(v) ? format("%.2f %%", kPercent * v) : std::string("—"); };
    table.rows.push_back({"worst apex error (relative)", percent(ourWorst), percent(theirWorst),
                          std::isfinite(ourWorst) && std::isfinite(theirWorst) && ourWorst > 0
                              ? format("%.2f", theirWorst / ourWorst)
                              : std::string("—")});
    targets.bounces.emplace_back(static_cast<int>(std::lround(1 / double(h))), ourWorst);
    return table;
}

Table incline(const std::string& path) {
    const Scene scene = loadSceneFile(path);
    const Real h = scene.settings.timeStep;
    const int steps = static_cast<int>(std::lround(kInclineTime / h));
    const CollisionPlane& slope = scene.planes.at(0);
    const Vec3 down = downSlope(slope, scene.settings.gravity);
    Table table{"Incline (lesson07_incline.scene): acceleration down the slope over the first " +
                format("%.0f", double(kInclineTime)) + " s, a = (v·d)/t, in m/s²", {}};
    StepwiseEngine ours{World(onOneThread(scene))};
    std::vector<BodyState> initial;
    ours.states(initial);
    std::vector<BodyState> ourEnd, theirEnd;
    runSteps(ours, steps, h, [&](const auto& s, Real) { ourEnd = s; });
    BulletWorld theirs(scene);
    runSteps(theirs, steps, h, [&](const auto& s, Real) { theirEnd = s; });
    const double t = double(steps) * double(h);
    for (std::size_t n = 0; n < scene.dynamics.size(); ++n) {
        const DynamicObject& body = scene.dynamics[n];
        const double expected = double(inclineAcceleration(body, slope, scene.settings.gravity));
        // From the speed, not the distance: symplectic Euler's distance after
        // n steps is ½·a·t²·(1 + 1/n), 0.8 % long at n = 120, its speed a·t exactly.
        const auto measured = [&](const std::vector<BodyState>& end) {
            return double(glm::dot(end[n].velocity - initial[n].velocity, down)) / t;
        };
        const double ours_a = measured(ourEnd), theirs_a = measured(theirEnd);
        table.addText(body.name + " (exact " + format("%.3f", expected) + ")", format("%.3f", ours_a),
                      format("%.3f", theirs_a));
        table.add(body.name + ": error abs(a − exact), m/s²", "%.3f", std::abs(ours_a - expected),
                  std::abs(theirs_a - expected));
    }
    return table;
}

/// The names --scenarios takes, in the order the tables come.
const std::string kScenarios[] = {"rain",     "rain-sweep", "stacks", "pyramid-sweep", "free-box", "bounce",  "incline",
                                  "reference", "wall-rain", "box-pile", "chain",   "ragdoll"};

/// The reference problems' time steps in both engines, s: the display rate,
/// and two quarterings of it, enough to show each method's order.
constexpr double kReferenceSteps[] = {1.0 / 60, 1.0 / 240, 1.0 / 960};
constexpr int kReferenceTimings = 5;  ///< Timed runs of each problem at 1/60 s (the median is shown).

/// Median wall time per step of @p steps steps of a fresh engine from @p make, ns (the building untimed).
template <class Make>
double nanosecondsPerStep(Make&& make, std::uint64_t steps) {
    std::vector<double> times;
    for (int r = 0; r < kReferenceTimings; ++r) {
        auto engine = make();
        const auto start = std::chrono::steady_clock::now();
        for (std::uint64_t i = 0; i < steps; ++i) engine->step();
        times.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
                        double(steps));
    }
    return median(times);
}

/// @brief One reference problem of `stepwise-bench precision` in both engines, judged by the same code.
///
/// Stepwise runs it with SymplecticEuler, the method Bullet integrates every
/// body with (v += h·F/m, then x += h·v), so that the two columns compare
/// engines and not methods; a row per step size adds Stepwise's Verlet, the
/// second-order method the scene files can choose.
Table referenceProblem(const ReferenceProblem& problem, const std::string& dir, bool quick, Targets& targets) {
    const Scene scene = loadSceneFile(dir + problem.sceneFile);
    const JudgeMaker ourJudges = problem.prepare(scene);
    // Bullet's pendulum is a pin at the pivot: its bob turns, and has its own exact period.
    const bool pinned = !scene.joints.empty();
    const JudgeMaker theirJudges = pinned ? preparePendulumTurningBob(scene) : ourJudges;
    Table table{problem.name + " (" + problem.sceneFile + "): " + problem.what +
                    (pinned ? "; Bullet's bob hangs from a pin at the pivot and turns, and is judged against that "
                              "compound pendulum's own exact period"
                            : "") +
                    "; Stepwise with SymplecticEuler (Bullet's method), and with Verlet",
                {}};
    std::string firstMetric;                  // the main error at h = 1/60, for the issue #33 verdicts
    double ourFirst = NAN, theirFirst = NAN;
    int theirIterations = 0;                  // Bullet's solver iterations, for the verdict's reason
    for (const double h : kReferenceSteps) {
        const std::string step = "h = 1/" + std::to_string(std::lround(1 / h)) + ": ";
        const Measurement ours = runInStepwise(scene, ourJudges, IntegratorKind::SymplecticEuler, h);
        BulletWorld theirWorld(withStep(scene, IntegratorKind::SymplecticEuler, h));
        const Measurement theirs = runJudged(theirWorld, theirJudges(h), h);
        theirIterations = theirWorld.solverIterations();
        if (firstMetric.empty() && !ours.metrics.empty()) {
            firstMetric = ours.metrics[0].name + " (" + ours.metrics[0].unit + ")";
            ourFirst = ours.metrics[0].value;
            theirFirst = theirs.metrics[0].value;
        }
        for (std::size_t k = 0; k < ours.metrics.size(); ++k) {
            const Metric& metric = ours.metrics[k];
            table.add(step + metric.name + " (" + metric.unit + ")", "%.3e", metric.value, theirs.metrics[k].value);
        }
        const Measurement verlet = runInStepwise(scene, ourJudges, IntegratorKind::Verlet, h);
        const double verletError = verlet.metrics[0].value;
        table.addText(step + verlet.metrics[0].name + ", Stepwise with Verlet",
                      std::isnan(verletError) ? "—" : format("%.3e", verletError), "");
        if (!ours.note.empty() || !theirs.note.empty()) table.addText(step + "note", ours.note, theirs.note);
        if (!verlet.note.empty()) table.addText(step + "note, Stepwise with Verlet", verlet.note, "");
        if (quick) break;
    }
    const double h = kReferenceSteps[0];
    const std::uint64_t steps = ourJudges(h).steps;
    const Scene stepped = onOneThread(withStep(scene, IntegratorKind::SymplecticEuler, h));
    const double ourNs =
        nanosecondsPerStep([&] { return std::make_unique<StepwiseEngine>(StepwiseEngine{World(stepped)}); }, steps);
    const double theirNs = nanosecondsPerStep([&] { return std::make_unique<BulletWorld>(stepped); }, steps);
    table.add("ns per step at h = 1/60 (median of " + std::to_string(kReferenceTimings) + " runs)", "%.0f", ourNs, theirNs);
    targets.others.push_back({problem.name, ourNs, theirNs});
    // The issue #33 verdicts take the pendulum (a joint); its times are wall-clock here (whole runs).
    constexpr double kSecondsPerNs = 1e-9;
    if (problem.name == "pendulum") {
        targets.scenes.push_back({problem.name, kSecondsPerNs * ourNs, kSecondsPerNs * theirNs, firstMetric + " at h = 1/60",
                                  ourFirst, theirFirst,
                                  whereTheStepGoes(stepped, static_cast<int>(steps), ourNs, theirNs, theirIterations)});
    }
    return table;
}

}  // namespace

int runSideBySide(const SideBySideOptions& options) {
    std::vector<std::size_t> sizes = options.rainSizes;
    if (sizes.empty()) sizes = options.quick ? std::vector<std::size_t>{kQuickRain} : std::vector<std::size_t>{1000, 4000, 16000};
    const std::string dir = options.configDir + "/";
    for (const std::string& name : options.scenarios) {
        if (std::find(std::begin(kScenarios), std::end(kScenarios), name) == std::end(kScenarios)) {
            std::string known;
            for (const std::string& scenario : kScenarios) known += (known.empty() ? "" : ", ") + scenario;
            std::fprintf(stderr, "stepwise-bench bullet: unknown scenario '%s' (known: %s)\n", name.c_str(), known.c_str());
            return 2;
        }
    }
    std::printf("stepwise-bench bullet: Stepwise against Bullet %d.%02d (btScalar = %s), same scene files\n",
                BT_BULLET_VERSION / 100, BT_BULLET_VERSION % 100, sizeof(btScalar) == 8 ? "double" : "float");
    std::vector<Table> tables;
    Targets targets;
    std::vector<SweepRun> sweepRuns;
    const auto show = [&](Table table) {
        table.print(stdout, false);
        std::fflush(stdout);
        tables.push_back(std::move(table));
    };
    try {
        const auto wanted = [&](const char* name) {
            return options.scenarios.empty() ||
                   std::find(options.scenarios.begin(), options.scenarios.end(), name) != options.scenarios.end();
        };
        if (wanted("rain")) {
            for (const std::size_t n : sizes) show(sphereRain(n, options.rainSteps, options.quick, targets));
        }
        if (wanted("rain-sweep")) {
            Table sweep = rainSweep(options.rainSteps, options.quick, sweepRuns);
            sweep.header = {"engine, setting", "CPU ms/step (median)", "worst overlap, any step", ""};
            show(std::move(sweep));
        }
        if (wanted("stacks")) {
            show(stack(dir + "lesson08_pyramid.scene", "Pyramid of 210 boxes", options.quick, targets));
            show(stack(dir + "lesson08_tower.scene", "Tower of 20 boxes", options.quick, targets));
        }
        if (wanted("pyramid-sweep")) show(pyramidSweep(dir + "lesson08_pyramid.scene", options.quick));
        if (wanted("free-box")) show(freeBox(dir + "reference_free_box.scene", options.quick, targets));
        if (wanted("bounce")) {
            show(bounce(dir + "reference_bounce.scene", kDefaultTimeStep, targets));
            show(bounce(dir + "reference_bounce.scene", kFineTimeStep, targets));
        }
        if (wanted("incline")) show(incline(dir + "lesson07_incline.scene"));
        if (wanted("reference")) {
            for (const ReferenceProblem& problem : referenceProblems()) show(referenceProblem(problem, dir, options.quick, targets));
        }
        // Issue #33: levels of static boxes and jointed bodies.
        std::vector<std::pair<std::string, Scene>> threaded;
        if (wanted("wall-rain")) {
            for (const std::size_t n : sizes) show(wallRain(n, options.rainSteps, options.quick, targets.scenes));
            threaded.emplace_back("wall rain " + std::to_string(sizes.back()), wallRainScene(sizes.back()));
        }
        const std::size_t pile = options.quick ? kQuickPile : kPileBoxes;
        if (wanted("box-pile")) {
            show(boxPile(pile, options.quick, targets.scenes));
            threaded.emplace_back("box pile " + std::to_string(pile), boxPileScene(pile));
        }
        if (wanted("chain")) show(chain(dir + "bench_chain.scene", options.quick, targets.scenes));
        if (wanted("ragdoll")) show(ragdoll(dir + "bench_ragdoll.scene", options.quick, targets.scenes));
        if (!threaded.empty()) {
            const int steps = options.quick ? kQuickSteps : options.rainSteps;
            Table table = threadScaling(threaded, steps, targets.threads);
            show(std::move(table));
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "stepwise-bench bullet: %s\n", error.what());
        return 1;
    }
    printTargets(stdout, targets, false);
    printIssue33Targets(stdout, targets, false);
    // An output file that cannot be opened is said on stderr (exit code 2).
    const auto openOutput = [](const std::string& path) {
        std::FILE* file = std::fopen(path.c_str(), "w");
        if (!file) std::fprintf(stderr, "stepwise-bench: cannot write %s\n", path.c_str());
        return file;
    };
    if (options.sweepCsvPath && !sweepRuns.empty()) {
        std::FILE* csv = openOutput(*options.sweepCsvPath);
        if (!csv) return 2;
        std::fprintf(csv, "engine,setting,cpu_ms_per_step,worst_overlap_mm,default\n");
        for (const SweepRun& r : sweepRuns) {
            std::fprintf(csv, "%s,%s,%.4f,%.3f,%d\n", r.engine.c_str(), r.setting.c_str(), kMs * r.cpu, kMs * r.overlap,
                         r.isDefault ? 1 : 0);
        }
        std::fclose(csv);
    }
    if (options.ratiosCsvPath) {
        std::FILE* csv = openOutput(*options.ratiosCsvPath);
        if (!csv) return 2;
        writeRatiosCsv(csv, targets);
        std::fclose(csv);
    }
    if (options.markdownPath) {
        std::FILE* out = openOutput(*options.markdownPath);
        if (!out) return 2;
        std::fprintf(out, "Bullet %d.%02d (btScalar = %s); last column: Bullet's figure / Stepwise's "
                          "(above 1: Stepwise better).\n", BT_BULLET_VERSION / 100, BT_BULLET_VERSION % 100,
                     sizeof(btScalar) == 8 ? "double" : "float");
        for (const Table& table : tables) table.print(out, true);
        printTargets(out, targets, true);
        printIssue33Targets(out, targets, true);
        std::fclose(out);
    }
    return 0;
}

}  // namespace stepwise::bench
