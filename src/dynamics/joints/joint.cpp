/// @file joint.cpp
/// @brief A joint's life: built from the scene, prepared each step, solved each substep, maybe broken (joint.hpp).
#include "dynamics/joints/joint.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/limits.hpp"
#include "dynamics/impulse_resolver.hpp"
#include "objects/inertia.hpp"
#include "dynamics/joints/joint_parts.hpp"

namespace stepwise {

namespace {

/// An axis shorter than this cannot be normalised into a direction.

void require(bool condition, const JointDef& def, const std::string& what) {
    if (!condition) throw std::invalid_argument("joint '" + def.name + "': " + what);
}

std::uint32_t findBody(std::span<const DynamicObject> bodies, const std::string& name, const JointDef& def) {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (bodies[i].name == name) return static_cast<std::uint32_t>(i);
    }
    require(false, def, "no dynamic body called '" + name + "'");
    return 0;
}

Joint makeJoint(const JointDef& def, std::span<const DynamicObject> bodies) {
    Joint joint;
    joint.name = def.name;
    joint.kind = def.kind;
    joint.bodyA = findBody(bodies, def.bodyA, def);
    if (!def.bodyB.empty()) joint.bodyB = findBody(bodies, def.bodyB, def);
    require(joint.bodyA != joint.bodyB, def, "BodyA and BodyB are the same body");

    const DynamicObject& a = bodies[joint.bodyA];
    const DynamicObject* b = joint.bodyB == kWorldAnchor ? nullptr : &bodies[joint.bodyB];
    const Quat orientationB = b ? b->orientation : Quat(1, 0, 0, 0);
    // Ball and hinge joints have one point, shared by both bodies; a motor has
    // none, and keeps the bodies' centres as anchors (for drawing and the island links only).
    const bool onePoint = def.kind == JointKind::Ball || def.kind == JointKind::Hinge;
    const bool noPoint = def.kind == JointKind::AngularMotor;
    const Vec3 anchorA = noPoint ? a.position : def.anchorA;
    const Vec3 anchorB = noPoint ? (b ? b->position : a.position) : onePoint ? def.anchorA : def.anchorB;

    // World → body frames: a point p of body (x, q) is q⁻¹·(p − x); a direction is q⁻¹·d.
    joint.localAnchorA = glm::conjugate(a.orientation) * (anchorA - a.position);
    joint.localAnchorB = b ? glm::conjugate(orientationB) * (anchorB - b->position) : anchorB;
    if (def.kind == JointKind::Hinge || def.kind == JointKind::AngularMotor) {
        require(usableDirection(def.axis), def, "the axis must be a direction of finite length > 0");
        const Vec3 axis = def.axis / glm::length(def.axis);
        joint.localAxisA = glm::conjugate(a.orientation) * axis;
        joint.localAxisB = glm::conjugate(orientationB) * axis;
        tangentBasis(joint.localAxisB, joint.localPerpendicularB);
    }
    joint.referenceRotation = glm::conjugate(orientationB) * a.orientation;

    if (def.kind == JointKind::Distance || def.kind == JointKind::Rope) {
        joint.length = def.length.value_or(glm::length(anchorB - anchorA));
        require(std::isfinite(joint.length) && joint.length >= kMinJointLength, def,
                "the length must be at least 1e-6 m (the anchors coincide: give a Length, or use a BallJoint)");
    }
    joint.hasLowerLimit = def.lowerAngle.has_value();
    joint.hasUpperLimit = def.upperAngle.has_value();
    joint.lowerAngle = def.lowerAngle.value_or(0);
    joint.upperAngle = def.upperAngle.value_or(0);
    require(!(joint.hasLowerLimit && joint.hasUpperLimit) || joint.lowerAngle <= joint.upperAngle, def,
            "the lower angle must not exceed the upper angle");
    joint.motor = def.motor || def.kind == JointKind::AngularMotor;
    joint.motorSpeed = def.motorSpeed;
    require(!(def.maxMotorTorque < 0), def, "the maximum motor torque must be >= 0 N m");
    joint.maxMotorTorque = def.maxMotorTorque;
    require(def.maxForce > 0, def, "the maximum force must be > 0 N");
    joint.maxForce = def.maxForce;
    joint.collideConnected = def.collideConnected;
    return joint;
}

/// The impulse the joint's point or axial rows carried in the last substep, N·s (its force times h_s).
Real reactionImpulse(const Joint& joint) {
    switch (joint.kind) {
        case JointKind::Distance:
        case JointKind::Rope: return std::abs(joint.axialImpulse);
        case JointKind::Ball:
        case JointKind::Hinge: return glm::length(joint.linearImpulse);
        case JointKind::AngularMotor: break;  // a motor is bounded by its torque instead
    }
    return 0;
}

void clearImpulses(Joint& joint) {
    joint.linearImpulse = Vec3(0);
    joint.axialImpulse = 0;
    joint.alignImpulse[0] = joint.alignImpulse[1] = 0;
    joint.lowerImpulse = joint.upperImpulse = 0;
    joint.motorImpulse = 0;
}

Pose poseOf(const DynamicObject& body) { return {body.position, body.orientation}; }

/// One number per unordered pair of dynamic bodies: the smaller index in the high half. The continuous
/// stage reads these keys (SweepWorkspace::unsweptPairs), and must build them alike (bodyPairKey(),
/// collision/continuous.hpp; tests/test_joints.cpp checks the two agree by the swinging chain).
std::uint64_t pairKey(std::uint32_t a, std::uint32_t b) {
    constexpr unsigned kHalf = 32;
    return (std::uint64_t(std::min(a, b)) << kHalf) | std::max(a, b);
}

}  // namespace

