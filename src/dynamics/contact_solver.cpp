/// @file contact_solver.cpp
/// @brief The sequential-impulse solver's contacts (the math is in contact_solver.hpp).
#include "dynamics/contact_solver.hpp"


#include <algorithm>
#include <cmath>

#include "dynamics/contact_body.hpp"
#include "objects/inertia.hpp"

namespace stepwise {

namespace {

/// Gives every dynamic body in a contact or a joint its solver-body record,
/// numbered in the order of the World's dynamic array: its mass, and its world
/// inertia and inverse inertia, once per body per step. In that order the copies in and
/// out of the records (copyVelocitiesIn(), copyVelocitiesOut(),
/// warmStartFromLastSubstep()) walk the objects front to back, as the memory
/// prefetcher likes, instead of jumping about a many-megabyte array in the
/// order the contacts happen to meet their bodies.
void makeBodyRecords(const BodySet& bodies, std::span<const Contact> contacts, std::span<const BodyLink> links,
                     SolverWorkspace& w) {
    constexpr std::uint32_t kInContact = 1;  // any value but kStaticSolverBody, overwritten below
    w.bodyRecord.assign(bodies.dynamics.size(), kStaticSolverBody);
    for (const Contact& contact : contacts) {
        w.bodyRecord[contact.a] = kInContact;
        if (contact.b.kind == BodyKind::Dynamic) w.bodyRecord[contact.b.index] = kInContact;
    }
    // A joint moves its bodies too, and the drift moves only bodies with a record (driftByVelocityChange())
    for (const BodyLink& link : links) {
        w.bodyRecord[link.a] = kInContact;
        if (link.b != kWorldAnchor) w.bodyRecord[link.b] = kInContact;
    }
    w.bodies.clear();
    w.inertias.clear();
    w.recordBody.clear();
    w.ballInertia.clear();
    w.bodies.emplace_back();  // record 0: the static body (m⁻¹ = 0, I⁻¹ = 0, at rest)
    w.inertias.emplace_back();
    w.recordBody.push_back(0);  // never read: the loops over records start at 1
    w.ballInertia.push_back(0);
    for (std::uint32_t index = 0; index < w.bodyRecord.size(); ++index) {
        if (w.bodyRecord[index] == kStaticSolverBody) continue;
        const DynamicObject& body = bodies.dynamics[index];
        w.bodyRecord[index] = static_cast<std::uint32_t>(w.bodies.size());
        // A ball's I and I⁻¹ are the same about every axis: numbers for its round contacts and
        // its write-back (zero marks a box, whose inertia is a tensor).
        const bool ball = body.shape == Shape::Sphere;
        w.bodies.push_back({body.velocity, body.angularVelocity, body.inverseMass,
                            ball ? body.inverseInertiaBody.x : Real(0)});
        w.inertias.push_back({worldInverseInertia(body.orientation, body.inverseInertiaBody),
                              worldInertia(body.orientation, body.inertiaBody)});
        w.recordBody.push_back(index);
        w.ballInertia.push_back(ball ? body.inertiaBody.x : Real(0));
    }
    w.turnSums.assign(w.bodies.size(), SpinSum{});
}

/// The three rows of a round contact, computed from its normal, tangents and
/// levers (solver_body.hpp); the two friction rows together, as one impulse
/// vector in the tangent plane.
struct RoundRows {
    const SolverContact& c;
    Real normalVelocity(const SolverBody& a, const SolverBody& b) const { return roundNormalVelocity(a, b, c.normal); }
    void applyNormal(SolverBody& a, SolverBody& b, Real lambda) const { applyRoundNormalImpulse(a, b, c.normal, lambda); }
    void tangentVelocities(const SolverBody& a, const SolverBody& b, Real (&out)[2]) const {
        roundFrictionVelocities(a, b, c.tangent, c.leverA, c.leverB, out);
    }
    void applyTangents(SolverBody& a, SolverBody& b, Real lambda0, Real lambda1) const {
        applyRoundFrictionImpulse(a, b, c.tangent, c.leverA, c.leverB, lambda0, lambda1);
    }
};

/// The three rows of any other contact, read from SolverWorkspace::rows; a
/// kinematic B's own surface speed is part of J·v.
struct StoredRows {
    const SolverContact& c;
    const ContactRows& r;
    Real normalVelocity(const SolverBody& a, const SolverBody& b) const {
        return rowVelocity(a, b, c.normal, r.normal) + r.normalSurfaceSpeed;
    }
    void applyNormal(SolverBody& a, SolverBody& b, Real lambda) const { applyRowImpulse(a, b, c.normal, r.normal, lambda); }
    void tangentVelocities(const SolverBody& a, const SolverBody& b, Real (&out)[2]) const {
        for (int k = 0; k < 2; ++k) out[k] = rowVelocity(a, b, c.tangent[k], r.tangent[k]) + r.tangentSurfaceSpeed[k];
    }
    void applyTangents(SolverBody& a, SolverBody& b, Real lambda0, Real lambda1) const {
        applyRowImpulse(a, b, c.tangent[0], r.tangent[0], lambda0);
        applyRowImpulse(a, b, c.tangent[1], r.tangent[1], lambda1);
    }
};

/// Calls @p work with contact @p c's rows, round or stored, and returns what it
/// returns: the one branch per contact a pass takes on the kind of contact.
template <class Work>
inline decltype(auto) withRows(const SolverContact& c, const SolverWorkspace& w, Work&& work) {
    if (c.rows == kRoundContact) return work(RoundRows{c});
    return work(StoredRows{c, w.rows[c.rows]});
}

/// Index of the fixed pose at the origin (the last one): a plane's "centre".
std::uint32_t planePose(const BodySet& bodies) {
    return static_cast<std::uint32_t>(bodies.dynamics.size() + bodies.kinematics.size());
}

/// The contact's pass record (returned) and its start record @p start.
SolverContact prepareOne(const BodySet& bodies, const Contact& contact, Real h, SolverWorkspace& w,
                         ContactStart& start) {
    SolverContact c;
    const DynamicObject& a = bodies.dynamics[contact.a];
    const ContactBody other = contactBody(bodies, contact.b, contact.point);
    c.bodyA = w.bodyRecord[contact.a];
    c.poseA = contact.a;
    start = ContactStart{};
    start.indexA = contact.a;
    start.refB = contact.b;
    const Vec3 rA = contact.point - a.position;  // used below from here, not read back from `start` (see the levers)
    start.rA = rA;
    start.startPoint = contact.point;
    start.startSeparation = -contact.depth;
    c.normal = contact.normal;

    // The separation's fixed part (SolverContact): C₀ plus the fixed offsets
    // r·n of the anchors that do not turn; the turning ones go to the side array.
    const bool turnsA = a.shape != Shape::Sphere;
    bool turnsB = false;
    Vec3 centreB{0, 0, 0};  // a plane's "centre" is the origin: its point is a fixed offset from there
    const Quat* orientationB = nullptr;
    c.poseB = planePose(bodies);
    if (other.dynamic) {
        c.bodyB = w.bodyRecord[contact.b.index];
        c.poseB = contact.b.index;
        centreB = other.dynamic->position;
        orientationB = &other.dynamic->orientation;
        turnsB = other.dynamic->shape != Shape::Sphere;
    } else {
        start.staticVelocity = other.velocity;  // the surface of a kinematic B moves; a plane's does not
        if (contact.b.kind == BodyKind::Kinematic) {
            const KinematicsObject& k = bodies.kinematics[contact.b.index];
            c.poseB = static_cast<std::uint32_t>(bodies.dynamics.size() + contact.b.index);
            centreB = k.position;
            orientationB = &k.orientation;
            turnsB = k.shape != Shape::Sphere;
        }
    }
    const Vec3 offsetB = contact.point - centreB;
    if (contact.b.kind != BodyKind::Plane) start.rB = offsetB;
    c.separationOffset = start.startSeparation + (turnsB ? Real(0) : glm::dot(offsetB, c.normal)) -
                         (turnsA ? Real(0) : glm::dot(rA, c.normal));
    if (turnsA || turnsB) {
        TurningAnchors anchors;
        if (turnsA) anchors.localA = glm::conjugate(a.orientation) * rA;
        if (turnsB) anchors.localB = glm::conjugate(*orientationB) * offsetB;
        c.turningAnchors = static_cast<std::uint32_t>(w.turningAnchors.size());
        w.turningAnchors.push_back(anchors);
    }

    const SolverBody& bodyA = w.bodies[c.bodyA];
    const SolverBody& bodyB = w.bodies[c.bodyB];
    tangentBasis(c.normal, c.tangent);
    // J's angular parts and K, once per step: r, d and I⁻¹ are fixed through it (solver_body.hpp).
    // A ball on a ball or a plane (no anchor turns, no surface moves): levers along n, rows computed by the pass.
    if (!turnsA && !turnsB && contact.b.kind != BodyKind::Kinematic) {
        // The levers from the local vectors: read back from `start`, a 16-byte load of a vector
        // just written as 8-byte stores waits for them (the processor cannot forward it).
        c.leverA = glm::dot(rA, c.normal);
        c.leverB = contact.b.kind != BodyKind::Plane ? glm::dot(offsetB, c.normal) : Real(0);
        c.normalMass = Real(1) / (bodyA.inverseMass + bodyB.inverseMass);
        c.tangentMass[0] = c.tangentMass[1] = Real(1) / roundTangentInverseMass(bodyA, bodyB, c.leverA, c.leverB);
    } else {
        const SolverBodyInertia& inertiaA = w.inertias[c.bodyA];
        const SolverBodyInertia& inertiaB = w.inertias[c.bodyB];
        ContactRows rows;
        rows.normal = makeContactRow(inertiaA, inertiaB, start.rA, start.rB, c.normal);
        c.normalMass = Real(1) / inverseEffectiveMass(bodyA, bodyB, rows.normal);
        rows.normalSurfaceSpeed = glm::dot(start.staticVelocity, c.normal);
        Real tangentInverseMass[2];
        for (int k = 0; k < 2; ++k) {
            rows.tangent[k] = makeContactRow(inertiaA, inertiaB, start.rA, start.rB, c.tangent[k]);
            tangentInverseMass[k] = inverseEffectiveMass(bodyA, bodyB, rows.tangent[k]);
            rows.tangentSurfaceSpeed[k] = glm::dot(start.staticVelocity, c.tangent[k]);
        }
        // One mass for the pair, or a sliding box's friction is not against its sliding (frictionPairMass())
        c.tangentMass[0] = c.tangentMass[1] = frictionPairMass(tangentInverseMass[0], tangentInverseMass[1]);
        c.rows = static_cast<std::uint32_t>(w.rows.size());
        w.rows.push_back(rows);
    }
    c.friction = combineFriction(a.friction, other.friction);

    // The bounce, decided before any impulse (contact_solver.hpp): the
    // approach speed when the surfaces meet, v_c² = v_n² + 2·a·C, with a the
    // approach acceleration −(a_B − a_A)·n.
    const Real vn = withRows(c, w, [&](const auto& rows) { return rows.normalVelocity(bodyA, bodyB); });
    const Real approachAcceleration = -glm::dot(other.acceleration - a.acceleration, c.normal);
    if (vn < 0) {
        start.approachAtTouch =
            std::sqrt(std::max(Real(0), vn * vn + Real(2) * approachAcceleration * start.startSeparation));
    }
    const Real stepAcceleration = std::max({std::abs(approachAcceleration), std::abs(glm::dot(a.acceleration, c.normal)),
                                            std::abs(glm::dot(other.acceleration, c.normal))});
    const bool resting = start.approachAtTouch <= kRestingContactSteps * stepAcceleration * h;
    start.elasticity = combineElasticity(a.elasticity, other.elasticity);
    start.restitution = resting ? Real(0) : start.elasticity;
    // Where the compression starts (applyRestitution()): the approach at touch for an impact, the
    // separation speed for bodies already parting, nothing for two that merely touch. A contact
    // an acceleration presses shut (a box's weight on the floor) carries a load, not an impact:
    // it is left out of the compression.
    start.carriesLoad = resting && stepAcceleration > Real(0);
    start.touchVelocity = vn >= 0 ? vn : resting ? Real(0) : -start.approachAtTouch;
    start.compression = 0;
    start.bounceImpulse = 0;
    return c;
}

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

ContactSolverSettings makeContactSolverSettings(const WorldSettings& settings, Real substep) {
    ContactSolverSettings s;
    s.substep = substep;
    s.inverseSubstep = Real(1) / substep;
    s.accumulate = settings.accumulateImpulses;
    s.positionCorrection = settings.positionCorrection;
    s.relaxBallFriction = settings.relaxBallFriction;
    s.softness = makeSoftness(contactHertzInUse(settings), settings.contactDampingRatio, substep);
    return s;
}

void prepareContacts(const BodySet& bodies, std::span<const Contact> contacts, std::span<const BodyLink> links, Real h,
                     bool warmStart, SolverWorkspace& workspace) {
    workspace.dynamics = bodies.dynamics;
    makeBodyRecords(bodies, contacts, links, workspace);  // last step's records are dropped
    workspace.contacts.resize(contacts.size());
    workspace.starts.resize(contacts.size());
    workspace.rows.clear();
    workspace.turningAnchors.clear();
    workspace.roundContacts.clear();
    workspace.otherContacts.clear();
    workspace.bouncing.clear();
    std::size_t nextCached = 0;  // the contacts come in key order, mostly: each lookup starts where the last ended
    for (std::uint32_t i = 0; i < contacts.size(); ++i) {
        SolverContact& c = workspace.contacts[i];
        c = prepareOne(bodies, contacts[i], h, workspace, workspace.starts[i]);
        (c.rows == kRoundContact ? workspace.roundContacts : workspace.otherContacts).push_back(i);
        if (workspace.starts[i].touchVelocity < Real(0)) workspace.bouncing.push_back(i);
        if (!warmStart) continue;
        if (const CachedImpulse* cached = findCachedImpulse(workspace.previousImpulses, keyOf(contacts[i]), nextCached)) {
            c.normalImpulse = cached->normalImpulse;
            // Tangent axes are rebuilt each step: the friction is carried as a world vector.
            for (int k = 0; k < 2; ++k) c.tangentImpulse[k] = glm::dot(cached->frictionImpulse, c.tangent[k]);
        }
    }
}

void recordPoses(const BodySet& bodies, SolverWorkspace& workspace) {
    const std::size_t dynamicCount = bodies.dynamics.size();
    workspace.poses.resize(dynamicCount + bodies.kinematics.size() + 1);
    for (std::size_t i = 0; i < dynamicCount; ++i) {
        workspace.poses[i] = {bodies.dynamics[i].position, bodies.dynamics[i].orientation};
    }
    recordKinematicPoses(bodies, workspace);
    workspace.poses.back() = Pose{};  // the planes' fixed pose at the origin
}

void recordKinematicPoses(const BodySet& bodies, SolverWorkspace& workspace) {
    const std::size_t dynamicCount = bodies.dynamics.size();
    for (std::size_t i = 0; i < bodies.kinematics.size(); ++i) {
        workspace.poses[dynamicCount + i] = {bodies.kinematics[i].position, bodies.kinematics[i].orientation};
    }
}

void copyVelocitiesIn(SolverWorkspace& workspace) {
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) {
        const DynamicObject& body = workspace.dynamics[workspace.recordBody[i]];
        workspace.bodies[i].velocity = body.velocity;
        workspace.bodies[i].angularVelocity = body.angularVelocity;
    }
}

void copyVelocitiesOut(SolverWorkspace& workspace) {
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) copyVelocitiesOut(workspace, i);
}

