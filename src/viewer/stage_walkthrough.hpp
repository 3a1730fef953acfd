/// @file stage_walkthrough.hpp
/// @brief The S key: what the World looked like after each stage of one step, captured by a StepObserver.
///
/// World::step() runs its stages in one call, and the viewer does not take
/// the World apart to run them one at a time. Instead, when S starts a
/// step, the viewer sets this observer (src/world/step_observer.hpp) and
/// calls World::step() once. After every stage the observer copies what the
/// screen needs — the pose and velocity of every dynamic and kinematic body,
/// the candidate pairs, the contacts, the impulses — and writes one line on
/// what the stage produced. Each later press of S shows the next of these
/// snapshots: the bodies where that stage left them (after integrate a
/// falling ball has sunk into the floor; after resolve-impulses its velocity
/// points up; after correct-positions it is back on the surface).
///
/// The step is not paused in the middle: it has already finished when the
/// first snapshot is shown, and the World is at its end. Physics is
/// deterministic and the observer only reads (it gets the World by const
/// reference), so the snapshots are exactly what running the stages one by
/// one would show. To stop *inside* a stage, use a debugger (README,
/// "Debugging a lesson").
///
/// Memory: the arrays are kept from step to step and only grow when a step
/// has more stage runs, bodies, pairs or contacts than any before it, so
/// after the first S the presses allocate nothing. Per snapshot: one
/// BodySnapshot (112 bytes with doubles) per dynamic and kinematic body, the
/// stage's description; pairs, contacts and impulses are copied only after
/// the stage that writes them (broadphase, narrowphase, resolve-impulses or
/// restitution) and shared by the snapshots after it.
///
/// Plain C++ (no OpenGL): the viewer's test checks it without a window.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "world/world.hpp"

namespace stepwise::viewer {

/// @brief The state of one dynamic or kinematic body after a stage.
struct BodySnapshot {
    Vec3 position{0, 0, 0};         ///< Centre, m.
    Quat orientation{1, 0, 0, 0};   ///< Body to world rotation.
    Vec3 velocity{0, 0, 0};         ///< m/s.
    Vec3 angularVelocity{0, 0, 0};  ///< rad/s.
    bool asleep = false;            ///< Dynamic bodies only (kinematic bodies never sleep).
};

/// @brief One stage run: when it ran, what it said, and where its pairs, contacts and impulses are.
struct StageSnapshot {
    StageEvent event;               ///< Stage, step, substep (−1 outside the substep loop).
    std::string description;        ///< One line, e.g. "narrowphase: 1 contact, deepest 12.3 mm (ball - floor)".
    double seconds = 0;             ///< Wall-clock time of this run of the stage, s.
    std::size_t pairsBegin = 0;     ///< First candidate pair in StageWalkthrough's pair array.
    std::size_t pairsCount = 0;     ///< Candidate pairs known after this stage (0 before this step's broadphase).
    std::size_t contactsBegin = 0;  ///< First contact in the contact array.
    std::size_t contactsCount = 0;  ///< Contacts known after this stage (0 before this step's narrowphase).
    std::size_t impulsesBegin = 0;  ///< First impulse report in the impulse array.
    std::size_t impulsesCount = 0;  ///< Impulse reports known after this stage (0 before they are computed).
};

/// @brief What the renderer draws: the live World, or one snapshot of the walk-through.
///
/// The body arrays are whole objects (names, shapes, colours) so that every
/// drawing routine, joints included (jointAnchors()), reads them unchanged.
struct SceneView {
    std::span<const DynamicObject> dynamics;       ///< Bodies, at the poses to draw.
    std::span<const KinematicsObject> kinematics;  ///< Kinematic bodies, at the poses to draw.
    std::span<const CandidatePair> pairs;          ///< Broadphase pairs to draw (B).
    std::span<const Contact> contacts;             ///< Contacts to draw (C).
    std::span<const ImpulseReport> impulses;       ///< One per contact, or empty.
};

/// @brief The live World as a SceneView (what the viewer draws outside the walk-through).
SceneView liveView(const World& world);

/// @brief Records one step stage by stage (set it with World::setObserver), then shows any of its snapshots.
class StageWalkthrough : public StepObserver {
public:
    /// @brief Before the step's first stage: copies the bodies and their poses at the start of the step.
    void beforeStage(const StageEvent& event, const World& world) override;
    /// @brief Copies the state the stage left and writes its description.
    void afterStage(const StageEvent& event, const World& world) override;
    /// @brief Closes the step: the next beforeStage() starts a new recording.
    void afterStep(const World& world) override;

    /// @brief Number of snapshots of the recorded step: one per stage run (0 before any step).
    std::size_t size() const { return count_; }
    /// @brief Snapshot @p k (0 ≤ k < size()).
    const StageSnapshot& snapshot(std::size_t k) const { return snapshots_[k]; }
    /// @brief Body @p i's state after snapshot @p k; dynamic bodies first, then kinematic ones.
    const BodySnapshot& body(std::size_t k, std::size_t i) const { return poses_[(k + 1) * bodies_ + i]; }
    /// @brief Body @p i's state at the start of the recorded step (before its first stage).
    const BodySnapshot& bodyAtStart(std::size_t i) const { return poses_[i]; }

    /// @brief Puts the bodies where snapshot @p k has them, for view().
    void show(std::size_t k);
    /// @brief Snapshot @p k's scene, as set by the last show(k).
    SceneView view() const;

    /// @brief True for the snapshots Shift+S stops at: outside the substep loop, or in its first or last substep.
    bool isSummaryStop(std::size_t k) const;

    /// @brief Bytes held by the snapshot arrays (their capacity, strings included).
    std::size_t memoryBytes() const;

    /// @brief Forgets the recording (after a reload: the bodies may differ).
    void clear();

private:
    void capturePoses(const World& world);
    void describe(StageSnapshot& snapshot, const World& world) const;

    std::vector<StageSnapshot> snapshots_;  ///< Grows only; count_ of them are in use.
    std::size_t count_ = 0;
    std::size_t bodies_ = 0;                ///< Dynamic plus kinematic bodies.
    std::vector<BodySnapshot> poses_;       ///< (count_ + 1) × bodies_: the start of the step, then one block per snapshot.
    std::vector<CandidatePair> pairs_;
    std::vector<Contact> contacts_;
    std::vector<ImpulseReport> impulses_;
    std::vector<DynamicObject> dynamics_;      ///< Copies of the World's bodies; show() sets their poses.
    std::vector<KinematicsObject> kinematics_; ///< Copies of the World's kinematic bodies.
    std::size_t shown_ = 0;
    bool recording_ = false;                ///< Between the step's first beforeStage() and afterStep().
    double secondsBefore_ = 0;              ///< The stage's StageRecord::lastSeconds before this run.
};

}  // namespace stepwise::viewer
