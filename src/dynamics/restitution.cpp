/// @file restitution.cpp
/// @brief Stage 8 of the soft step: bounces by Poisson's law, once per step, after the substeps (contact_solver.hpp, "Restitution").
#include "dynamics/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dynamics/contact_rows.hpp"

namespace stepwise {

bool applyRestitution(SolverWorkspace& workspace) {
    // 1. The impacts: contacts that approached faster than resting and pushed. None: no bounce.
    Real fastest = 0;
    for (const std::uint32_t i : workspace.bouncing) {
        if (workspace.contacts[i].maxNormalImpulse > Real(0)) fastest = std::max(fastest, -workspace.starts[i].touchVelocity);
    }
    if (fastest == Real(0)) return false;

    // 2. The compression: every contact that pushed this step takes part, for an impact's impulse
    //    passes on through bodies in touch (a ball into a row of balls); those that carry a load
    //    (a stack's weight) do not, as they never bounce: a pile hit by a ball is not a gas. The passes work on each
    //    record's velocity change, from zero; a static record keeps its zero inverse mass.
    std::vector<std::uint32_t>& pressed = workspace.pressed;
    pressed.clear();
    bool elastic = false;  // does any of them bounce at all?
    for (std::uint32_t i = 0; i < workspace.contacts.size(); ++i) {
        if (workspace.contacts[i].maxNormalImpulse > Real(0) && !workspace.starts[i].carriesLoad) {
            pressed.push_back(i);
            elastic = elastic || workspace.starts[i].elasticity > Real(0);
        }
    }
    // With e = 0 everywhere (a pile of dead boxes) step 3 below applies nothing: Poisson's law
    // asks for no rebound, so the compression need not be measured either.
    if (!elastic) return false;
    std::vector<SolverBody>& change = workspace.impactBodies;
    change = workspace.bodies;
    for (SolverBody& record : change) record.velocity = record.angularVelocity = Vec3(0);
    const Real tolerance = kCompressionTolerance * fastest;
    for (int pass = 0; pass < kMaxCompressionPasses; ++pass) {
        Real largest = 0;  // the largest change of a normal velocity in this pass, m/s
        for (const std::uint32_t i : pressed) {
            const SolverContact& c = workspace.contacts[i];
            ContactStart& start = workspace.starts[i];
            withRows(c, workspace, [&](const auto& rows) {
                SolverBody& a = change[c.bodyA];
                SolverBody& b = change[c.bodyB];
                // w + J·Δu; a kinematic surface's speed is in w already, so it comes out of J·Δu.
                const Real vn = start.touchVelocity + rows.normalVelocity(a, b) - rows.normalVelocity(change[0], change[0]);
                const Real total = std::max(start.compression - c.normalMass * vn, Real(0));
                const Real impulse = total - start.compression;
                rows.applyNormal(a, b, impulse);
                start.compression = total;
                largest = std::max(largest, std::abs(impulse) / c.normalMass);
            });
        }
        if (largest <= tolerance) break;
    }

    // 3. The restitution. Poisson's law says where the impact ends: every contact that pushed in
    //    the compression parts at v_n = e·(J·Δu) (for one contact, e·v_c). The substeps have done
    //    the compression on the real velocities, softly: a soft contact springs back a little of
    //    its overlap, gravity and joints act too. So the bounce is not e·P added blindly, but the
    //    impulse that brings each such contact to its Poisson velocity, by the same passes.
    for (const std::uint32_t i : pressed) {
        const SolverContact& c = workspace.contacts[i];
        ContactStart& start = workspace.starts[i];
        start.bounceVelocity = withRows(c, workspace, [&](const auto& rows) {
            return start.elasticity * (rows.normalVelocity(change[c.bodyA], change[c.bodyB]) -
                                       rows.normalVelocity(change[0], change[0]));
        });
    }
    bool bounced = false;
    for (int pass = 0; pass < kMaxCompressionPasses; ++pass) {
        Real largest = 0;
        for (const std::uint32_t i : pressed) {
            SolverContact& c = workspace.contacts[i];
            ContactStart& start = workspace.starts[i];
            if (start.compression == Real(0) || start.elasticity == Real(0)) continue;
            withRows(c, workspace, [&](const auto& rows) {
                SolverBody& a = workspace.bodies[c.bodyA];
                SolverBody& b = workspace.bodies[c.bodyB];
                const Real impulse = c.normalMass * (start.bounceVelocity - rows.normalVelocity(a, b));
                // It may take back what the soft solve sprang back beyond the compression, never
                // more than the step pushed: the impact's impulses together never pull.
                const Real total = std::max(start.bounceImpulse + impulse, -(start.compression + c.maxNormalImpulse));
                rows.applyNormal(a, b, total - start.bounceImpulse);
                largest = std::max(largest, std::abs(total - start.bounceImpulse) / c.normalMass);
                c.normalImpulse += total - start.bounceImpulse;
                start.bounceImpulse = total;
            });
            bounced = true;
        }
        if (largest <= tolerance) break;
    }
    return bounced;
}

}  // namespace stepwise