void recordSubstepStart(SolverWorkspace& workspace) {
    workspace.substepStart.resize(workspace.bodies.size());
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) {
        const DynamicObject& body = workspace.dynamics[workspace.recordBody[i]];
        workspace.substepStart[i] = {body.velocity, body.angularVelocity};
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
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) {
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
}

namespace {

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

void solveContacts(SolverWorkspace& workspace, const ContactSolverSettings& settings, bool useBias) {
    for (const std::uint32_t index : workspace.roundContacts) solveOne(workspace.contacts[index], workspace, settings, useBias);
    for (const std::uint32_t index : workspace.otherContacts) solveOne(workspace.contacts[index], workspace, settings, useBias);
}

void solveContact(SolverWorkspace& workspace, std::uint32_t index, const ContactSolverSettings& settings, bool useBias) {
    solveOne(workspace.contacts[index], workspace, settings, useBias);
}

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
    for (std::uint32_t i = 0; i < workspace.contacts.size(); ++i) {
        if (workspace.contacts[i].maxNormalImpulse > Real(0) && !workspace.starts[i].carriesLoad) pressed.push_back(i);
    }
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

namespace {

template <class T>
std::size_t bytesOf(const std::vector<T>& array) {
    return array.size() * sizeof(T);
}

}  // namespace

SolverFootprint solverFootprint(const SolverWorkspace& w) {
    SolverFootprint f;
    f.passBytes = bytesOf(w.bodies) + bytesOf(w.contacts) + bytesOf(w.rows) + bytesOf(w.turningAnchors) + bytesOf(w.poses) +
                  bytesOf(w.roundContacts) + bytesOf(w.otherContacts);
    f.allBytes = f.passBytes + bytesOf(w.starts) + bytesOf(w.bouncing) + bytesOf(w.inertias) + bytesOf(w.recordBody) +
                 bytesOf(w.ballInertia) + bytesOf(w.bodyRecord) + bytesOf(w.previousImpulses) +
                 bytesOf(w.currentImpulses) + bytesOf(w.substepStart) + bytesOf(w.turnSums);
    return f;
}

void storeContactImpulses(std::span<const Contact> contacts, SolverWorkspace& workspace,
                          std::span<ImpulseReport> reports) {
    workspace.currentImpulses.clear();
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const SolverContact& c = workspace.contacts[i];
        const ContactStart& start = workspace.starts[i];
        const Vec3 friction = c.tangentImpulse[0] * c.tangent[0] + c.tangentImpulse[1] * c.tangent[1];
        workspace.currentImpulses.push_back({keyOf(contacts[i]), c.normalImpulse, friction});
        if (!reports.empty()) {
            reports[i] = {start.approachAtTouch, start.approachAtTouch, start.restitution, c.normalImpulse,
                          glm::length(friction)};
        }
    }
    // In key order for next step's lookups. The narrowphase's order is the keys' order but for
    // the points of one pair, whose feature ids need not ascend: most steps there is nothing to sort.
    const auto byKey = [](const CachedImpulse& x, const CachedImpulse& y) { return x.key < y.key; };
    if (!std::is_sorted(workspace.currentImpulses.begin(), workspace.currentImpulses.end(), byKey)) {
        std::sort(workspace.currentImpulses.begin(), workspace.currentImpulses.end(), byKey);
    }
    std::swap(workspace.previousImpulses, workspace.currentImpulses);
    // ω was updated alongside L with the step's fixed I⁻¹; make them agree exactly again.
    // Once per body in a contact: the result depends only on L and the orientation.
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) updateAngularVelocity(workspace.dynamics[workspace.recordBody[i]]);
}

}  // namespace stepwise