const char* toString(JointKind kind) {
    switch (kind) {
        case JointKind::Distance: return "DistanceJoint";
        case JointKind::Rope: return "Rope";
        case JointKind::Ball: return "BallJoint";
        case JointKind::Hinge: return "HingeJoint";
        case JointKind::AngularMotor: return "AngularMotor";
    }
    return "?";
}

Real jointHertzInUse(const WorldSettings& settings) {
    const Real cap = kMaxHertzPerSubstepRate * Real(settings.substeps) / settings.timeStep;
    return std::min(settings.jointHertz, cap);
}

JointSolverSettings jointSolverSettings(const WorldSettings& settings, Real substep) {
    JointSolverSettings s;
    s.substep = substep;
    s.softness = makeSoftness(jointHertzInUse(settings), settings.jointDampingRatio, substep);
    s.positionCorrection = settings.positionCorrection;
    return s;
}

std::vector<Joint> makeJoints(std::span<const JointDef> defs, std::span<const DynamicObject> bodies, SolverKind solver) {
    std::vector<Joint> joints;
    for (const JointDef& def : defs) {
        require(solver == SolverKind::SequentialImpulse, def, "joints need Solver=SequentialImpulse");
        joints.push_back(makeJoint(def, bodies));
    }
    return joints;
}

void jointLinks(std::span<const Joint> joints, std::vector<BodyLink>& links) {
    links.clear();
    for (const Joint& joint : joints) {
        if (!joint.broken) links.push_back({joint.bodyA, joint.bodyB});
    }
}

void dropJointedPairs(std::span<const Joint> joints, JointWorkspace& workspace, std::vector<CandidatePair>& pairs) {
    std::vector<std::uint64_t>& keys = workspace.jointedPairs;
    keys.clear();
    for (const Joint& joint : joints) {
        if (!joint.broken && !joint.collideConnected && joint.bodyB != kWorldAnchor) {
            keys.push_back(pairKey(joint.bodyA, joint.bodyB));
        }
    }
    if (keys.empty()) return;
    std::sort(keys.begin(), keys.end());
    std::erase_if(pairs, [&](const CandidatePair& pair) {
        return pair.b.kind == BodyKind::Dynamic && std::binary_search(keys.begin(), keys.end(), pairKey(pair.a, pair.b.index));
    });
}

