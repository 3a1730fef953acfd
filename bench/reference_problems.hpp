/// @file reference_problems.hpp
/// @brief The reference problems of `stepwise-bench precision`: scenes with known solutions, and their error measures.
///
/// Each problem is a scene file in config/ (so a student can open, run and
/// change it) plus the exact solution it is judged against. The benchmark
/// loads the file once, overrides only the World's TimeStep and Integrator,
/// runs the engine's own World::step() and compares.
///
/// | problem            | scene file                          | primary error (first metric)                      | also measured |
/// |--------------------|-------------------------------------|---------------------------------------------------|---------------|
/// | projectile         | reference_projectile.scene          | position error at t = Duration (2 s), m           | velocity error |
/// | spring             | reference_spring.scene              | phase error after 10 periods, rad                 | amplitude error, energy error |
/// | kepler-circular    | reference_kepler_circular.scene     | position error after 10 orbits, m                 | energy drift |
/// | kepler-eccentric   | reference_kepler_eccentric.scene    | position error after 10 orbits, m                 | energy drift |
/// | free-box           | reference_free_box.scene            | largest flip-time error (Dzhanibekov), s          | energy drift, \|L\| drift |
/// | bounce             | reference_bounce.scene              | largest apex-height error, first 4 bounces, rel.  | first apex error |
/// | pendulum           | reference_pendulum.scene            | mean period over 10 swings against 4√(L/g)·K(sin(θ₀/2)), rel. | rod length error, energy error |
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "world/scene.hpp"

namespace stepwise::bench {

/// @brief One measured quantity of one run.
struct Metric {
    std::string name;   ///< Short column name, e.g. "phase_error".
    std::string unit;   ///< "m", "rad", "s", "1" (relative), …
    double value = 0;   ///< NaN when the run could not measure it (it blew up, a flip never came).
};

/// @brief What one run of a reference problem at one integrator and time step showed.
struct Measurement {
    std::uint64_t steps = 0;      ///< Steps simulated (fewer than planned if the run blew up).
    std::vector<Metric> metrics;  ///< The first is the problem's primary error, the one plotted.
    std::string note;             ///< Anything a reader must know: "blew up at step 812", "2 of 3 flips".
};

/// @brief Runs the prepared problem with @p integrator at step @p h (s) and measures its errors.
using ProblemRunner = std::function<Measurement(IntegratorKind integrator, double h)>;

/// @brief A reference problem: its scene file and how to judge a run of it.
struct ReferenceProblem {
    std::string name;       ///< As used on the command line and in the CSV: "spring".
    std::string sceneFile;  ///< File name in config/; empty while the problem cannot be built yet.
    std::string what;       ///< One line for the report.
    /// @brief Checks the loaded scene is the problem it should be, computes the
    /// exact reference once, and returns the runner. @throws std::runtime_error naming what is wrong.
    std::function<ProblemRunner(const Scene& scene)> prepare;
    std::string unavailable;  ///< Non-empty: why the problem is skipped (prepare is then empty).
};

/// @brief Every reference problem, in the order the report lists them.
std::span<const ReferenceProblem> referenceProblems();

/// @brief A copy of @p scene with the World's time step and integrator replaced.
Scene withStep(const Scene& scene, IntegratorKind integrator, double h);

}  // namespace stepwise::bench
