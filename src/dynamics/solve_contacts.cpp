/// @file solve_contacts.cpp
/// @brief The solve and relax passes: one Gauss–Seidel sweep of soft impulses over every contact (the maths is in contact_solver.hpp).
#include "dynamics/contact_solver.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/contact_rows.hpp"

namespace stepwise {

namespace {

/// One friction pass of contact @p c, whose rows are @p rows, on the bodies' copies @p a, @p b (solveContacts()).
template <class Rows>
inline void solveFriction(SolverContact& c, const Rows& rows, SolverBody& a, SolverBody& b) {
    // Friction on what is left sliding, inside Coulomb's circle |λ_t| ≤ μ·λ_n.
    // Both tangent velocities are read after the normal impulse (friction acts
    // on the sliding that is left) and before either friction impulse, so the
    // pair is clamped to the circle together. A point that does not push
    // (λ_n = 0: a speculative gap, or surfaces parting) and holds no friction
    // impulse would be clamped back to zero friction: nothing to do.
    const Real limit = c.friction * c.normalImpulse;
    if (limit == Real(0) && c.tangentImpulse[0] == Real(0) && c.tangentImpulse[1] == Real(0)) return;
    Real vt[2];
    rows.tangentVelocities(a, b, vt);
    Real total[2];
    for (int k = 0; k < 2; ++k) total[k] = c.tangentImpulse[k] - c.tangentMass[k] * vt[k];
    // Back onto Coulomb's circle: scale = min(1, μλ_n/|λ_t|), which is exactly 1
    // for a point that sticks and 0 for one that does not push (λ_n = 0, a
    // speculative gap). Written as a comparison, only a slipping point pays
    // for the division; std::min(1, μλ_n/|λ_t|) would divide for every point.
    // (The squares would overflow only for impulses near 1e154 N·s.)
    const Real magnitude = std::sqrt(total[0] * total[0] + total[1] * total[1]);
    const Real scale = magnitude > limit ? limit / magnitude : Real(1);
    total[0] *= scale;
    total[1] *= scale;
    rows.applyTangents(a, b, total[0] - c.tangentImpulse[0], total[1] - c.tangentImpulse[1]);
    c.tangentImpulse[0] = total[0];
    c.tangentImpulse[1] = total[1];
}

/// One contact's rows solved once (solveContact()). Always inlined: a pass is then one loop over
/// its contacts, with what the settings say worked out once, not a call per contact.
[[gnu::always_inline]] inline void solveOne(SolverContact& c, SolverWorkspace& workspace, const ContactSolverSettings& settings, bool useBias) {
    // Normal: λ = −K⁻¹·s_m·(v_n + bias) − s_i·λ_acc (softness.hpp).
    const Real separation = currentSeparation(c, workspace);
    Real bias = 0;
    Real massScale = 1;
    Real impulseScale = 0;
    if (separation > 0) {
        bias = separation * settings.inverseSubstep;  // speculative: close the gap in this substep, no further
    } else if (useBias && settings.positionCorrection) {
        bias = std::max(settings.softness.biasRate * separation, -kMaxPushOutSpeed);
        massScale = settings.softness.massScale;
        impulseScale = settings.softness.impulseScale;
    }
    SolverBody a = workspace.bodies[c.bodyA];  // copies: kept in registers, stored once (solver_body.hpp)
    SolverBody b = workspace.bodies[c.bodyB];
    withRows(c, workspace, [&](const auto& rows) {
        const Real vn = rows.normalVelocity(a, b);
        const Real impulse = -c.normalMass * massScale * (vn + bias) - impulseScale * c.normalImpulse;
        Real applied = 0;
        if (settings.accumulate) {
            const Real total = std::max(c.normalImpulse + impulse, Real(0));
            applied = total - c.normalImpulse;
            c.normalImpulse = total;
        } else {  // Box2D-Lite's switch: clamp each increment, which cannot undo an earlier overshoot
            applied = std::max(impulse, Real(0));
            c.normalImpulse += applied;
        }
        c.maxNormalImpulse = std::max(c.maxNormalImpulse, c.normalImpulse);
        rows.applyNormal(a, b, applied);
        if (passSolvesFriction(c, settings, useBias)) solveFriction(c, rows, a, b);
    });
    workspace.bodies[c.bodyA] = a;
    workspace.bodies[c.bodyB] = b;
}

}  // namespace

Real currentSeparation(const SolverContact& c, const SolverWorkspace& w) {
    const Pose& poseA = w.poses[c.poseA];
    const Pose& poseB = w.poses[c.poseB];
    Real separation = glm::dot(poseB.position - poseA.position, c.normal) + c.separationOffset;
    if (c.turningAnchors != kNoTurningAnchors) {
        const TurningAnchors& anchors = w.turningAnchors[c.turningAnchors];
        separation += glm::dot(poseB.orientation * anchors.localB - poseA.orientation * anchors.localA, c.normal);
    }
    return separation;
}

void solveContacts(SolverWorkspace& workspace, const ContactSolverSettings& settings, bool useBias) {
    for (const std::uint32_t index : workspace.roundContacts) solveOne(workspace.contacts[index], workspace, settings, useBias);
    for (const std::uint32_t index : workspace.otherContacts) solveOne(workspace.contacts[index], workspace, settings, useBias);
}

void solveContact(SolverWorkspace& workspace, std::uint32_t index, const ContactSolverSettings& settings, bool useBias) {
    solveOne(workspace.contacts[index], workspace, settings, useBias);
}

}  // namespace stepwise
