/// @file finite_state.cpp
/// @brief The finite-state check after every stage (finite_state.hpp).
#include "objects/finite_state.hpp"

#include "core/errors.hpp"

namespace stepwise {

Real finiteProbe(const DynamicObject& body, unsigned parts) {
    Real probe = 0;
    if (parts & kPose) probe += zeroIfFinite(body.position) + zeroIfFinite(body.orientation);
    if (parts & kMotion) {
        probe += zeroIfFinite(body.velocity) + zeroIfFinite(body.angularVelocity) + zeroIfFinite(body.angularMomentum);
    }
    if (parts & kForces) probe += zeroIfFinite(body.acceleration) + zeroIfFinite(body.torque);
    return probe;
}

void failNonFinite(const std::string& object, const char* quantity, const StageAtStep& where) {
    throw SimulationError(object, stageName(where.stage), where.step, where.time,
                          std::string("non-finite ") + quantity + " (check masses, time step and forces in the scene)");
}

namespace {

/// Names the first quantity of @p body that is not finite (its probe found one).
void failOnBody(const DynamicObject& body, const StageAtStep& where) {
    if (!isFinite(body.position)) failNonFinite(body.name, "position", where);
    if (!isFinite(body.velocity)) failNonFinite(body.name, "velocity", where);
    if (!isFinite(body.acceleration)) failNonFinite(body.name, "acceleration", where);
    if (!isFinite(body.orientation)) failNonFinite(body.name, "orientation", where);
    if (!isFinite(body.angularVelocity)) failNonFinite(body.name, "angular velocity", where);
    if (!isFinite(body.angularMomentum)) failNonFinite(body.name, "angular momentum", where);
    if (!isFinite(body.torque)) failNonFinite(body.name, "torque", where);
}

}  // namespace

void requireFiniteState(std::span<const DynamicObject> bodies, unsigned parts, const StageAtStep& where) {
    if (parts == 0) return;
    for (const DynamicObject& body : bodies) {
        if (finiteProbe(body, parts) != Real(0)) failOnBody(body, where);  // else all finite: nothing to name
    }
}

void requireFiniteState(std::span<const DynamicObject> bodies, std::span<const std::uint32_t> which, unsigned parts,
                        const StageAtStep& where) {
    if (parts == 0) return;
    for (const std::uint32_t index : which) {
        if (finiteProbe(bodies[index], parts) != Real(0)) failOnBody(bodies[index], where);
    }
}

void requireFiniteState(std::span<const KinematicsObject> bodies, const StageAtStep& where) {
    for (const KinematicsObject& body : bodies) {
        if (!isFinite(body.position)) failNonFinite(body.name, "position", where);
        if (!isFinite(body.orientation)) failNonFinite(body.name, "orientation", where);
    }
}

}  // namespace stepwise
