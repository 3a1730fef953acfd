/// @file stage_costs.cpp
/// @brief `stepwise-bench stage-costs`: the cost of each stage per body, sizes of the settled rain timed in turn (why: stage_costs.hpp).
#include "stage_costs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

#include "config/scene_loader.hpp"
#include "scenario_metrics.hpp"
#include "sphere_rain_scene.hpp"
#include "world/world.hpp"

namespace stepwise::bench {

namespace {

constexpr double kNanosecondsPerSecond = 1e9;
/// Quick mode: a smoke test of seconds.
constexpr std::size_t kQuickSizes[] = {200, 800};
constexpr int kQuickSettle = 20;
constexpr int kQuickRounds = 3;

/// One size of the rain: its world, how many steps it takes per round, and what they cost.
struct Run {
    std::unique_ptr<World> world;
    std::size_t bodies = 0;
    int stepsPerRound = 1;
    int steps = 0;                      ///< timed steps so far
    StageRecords before{};              ///< the stage clocks when the timing began
    std::unique_ptr<StepTimer> timer;   ///< CPU time of each timed step
    double contacts = 0;                ///< summed over the timed steps
};

/// Wall-clock ns per body per step that @p stage took in @p run's timed steps.
double stageCost(const Run& run, std::size_t stage) {
    const double seconds = run.world->stageRecords()[stage].totalSeconds - run.before[stage].totalSeconds;
    return kNanosecondsPerSecond * seconds / (double(run.bodies) * run.steps);
}

/// The table: a row per stage that ran, then the stages' sum, the whole step's CPU time and the
/// contacts per body; a column per size, then the largest size's figure over the smallest's.
void printTable(std::FILE* out, const std::vector<Run>& runs, bool markdown) {
    const Run& first = runs.front();
    const Run& last = runs.back();
    if (markdown) {
        std::fprintf(out, "\n| stage |");
        for (const Run& r : runs) std::fprintf(out, " %zu |", r.bodies);
        std::fprintf(out, " %zu ÷ %zu |\n|---|", last.bodies, first.bodies);
        for (std::size_t i = 0; i <= runs.size(); ++i) std::fprintf(out, "---:|");
        std::fprintf(out, "\n");
    } else {
        std::fprintf(out, "\n%-24s", "ns per body per step");
        for (const Run& r : runs) std::fprintf(out, " %10zu", r.bodies);
        std::fprintf(out, " %10s\n", "ratio");
    }
    const auto row = [&](const char* name, const std::vector<double>& values, const char* format) {
        std::fprintf(out, markdown ? "| %s |" : "%-24s", name);
        for (const double v : values) {
            char cell[32];
            std::snprintf(cell, sizeof cell, format, v);
            std::fprintf(out, markdown ? " %s |" : " %10s", cell);
        }
        std::fprintf(out, markdown ? " %.2f |\n" : " %10.2f\n", values.back() / values.front());
    };
    std::vector<double> sum(runs.size(), 0);
    for (std::size_t stage = 0; stage < kStageCount; ++stage) {
        std::vector<double> values;
        for (std::size_t i = 0; i < runs.size(); ++i) {
            values.push_back(stageCost(runs[i], stage));
            sum[i] += values.back();
        }
        if (values.front() > 0) row(stageName(static_cast<Stage>(stage)), values, "%.0f");
    }
    row(markdown ? "**sum of the stages** (wall clock)" : "sum of the stages", sum, "%.0f");
    std::vector<double> cpu;
    std::vector<double> contacts;
    for (const Run& r : runs) {
        cpu.push_back(kNanosecondsPerSecond * r.timer->meanCpu() / double(r.bodies));
        contacts.push_back(r.contacts / (double(r.bodies) * r.steps));
    }
    row(markdown ? "**whole step** (process CPU time)" : "whole step (CPU)", cpu, "%.0f");
    row("contacts per body", contacts, "%.2f");
}

constexpr double kBytesPerMegabyte = 1024.0 * 1024.0;

/// The data caches of the processor this runs on, as Linux describes them
/// (/sys/devices/system/cpu/cpu0/cache): "L1 48K, L2 2048K, L3 266240K (shared by 0-1)";
/// empty where the system does not say.
std::string dataCaches() {
    std::string caches;
    for (int index = 0;; ++index) {
        const std::string dir = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(index) + "/";
        std::ifstream level(dir + "level"), type(dir + "type"), size(dir + "size"), shared(dir + "shared_cpu_list");
        std::string levelText, typeText, sizeText, sharedText;
        if (!(level >> levelText) || !(type >> typeText) || !(size >> sizeText)) break;
        if (typeText == "Instruction") continue;
        shared >> sharedText;
        caches += (caches.empty() ? "L" : ", L") + levelText + " " + sizeText;
        if (sharedText.find_first_of(",-") != std::string::npos) caches += " (shared by cores " + sharedText + ")";
    }
    return caches;
}

/// Where the step's data lives: the megabytes the arrays of each size hold, against the caches.
/// A size whose walks fit in a core's own cache is served from it; a larger one streams the same
/// walks from the next level, and the cost per body grows by the difference while the work per
/// body (contacts per body, above) does not.
void printFootprint(std::FILE* out, const std::vector<Run>& runs, bool markdown) {
    if (markdown) {
        std::fprintf(out, "\n| arrays, MB |");
        for (const Run& r : runs) std::fprintf(out, " %zu |", r.bodies);
        std::fprintf(out, "\n|---|");
        for (std::size_t i = 0; i < runs.size(); ++i) std::fprintf(out, "---:|");
        std::fprintf(out, "\n");
    } else {
        std::fprintf(out, "\n%-40s", "arrays, MB");
        for (const Run& r : runs) std::fprintf(out, " %10zu", r.bodies);
        std::fprintf(out, "\n");
    }
    const auto row = [&](const char* name, auto&& megabytes) {
        std::fprintf(out, markdown ? "| %s |" : "%-40s", name);
        for (const Run& r : runs) std::fprintf(out, markdown ? " %.1f |" : " %10.1f", megabytes(r));
        std::fprintf(out, "\n");
    };
    row("the bodies (DynamicObject)", [](const Run& r) {
        return double(r.world->dynamics().size() * sizeof(DynamicObject)) / kBytesPerMegabyte;
    });
    row("the contacts (narrowphase)", [](const Run& r) {
        return double(r.world->contacts().size() * sizeof(Contact)) / kBytesPerMegabyte;
    });
    // As the last timed step left them
    row("the contact solver's, all", [](const Run& r) {
        return double(r.world->solverFootprint().allBytes) / kBytesPerMegabyte;
    });
    row("the contact solver's, read by each pass", [](const Run& r) {
        return double(r.world->solverFootprint().passBytes) / kBytesPerMegabyte;
    });
    // The passes and the moves between them: what must stay in a cache from substep to substep
    row("the contact solver's, a substep walks", [](const Run& r) {
        return double(r.world->solverFootprint().substepBytes) / kBytesPerMegabyte;
    });
    const std::string caches = dataCaches();
    std::fprintf(out, markdown ? "\nThe processor's data caches, per core unless shared: %s.\n" : "caches: %s\n",
                 caches.empty() ? "not known" : caches.c_str());
}

}  // namespace

int runStageCosts(const StageCostOptions& options) {
    std::vector<std::size_t> sizes = options.sizes;
    if (options.quick) sizes.assign(std::begin(kQuickSizes), std::end(kQuickSizes));
    if (sizes.empty()) sizes = {1000, 16000, 64000};
    std::sort(sizes.begin(), sizes.end());
    const int settle = options.quick ? kQuickSettle : options.settleSteps;
    const int rounds = options.quick ? kQuickRounds : options.rounds;

    std::vector<Run> runs;
    for (const std::size_t n : sizes) {
        Run run;
        run.world = std::make_unique<World>(onOneThread(parseScene(sphereRainSceneText(n, options.seed), "sphere-rain")));
        run.world->timeStages(true);  // this benchmark reads the stage times
        run.bodies = run.world->dynamics().size();
        // As many body-steps a round as the largest size's one step: every size is timed for about as long
        run.stepsPerRound = std::max(1, int(std::lround(double(sizes.back()) / double(n))));
        run.timer = std::make_unique<StepTimer>(std::size_t(run.stepsPerRound) * std::size_t(rounds));
        std::fprintf(stderr, "stage-costs: %zu spheres, %d steps to settle\n", n, settle);
        for (int i = 0; i < settle; ++i) run.world->step();
        run.before = run.world->stageRecords();
        runs.push_back(std::move(run));
    }
    for (int round = 0; round < rounds; ++round) {
        for (Run& run : runs) {
            for (int i = 0; i < run.stepsPerRound; ++i) {
                run.timer->start();
                run.world->step();
                run.timer->stop();
                run.contacts += double(run.world->contacts().size());
                ++run.steps;
            }
        }
    }

    std::printf("stepwise-bench stage-costs: the sphere rain after %d untimed steps, the sizes stepped in turn for %d\n"
                "rounds; each stage's wall-clock time (World::stageRecords()) and the whole step's CPU time, in ns per\n"
                "body per step; ratio = largest size / smallest\n", settle, rounds);
    printTable(stdout, runs, false);
    printFootprint(stdout, runs, false);
    if (options.markdownPath) {
        std::FILE* markdown = std::fopen(options.markdownPath->c_str(), "w");
        if (!markdown) {
            std::fprintf(stderr, "stepwise-bench: cannot write %s\n", options.markdownPath->c_str());
            return 2;
        }
        std::string steps;
        for (const Run& r : runs) steps += (steps.empty() ? "" : ", ") + std::to_string(r.steps);
        std::fprintf(markdown, "\n**Cost per body, stage by stage** (the rain settled for %d steps, then the sizes "
                               "stepped in turn for %d rounds: %s steps), ns per body per step:\n",
                     settle, rounds, steps.c_str());
        printTable(markdown, runs, true);
        printFootprint(markdown, runs, true);
        std::fclose(markdown);
    }
    return 0;
}

}  // namespace stepwise::bench
