/// @file precision.cpp
/// @brief The precision sweep: errors from one careful run, nanoseconds per step from the median of several.
///
/// The error of a run is deterministic, so each (problem, integrator, h) is
/// measured once, with the problem's observer watching every step. The
/// time is measured separately, with nothing but World::step() in the loop,
/// `repeats` times from a fresh World; the median is reported because on a
/// shared machine the mean is pulled up by whoever else is running.
#include "precision.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <stdexcept>

#include "config/scene_loader.hpp"
#include "core/errors.hpp"
#include "reference_problems.hpp"
#include "world/world.hpp"

namespace stepwise::bench {

namespace {

/// Coarsest step swept, s: 30 steps per second, half the usual display rate.
constexpr double kCoarsestStep = 1.0 / 30;
/// Halvings: 1/30, 1/60, …, 1/1920 s.
constexpr int kStepCount = 7;
/// --quick runs only the first this many steps.
constexpr int kQuickStepCount = 2;

constexpr IntegratorKind kIntegrators[] = {IntegratorKind::ExplicitEuler, IntegratorKind::SymplecticEuler,
                                           IntegratorKind::Verlet};

using Clock = std::chrono::steady_clock;

/// One line of the result: a problem run with one integrator at one step.
struct Row {
    std::string problem;
    IntegratorKind integrator;
    double h;
    Measurement measurement;
    double nsPerStep;
};

/// Wall time of @p steps calls of World::step(), per step, ns; the World is built outside the clock.
double nanosecondsPerStep(const Scene& scene, std::uint64_t steps) {
    World world(scene);
    const auto start = Clock::now();
    try {
        for (std::uint64_t i = 0; i < steps; ++i) world.step();
    } catch (const SimulationError&) {
        // The measured run blew up too: its steps up to there were counted.
    }
    const double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count();
    return world.stepCount() > 0 ? ns / double(world.stepCount()) : 0.0;
}

/// "1/60" for the steps swept (all are 1/n s), else the number.
std::string stepLabel(double h) {
    const double perSecond = 1 / h;
    char text[32];
    if (std::abs(perSecond - std::round(perSecond)) < 1e-9) std::snprintf(text, sizeof text, "1/%.0f", perSecond);
    else std::snprintf(text, sizeof text, "%.6g", h);
    return text;
}

std::string number(double value) {
    if (std::isnan(value)) return "—";
    char text[32];
    std::snprintf(text, sizeof text, "%.3e", value);
    return text;
}

bool wanted(const PrecisionOptions& options, const std::string& name) {
    return options.only.empty() || std::find(options.only.begin(), options.only.end(), name) != options.only.end();
}

void printTable(std::FILE* out, const std::vector<Row>& rows) {
    if (rows.empty()) return;
    std::fprintf(out, "  %-16s %-7s %7s %9s", "integrator", "h (s)", "steps", "ns/step");
    for (const Metric& m : rows.front().measurement.metrics) {
        std::fprintf(out, "  %20s", (m.name + " (" + m.unit + ")").c_str());
    }
    std::fprintf(out, "\n");
    for (const Row& row : rows) {
        std::fprintf(out, "  %-16s %-7s %7llu %9.0f", toString(row.integrator), stepLabel(row.h).c_str(),
                     static_cast<unsigned long long>(row.measurement.steps), row.nsPerStep);
        for (const Metric& m : row.measurement.metrics) std::fprintf(out, "  %20s", number(m.value).c_str());
        std::fprintf(out, "%s%s\n", row.measurement.note.empty() ? "" : "  ", row.measurement.note.c_str());
    }
}

/// The rows of @p rows measured with @p integrator at @p h (there is one).
const Row* find(const std::vector<Row>& rows, IntegratorKind integrator, double h) {
    for (const Row& row : rows) {
        if (row.integrator == integrator && row.h == h) return &row;
    }
    return nullptr;
}

/// One Markdown table per metric, and one of ns/step: a row per time step, a column per integrator.
void writeMarkdown(std::FILE* out, const std::vector<Row>& rows, const std::vector<double>& steps) {
    if (rows.empty()) return;
    const std::vector<Metric>& metrics = rows.front().measurement.metrics;
    const auto table = [&](const std::string& title, auto&& cell) {
        std::fprintf(out, "%s\n\n| h (s) |", title.c_str());
        for (IntegratorKind integrator : kIntegrators) std::fprintf(out, " %s |", toString(integrator));
        std::fprintf(out, "\n|---|");
        for (std::size_t i = 0; i < std::size(kIntegrators); ++i) std::fprintf(out, "---:|");
        std::fprintf(out, "\n");
        for (double h : steps) {
            std::fprintf(out, "| %s |", stepLabel(h).c_str());
            for (IntegratorKind integrator : kIntegrators) {
                const Row* row = find(rows, integrator, h);
                std::fprintf(out, " %s |", row ? cell(*row).c_str() : "");
            }
            std::fprintf(out, "\n");
        }
        std::fprintf(out, "\n");
    };
    for (std::size_t k = 0; k < metrics.size(); ++k) {
        table("`" + metrics[k].name + "` (" + metrics[k].unit + ")",
              [&](const Row& row) { return number(row.measurement.metrics[k].value); });
    }
    table("ns per step (median)", [](const Row& row) {
        char text[32];
        std::snprintf(text, sizeof text, "%.0f", row.nsPerStep);
        return std::string(text);
    });
    for (const Row& row : rows) {
        if (row.measurement.note.empty()) continue;
        std::fprintf(out, "- %s at h = %s s: %s\n", toString(row.integrator), stepLabel(row.h).c_str(),
                     row.measurement.note.c_str());
    }
    std::fprintf(out, "\n");
}

void writeCsv(std::FILE* out, const std::vector<Row>& rows) {
    // One row per metric ("long" format): a plotting script filters on problem, metric and integrator.
    std::fprintf(out, "problem,integrator,timestep_s,steps,ns_per_step,metric,unit,value\n");
    for (const Row& row : rows) {
        for (const Metric& m : row.measurement.metrics) {
            std::fprintf(out, "%s,%s,%.17g,%llu,%.1f,%s,%s,%.6e\n", row.problem.c_str(), toString(row.integrator),
                         row.h, static_cast<unsigned long long>(row.measurement.steps), row.nsPerStep, m.name.c_str(),
                         m.unit.c_str(), m.value);
        }
    }
}

}  // namespace

std::vector<double> sweptTimeSteps(bool quick) {
    std::vector<double> steps;
    const int count = quick ? kQuickStepCount : kStepCount;
    for (int i = 0; i < count; ++i) steps.push_back(kCoarsestStep / std::pow(2.0, i));
    return steps;
}

int runPrecision(const PrecisionOptions& options) {
    const int repeats = options.quick ? 1 : options.repeats;
    const std::vector<double> timeSteps = sweptTimeSteps(options.quick);
#ifndef NDEBUG
    std::fprintf(stderr, "stepwise-bench: warning: built without optimisation (not Release): the ns/step are not "
                         "the engine's speed\n");
#endif
    std::printf("stepwise-bench precision: %zu time steps from %s to %s s, %d timed repetition(s), median ns/step\n",
                timeSteps.size(), stepLabel(timeSteps.front()).c_str(), stepLabel(timeSteps.back()).c_str(), repeats);

    std::FILE* markdown = nullptr;
    if (options.markdownPath) {
        markdown = std::fopen(options.markdownPath->c_str(), "w");
        if (!markdown) {
            std::fprintf(stderr, "stepwise-bench: error: cannot write '%s'\n", options.markdownPath->c_str());
            return 2;
        }
    }
    std::vector<Row> all;
    int exitCode = 0;
    for (const ReferenceProblem& problem : referenceProblems()) {
        if (!wanted(options, problem.name)) continue;
        std::printf("\n%s: %s\n", problem.name.c_str(), problem.what.c_str());
        if (!problem.unavailable.empty()) {
            std::printf("  skipped: %s\n", problem.unavailable.c_str());
            if (markdown) std::fprintf(markdown, "### %s {#bench-%s}\n\nNot measured yet: %s.\n\n", problem.name.c_str(),
                                       problem.name.c_str(), problem.unavailable.c_str());
            continue;
        }
        const std::string path = options.configDir + "/" + problem.sceneFile;
        JudgeMaker judgeAt;
        Scene scene;
        try {
            scene = loadSceneFile(path);
            judgeAt = problem.prepare(scene);
        } catch (const std::exception& error) {
            std::fprintf(stderr, "stepwise-bench: %s: %s\n", problem.name.c_str(), error.what());
            exitCode = 1;
            continue;
        }
        std::printf("  scene %s\n", path.c_str());
        std::vector<Row> rows;
        for (IntegratorKind integrator : kIntegrators) {
            for (double h : timeSteps) {
                Row row{problem.name, integrator, h, runInStepwise(scene, judgeAt, integrator, h), 0};
                std::vector<double> times;
                const Scene stepped = withStep(scene, integrator, h);
                for (int r = 0; r < repeats; ++r) times.push_back(nanosecondsPerStep(stepped, row.measurement.steps));
                row.nsPerStep = median(times);
                rows.push_back(std::move(row));
            }
        }
        printTable(stdout, rows);
        if (markdown) {
            std::fprintf(markdown, "### %s {#bench-%s}\n\n%s (`config/%s`).\n\n", problem.name.c_str(),
                         problem.name.c_str(), problem.what.c_str(), problem.sceneFile.c_str());
            writeMarkdown(markdown, rows, timeSteps);
        }
        all.insert(all.end(), rows.begin(), rows.end());
    }
    if (markdown) std::fclose(markdown);

    if (options.csvPath) {
        std::FILE* csv = std::fopen(options.csvPath->c_str(), "w");
        if (!csv) {
            std::fprintf(stderr, "stepwise-bench: error: cannot write '%s'\n", options.csvPath->c_str());
            return 2;
        }
        writeCsv(csv, all);
        std::fclose(csv);
        std::printf("\nCSV written to %s\n", options.csvPath->c_str());
    }
    return exitCode;
}

}  // namespace stepwise::bench
