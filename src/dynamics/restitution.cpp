/// @file restitution.cpp
/// @brief Stage 8 of the soft step: bounces by Poisson's law, once per step, after the substeps (contact_solver.hpp, "Restitution").
#include "dynamics/contact_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "core/parallel_ranges.hpp"
#include "dynamics/contact_colours.hpp"
#include "dynamics/contact_rows.hpp"

namespace stepwise {

namespace {

/// One pass of @p visit over the contacts of the compression, returning the largest change any of
/// them made. Without @p waves: `visit(pressed)`, in order, on the calling thread. With them: wave
/// by wave, each wave of at least kParallelRestitutionWave contacts cut into ranges on @p pool's
/// threads, the runs of smaller waves between on the calling thread. A contact reads and writes only
/// its two bodies, every body meets its contacts in the same order either way, and a maximum does
/// not depend on the order it is taken in: the same bits (contact_solver.hpp, applyRestitution()).
template <class Visit>
Real passOver(const std::vector<std::uint32_t>& pressed, const ContactWaveSchedule* waves, ThreadPool* pool,
              Visit&& visit) {
    if (waves == nullptr) return visit(std::span<const std::uint32_t>(pressed));
    const std::span<const std::uint32_t> order(waves->order);
    Real largest = 0;
    std::size_t serialFrom = 0;  // the first contact not yet visited
    for (std::uint32_t wave = 0; wave < waves->waves; ++wave) {
        const std::size_t first = wave == 0 ? 0 : waves->ends[wave - 1];
        const std::size_t end = waves->ends[wave];
        if (end - first < kParallelRestitutionWave) continue;
        if (serialFrom < first) largest = std::max(largest, visit(order.subspan(serialFrom, first - serialFrom)));
        const RangeSplit split = splitRanges(pool, first, end, 0);
        std::array<Real, kMaxRanges> largestOf{};
        runRanges(pool, split, [&](std::size_t i, std::size_t from, std::size_t to) {
            largestOf[i] = visit(order.subspan(from, to - from));
        });
        for (std::size_t i = 0; i < split.count; ++i) largest = std::max(largest, largestOf[i]);
        serialFrom = end;
    }
    if (serialFrom < order.size()) largest = std::max(largest, visit(order.subspan(serialFrom)));
    return largest;
}

}  // namespace

bool applyRestitution(SolverWorkspace& workspace, ThreadPool* pool) {
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
    // Enough contacts for threads: the same contacts in waves (passOver())
    const bool onThreads = pool != nullptr && pool->threadCount() > 1 && pressed.size() >= kParallelRestitution;
    if (onThreads) scheduleWaves(workspace, pressed, workspace.pressedWaves);
    const ContactWaveSchedule* waves = onThreads ? &workspace.pressedWaves : nullptr;
    // The static record: nothing moves it (its inverse masses are zero, so an impulse adds +0 to its
    // zero velocities). Each visit reads, and writes to no effect, a copy of its own, so that two
    // threads never write one record.
    auto compress = [&](std::span<const std::uint32_t> contacts) {
        SolverBody fixed = change[kStaticSolverBody];
        Real largest = 0;  // the largest change of a normal velocity in this pass, m/s
        for (const std::uint32_t i : contacts) {
            const SolverContact& c = workspace.contacts[i];
            ContactStart& start = workspace.starts[i];
            withRows(c, workspace, [&](const auto& rows) {
                SolverBody& a = change[c.bodyA];
                SolverBody& b = c.bodyB == kStaticSolverBody ? fixed : change[c.bodyB];
                // w + J·Δu; a kinematic surface's speed is in w already, so it comes out of J·Δu.
                const Real vn = start.touchVelocity + rows.normalVelocity(a, b) - rows.normalVelocity(fixed, fixed);
                const Real total = std::max(start.compression - c.normalMass * vn, Real(0));
                const Real impulse = total - start.compression;
                rows.applyNormal(a, b, impulse);
                start.compression = total;
                largest = std::max(largest, std::abs(impulse) / c.normalMass);
            });
        }
        return largest;
    };
    for (int pass = 0; pass < kMaxCompressionPasses; ++pass) {
        if (passOver(pressed, waves, pool, compress) <= tolerance) break;
    }

    // 3. The restitution. Poisson's law says where the impact ends: every contact that pushed in
    //    the compression parts at v_n = e·(J·Δu) (for one contact, e·v_c). The substeps have done
    //    the compression on the real velocities, softly: a soft contact springs back a little of
    //    its overlap, gravity and joints act too. So the bounce is not e·P added blindly, but the
    //    impulse that brings each such contact to its Poisson velocity, by the same passes.
    bool bounced = false;  // does any contact push back at all?
    for (const std::uint32_t i : pressed) {
        const SolverContact& c = workspace.contacts[i];
        ContactStart& start = workspace.starts[i];
        start.bounceVelocity = withRows(c, workspace, [&](const auto& rows) {
            return start.elasticity * (rows.normalVelocity(change[c.bodyA], change[c.bodyB]) -
                                       rows.normalVelocity(change[0], change[0]));
        });
        bounced = bounced || (start.compression != Real(0) && start.elasticity != Real(0));
    }
    auto bounce = [&](std::span<const std::uint32_t> contacts) {
        SolverBody fixed = workspace.bodies[kStaticSolverBody];  // a copy of its own, as in the compression
        Real largest = 0;
        for (const std::uint32_t i : contacts) {
            SolverContact& c = workspace.contacts[i];
            ContactStart& start = workspace.starts[i];
            if (start.compression == Real(0) || start.elasticity == Real(0)) continue;
            withRows(c, workspace, [&](const auto& rows) {
                SolverBody& a = workspace.bodies[c.bodyA];
                SolverBody& b = c.bodyB == kStaticSolverBody ? fixed : workspace.bodies[c.bodyB];
                const Real impulse = c.normalMass * (start.bounceVelocity - rows.normalVelocity(a, b));
                // It may take back what the soft solve sprang back beyond the compression, never
                // more than the step pushed: the impact's impulses together never pull.
                const Real total = std::max(start.bounceImpulse + impulse, -(start.compression + c.maxNormalImpulse));
                rows.applyNormal(a, b, total - start.bounceImpulse);
                largest = std::max(largest, std::abs(total - start.bounceImpulse) / c.normalMass);
                c.normalImpulse += total - start.bounceImpulse;
                start.bounceImpulse = total;
            });
        }
        return largest;
    };
    if (!bounced) return false;
    for (int pass = 0; pass < kMaxCompressionPasses; ++pass) {
        if (passOver(pressed, waves, pool, bounce) <= tolerance) break;
    }
    return true;
}

}  // namespace stepwise
