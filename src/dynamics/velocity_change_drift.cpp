/// @file velocity_change_drift.cpp
/// @brief The "move" of a substep: bodies move by what the constraints did to their velocities
/// (the maths is in velocity_change_drift.hpp).
#include "dynamics/velocity_change_drift.hpp"

#include <cstddef>

#include "integrators/integrators.hpp"

namespace stepwise {

namespace {

/// Record @p i is a ball moved by symplectic Euler: it turns again from the substep's start, by h·ω_{n+1}.
bool turnsWithNewVelocity(const SolverWorkspace& workspace, std::size_t i, IntegratorKind integrator) {
    return integrator == IntegratorKind::SymplecticEuler && workspace.ballInertia[i] != Real(0);
}

/// The drift of record @p i (driftByVelocityChange()); @p lag = 1 − positionShareOfVelocityChange().
inline void driftRecord(SolverWorkspace& workspace, std::size_t i, Real h, IntegratorKind integrator, bool lastSubstep,
                        Real lag) {
    const std::uint32_t index = workspace.recordBody[i];
    DynamicObject& body = copyVelocitiesOut(workspace, i);  // the solved v and ω, in the same pass
    const BodyVelocity& before = workspace.substepStart[i];  // as free flight left it (recordSubstepStart())
    const Vec3 change = body.velocity - before.velocity;
    const Vec3 turn = body.angularVelocity - before.angularVelocity;
    const bool ball = turnsWithNewVelocity(workspace, i, integrator);
    if (!body.asleep && ball && workspace.ballsTurnOnce) {
        // Once a step: back to the step's start (the last drift's pose), the substep's ω added to the sum
        if (change != Vec3(0) || turn != Vec3(0)) body.position += h * change;
        Vec3& sum = workspace.turnSums[i].sum;
        sum += turn != Vec3(0) ? body.angularVelocity : before.angularVelocity;
        body.orientation = lastSubstep ? rotateByAngularVelocity(workspace.poses[index].orientation, sum, h)
                                       : workspace.poses[index].orientation;
    } else if (!body.asleep && (change != Vec3(0) || turn != Vec3(0))) {  // else free flight's own step stands
        Vec3 move = h * change;
        if (lag != Real(0)) move += lag * h * h * body.acceleration;  // explicit Euler, Verlet: an older velocity
        body.position += move;
        if (turn != Vec3(0)) {
            body.orientation = ball ? rotateByAngularVelocity(workspace.poses[index].orientation, body.angularVelocity, h)
                                    : turnBySmallAngle(body.orientation, turn, h);
        }
    }
    // The relax passes measure separations here; no other body's pose is read by a constraint.
    workspace.poses[index] = {body.position, body.orientation};
}

}  // namespace

void driftByVelocityChange(SolverWorkspace& workspace, Real h, IntegratorKind integrator, bool lastSubstep) {
    const Real lag = Real(1) - positionShareOfVelocityChange(integrator);
    // Only a body with a solver record can have been pushed: one in a contact or a joint (prepareContacts()).
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) driftRecord(workspace, i, h, integrator, lastSubstep, lag);
}

void driftByVelocityChange(SolverWorkspace& workspace, std::span<const std::uint32_t> records, Real h,
                           IntegratorKind integrator, bool lastSubstep) {
    const Real lag = Real(1) - positionShareOfVelocityChange(integrator);
    for (const std::uint32_t i : records) driftRecord(workspace, i, h, integrator, lastSubstep, lag);
}

}  // namespace stepwise
