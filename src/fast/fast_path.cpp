/// @file fast_path.cpp
/// @brief The fast path's substeps (fast_path.hpp says what and why): the plain loop's stages, in its
/// order, with the round contacts in lanes and, for a step of balls, on the packed records.
#include "fast/fast_path.hpp"

#include "dynamics/kinematic_motion.hpp"
#include "dynamics/velocity_change_drift.hpp"
#include "fast/box_contact_lanes.hpp"
#include "fast/fast_workspace.hpp"
#include "fast/packed_substeps.hpp"
#include "fast/parallel_records.hpp"
#include "fast/parallel_waves.hpp"
#include "fast/round_contact_lanes.hpp"
#include "integrators/integrators.hpp"
#include "objects/finite_state.hpp"

namespace stepwise {

namespace {

/// Bodies integrated between two finite probes: 32 objects of some 400 bytes are 12.8 kB,
/// inside a 32 kB L1 data cache, so the probe reads them while they are still there.
constexpr std::size_t kProbeBlock = 32;

/// Runs @p move over the runs of dynamic bodies that @p picks, each run at most kProbeBlock long,
/// and probes each run for non-finite numbers straight after, while it is still in cache. Returns
/// the sum of the probes: zero exactly when every body moved is finite.
template <class Picks, class Move>
Real moveAndProbe(std::span<DynamicObject> all, Picks&& picks, Move&& move) {
    Real probe = 0;
    for (std::size_t first = 0; first < all.size();) {
        if (!picks(first)) {
            ++first;
            continue;
        }
        std::size_t end = first + 1;
        while (end < all.size() && end - first < kProbeBlock && picks(end)) ++end;
        const std::span<DynamicObject> run = all.subspan(first, end - first);
        move(run);
        for (const DynamicObject& body : run) probe += finiteProbe(body, kPose | kMotion);
        first = end;
    }
    return probe;
}

/// moveAndProbe(); only when a probe fails are the bodies searched, to name the first bad one.
template <class Picks, class Move>
void moveInProbedRuns(std::span<DynamicObject> all, Picks&& picks, Move&& move, const StageAtStep& where) {
    if (moveAndProbe(all, picks, move) != Real(0)) requireFiniteState(all, kPose | kMotion, where);
}

/// How a check of the solver's records reads them.
enum class RecordsHold {
    Velocities,        ///< v and ω only.
    VelocitiesPoses,   ///< v and ω, and the pose recorded for each record's body (the fast path on the objects).
    PackedPoses,       ///< v and ω, and the packed centre, orientation and summed turn (the packed road).
};

/// Zero exactly when every record's numbers that @p hold names are finite.
Real probeRecords(const SolverWorkspace& w, const FastWorkspace& fast, RecordsHold hold) {
    Real probe = 0;
    for (std::size_t i = 1; i < w.bodies.size(); ++i) {
        probe += zeroIfFinite(w.bodies[i].velocity) + zeroIfFinite(w.bodies[i].angularVelocity);
        if (hold == RecordsHold::VelocitiesPoses) {
            const Pose& pose = w.poses[w.recordBody[i]];
            probe += zeroIfFinite(pose.position) + zeroIfFinite(pose.orientation);
        } else if (hold == RecordsHold::PackedPoses) {
            probe += zeroIfFinite(fast.centres[i].position) + zeroIfFinite(w.turnSums[i].sum) +
                     zeroIfFinite(fast.orientations[i]);
        }
    }
    return probe;
}

/// Names the first record whose numbers are not finite (after a probe found one): its body, and what.
[[noreturn]] void failOnRecords(const SolverWorkspace& w, const FastWorkspace& fast, RecordsHold hold,
                                const StageAtStep& where) {
    for (std::size_t i = 1; i < w.bodies.size(); ++i) {
        const std::string& name = w.dynamics[w.recordBody[i]].name;
        if (!isFinite(w.bodies[i].velocity)) failNonFinite(name, "velocity", where);
        if (!isFinite(w.bodies[i].angularVelocity)) failNonFinite(name, "angular velocity", where);
        if (hold == RecordsHold::PackedPoses) {
            if (!isFinite(fast.centres[i].position)) failNonFinite(name, "position", where);
            if (!isFinite(fast.orientations[i]) || !isFinite(w.turnSums[i].sum)) failNonFinite(name, "orientation", where);
        }
    }
    failNonFinite("a body with a solver record", "number", where);  // not reached: the probe saw one of the above
}

/// On the objects: after a stage that moved only the bodies with records, their records and
/// poses say whether anything went wrong; only then are the objects searched, to name it.
void requireFiniteRecords(std::span<const DynamicObject> dynamics, const SolverWorkspace& w, const FastWorkspace& fast,
                          unsigned parts, const StageAtStep& where) {
    const RecordsHold hold = (parts & kPose) ? RecordsHold::VelocitiesPoses : RecordsHold::Velocities;
    if (probeRecords(w, fast, hold) != Real(0)) requireFiniteState(dynamics, parts, where);
}

/// warmStartContacts() with the contacts in lanes: the round ones, then the others, as the plain pass.
void warmStartContactsInLanes(SolverWorkspace& w, FastWorkspace& fast, bool accumulate) {
    if (!accumulate) {  // each substep's impulses stand alone, as warmStartContacts() says
        for (SolverContact& c : w.contacts) {
            c.normalImpulse = 0;
            c.tangentImpulse[0] = c.tangentImpulse[1] = 0;
        }
        clearRoundContactImpulses(fast);
        clearBoxContactImpulses(fast);
        return;
    }
    warmStartRoundContacts(w, fast);
    if (fast.boxBatches.empty()) {  // waves too thin for the lanes (kMinBoxContactsPerWave)
        for (const std::uint32_t index : w.otherContacts) warmStartContact(w, index);
    } else {
        warmStartBoxContacts(w, fast);
    }
}

/// solveContacts() with the contacts in lanes: the round ones, then the others; the same order, the same numbers.
void solveContactsInLanes(SolverWorkspace& w, FastWorkspace& fast, const ContactSolverSettings& settings, bool useBias,
                          ThreadPool& pool) {
    solveRoundContactsOnThreads(w, fast, settings, useBias, pool);
    if (fast.boxBatches.empty()) {  // waves too thin for the lanes (kMinBoxContactsPerWave)
        for (const std::uint32_t index : w.otherContacts) solveContact(w, index, settings, useBias);
    } else {
        solveBoxContactsOnThreads(w, fast, settings, useBias, pool);
    }
}

/// The substeps on the objects, as the plain loop runs them, with the contact passes in lanes.
void substepsOnObjects(const FastSubsteps& in, FastWorkspace& fast) {
    SolverWorkspace& w = in.contacts;
    const BodySet bodies{in.dynamics, in.kinematics, in.planes};
    const Real hs = in.contactSettings.substep;
    for (int substep = 0; substep < in.substeps; ++substep) {
        const bool lastSubstep = substep + 1 == in.substeps;
        auto at = [&](Stage stage) { return StageAtStep{stage, in.step, in.time}; };
        // 5. Free flight for h_s
        if (substep > 0 && in.forcesEverySubstep) {
            timeStage(in.records, Stage::ApplyForces, [&] {
                in.forces(in.dynamics);
                requireFiniteState(in.dynamics, kForces, at(Stage::ApplyForces));
            });
        }
        timeStage(in.records, Stage::Integrate, [&] {
            // The solve measures separations from here. From the second substep on, the last drift
            // (the bodies with a record) and relax (the kinematic ones) recorded these very poses and
            // centres, and nothing has moved since: the plain loop records them again to the same bits.
            if (substep == 0) {
                recordPoses(bodies, w);
                recordCentres(w, fast);
            }
            if (in.integrator == IntegratorKind::Verlet) {  // its forces join bodies anywhere in the array: whole
                integrateBodies(in.integrator, in.dynamics, hs, in.forces);
                requireFiniteState(in.dynamics, kEverything, at(Stage::Integrate));
                return;
            }
            // Each body flies on its own numbers: ranges of bodies on the pool's threads
            // (parallel_records.hpp), the failure named on this thread, after the ranges.
            const Real probe = forBodyRanges(in.pool, in.dynamics.size(), [&](std::size_t first, std::size_t end) {
                return moveAndProbe(
                    in.dynamics.subspan(first, end - first), [](std::size_t) { return true; },
                    [&](std::span<DynamicObject> run) { integrateBodies(in.integrator, run, hs, in.forces); });
            });
            if (probe != Real(0)) requireFiniteState(in.dynamics, kPose | kMotion, at(Stage::Integrate));
        });
        if (in.moveKinematics) {
            timeStage(in.records, Stage::MoveKinematics, [&] {
                moveKinematics(in.kinematics, hs);
                requireFiniteState(in.kinematics, at(Stage::MoveKinematics));
            });
        }
        // 6. Warm start, solve, move
        timeStage(in.records, Stage::SolveConstraints, [&] {
            recordBoxSeparations(w, fast);  // at the poses the solve measures from (above)
            if (substep > 0 && in.accumulateImpulses && in.joints.joints.empty()) {
                warmStartFromLastSubstep(w);
            } else {
                recordSubstepStart(w);
                if (in.jointSolver) warmStartJoints(in.joints, w.poses);
                copyVelocitiesIn(w);
                warmStartContactsInLanes(w, fast, in.accumulateImpulses);
            }
            for (int pass = 0; pass < in.velocityIterations; ++pass) {
                if (in.jointSolver) solveJointsBetweenContactPasses(in.joints, w, in.jointSettings, true);
                solveContactsInLanes(w, fast, in.contactSettings, true, in.pool);
            }
            driftByVelocityChange(w, hs, in.integrator, lastSubstep);
            recordCentres(w, fast);  // the relax measures separations where the drift moved the bodies
            requireFiniteRecords(in.dynamics, w, fast, kPose | kMotion, at(Stage::SolveConstraints));
        });
        // 7. Relax
        timeStage(in.records, Stage::RelaxConstraints, [&] {
            recordKinematicPoses(bodies, w);
            recordBoxSeparations(w, fast);  // where the drift and move-kinematics left the bodies
            for (int pass = 0; pass < in.relaxIterations; ++pass) {
                if (in.jointSolver) solveJointsBetweenContactPasses(in.joints, w, in.jointSettings, false);
                solveContactsInLanes(w, fast, in.contactSettings, false, in.pool);
            }
            copyVelocitiesOut(w);
            requireFiniteRecords(in.dynamics, w, fast, kMotion, at(Stage::RelaxConstraints));
        });
    }
}

/// The substeps of a step whose contacts all hold awake balls, on the packed records (packed_substeps.hpp).
void substepsOnRecords(const FastSubsteps& in, FastWorkspace& fast) {
    SolverWorkspace& w = in.contacts;
    const Real hs = in.contactSettings.substep;
    const std::vector<std::uint32_t>& recordOf = w.bodyRecord;
    for (int substep = 0; substep < in.substeps; ++substep) {
        const bool lastSubstep = substep + 1 == in.substeps;
        auto at = [&](Stage stage) { return StageAtStep{stage, in.step, in.time}; };
        // 5. Free flight: the kick on the records (the move follows the solve), whole flight for the bodies without one
        timeStage(in.records, Stage::Integrate, [&] {
            const Real kicked = forRecordRanges(in.pool, w.bodies.size(), [&](std::size_t first, std::size_t end) {
                return kickPackedRecords(w, fast, hs, in.canTurn, substep == 0, first, end);
            });
            if (kicked != Real(0)) {
                failOnRecords(w, fast, RecordsHold::Velocities, at(Stage::Integrate));
            }
            moveInProbedRuns(
                in.dynamics, [&](std::size_t i) { return recordOf[i] == kStaticSolverBody; },
                [&](std::span<DynamicObject> run) { integrateSymplecticEuler(run, hs); }, at(Stage::Integrate));
        });
        if (in.moveKinematics) {
            timeStage(in.records, Stage::MoveKinematics, [&] {
                moveKinematics(in.kinematics, hs);
                requireFiniteState(in.kinematics, at(Stage::MoveKinematics));
            });
        }
        // 6. Warm start (the first substep from the contacts; later ones rode along with the kick), solve, move
        timeStage(in.records, Stage::SolveConstraints, [&] {
            if (substep == 0) warmStartContactsInLanes(w, fast, true);
            for (int pass = 0; pass < in.velocityIterations; ++pass) solveRoundContactsOnThreads(w, fast, in.contactSettings, true, in.pool);
            const Real drifted = forRecordRanges(in.pool, w.bodies.size(), [&](std::size_t first, std::size_t end) {
                return driftPackedRecords(w, fast, hs, lastSubstep, first, end);
            });
            if (drifted != Real(0)) {
                failOnRecords(w, fast, RecordsHold::PackedPoses, at(Stage::SolveConstraints));
            }
        });
        // 7. Relax; after the last one the objects get their balls' state back
        timeStage(in.records, Stage::RelaxConstraints, [&] {
            for (int pass = 0; pass < in.relaxIterations; ++pass) solveRoundContactsOnThreads(w, fast, in.contactSettings, false, in.pool);
            if (probeRecords(w, fast, RecordsHold::Velocities) != Real(0)) {
                failOnRecords(w, fast, RecordsHold::Velocities, at(Stage::RelaxConstraints));
            }
            if (lastSubstep) unpackRecords(w, fast);
        });
    }
}

template <class T>
std::size_t bytesOf(const std::vector<T>& array) {
    return array.size() * sizeof(T);
}

}  // namespace

void runFastSubsteps(const FastSubsteps& in, FastWorkspace& fast) {
    // The contacts into lanes, and the balls into packed records if this step can take them:
    // more of the prepare stage's work.
    bool packed = false;
    timeStage(in.records, Stage::PrepareConstraints, [&] {
        batchRoundContacts(in.contacts, fast);
        batchBoxContacts(in.contacts, fast);
        packed = in.packedSubsteps && packRecords(in.contacts, fast);
    }, StageRun::Continued);
    fast.packedStep = packed;
    fast.counts.steps += 1;
    if (!fast.boxBatches.empty()) fast.counts.boxLaneSteps += 1;
    if (packed) {
        fast.counts.packedSteps += 1;
        substepsOnRecords(in, fast);
    } else {
        substepsOnObjects(in, fast);
    }
    // The contacts' impulses back from their lanes, for the bounce and the next step's warm start
    timeStage(in.records, Stage::RelaxConstraints, [&] {
        syncRoundContacts(fast, in.contacts);
        syncBoxContacts(fast, in.contacts);
    }, StageRun::Continued);
}

SolverFootprint fastFootprint(const SolverWorkspace& w, const FastWorkspace& fast) {
    SolverFootprint f;
    // A pass reads the records, their centres and the batches of both kinds; the contacts with
    // stored rows solved one at a time (thin waves), their SolverContact, rows, anchors and poses.
    f.passBytes = bytesOf(w.bodies) + bytesOf(fast.centres) + bytesOf(fast.roundBatches) + bytesOf(fast.boxBatches);
    if (fast.boxBatches.empty() && !w.otherContacts.empty()) {
        f.passBytes += w.otherContacts.size() * sizeof(SolverContact) + bytesOf(w.rows) + bytesOf(w.turningAnchors) +
                       bytesOf(w.poses);
    }
    f.substepBytes = f.passBytes + bytesOf(w.substepStart) + bytesOf(w.turnSums);
    if (fast.packedStep) {
        f.substepBytes += (fast.sharedFlight ? sizeof(FreeFlight) : bytesOf(fast.freeFlight)) + bytesOf(w.ballInertia);
    }
    f.allBytes = solverFootprint(w).allBytes + bytesOf(fast.roundBatches) + bytesOf(fast.boxBatches) + bytesOf(fast.schedule.nextWave) +
                 bytesOf(fast.waveBatches) + bytesOf(fast.schedule.waveOf) + bytesOf(fast.schedule.ends) +
                 bytesOf(fast.schedule.order) + bytesOf(fast.centres) +
                 bytesOf(fast.orientations) + bytesOf(fast.freeFlight) + bytesOf(fast.startMomentum);
    return f;
}

}  // namespace stepwise
