/// @file trace_writer.hpp
/// @brief `stepwise trace`: a StepObserver that writes, stage by stage, what each stage took in and produced.
///
/// The printer reads the World through its const accessors after (and, for
/// before → after values, before) every stage; it never recomputes physics.
/// The one derived quantity it computes is the relative normal velocity of a
/// contact, v_n = ((v_B + ω_B × r_B) − (v_A + ω_A × r_A))·n, from the bodies'
/// velocities, to show what an impulse did to it; and the force F = m·a of
/// the apply-forces stage. Every number is printed with a fixed number of
/// decimals, so two runs of a scene print the same bytes.
///
/// Each line starts with a header of whitespace-separated words,
/// `step N [s/S] STAGE OBJECT`, then `label value unit` fields; a value that
/// a stage changed reads `label before unit -> after unit`. OBJECT is a body's
/// name, `A|B` for a contact or pair, `joint:NAME`, or `all` for a count.
/// A contact's line goes on `contact I  feature F`: its index in the step's
/// contact list (World::contacts(); gdb's `contacts_[I]`) and its feature id,
/// so the four corners of a box on a box are four different lines.
/// Steps count from 1: step N runs from t = (N − 1)·h to N·h, and while it
/// runs World::stepCount() is N − 1 (docs/architecture.md, "Step numbers").
/// docs/trace.md lists every line; the lectures' trace-check blocks select
/// lines by their header (tests/test_lecture_values.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "world/scene.hpp"
#include "core/stages.hpp"
#include "world/step_observer.hpp"

namespace stepwise {

/// Decimals printed when `--digits` is not given: 0.1 mm, 0.1 mm/s.
inline constexpr int kDefaultTraceDigits = 4;
/// Most decimals `--digits` accepts: a double holds about 16 significant digits.
inline constexpr int kMaxTraceDigits = 12;

/// @brief What `stepwise trace` prints: which steps, stages and objects.
struct TraceOptions {
    std::uint64_t from = 1;            ///< --from STEP: first step printed (steps count from 1).
    std::uint64_t steps = 1;           ///< --steps N: steps printed, from `from` on.
    std::vector<Stage> stages;         ///< --stage NAME (repeatable, or comma-separated): empty means all.
    std::vector<std::string> objects;  ///< --object NAME (repeatable): empty means all.
    bool allSubsteps = false;          ///< --substeps all: every substep's lines, not only the first's.
    int digits = kDefaultTraceDigits;  ///< --digits D: decimals of every number (0 … kMaxTraceDigits).
};

/// @brief Throws std::invalid_argument naming the first object of @p options that @p scene does not have.
void checkTraceObjects(const TraceOptions& options, const Scene& scene);

/// @brief The Stage called @p name (as stageName() prints it).
/// @throws std::invalid_argument listing the valid names when there is none.
Stage stageFromName(const std::string& name);

/// @brief Writes the trace lines of the stages and objects @p options selects to @p out.
///
/// Set it on a World with World::setObserver(). It keeps snapshots of the
/// bodies' state taken before each stage, in arrays reused from stage to
/// stage; it does not change the World.
class TraceObserver : public StepObserver {
public:
    /// @brief Writes to @p out, which must outlive the observer.
    TraceObserver(std::ostream& out, TraceOptions options);
    /// @brief Snapshots what the stage may change (positions, velocities, sleep state).
    void beforeStage(const StageEvent& event, const World& world) override;
    /// @brief Writes the stage's lines.
    void afterStage(const StageEvent& event, const World& world) override;

private:
    bool selected(const StageEvent& event) const;
    bool objectSelected(const std::string& name) const;
    void writeStage(const StageEvent& event, const World& world);
    void writeForces(const std::string& head, const World& world);
    void writeMotion(const std::string& head, const World& world);
    void writeVelocityChanges(const std::string& head, const World& world);
    void writeKinematics(const std::string& head, const World& world);
    void writePairs(const std::string& head, const World& world);
    void writeContacts(const std::string& head, const World& world);
    void writeImpulses(const std::string& head, const World& world);
    void writeCorrections(const std::string& head, const World& world);
    void writePreparedConstraints(const std::string& head, const World& world);
    void writeSolve(const std::string& head, const World& world);
    void writeJoints(const std::string& head, const World& world);
    void writeRestitution(const std::string& head, const World& world);
    void writeSleep(const std::string& head, const World& world);
    void writeSoftBodies(const std::string& head, const World& world);
    void line(const std::string& head, const std::string& object, const std::string& fields);
    std::string num(Real value) const;
    std::string vec(const Vec3& value) const;
    std::string quat(const Quat& value) const;

    std::ostream& out_;
    TraceOptions options_;
    std::uint64_t headedStep_ = 0;        ///< Last step whose time line was written (0: none yet).
    std::vector<Vec3> positionBefore_;    ///< Per dynamic body, before the stage, m.
    std::vector<Vec3> velocityBefore_;    ///< Per dynamic body, m/s.
    std::vector<Vec3> angularBefore_;     ///< Per dynamic body, rad/s.
    std::vector<Quat> orientationBefore_; ///< Per dynamic body, before the stage.
    std::vector<char> asleepBefore_;      ///< Per dynamic body: asleep before the stage.
    std::vector<char> softAsleepBefore_;  ///< Per soft body: asleep before the stage.
    std::vector<Vec3> kinematicBefore_;   ///< Per kinematic body, position before the stage, m.
    std::vector<char> jointBrokenBefore_; ///< Per joint: broken before the stage.
};

/// @brief Simulates a copy of @p scene up to the last selected step, writing the trace to @p out.
/// A scene with spaces is traced space by space, each under a line `=== Space NAME`.
/// @param stopNow asked before every step; when it answers true the trace ends there (a time
///        budget, Ctrl-C). @return false when it stopped early.
/// @throws std::invalid_argument for an object name the scene lacks; SimulationError when a step fails.
bool writeTrace(const Scene& scene, const TraceOptions& options, std::ostream& out,
                const std::function<bool()>& stopNow = {});

}  // namespace stepwise
