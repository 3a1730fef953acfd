/// @file warm_start_contacts.cpp
/// @brief Each substep's warm start: last substep's (or step's) impulses applied again before the first pass (Catto, GDC 2005).
#include "dynamics/contact_solver.hpp"

#include "dynamics/contact_rows.hpp"

namespace stepwise {

namespace {

/// recordSubstepStart() of record @p i.
inline void recordStartOf(SolverWorkspace& workspace, std::size_t i) {
    const DynamicObject& body = workspace.dynamics[workspace.recordBody[i]];
    workspace.substepStart[i] = {body.velocity, body.angularVelocity};
}

/// warmStartFromLastSubstep() of record @p i.
inline void warmStartRecordFromLastSubstep(SolverWorkspace& workspace, std::size_t i) {
    SolverBody& record = workspace.bodies[i];
    BodyVelocity& start = workspace.substepStart[i];
    // What the contacts did to this body in the last substep: Σ_c λ_c·M⁻¹J_cᵀ (contact_solver.hpp).
    const Vec3 change = record.velocity - start.velocity;
    const Vec3 turn = record.angularVelocity - start.angularVelocity;
    const DynamicObject& body = workspace.dynamics[workspace.recordBody[i]];
    start = {body.velocity, body.angularVelocity};
    record.velocity = body.velocity + change;
    record.angularVelocity = body.angularVelocity + turn;
}

}  // namespace

void recordSubstepStart(SolverWorkspace& workspace) {
    workspace.substepStart.resize(workspace.bodies.size());
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) recordStartOf(workspace, i);
}

void recordSubstepStart(SolverWorkspace& workspace, std::span<const std::uint32_t> records) {
    workspace.substepStart.resize(workspace.bodies.size());
    for (const std::uint32_t i : records) recordStartOf(workspace, i);
}

void warmStartContacts(SolverWorkspace& workspace, bool accumulate) {
    if (!accumulate) {
        // Without accumulation each substep's impulses stand alone (Box2D-Lite
        // does not warm start in this mode either): the running sum only grows,
        // and re-applying it every substep would push harder and harder.
        for (SolverContact& c : workspace.contacts) {
            c.normalImpulse = 0;
            c.tangentImpulse[0] = c.tangentImpulse[1] = 0;
        }
        return;
    }
    for (const std::uint32_t index : workspace.roundContacts) warmStartContact(workspace, index);
    for (const std::uint32_t index : workspace.otherContacts) warmStartContact(workspace, index);
}

void warmStartContact(SolverWorkspace& workspace, std::uint32_t index) {
    const SolverContact& c = workspace.contacts[index];
    SolverBody a = workspace.bodies[c.bodyA];  // copies: kept in registers, stored once (solver_body.hpp)
    SolverBody b = workspace.bodies[c.bodyB];
    withRows(c, workspace, [&](const auto& rows) {
        rows.applyNormal(a, b, c.normalImpulse);
        rows.applyTangents(a, b, c.tangentImpulse[0], c.tangentImpulse[1]);
    });
    workspace.bodies[c.bodyA] = a;
    workspace.bodies[c.bodyB] = b;
}

void warmStartFromLastSubstep(SolverWorkspace& workspace) {
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) warmStartRecordFromLastSubstep(workspace, i);
}

void warmStartFromLastSubstep(SolverWorkspace& workspace, std::span<const std::uint32_t> records) {
    for (const std::uint32_t i : records) warmStartRecordFromLastSubstep(workspace, i);
}

}  // namespace stepwise
