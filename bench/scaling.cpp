/// @file scaling.cpp
/// @brief `stepwise-bench scaling`: time per step and per body for sphere rain, box piles and pyramids.
///
/// A good step costs O(n) (a broadphase that finds the candidate pairs in
/// O(n log n) or better, and a solver whose work grows with the contacts, about
/// 6 per sphere in a pile), so the cost per body, ms/step ÷ n, should stay flat
/// as n grows from 1k to 64k. Each run times World::step() alone, step by step,
/// and reports the median (the machine is shared: the median ignores the steps
/// another process interrupted). The measurements (overlaps, the broadphase
/// tracker) run between the timed steps.
#include "scaling.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "collision/broadphase_tracker.hpp"
#include "config/scene_generator.hpp"
#include "config/scene_loader.hpp"
#include "io/broadphase_table.hpp"
#include "scenario_metrics.hpp"
#include "sphere_rain_scene.hpp"
#include "world/world.hpp"

namespace stepwise::bench {

namespace {

/// The tracker runs all four broadphases (and brute force to check them):
/// observing one step in this many keeps a 64k run's wall time reasonable;
/// its table is per observed step, so it is not changed by the sampling.
constexpr int kTrackEvery = 10;
/// Brute force, the tracker's reference, is O(n²): compared only up to this many bodies.
constexpr std::size_t kLargestChecked = 20000;
/// Quick mode: sizes and steps of a smoke test that takes seconds.
constexpr std::size_t kQuickRain = 200;
constexpr std::size_t kQuickPile = 100;
constexpr int kQuickSteps = 30;
constexpr double kMillisecondsPerSecond = 1e3;
constexpr double kMicrosecondsPerSecond = 1e6;
constexpr double kMillimetresPerMetre = 1e3;

struct Row {
    std::string scene;
    std::size_t bodies = 0;
    int steps = 0;
    double medianSeconds = 0;      ///< CPU time per step, median, s
    double meanSeconds = 0;        ///< CPU time per step, mean, s
    double medianWallSeconds = 0;  ///< wall-clock time per step, median, s
    double contactsPerStep = 0;
    std::optional<double> worstOverlap;  ///< m (sphere rain only)
    std::optional<std::size_t> escaped;  ///< spheres out of the box (sphere rain only)
    std::string broadphase;              ///< the World's broadphase (Auto's choice)
};

/// Runs @p text for @p steps steps; prints and (when @p markdown) writes the tracker's table.
Row runOne(const std::string& label, const std::string& text, int steps, bool rain, std::FILE* markdown,
           bool& agrees) {
    World world(onOneThread(parseScene(text, label)));
    std::vector<BodyState> states;
    statesOf(world, states);
    RainMeter rainMeter(world.planes(), kRainRadius);
    BroadphaseTracker tracker;
    StepTimer timer(static_cast<std::size_t>(steps));
    double contacts = 0;
    const bool check = world.dynamics().size() <= kLargestChecked;
    for (int i = 0; i < steps; ++i) {
        timer.start();
        world.step();
        timer.stop();
        contacts += double(world.contacts().size());
        if (rain) {
            statesOf(world, states);
            rainMeter.observe(states);
        }
        if ((i + 1) % kTrackEvery == 0 || i + 1 == steps) {
            const BodySet bodies{world.dynamics(), world.kinematics(), world.planes()};
            tracker.observe(bodies, world.stepCount(), check && i + 1 == steps);
        }
    }
    Row row;
    row.scene = label;
    row.bodies = world.dynamics().size();
    row.steps = steps;
    row.meanSeconds = timer.meanCpu();
    row.medianSeconds = timer.medianCpu();
    row.medianWallSeconds = timer.medianWall();
    row.contactsPerStep = contacts / double(steps);
    row.broadphase = toString(world.broadphase().lastKind());
    if (rain) {
        statesOf(world, states);
        row.worstOverlap = double(rainMeter.worstOverlap());
        row.escaped = rainMeter.escaped(states);
    }
    const BodySet bodies{world.dynamics(), world.kinematics(), world.planes()};
    std::printf("\nBroadphase tracker, %s (%zu bodies, one step in %d observed%s):\n", label.c_str(), row.bodies,
                kTrackEvery, check ? ", checked against brute force on the last" : ", too many for brute force");
    writeBroadphaseTable(stdout, tracker, bodies);
    std::fflush(stdout);
    if (markdown) {
        std::fprintf(markdown, "\n%s, %zu bodies:\n\n```\n", label.c_str(), row.bodies);
        writeBroadphaseTable(markdown, tracker, bodies);
        std::fprintf(markdown, "```\n");
    }
    agrees = agrees && tracker.agrees();
    return row;
}

void printRows(std::FILE* out, const std::vector<Row>& rows, bool markdown) {
    const char* header[] = {"scene", "bodies", "steps", "CPU ms/step (median)", "CPU ms/step (mean)",
                            "wall ms/step (median)", "CPU us/body/step", "contacts/step", "worst overlap (mm)",
                            "escaped", "broadphase"};
    if (markdown) {
        std::fprintf(out, "\n|");
        for (const char* h : header) std::fprintf(out, " %s |", h);
        std::fprintf(out, "\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    } else {
        std::fprintf(out, "\n%-12s %7s %6s %21s %19s %22s %17s %14s %19s %8s  %s\n", header[0], header[1],
                     header[2], header[3], header[4], header[5], header[6], header[7], header[8], header[9],
                     header[10]);
    }
    for (const Row& r : rows) {
        char overlap[32] = "-";
        char escaped[32] = "-";
        if (r.worstOverlap) std::snprintf(overlap, sizeof overlap, "%.1f", kMillimetresPerMetre * *r.worstOverlap);
        if (r.escaped) std::snprintf(escaped, sizeof escaped, "%zu", *r.escaped);
        const double perBody = kMicrosecondsPerSecond * r.medianSeconds / double(r.bodies);
        const char* format = markdown ? "| %s | %zu | %d | %.2f | %.2f | %.2f | %.2f | %.0f | %s | %s | %s |\n"
                                      : "%-12s %7zu %6d %21.2f %19.2f %22.2f %17.2f %14.0f %19s %8s  %s\n";
        std::fprintf(out, format, r.scene.c_str(), r.bodies, r.steps, kMillisecondsPerSecond * r.medianSeconds,
                     kMillisecondsPerSecond * r.meanSeconds, kMillisecondsPerSecond * r.medianWallSeconds, perBody,
                     r.contactsPerStep, overlap, escaped, r.broadphase.c_str());
    }
}

/// The question, "does the cost per body stay flat?", one line per
/// scene: CPU µs per body per step at each size, and the growth from the
/// smallest size to the largest. The median and the mean are both given: a
/// pile that falls asleep has a median far below its mean, and the mean is
/// then the fair figure.
void printCostPerBody(std::FILE* out, const std::vector<Row>& rows, bool markdown) {
    std::vector<std::string> scenes;
    for (const Row& r : rows) {
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    }
    std::fprintf(out, markdown ? "\n**Cost per body**, CPU µs per body per step (median / mean of the run):\n\n"
                                 "| scene | per size | growth, smallest to largest (median / mean) |\n|---|---|---|\n"
                               : "\nCost per body, CPU us per body per step (median / mean of the run):\n");
    for (const std::string& scene : scenes) {
        std::string sizes;
        const Row* first = nullptr;
        const Row* last = nullptr;
        for (const Row& r : rows) {
            if (r.scene != scene) continue;
            first = first ? first : &r;
            last = &r;
            char cell[96];
            std::snprintf(cell, sizeof cell, "%s%zu: %.1f / %.1f", sizes.empty() ? "" : ", ", r.bodies,
                          kMicrosecondsPerSecond * r.medianSeconds / double(r.bodies),
                          kMicrosecondsPerSecond * r.meanSeconds / double(r.bodies));
            sizes += cell;
        }
        const auto growth = [&](double Row::*seconds) {
            return 100 * ((last->*seconds / double(last->bodies)) / (first->*seconds / double(first->bodies)) - 1);
        };
        char change[96];
        std::snprintf(change, sizeof change, "%+.0f %% / %+.0f %% over %.0f times the bodies", growth(&Row::medianSeconds),
                      growth(&Row::meanSeconds), double(last->bodies) / double(first->bodies));
        std::fprintf(out, markdown ? "| %s | %s | %s |\n" : "  %-12s %s; %s\n", scene.c_str(), sizes.c_str(), change);
    }
}

}  // namespace

int runScaling(const ScalingOptions& options) {
    std::vector<std::size_t> rainSizes = options.rainSizes;
    std::vector<std::size_t> pileSizes = options.pileSizes;
    if (rainSizes.empty()) rainSizes = options.quick ? std::vector<std::size_t>{kQuickRain}
                                                     : std::vector<std::size_t>{1000, 4000, 16000, 64000};
    if (pileSizes.empty()) pileSizes = options.quick ? std::vector<std::size_t>{kQuickPile}
                                                     : std::vector<std::size_t>{1000, 4000, 16000};
    std::FILE* markdown = nullptr;
    if (options.markdownPath) {
        markdown = std::fopen(options.markdownPath->c_str(), "w");
        if (!markdown) {
            std::fprintf(stderr, "stepwise-bench: cannot write %s\n", options.markdownPath->c_str());
            return 2;
        }
        std::fprintf(markdown, "**Broadphase tracker, one table per run** (`stepwise bench broadphase`'s table):\n");
    }
    std::printf("stepwise-bench scaling: World::step() timed alone, in process CPU time and wall-clock time;\n"
                "the median is over the steps of one run\n");
    std::vector<Row> rows;
    bool agrees = true;
    const auto wanted = [&](const char* name) {
        return options.scenes.empty() || std::find(options.scenes.begin(), options.scenes.end(), name) != options.scenes.end();
    };
    for (const std::size_t n : rainSizes) {
        if (!wanted("sphere-rain")) break;
        int steps = n >= kLargeRain ? options.largeRainSteps : options.rainSteps;
        if (options.quick) steps = kQuickSteps;
        rows.push_back(runOne("sphere-rain", sphereRainSceneText(n, options.seed), steps, true, markdown, agrees));
    }
    for (const GeneratedScene scene : {GeneratedScene::BoxPile, GeneratedScene::Pyramids}) {
        for (const std::size_t n : pileSizes) {
            if (!wanted(toString(scene))) break;
            GeneratorOptions generator;
            generator.scene = scene;
            generator.count = n;
            generator.seed = options.seed;
            const int steps = options.quick ? kQuickSteps : options.pileSteps;
            rows.push_back(runOne(toString(scene), generateSceneText(generator), steps, false, markdown, agrees));
        }
    }
    std::printf("\nScaling: time per step (median and mean over the run), per body, contacts, and for the\n"
                "sphere rain the deepest overlap seen at any step and the spheres outside the box at the end\n");
    printRows(stdout, rows, false);
    printCostPerBody(stdout, rows, false);
    if (markdown) {
        std::fprintf(markdown, "\n**Scaling** (Stepwise alone):\n");
        printRows(markdown, rows, true);
        printCostPerBody(markdown, rows, true);
        std::fclose(markdown);
    }
    if (!agrees) {
        std::fprintf(stderr, "stepwise-bench scaling: a broadphase differs from brute force (see the tables)\n");
        return 1;
    }
    return 0;
}

}  // namespace stepwise::bench