namespace {

/// The place of dynamic body @p index in @p workspace's bodies, given one if it has none yet.
std::uint32_t placeOfBody(JointWorkspace& workspace, std::span<DynamicObject> dynamics, std::uint32_t index) {
    std::uint32_t& place = workspace.placeOf[index];
    if (place == kNoJointBody) {
        place = static_cast<std::uint32_t>(workspace.bodies.size());
        workspace.bodies.push_back(&dynamics[index]);
    }
    return place;
}

}  // namespace

void prepareJoints(const BodySet& bodies, std::span<Joint> joints, bool warmStart, JointWorkspace& workspace) {
    workspace.joints.clear();
    workspace.bodies.clear();
    workspace.placeOf.assign(bodies.dynamics.size(), kNoJointBody);
    for (Joint& joint : joints) {
        if (joint.broken) continue;
        DynamicObject& a = bodies.dynamics[joint.bodyA];
        DynamicObject* b = joint.bodyB == kWorldAnchor ? nullptr : &bodies.dynamics[joint.bodyB];
        // wakeTouchedIslands() has run: a joint's bodies are both awake or both asleep.
        if (a.asleep && (b == nullptr || b->asleep)) continue;
        if (!warmStart) clearImpulses(joint);
        SolverJoint j;
        j.joint = &joint;
        j.a = &a;
        j.b = b;
        j.placeA = placeOfBody(workspace, bodies.dynamics, joint.bodyA);
        if (b) j.placeB = placeOfBody(workspace, bodies.dynamics, joint.bodyB);
        j.inverseMassA = a.inverseMass;
        if (b) j.inverseMassB = b->inverseMass;
        workspace.joints.push_back(j);  // the inverse inertias: each substep (warmStartJoints())
    }
    workspace.inverseInertias.resize(workspace.bodies.size());
}

void warmStartJoints(JointWorkspace& workspace, std::span<const Pose> poses) {
    // I⁻¹ = R·I_body⁻¹·Rᵀ at the orientation the substep starts from, once a body. Kept from the
    // start of the step instead, a body turned by θ since then would answer an impulse with
    // Δω = I⁻¹(q₀)·ΔL where ω = I⁻¹(q)·L holds: for a rod whose moments differ 8:1, up to
    // 8 times the turn the joint asked for, fed back by every warm start (a chain's whip).
    for (std::size_t k = 0; k < workspace.bodies.size(); ++k) {
        const DynamicObject& body = *workspace.bodies[k];
        workspace.inverseInertias[k] = worldInverseInertia(body.orientation, body.inverseInertiaBody);
    }
    // Each type is handed what its rows read: the anchors (frameAt()), the orientations (orientationsAt()), or both.
    for (SolverJoint& j : workspace.joints) {
        j.inverseInertiaA = workspace.inverseInertias[j.placeA];
        if (j.b) j.inverseInertiaB = workspace.inverseInertias[j.placeB];
        switch (j.joint->kind) {
            case JointKind::Distance:
            case JointKind::Rope: warmStartAxial(j, frameAt(j, poses)); break;
            case JointKind::Ball: warmStartBallJoint(j, frameAt(j, poses)); break;
            case JointKind::Hinge: warmStartHingeJoint(j, frameAt(j, poses), orientationsAt(j, poses)); break;
            case JointKind::AngularMotor: warmStartAngularMotor(j, orientationsAt(j, poses)); break;
        }
    }
}

void solveJoints(JointWorkspace& workspace, std::span<const Pose> poses, const JointSolverSettings& settings,
                 bool useBias) {
    for (SolverJoint& j : workspace.joints) {
        switch (j.joint->kind) {
            case JointKind::Distance: solveDistanceJoint(j, frameAt(j, poses), settings, useBias); break;
            case JointKind::Rope: solveRope(j, frameAt(j, poses), settings, useBias); break;
            case JointKind::Ball: solveBallJoint(j, frameAt(j, poses), settings, useBias); break;
            case JointKind::Hinge:
                solveHingeJoint(j, frameAt(j, poses), orientationsAt(j, poses), settings, useBias);
                break;
            case JointKind::AngularMotor: solveAngularMotor(j, orientationsAt(j, poses), settings); break;
        }
    }
}

