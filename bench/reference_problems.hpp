/// @file reference_problems.hpp
/// @brief The reference problems of `stepwise-bench precision`: scenes with known solutions, and their error measures.
///
/// Each problem is a scene file in config/ (so a student can open, run and
/// change it) plus the exact solution it is judged against. The benchmark
/// loads the file once, overrides only the World's TimeStep and Integrator,
/// runs the engine's own World::step() and compares. The comparing is a
/// Judge, which sees only the body's state after each step, so the Bullet
/// side by side (bench/bullet/side_by_side.cpp) judges Bullet's run of the
/// same scene with the same code.
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

#include "core/errors.hpp"
#include "scenario_metrics.hpp"
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

/// @brief How a run of one problem at one time step is judged, whichever engine runs it.
///
/// A judge sees only the body's state after each step (BodyState, which
/// Stepwise and Bullet both give), so `stepwise-bench precision` and the
/// side-by-side with Bullet measure the same errors with the same code.
struct Judge {
    std::uint64_t steps = 0;  ///< Steps to run: the problem's duration ÷ h, rounded.
    /// Called after step n = 1, 2, … with the body's state and t = n·h, s.
    std::function<void(const BodyState& body, double time)> observe;
    /// Writes the errors into @p m once the run has ended (m.steps and m.note
    /// are set): @p last is the body's last state. Errors that need the run's
    /// planned end are NaN when it was cut short.
    std::function<void(const BodyState& last, Measurement& m)> finish;
};

/// @brief Makes the judge of a run at time step @p h (s).
using JudgeMaker = std::function<Judge(double h)>;

/// @brief A reference problem: its scene file and how to judge a run of it.
struct ReferenceProblem {
    std::string name;       ///< As used on the command line and in the CSV: "spring".
    std::string sceneFile;  ///< File name in config/; empty while the problem cannot be built yet.
    std::string what;       ///< One line for the report.
    /// @brief Checks the loaded scene is the problem it should be, computes the
    /// exact reference once, and returns the judges. @throws std::runtime_error naming what is wrong.
    std::function<JudgeMaker(const Scene& scene)> prepare;
    std::string unavailable;  ///< Non-empty: why the problem is skipped (prepare is then empty).
};

/// @brief Every reference problem, in the order the report lists them.
std::span<const ReferenceProblem> referenceProblems();

/// @brief The pendulum's judges for an engine whose rod is a pin at the pivot
/// (Bullet's btPoint2PointConstraint), so that the bob turns with the rod.
///
/// That bob is a *compound* pendulum: about the pivot its moment of inertia is
/// I_p = I + m·L² (I the bob's own, about its centre, across the swing), so
/// its equation of motion I_p·θ¨ = −m·g·L·sin θ is the simple pendulum's with
/// the length I_p/(m·L) = L + I/(m·L): 1 mm longer for the reference scene's
/// ball of 1 kg and 5 cm on its 1 m rod, a period 0.05 % longer. Its energy
/// counts the bob's turning, ½·ω·L_bob.
/// Stepwise's DistanceJoint holds the bob's centre and never turns it, so its
/// judges (referenceProblems()) use L itself.
JudgeMaker preparePendulumTurningBob(const Scene& scene);

/// @brief Runs @p judge over @p engine (anything with step() and states(out)):
/// judge.steps steps, observing each; a SimulationError ends the run early
/// and is noted. The first body of the engine's states is the one judged.
template <class Engine>
Measurement runJudged(Engine& engine, const Judge& judge, double h) {
    Measurement m;
    std::vector<BodyState> states;
    engine.states(states);
    try {
        for (std::uint64_t n = 1; n <= judge.steps; ++n) {
            engine.step();
            m.steps = n;
            engine.states(states);
            judge.observe(states.front(), double(n) * h);
        }
    } catch (const SimulationError& error) {
        m.note = "blew up at step " + std::to_string(m.steps) + " (" + error.what() + ")";
    }
    judge.finish(states.front(), m);
    return m;
}

/// @brief Runs a problem in Stepwise's World with @p integrator at step @p h (s), judged by @p judgeAt.
Measurement runInStepwise(const Scene& scene, const JudgeMaker& judgeAt, IntegratorKind integrator, double h);

/// @brief A copy of @p scene with the World's time step and integrator replaced.
Scene withStep(const Scene& scene, IntegratorKind integrator, double h);

}  // namespace stepwise::bench
