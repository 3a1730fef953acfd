/// @file plot.cpp
/// @brief `stepwise plot`: simulate a scene, sample one quantity of chosen bodies, draw it with gnuplot.
///
/// The program does the physics, gnuplot the drawing: the numbers come from a
/// QuantityTable (src/io/quantity_table.hpp), sampled between steps as
/// `stepwise run --csv` samples the state, and reach gnuplot inside the script
/// it reads on its standard input (a data block, `$data << EOD`), so no
/// temporary file is left behind. `--data` writes the same numbers as CSV, to
/// check a plot or to draw one's own.
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "app/cli.hpp"
#include "config/scene_loader.hpp"
#include "core/errors.hpp"
#include "io/output_file.hpp"
#include "world/world.hpp"

/// The program's environment (POSIX): gnuplot is started with it unchanged.
extern char** environ;

namespace stepwise::cli {

namespace {

/// The plot's line colours, in order (those of bench/plot_precision.gp first).
constexpr const char* kColours[] = {"#d62728", "#1f77b4", "#2ca02c", "#ff7f0e",
                                    "#9467bd", "#8c564b", "#e377c2", "#17becf"};
/// The whole scene's line: black and dashed, beside the bodies' colours.
constexpr const char* kWholeSceneColour = "#000000";
/// Relative spread below which a panel's numbers count as one value that round-off blurred
/// (doubles carry about 16 digits; a long run's sums lose a few).
constexpr double kRoundOff = 1e-9;

/// @p text as a gnuplot single-quoted string: inside one, a quote is written twice.
std::string quoted(const std::string& text) {
    std::string out = "'";
    for (const char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

/// The file name without its folders: what a plot's title shows of the scene.
std::string baseName(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// A tic spacing of 1, 2 or 5 times a power of ten that cuts [@p low, @p high] into about four:
/// gnuplot's own choice depends on the range only, and crowds a short panel.
double ticStep(double low, double high) {
    const double rough = (high - low) / 4;
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    for (const double factor : {1.0, 2.0, 5.0}) {
        if (factor * power >= rough) return factor * power;
    }
    return 10 * power;
}

/// The gnuplot script that draws @p table: one panel per component, stacked, one line per series.
std::string gnuplotScript(const QuantityTable& table, const PlotOptions& options) {
    std::string s;
    s += "set terminal pngcairo size " + std::to_string(options.width) + "," + std::to_string(options.height) +
         " enhanced font 'DejaVu Sans,10' linewidth 1.5\n";
    s += "set output " + quoted(*options.outPath) + "\n";
    s += "set datafile separator ','\n";
    s += "$data << EOD\n";
    char number[32];
    for (const std::vector<double>& row : table.rows()) {
        for (std::size_t i = 0; i < row.size(); ++i) {
            std::snprintf(number, sizeof number, i == 0 ? "%.17g" : ",%.17g", row[i]);  // as --data writes them
            s += number;
        }
        s += "\n";
    }
    s += "EOD\n";
    s += "set grid xtics ytics lc rgb '#dddddd'\n";
    s += "set key outside right top noenhanced\n";
    // Every panel keeps the same margins, so their time axes line up.
    s += "set lmargin 12\nset rmargin 18\n";
    const std::size_t panels = table.components().size();
    const std::string title = baseName(options.scenePath) + ": " + toString(table.quantity());
    s += "set multiplot layout " + std::to_string(panels) + ",1 title " + quoted(title) + " noenhanced\n";
    for (std::size_t p = 0; p < panels; ++p) {
        s += "set ylabel " + quoted(table.components()[p] + " (" + plotUnit(table.quantity()) + ")") + " noenhanced\n";
        s += p + 1 == panels ? "set xlabel 'time t (s)'\nset format x '%g'\n" : "unset xlabel\nset format x ''\n";
        // The key once, beside the top panel: every panel has the same lines.
        if (p == 1) s += "unset key\n";
        // A panel whose numbers are all one value (a ball's z, a potential of 0), or differ only by
        // round-off (a conserved energy: 1e-13 J on 110 J), gets a range around it: gnuplot would
        // otherwise warn that the range is empty, or stretch the round-off over the whole panel.
        double low = HUGE_VAL, high = -HUGE_VAL;
        for (const std::vector<double>& row : table.rows()) {
            for (std::size_t k = 0; k < table.series().size(); ++k) {
                low = std::min(low, row[1 + k * panels + p]);
                high = std::max(high, row[1 + k * panels + p]);
            }
        }
        char range[96] = "set yrange [*:*]\nset ytics autofreq\n";
        const double scale = std::max(std::abs(low), std::abs(high));
        if (std::isfinite(high - low) && high - low <= kRoundOff * scale) {
            const double middle = 0.5 * (low + high);
            const double pad = middle == 0 ? 1.0 : std::abs(middle) * 0.1;
            std::snprintf(range, sizeof range, "set yrange [%.10g:%.10g]\nset ytics autofreq\n", middle - pad, middle + pad);
        } else if (low < high && std::isfinite(high - low)) {
            std::snprintf(range, sizeof range, "set yrange [*:*]\nset ytics %.10g\n", ticStep(low, high));
        }
        s += range;
        s += "plot";
        for (std::size_t k = 0; k < table.series().size(); ++k) {
            const std::string& name = table.series()[k];
            const bool whole = name == kWholeSceneSeries;
            const std::size_t column = 2 + k * panels + p;  // column 1 is the time
            s += std::string(k == 0 ? " " : ", ") + "$data using 1:" + std::to_string(column) + " with lines lc rgb '" +
                 (whole ? kWholeSceneColour : kColours[k % std::size(kColours)]) + "'" + (whole ? " dt 2" : "") +
                 " title " + quoted(whole ? "whole scene" : name);
        }
        s += "\n";
    }
    s += "unset multiplot\n";
    return s;
}

/// Runs gnuplot (or the program $STEPWISE_GNUPLOT names) on @p script; "" when it drew, else why not.
std::string runGnuplot(const std::string& script) {
    const char* fromEnvironment = std::getenv("STEPWISE_GNUPLOT");
    const std::string program = fromEnvironment && *fromEnvironment ? fromEnvironment : "gnuplot";
    int fds[2];
    if (pipe(fds) != 0) return std::string("cannot make a pipe to gnuplot: ") + std::strerror(errno);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    std::string argument0 = program;
    char* argv[] = {argument0.data(), nullptr};
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[0]);
    if (spawned != 0) {
        close(fds[1]);
        return "cannot run '" + program + "': " + std::strerror(spawned) +
               ". Install gnuplot (Debian: gnuplot-nox; scripts/setup.sh does), or write the numbers with "
               "--data FILE.csv and draw them with another program";
    }
    // A gnuplot that stops reading early closes the pipe: the write must fail, not kill this program.
    struct sigaction ignore {}, previous {};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &previous);
    std::size_t written = 0;
    while (written < script.size()) {
        const ssize_t n = write(fds[1], script.data() + written, script.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        written += static_cast<std::size_t>(n);
    }
    close(fds[1]);
    sigaction(SIGPIPE, &previous, nullptr);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        return "'" + program + "' failed (" +
               (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                  : std::string("stopped by a signal")) +
               "; what it printed is above)";
    }
    if (written < script.size()) return "'" + program + "' stopped reading its script before the end";
    return "";
}

/// True when @p path is a file of more than zero bytes.
bool nonEmptyFile(const std::string& path) {
    struct stat info {};
    return stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0;
}

}  // namespace

int plotCommand(const PlotOptions& options) {
    std::unique_ptr<Scene> scene = loadOrReport(options.scenePath);
    if (!scene) return kExitUsageError;
    World world(std::move(*scene));
    std::optional<QuantityTable> table;
    try {
        table.emplace(world, options.quantity, options.objects, options.components);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }

    // Both files are opened before the run, so a path that cannot be written is found at once.
    std::optional<OutputFile> data;
    if (options.dataPath) {
        data.emplace(*options.dataPath);
        if (!data->ok()) {
            std::fprintf(stderr, "stepwise: error: %s\n", data->error().c_str());
            return kExitUsageError;
        }
    }
    if (options.outPath) {
        OutputFile picture(*options.outPath);  // gnuplot writes it; here only whether it can be written
        if (!picture.ok()) {
            std::fprintf(stderr, "stepwise: error: %s\n", picture.error().c_str());
            return kExitUsageError;
        }
    }

    const double h = double(world.settings().timeStep);
    const double duration = options.duration.value_or(double(world.settings().duration));
    // Round to the nearest whole step, as `run` does: 10 s at 1/60 s is 600 steps.
    const std::uint64_t steps = options.steps.value_or(static_cast<std::uint64_t>(std::llround(duration / h)));
    table->sample(world);
    // A run that fails (a non-finite state) is still drawn up to the last whole step: a blow-up is
    // worth seeing. The exit code says it failed.
    int exitCode = kExitOk;
    try {
        for (std::uint64_t i = 0; i < steps; ++i) {
            world.step();
            if (world.stepCount() % options.every == 0) table->sample(world);
        }
    } catch (const SimulationError& error) {
        std::fprintf(stderr, "stepwise: simulation failed: %s; plotting the steps before it\n", error.what());
        exitCode = kExitSimulationError;
    }

    if (data) {
        table->writeCsv(data->file());
        const std::string error = data->close();
        if (!error.empty()) {
            std::fprintf(stderr, "stepwise: error: %s\n", error.c_str());
            return kExitSimulationError;
        }
    }
    if (options.outPath) {
        const std::string error = runGnuplot(gnuplotScript(*table, options));
        if (!error.empty()) {
            std::fprintf(stderr, "stepwise: error: cannot draw '%s': %s\n", options.outPath->c_str(), error.c_str());
            return kExitSimulationError;
        }
        if (!nonEmptyFile(*options.outPath)) {
            std::fprintf(stderr, "stepwise: error: gnuplot ran but left no picture in '%s'\n", options.outPath->c_str());
            return kExitSimulationError;
        }
    }
    // Standard output may be the data itself (--data -): then the report goes to stderr.
    std::FILE* report = options.dataPath && *options.dataPath == "-" ? stderr : stdout;
    std::fprintf(report, "Sampled %s of %zu series at %zu times, t = 0 to %.6g s\n", toString(options.quantity),
                 table->series().size(), table->rows().size(), table->rows().back().front());
    if (options.dataPath && *options.dataPath != "-") std::fprintf(report, "Data written to %s\n", options.dataPath->c_str());
    if (options.outPath) std::fprintf(report, "Plot written to %s\n", options.outPath->c_str());
    return exitCode;
}

}  // namespace stepwise::cli
