/// @file contact_solver.cpp
/// @brief The sequential-impulse solver's contacts (the math is in contact_solver.hpp).
#include "dynamics/contact_solver.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/contact_body.hpp"
#include "dynamics/inertia.hpp"
#include "dynamics/point_impulse.hpp"

namespace stepwise {

namespace {

Vec3 totalImpulse(const SolverContact& c) {
    return c.normalImpulse * c.normal + c.tangentImpulse[0] * c.tangent[0] + c.tangentImpulse[1] * c.tangent[1];
}

/// Where an anchor is now: a box's material point turns with the box; a
/// sphere's contact point stays at the same offset from its centre (a rolling
/// ball's support is always underneath it).
Vec3 anchorNow(const Vec3& centre, const Quat& orientation, const Vec3& local, const Vec3& startOffset, bool turns) {
    return centre + (turns ? orientation * local : startOffset);
}

/// C at the recorded poses: the start-of-step separation plus how far the
/// anchors have moved apart along n since (Box2D v3 tracks separation the
/// same way between collision passes). No new collision test is needed.
Real currentSeparation(const SolverContact& c, const SolverWorkspace& w) {
    const Pose& poseA = w.dynamicPoses[c.indexA];
    const Vec3 pA = anchorNow(poseA.position, poseA.orientation, c.localAnchorA, c.rA, c.anchorTurnsWithA);
    Vec3 pB = c.startPointB;  // a plane never moves
    if (c.refB.kind != BodyKind::Plane) {
        const Pose& poseB = c.refB.kind == BodyKind::Dynamic ? w.dynamicPoses[c.refB.index] : w.kinematicPoses[c.refB.index];
        pB = anchorNow(poseB.position, poseB.orientation, c.localAnchorB, c.rB, c.anchorTurnsWithB);
    }
    return c.startSeparation + glm::dot((pB - c.startPointB) - (pA - c.startPointA), c.normal);
}

SolverContact prepareOne(const BodySet& bodies, const Contact& contact, Real h) {
    SolverContact c;
    DynamicObject& a = bodies.dynamics[contact.a];
    const ContactBody other = contactBody(bodies, contact.b, contact.point);
    c.indexA = contact.a;
    c.refB = contact.b;
    c.a = &a;
    c.b = other.dynamic;
    c.staticVelocity = other.velocity;
    c.inverseMassA = a.inverseMass;
    c.inverseInertiaA = worldInverseInertia(a.orientation, a.inverseInertiaBody);
    c.rA = contact.point - a.position;
    c.localAnchorA = glm::conjugate(a.orientation) * c.rA;
    c.anchorTurnsWithA = a.shape != Shape::Sphere;
    c.startPointA = contact.point;
    c.startPointB = contact.point;
    if (c.b) {
        c.inverseMassB = c.b->inverseMass;
        c.inverseInertiaB = worldInverseInertia(c.b->orientation, c.b->inverseInertiaBody);
        c.rB = contact.point - c.b->position;
        c.localAnchorB = glm::conjugate(c.b->orientation) * c.rB;
        c.anchorTurnsWithB = c.b->shape != Shape::Sphere;
    } else if (contact.b.kind == BodyKind::Kinematic) {
        const KinematicsObject& k = bodies.kinematics[contact.b.index];
        c.rB = contact.point - k.position;
        c.localAnchorB = glm::conjugate(k.orientation) * c.rB;
        c.anchorTurnsWithB = k.shape != Shape::Sphere;
    }
    c.startSeparation = -contact.depth;
    c.normal = contact.normal;
    tangentBasis(c.normal, c.tangent);
    c.normalMass = Real(1) / inverseEffectiveMass(c, c.normal);
    for (int k = 0; k < 2; ++k) c.tangentMass[k] = Real(1) / inverseEffectiveMass(c, c.tangent[k]);
    c.friction = combineFriction(a.friction, other.friction);

    // The bounce, decided before any impulse (contact_solver.hpp): the
    // approach speed when the surfaces meet, v_c² = v_n² + 2·a·C, with a the
    // approach acceleration −(a_B − a_A)·n.
    const Real vn = glm::dot(relativeVelocity(c), c.normal);
    const Real approachAcceleration = -glm::dot(other.acceleration - a.acceleration, c.normal);
    if (vn < 0) {
        c.approachAtTouch = std::sqrt(std::max(Real(0), vn * vn + Real(2) * approachAcceleration * c.startSeparation));
    }
    const Real stepAcceleration = std::max({std::abs(approachAcceleration), std::abs(glm::dot(a.acceleration, c.normal)),
                                            std::abs(glm::dot(other.acceleration, c.normal))});
    const bool resting = c.approachAtTouch <= kRestingContactSteps * stepAcceleration * h;
    c.restitution = resting ? Real(0) : combineElasticity(a.elasticity, other.elasticity);
    return c;
}

}  // namespace

void prepareContacts(const BodySet& bodies, std::span<const Contact> contacts, Real h, bool warmStart,
                     SolverWorkspace& workspace) {
    workspace.contacts.resize(contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        SolverContact& c = workspace.contacts[i];
        c = prepareOne(bodies, contacts[i], h);
        if (!warmStart) continue;
        if (const CachedImpulse* cached = findCachedImpulse(workspace.previousImpulses, keyOf(contacts[i]))) {
            c.normalImpulse = cached->normalImpulse;
            // Tangent axes are rebuilt each step: the friction is carried as a world vector.
            for (int k = 0; k < 2; ++k) c.tangentImpulse[k] = glm::dot(cached->frictionImpulse, c.tangent[k]);
        }
    }
}

void recordPoses(const BodySet& bodies, SolverWorkspace& workspace) {
    workspace.dynamicPoses.resize(bodies.dynamics.size());
    for (std::size_t i = 0; i < bodies.dynamics.size(); ++i) {
        workspace.dynamicPoses[i] = {bodies.dynamics[i].position, bodies.dynamics[i].orientation};
    }
    workspace.kinematicPoses.resize(bodies.kinematics.size());
    for (std::size_t i = 0; i < bodies.kinematics.size(); ++i) {
        workspace.kinematicPoses[i] = {bodies.kinematics[i].position, bodies.kinematics[i].orientation};
    }
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
    for (SolverContact& c : workspace.contacts) applyImpulse(c, totalImpulse(c));
}

void solveContacts(SolverWorkspace& workspace, const ContactSolverSettings& settings, bool useBias) {
    const Real inverseSubstep = Real(1) / settings.substep;
    for (SolverContact& c : workspace.contacts) {
        // Normal: λ = −K⁻¹·s_m·(v_n + bias) − s_i·λ_acc (softness.hpp).
        const Real separation = currentSeparation(c, workspace);
        Real bias = 0;
        Real massScale = 1;
        Real impulseScale = 0;
        if (separation > 0) {
            bias = separation * inverseSubstep;  // speculative: close the gap in this substep, no further
        } else if (useBias && settings.positionCorrection) {
            bias = std::max(settings.softness.biasRate * separation, -kMaxPushOutSpeed);
            massScale = settings.softness.massScale;
            impulseScale = settings.softness.impulseScale;
        }
        const Real vn = glm::dot(relativeVelocity(c), c.normal);
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
        applyImpulse(c, applied * c.normal);

        // Friction on what is left sliding, inside Coulomb's circle |λ_t| ≤ μ·λ_n.
        const Vec3 relative = relativeVelocity(c);
        const Real limit = c.friction * c.normalImpulse;
        Real total[2];
        for (int k = 0; k < 2; ++k) total[k] = c.tangentImpulse[k] - c.tangentMass[k] * glm::dot(relative, c.tangent[k]);
        const Real magnitude = std::hypot(total[0], total[1]);
        if (magnitude > limit) {
            const Real scale = magnitude > 0 ? limit / magnitude : Real(0);
            total[0] *= scale;
            total[1] *= scale;
        }
        const Vec3 change = (total[0] - c.tangentImpulse[0]) * c.tangent[0] + (total[1] - c.tangentImpulse[1]) * c.tangent[1];
        c.tangentImpulse[0] = total[0];
        c.tangentImpulse[1] = total[1];
        applyImpulse(c, change);
    }
}

void applyRestitution(SolverWorkspace& workspace) {
    for (SolverContact& c : workspace.contacts) {
        if (c.restitution == Real(0) || c.maxNormalImpulse == Real(0)) continue;
        // Drive v_n to e·v_c (separating), never pulling: the accumulated λ stays ≥ 0.
        const Real vn = glm::dot(relativeVelocity(c), c.normal);
        const Real impulse = c.normalMass * (c.restitution * c.approachAtTouch - vn);
        const Real total = std::max(c.normalImpulse + impulse, Real(0));
        applyImpulse(c, (total - c.normalImpulse) * c.normal);
        c.normalImpulse = total;
    }
}

void storeContactImpulses(std::span<const Contact> contacts, SolverWorkspace& workspace,
                          std::span<ImpulseReport> reports) {
    workspace.currentImpulses.clear();
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const SolverContact& c = workspace.contacts[i];
        const Vec3 friction = c.tangentImpulse[0] * c.tangent[0] + c.tangentImpulse[1] * c.tangent[1];
        workspace.currentImpulses.push_back({keyOf(contacts[i]), c.normalImpulse, friction});
        if (!reports.empty()) {
            reports[i] = {c.approachAtTouch, c.approachAtTouch, c.restitution, c.normalImpulse, glm::length(friction)};
        }
    }
    std::sort(workspace.currentImpulses.begin(), workspace.currentImpulses.end(),
              [](const CachedImpulse& x, const CachedImpulse& y) { return x.key < y.key; });
    std::swap(workspace.previousImpulses, workspace.currentImpulses);
    // ω was updated alongside L with the step's fixed I⁻¹; make them agree exactly again.
    for (SolverContact& c : workspace.contacts) {
        updateAngularVelocity(*c.a);
        if (c.b) updateAngularVelocity(*c.b);
    }
}

}  // namespace stepwise
