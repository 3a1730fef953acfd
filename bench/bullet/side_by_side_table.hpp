/// @file side_by_side_table.hpp
/// @brief What the side-by-side scenarios share: stepping an engine with timing, and the printed table.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "../scenario_metrics.hpp"

namespace stepwise::bench {

/// @brief Steps of every long run in --quick mode.
inline constexpr int kQuickSteps = 60;
/// @brief ms per s (and mm per m).
inline constexpr double kMs = 1e3;

/// @brief Median times per step, s.
struct Timing {
    double cpu = 0;   ///< CPU time of the process (every thread), s.
    double wall = 0;  ///< Wall-clock time, s.
};

/// @brief Steps @p engine @p steps times, timing each step; calls @p observe(states, t) after each.
template <class Engine>
Timing runSteps(Engine& engine, int steps, Real h, const std::function<void(const std::vector<BodyState>&, Real)>& observe) {
    std::vector<BodyState> states;
    StepTimer timer(static_cast<std::size_t>(steps));
    for (int i = 0; i < steps; ++i) {
        timer.start();
        engine.step();
        timer.stop();
        engine.states(states);
        observe(states, Real(i + 1) * h);
    }
    return {timer.medianCpu(), timer.medianWall()};
}

/// @brief @p value printed with the printf format @p fmt.
inline std::string format(const char* fmt, double value) {
    char text[64];
    std::snprintf(text, sizeof text, fmt, value);
    return text;
}

/// @brief One table: a row per figure, Stepwise, Bullet and Bullet/Stepwise.
struct Table {
    std::string title;  ///< Printed above the table.
    /// @brief One row: the figure's name, each engine's value, and Bullet's ÷ Stepwise's.
    struct Row {
        std::string figure;    ///< What is measured, with its unit.
        std::string stepwise;  ///< Stepwise's value, printed.
        std::string bullet;    ///< Bullet's value, printed.
        std::string ratio;     ///< Bullet's ÷ Stepwise's, or "—".
    };
    std::vector<Row> rows;  ///< In the order printed.
    /// Column heads; the default is the side-by-side's (a sweep lists runs, not engines).
    std::array<std::string, 4> header{"figure", "Stepwise", "Bullet", "Bullet / Stepwise"};

    /// A figure where smaller is better: the ratio column is bullet/stepwise, unless
    /// Stepwise's figure prints as 0 (rounding error only: the ratio would be noise).
    /// A figure a run could not measure (NaN: a flip or a crossing that never came) shows as "—".
    void add(const std::string& figure, const char* fmt, double stepwise, double bullet) {
        std::string ratio = "—";
        const std::string shown = std::isnan(stepwise) ? "—" : format(fmt, stepwise);
        if (std::strtod(shown.c_str(), nullptr) > 0 && bullet >= 0 && std::isfinite(stepwise) && std::isfinite(bullet)) {
            ratio = format("%.2f", bullet / stepwise);
        }
        rows.push_back({figure, shown, std::isnan(bullet) ? "—" : format(fmt, bullet), ratio});
    }
    /// A figure without a meaningful ratio.
    void addText(const std::string& figure, std::string stepwise, std::string bullet) {
        rows.push_back({figure, std::move(stepwise), std::move(bullet), "—"});
    }

    /// Prints the table to @p out, as Markdown or as aligned text.
    void print(std::FILE* out, bool markdown) const {
        if (markdown) {
            const bool threeColumns = header[3].empty();
            std::fprintf(out, "\n**%s**\n\n| %s | %s | %s |", title.c_str(), header[0].c_str(), header[1].c_str(),
                         header[2].c_str());
            std::fprintf(out, threeColumns ? "\n|---|---:|---:|\n" : " %s |\n|---|---:|---:|---:|\n", header[3].c_str());
            for (const Row& r : rows) {
                std::fprintf(out, "| %s | %s | %s |", r.figure.c_str(), r.stepwise.c_str(), r.bullet.c_str());
                std::fprintf(out, threeColumns ? "\n" : " %s |\n", r.ratio.c_str());
            }
            return;
        }
        std::fprintf(out, "\n%s\n  %-40s %14s %14s %18s\n", title.c_str(), header[0].c_str(), header[1].c_str(),
                     header[2].c_str(), header[3].c_str());
        for (const Row& r : rows) {
            std::fprintf(out, "  %-40s %14s %14s %18s\n", r.figure.c_str(), r.stepwise.c_str(), r.bullet.c_str(),
                         r.ratio.c_str());
        }
    }
};

}  // namespace stepwise::bench