void solveJointsBetweenContactPasses(JointWorkspace& joints, SolverWorkspace& contacts,
                                     const JointSolverSettings& settings, bool useBias) {
    if (joints.joints.empty()) return;
    copyVelocitiesOut(contacts);
    solveJoints(joints, contacts.poses, settings, useBias);
    copyVelocitiesIn(contacts);
}

void solveJointsBetweenContactPasses(JointWorkspace& joints, SolverWorkspace& contacts,
                                     std::span<const std::uint32_t> records, const JointSolverSettings& settings,
                                     bool useBias) {
    if (joints.joints.empty()) return;
    copyVelocitiesOut(contacts, records);
    solveJoints(joints, contacts.poses, settings, useBias);
    copyVelocitiesIn(contacts, records);
}

std::size_t finishJoints(JointWorkspace& workspace, std::span<Joint> joints, Real substep, std::uint64_t step,
                         Real time, std::vector<BodyLink>& links) {
    std::size_t broke = 0;
    for (SolverJoint& j : workspace.joints) {
        Joint& joint = *j.joint;
        // The accumulated impulse is what the joint applied in the last substep: force = λ_acc / h_s.
        const Real force = reactionImpulse(joint) / substep;
        if (force > joint.maxForce) {
            joint.broken = true;
            joint.brokenAtStep = step;
            joint.brokenAtTime = time;
            joint.brokenForce = force;
            clearImpulses(joint);
            ++broke;
        }
        // ω was changed alongside L with the step's fixed I⁻¹; make them agree exactly again.
        updateAngularVelocity(*j.a);
        if (j.b) updateAngularVelocity(*j.b);
    }
    if (broke > 0) jointLinks(joints, links);
    return broke;
}

JointAnchors jointAnchors(const Joint& joint, std::span<const DynamicObject> bodies) {
    const Pose poseA = poseOf(bodies[joint.bodyA]);
    const JointFrame f = frameAt(joint, poseA, joint.bodyB == kWorldAnchor ? poseA : poseOf(bodies[joint.bodyB]));
    return {f.pA, f.pB};
}

JointError measureJoint(const Joint& joint, std::span<const DynamicObject> bodies) {
    const DynamicObject& a = bodies[joint.bodyA];
    const DynamicObject* b = joint.bodyB == kWorldAnchor ? nullptr : &bodies[joint.bodyB];
    const JointFrame f = frameAt(joint, poseOf(a), b ? poseOf(*b) : poseOf(a));
    const Quat orientationB = b ? b->orientation : Quat(1, 0, 0, 0);  // the world's axis is fixed
    const Vec3 axisB = orientationB * joint.localAxisB;
    const Real relativeSpeed = glm::dot(a.angularVelocity - (b ? b->angularVelocity : Vec3(0)), axisB);
    const Real distance = glm::length(f.pB - f.pA);
    JointError error;
    switch (joint.kind) {
        case JointKind::Distance: error.distance = distance - joint.length; break;
        case JointKind::Rope: error.distance = std::max(distance - joint.length, Real(0)); break;
        case JointKind::Ball: error.distance = distance; break;
        case JointKind::Hinge: {
            error.distance = distance;
            const Vec3 axisA = a.orientation * joint.localAxisA;
            error.angle = std::acos(std::clamp(glm::dot(axisA, axisB), Real(-1), Real(1)));
            const Real angle = hingeAngle(joint, a.orientation, orientationB);
            if (joint.hasLowerLimit) error.angle += std::max(joint.lowerAngle - angle, Real(0));
            if (joint.hasUpperLimit) error.angle += std::max(angle - joint.upperAngle, Real(0));
            if (joint.motor) error.speed = relativeSpeed;
            break;
        }
        case JointKind::AngularMotor: error.speed = relativeSpeed; break;
    }
    return error;
}

}  // namespace stepwise
