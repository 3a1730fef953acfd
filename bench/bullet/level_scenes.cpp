/// @file level_scenes.cpp
/// @brief The wall rain, box pile, chain and ragdoll side by side, and the threads table (level_scenes.hpp).
#include "level_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../box_pile_scene.hpp"
#include "../joint_metrics.hpp"
#include "../overlap_depth.hpp"
#include "../pile_metrics.hpp"
#include "../sphere_rain_scene.hpp"
#include "../wall_rain_scene.hpp"
#include "bullet_world.hpp"
#include "config/scene_loader.hpp"
#include "world/world.hpp"

namespace stepwise::bench {

namespace {

/// "At rest" at the end: no body's centre faster than this, m/s. A body
/// resting on a step of h = 1/60 s jitters by g·h = 0.16 m/s at most within
/// a step when its contact lets go; 1 cm/s is well under that and well over
/// the rounding of a resting solve.
constexpr Real kRestSpeed = Real(0.01);
constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;
constexpr double kPercent = 100;

int stepsOf(const Scene& scene, bool quick) {
    const int steps = static_cast<int>(std::lround(scene.settings.duration / scene.settings.timeStep));
    return quick ? std::min(steps, kQuickSteps) : steps;
}

std::string restText(Real speed) { return speed < kRestSpeed ? "yes" : "no"; }

}  // namespace

Scene wallRainScene(std::size_t count) {
    return parseScene(wallRainSceneText(count, 1), "wall-rain-" + std::to_string(count));
}

Scene boxPileScene(std::size_t count) {
    return parseScene(boxPileSceneText(count, 1), "box-pile-" + std::to_string(count));
}

Table wallRain(std::size_t count, int steps, bool quick, std::vector<SceneFigure>& figures) {
    const Scene scene = wallRainScene(count);
    if (quick) steps = kQuickSteps;
    const Real h = scene.settings.timeStep;
    const std::vector<OrientedBox> walls = staticBoxesOf(scene);
    Table table{"Wall rain, " + std::to_string(count) + " spheres of r = 0.5 m into a box of 5 static boxes, " +
                    std::to_string(steps) + " steps of 1/60 s, Sleep=false",
                {}};
    StepwiseEngine ours{World(onOneThread(scene))};
    RainMeter ourMeter(scene.planes, kRainRadius, walls);
    const Timing ourSeconds = runSteps(ours, steps, h, [&](const auto& s, Real) { ourMeter.observe(s); });
    std::vector<BodyState> ourEnd, theirEnd;
    ours.states(ourEnd);
    BulletWorld theirs(scene);
    RainMeter theirMeter(scene.planes, kRainRadius, walls);
    const Timing theirSeconds = runSteps(theirs, steps, h, [&](const auto& s, Real) { theirMeter.observe(s); });
    theirs.states(theirEnd);

    table.add("CPU ms/step (median)", "%.2f", kMs * ourSeconds.cpu, kMs * theirSeconds.cpu);
    table.add("wall ms/step (median)", "%.2f", kMs * ourSeconds.wall, kMs * theirSeconds.wall);
    table.add("worst overlap, sphere–sphere or sphere–wall, any step (mm)", "%.1f", kMs * double(ourMeter.worstOverlap()),
              kMs * double(theirMeter.worstOverlap()));
    table.add("spheres out of the box at the end", "%.0f", double(ourMeter.escaped(ourEnd)),
              double(theirMeter.escaped(theirEnd)));
    table.add("largest speed at the end (m/s)", "%.3f", double(largestSpeed(ourEnd)), double(largestSpeed(theirEnd)));
    figures.push_back({"wall rain " + std::to_string(count), ourSeconds.cpu, theirSeconds.cpu,
                       "worst overlap (mm)", kMs * double(ourMeter.worstOverlap()), kMs * double(theirMeter.worstOverlap()),
                       whereTheStepGoes(scene, steps, ourSeconds.cpu, theirSeconds.cpu, theirs.solverIterations())});
    return table;
}

Table boxPile(std::size_t count, bool quick, std::vector<SceneFigure>& figures) {
    const Scene scene = boxPileScene(count);
    const int steps = stepsOf(scene, quick);
    const Real h = scene.settings.timeStep;
    const std::vector<OrientedBox> walls = staticBoxesOf(scene);
    const std::vector<Vec3> half = boxHalfExtentsOf(scene);
    Table table{"Box pile, " + std::to_string(count) + " boxes (edges 0.8 to 1.2 m) into a box of 5 static boxes, " +
                    std::to_string(steps) + " steps of 1/60 s, Sleep=false",
                {}};
    StepwiseEngine ours{World(onOneThread(scene))};
    BoxPileMeter ourMeter(half, walls, scene.planes);
    const Timing ourSeconds = runSteps(ours, steps, h, [&](const auto& s, Real) { ourMeter.observe(s); });
    std::vector<BodyState> ourEnd, theirEnd;
    ours.states(ourEnd);
    BulletWorld theirs(scene);
    BoxPileMeter theirMeter(half, walls, scene.planes);
    const Timing theirSeconds = runSteps(theirs, steps, h, [&](const auto& s, Real) { theirMeter.observe(s); });
    theirs.states(theirEnd);

    table.add("CPU ms/step (median)", "%.2f", kMs * ourSeconds.cpu, kMs * theirSeconds.cpu);
    table.add("wall ms/step (median)", "%.2f", kMs * ourSeconds.wall, kMs * theirSeconds.wall);
    table.add("worst box–box overlap, any step (mm)", "%.1f", kMs * double(ourMeter.worstBoxOverlap()),
              kMs * double(theirMeter.worstBoxOverlap()));
    table.add("worst box–wall overlap, any step (mm)", "%.1f", kMs * double(ourMeter.worstWallOverlap()),
              kMs * double(theirMeter.worstWallOverlap()));
    table.add("worst box–box overlap at the end (mm)", "%.1f", kMs * double(ourMeter.lastBoxOverlap()),
              kMs * double(theirMeter.lastBoxOverlap()));
    table.add("worst box–wall overlap at the end (mm)", "%.1f", kMs * double(ourMeter.lastWallOverlap()),
              kMs * double(theirMeter.lastWallOverlap()));
    table.add("boxes out of the box at the end", "%.0f", double(ourMeter.escaped(ourEnd)), double(theirMeter.escaped(theirEnd)));
    table.add("largest speed at the end (m/s)", "%.3f", double(largestSpeed(ourEnd)), double(largestSpeed(theirEnd)));
    table.add("largest spin at the end (rad/s)", "%.3f", double(largestSpin(ourEnd)), double(largestSpin(theirEnd)));
    table.addText("at rest at the end (every centre under 1 cm/s)", restText(largestSpeed(ourEnd)),
                  restText(largestSpeed(theirEnd)));
    const double ourWorst = double(std::max(ourMeter.worstBoxOverlap(), ourMeter.worstWallOverlap()));
    const double theirWorst = double(std::max(theirMeter.worstBoxOverlap(), theirMeter.worstWallOverlap()));
    figures.push_back({"box pile " + std::to_string(count), ourSeconds.cpu, theirSeconds.cpu, "worst overlap (mm)",
                       kMs * ourWorst, kMs * theirWorst,
                       whereTheStepGoes(scene, steps, ourSeconds.cpu, theirSeconds.cpu, theirs.solverIterations())});
    return table;
}

Table chain(const std::string& path, bool quick, std::vector<SceneFigure>& figures) {
    const Scene scene = loadSceneFile(path);
    const int steps = stepsOf(scene, quick);
    const Real h = scene.settings.timeStep;
    // The energy scale: the chain lies straight at the start, so it is ℓ long, from
    // the pivot to the far end of its farthest link; falling from horizontal to
    // hanging its centre of mass drops ℓ/2, giving up M·g·ℓ/2.
    const Vec3 pivot = scene.joints.at(0).anchorA;
    double length = 0, mass = 0;
    for (const DynamicObject& link : scene.dynamics) {
        length = std::max(length, double(glm::length(link.position - pivot) + link.halfExtents().x));
        mass += double(link.mass);
    }
    const double scale = mass * double(glm::length(scene.settings.gravity)) * length / 2;
    Table table{"Chain (" + path.substr(path.find_last_of('/') + 1) + "): " + std::to_string(scene.dynamics.size()) +
                    " links on BallJoints, " + format("%.0f", length) + " m, released horizontal, " +
                    std::to_string(steps) + " steps of 1/60 s",
                {}};
    std::vector<BodyState> start;
    StepwiseEngine ours{World(onOneThread(scene))};
    ours.states(start);
    const double e0 = mechanicalEnergy(start, scene);
    JointMeter ourMeter(scene), theirMeter(scene);
    const Timing ourSeconds = runSteps(ours, steps, h, [&](const auto& s, Real) { ourMeter.observe(s); });
    std::vector<BodyState> ourEnd, theirEnd;
    ours.states(ourEnd);
    BulletWorld theirs(scene);
    const Timing theirSeconds = runSteps(theirs, steps, h, [&](const auto& s, Real) { theirMeter.observe(s); });
    theirs.states(theirEnd);

    table.add("CPU ms/step (median)", "%.3f", kMs * ourSeconds.cpu, kMs * theirSeconds.cpu);
    table.add("wall ms/step (median)", "%.3f", kMs * ourSeconds.wall, kMs * theirSeconds.wall);
    table.add("worst gap between a joint's anchors, any step (mm)", "%.2f", kMs * double(ourMeter.worstSeparation()),
              kMs * double(theirMeter.worstSeparation()));
    table.add("worst gap at the end (mm)", "%.2f", kMs * double(ourMeter.lastSeparation()),
              kMs * double(theirMeter.lastSeparation()));
    table.add("worst stretch, the sum of every joint's gap, any step (mm)", "%.1f", kMs * double(ourMeter.worstStretch()),
              kMs * double(theirMeter.worstStretch()));
    const auto drift = [&](const std::vector<BodyState>& end) { return (mechanicalEnergy(end, scene) - e0) / scale; };
    table.addText("energy at the end, (E − E0) / (M·g·ℓ/2)", format("%+.2f %%", kPercent * drift(ourEnd)),
                  format("%+.2f %%", kPercent * drift(theirEnd)));
    figures.push_back({"chain", ourSeconds.cpu, theirSeconds.cpu, "worst joint gap (mm)",
                       kMs * double(ourMeter.worstSeparation()), kMs * double(theirMeter.worstSeparation()),
                       whereTheStepGoes(scene, steps, ourSeconds.cpu, theirSeconds.cpu, theirs.solverIterations())});
    return table;
}

Table ragdoll(const std::string& path, bool quick, std::vector<SceneFigure>& figures) {
    const Scene scene = loadSceneFile(path);
    const int steps = stepsOf(scene, quick);
    const Real h = scene.settings.timeStep;
    const std::size_t hinges = static_cast<std::size_t>(std::count_if(
        scene.joints.begin(), scene.joints.end(), [](const JointDef& j) { return j.kind == JointKind::Hinge; }));
    Table table{"Ragdoll (" + path.substr(path.find_last_of('/') + 1) + "): " + std::to_string(scene.dynamics.size()) +
                    " boxes, " + std::to_string(scene.joints.size() - hinges) + " BallJoints and " +
                    std::to_string(hinges) + " HingeJoints with limits, onto a static box, " + std::to_string(steps) +
                    " steps of 1/60 s",
                {}};
    // Only the floor is measured: joined boxes meet at their joints and may overlap there.
    const std::vector<Vec3> half = boxHalfExtentsOf(scene);
    const std::vector<OrientedBox> floor = staticBoxesOf(scene);
    StepwiseEngine ours{World(onOneThread(scene))};
    JointMeter ourJoints(scene), theirJoints(scene);
    BoxPileMeter ourFloor(half, floor, scene.planes), theirFloor(half, floor, scene.planes);
    const Timing ourSeconds = runSteps(ours, steps, h, [&](const auto& s, Real) {
        ourJoints.observe(s);
        ourFloor.observe(s);
    });
    std::vector<BodyState> ourEnd, theirEnd;
    ours.states(ourEnd);
    BulletWorld theirs(scene);
    const Timing theirSeconds = runSteps(theirs, steps, h, [&](const auto& s, Real) {
        theirJoints.observe(s);
        theirFloor.observe(s);
    });
    theirs.states(theirEnd);

    table.add("CPU ms/step (median)", "%.3f", kMs * ourSeconds.cpu, kMs * theirSeconds.cpu);
    table.add("wall ms/step (median)", "%.3f", kMs * ourSeconds.wall, kMs * theirSeconds.wall);
    table.add("worst gap between a joint's anchors, any step (mm)", "%.2f", kMs * double(ourJoints.worstSeparation()),
              kMs * double(theirJoints.worstSeparation()));
    table.add("worst gap at the end (mm)", "%.2f", kMs * double(ourJoints.lastSeparation()),
              kMs * double(theirJoints.lastSeparation()));
    table.add("worst angle between a hinge's two axes, any step (degrees)", "%.2f",
              kDegreesPerRadian * double(ourJoints.worstAxisAngle()), kDegreesPerRadian * double(theirJoints.worstAxisAngle()));
    table.add("worst overlap with the floor, any step (mm)", "%.1f", kMs * double(ourFloor.worstWallOverlap()),
              kMs * double(theirFloor.worstWallOverlap()));
    table.add("largest speed at the end (m/s)", "%.3f", double(largestSpeed(ourEnd)), double(largestSpeed(theirEnd)));
    table.addText("at rest at the end (every centre under 1 cm/s)", restText(largestSpeed(ourEnd)),
                  restText(largestSpeed(theirEnd)));
    figures.push_back({"ragdoll", ourSeconds.cpu, theirSeconds.cpu, "worst joint gap (mm)",
                       kMs * double(ourJoints.worstSeparation()), kMs * double(theirJoints.worstSeparation()),
                       whereTheStepGoes(scene, steps, ourSeconds.cpu, theirSeconds.cpu, theirs.solverIterations())});
    return table;
}

std::string whereTheStepGoes(const Scene& scene, int steps, double ourCpu, double theirCpu, int bulletIterations) {
    if (theirCpu >= kSpeedTarget * ourCpu) return "";
    World world(onOneThread(scene));
    world.timeStages(true);
    for (int i = 0; i < steps; ++i) world.step();
    const StageRecords& records = world.stageRecords();
    std::vector<std::pair<double, Stage>> stages;
    double total = 0;
    for (std::size_t k = 0; k < records.size(); ++k) {
        total += records[k].totalSeconds;
        stages.emplace_back(records[k].totalSeconds, static_cast<Stage>(k));
    }
    std::sort(stages.begin(), stages.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    constexpr std::size_t kLargest = 3;
    std::string text;
    for (std::size_t k = 0; k < kLargest && k < stages.size() && total > 0; ++k) {
        text += (k == 0 ? "" : ", ") + std::string(stageName(stages[k].second)) + " " +
                format("%.0f %%", kPercent * stages[k].first / total);
    }
    const WorldSettings& s = scene.settings;
    if (s.solver == SolverKind::SequentialImpulse) {
        const int perSubstep = s.velocityIterations + s.relaxIterations;
        text += "; " + std::to_string(s.substeps * perSubstep) + " passes a step (" + std::to_string(s.substeps) +
                " substeps × " + std::to_string(perSubstep) + "), Bullet " +
                std::to_string(bulletIterations) + " iterations";
    }
    return text;
}

Table threadScaling(const std::vector<std::pair<std::string, Scene>>& scenes, int steps,
                    std::vector<ThreadFigure>& figures) {
    Table table{"Stepwise on one thread and on two (`Threads`), the two worlds stepped in turn, " + std::to_string(steps) +
                    " steps: wall-clock ms per step (median)",
                {}};
    table.header = {"scene", "Threads=1", "Threads=2", "speed-up"};
    for (const auto& [name, scene] : scenes) {
        Scene one = scene, two = scene;
        one.settings.threads = 1;
        two.settings.threads = 2;
        World worldOne(one), worldTwo(two);
        // Wall-clock time: two threads spend more CPU time in all than one; what
        // they buy is the wait for a step. Stepped in turn, a slow minute of the
        // shared machine falls on both.
        StepTimer timeOne(static_cast<std::size_t>(steps)), timeTwo(static_cast<std::size_t>(steps));
        for (int i = 0; i < steps; ++i) {
            timeOne.start();
            worldOne.step();
            timeOne.stop();
            timeTwo.start();
            worldTwo.step();
            timeTwo.stop();
        }
        const ThreadFigure figure{name, timeOne.medianWall(), timeTwo.medianWall()};
        figures.push_back(figure);
        table.rows.push_back({name, format("%.2f", kMs * figure.oneThread), format("%.2f", kMs * figure.twoThreads),
                              format("%.2f×", figure.oneThread / figure.twoThreads)});
    }
    return table;
}

}  // namespace stepwise::bench
