/// @file trace_writer.cpp
/// @brief The lines of `stepwise trace`, one function per stage (see trace_writer.hpp and docs/trace.md).
#include "io/trace_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

#include "forces/conveyor.hpp"
#include "world/world.hpp"
#include "world/object_name.hpp"
#include "world/spaces.hpp"

namespace stepwise {

namespace {

/// Longest formatted number: sign, 15 integer digits, point, kMaxTraceDigits decimals.
constexpr std::size_t kNumberBuffer = 48;

std::string validStageNames() {
    std::string names;
    for (std::size_t i = 0; i < kStageCount; ++i) {
        if (i > 0) names += ", ";
        names += stageName(static_cast<Stage>(i));
    }
    return names;
}


/// Velocity of B's material point at @p point, m/s: v + ω × (p − x); a plane does not move.
Vec3 pointVelocity(const World& world, const BodyRef& ref, const Vec3& point) {
    switch (ref.kind) {
        case BodyKind::Dynamic: {
            const DynamicObject& b = world.dynamics()[ref.index];
            return b.velocity + glm::cross(b.angularVelocity, point - b.position);
        }
        case BodyKind::Kinematic: {
            const KinematicsObject& b = world.kinematics()[ref.index];
            return b.velocity + glm::cross(b.angularVelocity, point - b.position);
        }
        case BodyKind::Plane: break;
    }
    return Vec3(0);
}

/// The first fields of every contact's line: `contact I  feature F`. I is the contact's index in the
/// step's list (World::contacts(), in the narrowphase's order; the solver's records and the impulse
/// reports share it, so it is the index gdb shows in `contacts_[I]` and `workspace.contacts[I]`). F is
/// its feature id, which names the features of A and B that touch. A box on a box has up to four
/// contacts between the same two bodies: the index tells their lines apart, and the feature id
/// follows one corner from step to step (it is the warm-start key).
std::string contactFields(const World& world, std::size_t index) {
    std::string fields = "contact " + std::to_string(index);
    if (index < world.contacts().size()) fields += "  feature " + std::to_string(world.contacts()[index].featureId);
    return fields + "  ";
}

/// Which bound held the impulses of a contact: "no", "j>=0" (a pass would have pulled), "cone" (sliding).
const char* clampText(const ImpulseReport& r) {
    if (r.normalClamped && r.frictionClamped) return "j>=0,cone";
    if (r.normalClamped) return "j>=0";
    return r.frictionClamped ? "cone" : "no";
}

}  // namespace

Stage stageFromName(const std::string& name) {
    for (std::size_t i = 0; i < kStageCount; ++i) {
        if (name == stageName(static_cast<Stage>(i))) return static_cast<Stage>(i);
    }
    throw std::invalid_argument("unknown stage '" + name + "' (stages: " + validStageNames() + ")");
}

void checkTraceObjects(const TraceOptions& options, const Scene& scene) {
    for (const std::string& name : options.objects) {
        const auto named = [&](const auto& objects) {
            return std::any_of(objects.begin(), objects.end(), [&](const auto& o) { return o.name == name; });
        };
        if (named(scene.dynamics) || named(scene.kinematics) || named(scene.planes) || named(scene.softBodies)) continue;
        bool joint = false;
        for (const JointDef& j : scene.joints) joint = joint || j.name == name;
        if (joint) continue;
        std::string known;
        const auto list = [&](const auto& objects) {
            for (const auto& o : objects) known += (known.empty() ? "" : ", ") + o.name;
        };
        list(scene.dynamics);
        list(scene.kinematics);
        list(scene.planes);
        list(scene.softBodies);
        throw std::invalid_argument("--object: the scene has no object named '" + name + "' (objects: " +
                                    (known.empty() ? std::string("none") : known) + ")");
    }
}

TraceObserver::TraceObserver(std::ostream& out, TraceOptions options) : out_(out), options_(std::move(options)) {}

bool TraceObserver::selected(const StageEvent& event) const {
    if (event.step < options_.from || event.step - options_.from >= options_.steps) return false;
    if (event.substep > 0 && !options_.allSubsteps) return false;
    return options_.stages.empty() ||
           std::find(options_.stages.begin(), options_.stages.end(), event.stage) != options_.stages.end();
}

bool TraceObserver::objectSelected(const std::string& name) const {
    return options_.objects.empty() || std::find(options_.objects.begin(), options_.objects.end(), name) !=
                                           options_.objects.end();
}

std::string TraceObserver::num(Real value) const {
    char text[kNumberBuffer];
    // Rounding may print -0.0000 for a tiny negative value; print it as 0 so
    // that the bytes do not depend on the sign of round-off.
    const double rounded = std::abs(double(value)) < 0.5 * std::pow(10.0, -options_.digits) ? 0.0 : double(value);
    std::snprintf(text, sizeof text, "%.*f", options_.digits, rounded);
    return text;
}

std::string TraceObserver::vec(const Vec3& value) const {
    return "(" + num(value.x) + ", " + num(value.y) + ", " + num(value.z) + ")";
}

std::string TraceObserver::quat(const Quat& value) const {
    return "(" + num(value.w) + ", " + num(value.x) + ", " + num(value.y) + ", " + num(value.z) + ")";
}

void TraceObserver::line(const std::string& head, const std::string& object, const std::string& fields) {
    out_ << head << "  " << object << "  " << fields << '\n';
}

void TraceObserver::beforeStage(const StageEvent& event, const World& world) {
    if (!selected(event)) return;
    const auto& bodies = world.dynamics();
    positionBefore_.resize(bodies.size());
    velocityBefore_.resize(bodies.size());
    angularBefore_.resize(bodies.size());
    asleepBefore_.resize(bodies.size());
    orientationBefore_.resize(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        positionBefore_[i] = bodies[i].position;
        velocityBefore_[i] = bodies[i].velocity;
        angularBefore_[i] = bodies[i].angularVelocity;
        asleepBefore_[i] = bodies[i].asleep;
        orientationBefore_[i] = bodies[i].orientation;
    }
    kinematicBefore_.resize(world.kinematics().size());
    for (std::size_t i = 0; i < world.kinematics().size(); ++i) kinematicBefore_[i] = world.kinematics()[i].position;
    jointBrokenBefore_.resize(world.joints().size());
    for (std::size_t i = 0; i < world.joints().size(); ++i) jointBrokenBefore_[i] = world.joints()[i].broken;
    softAsleepBefore_.resize(world.softBodies().size());
    for (std::size_t i = 0; i < world.softBodies().size(); ++i) softAsleepBefore_[i] = world.softBodies()[i].asleep;
}

void TraceObserver::afterStage(const StageEvent& event, const World& world) {
    if (!selected(event)) return;
    if (headedStep_ != event.step) {
        headedStep_ = event.step;
        out_ << "step " << event.step << "  t " << num(event.stepStartTime) << " s -> "
             << num(event.stepStartTime + event.timeStep) << " s  h " << num(event.timeStep) << " s\n";
    }
    writeStage(event, world);
}

void TraceObserver::writeStage(const StageEvent& event, const World& world) {
    std::string head = "step " + std::to_string(event.step);
    if (event.substep >= 0) head += " [" + std::to_string(event.substep + 1) + "/" + std::to_string(event.substeps) + "]";
    head += "  ";
    head += stageName(event.stage);
    switch (event.stage) {
        case Stage::ApplyForces: writeForces(head, world); break;
        case Stage::Integrate: writeMotion(head, world); break;
        case Stage::MoveKinematics: writeKinematics(head, world); break;
        case Stage::Broadphase: writePairs(head, world); break;
        case Stage::Narrowphase: writeContacts(head, world); break;
        case Stage::ResolveImpulses:
            writeImpulses(head, world);
            writeVelocityChanges(head, world);
            break;
        case Stage::CorrectPositions: writeCorrections(head, world); break;
        case Stage::PrepareConstraints: writePreparedConstraints(head, world); break;
        case Stage::SolveConstraints:
        case Stage::RelaxConstraints:
            writeSolve(head, world);
            writeJoints(head, world);
            break;
        case Stage::Restitution:
            writeRestitution(head, world);
            writeVelocityChanges(head, world);
            break;
        case Stage::Sleep: writeSleep(head, world); break;
        case Stage::Continuous:
            line(head, "fast bodies", "stopped at their time of impact: " + std::to_string(world.bodiesStoppedAtImpact()));
            break;
        case Stage::SoftBodies: writeSoftBodies(head, world); break;
        case Stage::Count: break;
    }
}

/// The total acceleration each awake body got, and the force F = m·a it stands for (derived).
void TraceObserver::writeForces(const std::string& head, const World& world) {
    const auto& bodies = world.dynamics();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const DynamicObject& b = bodies[i];
        if (b.asleep || !objectSelected(b.name)) continue;
        std::string fields = "F " + vec(b.mass * b.acceleration) + " N  a " + vec(b.acceleration) + " m/s^2";
        if (b.torque != Vec3(0)) fields += "  torque " + vec(b.torque) + " N*m";
        // The regions that acted on it: known once they have looked for their bodies, after the broadphase
        std::string inside;
        for (std::size_t r = 0; r < world.regions().size(); ++r) {
            const std::span<const std::uint32_t> held = world.regionMembers().of(r);
            if (!std::binary_search(held.begin(), held.end(), static_cast<std::uint32_t>(i))) continue;
            inside += (inside.empty() ? "" : ",") + world.regions()[r].name + "(" + toString(world.regions()[r].effect) + ")";
        }
        if (!inside.empty()) fields += "  regions " + inside;
        line(head, b.name, fields);
    }
}

/// Position and velocity before and after the stage; angular velocity when the body turns.
void TraceObserver::writeMotion(const std::string& head, const World& world) {
    const auto& bodies = world.dynamics();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const DynamicObject& b = bodies[i];
        if (b.asleep || !objectSelected(b.name)) continue;
        std::string fields = "x " + vec(positionBefore_[i]) + " m -> " + vec(b.position) + " m  v " +
                             vec(velocityBefore_[i]) + " m/s -> " + vec(b.velocity) + " m/s";
        if (angularBefore_[i] != Vec3(0) || b.angularVelocity != Vec3(0)) {
            fields += "  w " + vec(angularBefore_[i]) + " rad/s -> " + vec(b.angularVelocity) + " rad/s  q " +
                      quat(orientationBefore_[i]) + " -> " + quat(b.orientation);
        }
        line(head, b.name, fields);
    }
}

/// Velocity and angular velocity of each body whose velocity the stage changed, before → after.
void TraceObserver::writeVelocityChanges(const std::string& head, const World& world) {
    const auto& bodies = world.dynamics();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const DynamicObject& b = bodies[i];
        if ((b.velocity == velocityBefore_[i] && b.angularVelocity == angularBefore_[i]) || !objectSelected(b.name)) {
            continue;
        }
        line(head, b.name,
             "v " + vec(velocityBefore_[i]) + " m/s -> " + vec(b.velocity) + " m/s  w " + vec(angularBefore_[i]) +
                 " rad/s -> " + vec(b.angularVelocity) + " rad/s");
    }
}

void TraceObserver::writeKinematics(const std::string& head, const World& world) {
    const auto& bodies = world.kinematics();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const KinematicsObject& b = bodies[i];
        if (!objectSelected(b.name)) continue;
        line(head, b.name, "x " + vec(kinematicBefore_[i]) + " m -> " + vec(b.position) + " m  v " + vec(b.velocity) +
                               " m/s  w " + vec(b.angularVelocity) + " rad/s");
    }
}

void TraceObserver::writePairs(const std::string& head, const World& world) {
    line(head, "all", "pairs " + std::to_string(world.candidatePairs().size()));
    for (const CandidatePair& pair : world.candidatePairs()) {
        const std::string& a = world.dynamics()[pair.a].name;
        const std::string& b = objectName(world, pair.b);
        if (objectSelected(a) || objectSelected(b)) line(head, a + "|" + b, "candidate");
    }
}

void TraceObserver::writeContacts(const std::string& head, const World& world) {
    line(head, "all", "contacts " + std::to_string(world.contacts().size()));
    for (std::size_t i = 0; i < world.contacts().size(); ++i) {
        const Contact& c = world.contacts()[i];
        const std::string& a = world.dynamics()[c.a].name;
        const std::string& b = objectName(world, c.b);
        if (!objectSelected(a) && !objectSelected(b)) continue;
        line(head, a + "|" + b,
             contactFields(world, i) + "point " + vec(c.point) + " m  normal " + vec(c.normal) + "  depth " +
                 num(c.depth) + " m");
    }
}

/// Per contact: effective mass, the approach, the restitution decision, the
/// impulses and whether a bound held them; v_n before → after is derived
/// from the bodies' velocities at the contact point.
void TraceObserver::writeImpulses(const std::string& head, const World& world) {
    const auto& contacts = world.contacts();
    const auto& reports = world.impulses();
    for (std::size_t i = 0; i < contacts.size() && i < reports.size(); ++i) {
        const Contact& c = contacts[i];
        const ImpulseReport& r = reports[i];
        const std::string& a = world.dynamics()[c.a].name;
        const std::string& b = objectName(world, c.b);
        if (!objectSelected(a) && !objectSelected(b)) continue;
        const Vec3 rA = c.point - positionBefore_[c.a];
        const Vec3 vA0 = velocityBefore_[c.a] + glm::cross(angularBefore_[c.a], rA);
        Vec3 vB0 = pointVelocity(world, c.b, c.point);
        if (c.b.kind == BodyKind::Dynamic) {
            vB0 = velocityBefore_[c.b.index] + glm::cross(angularBefore_[c.b.index], c.point - positionBefore_[c.b.index]);
        }
        const DynamicObject& bodyA = world.dynamics()[c.a];
        const Vec3 vA1 = bodyA.velocity + glm::cross(bodyA.angularVelocity, c.point - bodyA.position);
        const Real vn0 = glm::dot(vB0 - vA0, c.normal);
        const Real vn1 = glm::dot(pointVelocity(world, c.b, c.point) - vA1, c.normal);
        line(head, a + "|" + b,
             contactFields(world, i) + "m_eff " + num(r.normalMass) + " kg  v_n " + num(vn0) + " m/s -> " + num(vn1) + " m/s  v_c " +
                 num(r.approachAtTouch) + " m/s  e " + num(r.restitution) + (r.resting ? " (resting)" : " (impact)") +
                 "  j " + num(r.normalImpulse) + " N*s  j_t " + num(r.frictionImpulse) + " N*s  clamped " +
                 clampText(r));
    }
}

void TraceObserver::writeCorrections(const std::string& head, const World& world) {
    const auto& bodies = world.dynamics();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const DynamicObject& b = bodies[i];
        if (b.position == positionBefore_[i] || !objectSelected(b.name)) continue;
        line(head, b.name,
             "x " + vec(positionBefore_[i]) + " m -> " + vec(b.position) + " m  moved " +
                 num(glm::length(b.position - positionBefore_[i])) + " m");
    }
}

/// The sequential-impulse constraints as prepared: effective mass, the gap C₀,
/// the approach at touch v_c, e, and the warm-start impulse.
void TraceObserver::writePreparedConstraints(const std::string& head, const World& world) {
    const auto& bodies = world.dynamics();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (asleepBefore_[i] && !bodies[i].asleep && objectSelected(bodies[i].name)) {
            line(head, bodies[i].name, "wakes (an awake body touches or is jointed to its island)");
        }
    }
    for (std::size_t i = 0; i < world.solverContacts().size(); ++i) {
        const SolverContact& c = world.solverContacts()[i];
        const ContactStart& start = world.solverContactStarts()[i];
        const std::string& a = bodies[start.indexA].name;
        const std::string& b = objectName(world, start.refB);
        if (!objectSelected(a) && !objectSelected(b)) continue;
        std::string belt;  // a conveyor's surface velocity, friction's target (src/forces/conveyor.hpp)
        if (const Vec3* u = beltUnder(world.beltVelocities(), start.indexA, start.refB.kind == BodyKind::Dynamic)) {
            belt = "  belt v_s " + vec(conveyorSurfaceVelocity(*u, c.normal)) + " m/s";
        }
        line(head, a + "|" + b,
             contactFields(world, i) + "m_eff " + num(c.normalMass) + " kg  C0 " + num(start.startSeparation) + " m  v_c " +
                 num(start.approachAtTouch) + " m/s  e " + num(start.restitution) + "  warm j " +
                 num(c.normalImpulse) + " N*s" + belt);
    }
    // SubstepsPerIsland=true: each island's count and the rule's inputs (src/dynamics/substep_rule.hpp)
    for (const IslandSubsteps& island : world.islandSubsteps()) {
        const std::string& first = bodies[island.firstBody].name;
        if (!objectSelected(first)) continue;
        line(head, "island " + first,
             std::to_string(island.bodies) + " bodies  " + std::to_string(island.contacts) + " contacts  height " +
                 std::to_string(island.height) +
                 (island.joints > 0 ? "  joints " + std::to_string(island.joints) : std::string()) +
                 "  mass ratio " + num(island.massRatio) + "  speed " +
                 num(island.speed) + " m/s  -> " + std::to_string(island.count) + " substeps (" +
                 substepReasonName(island.reason) + ")");
    }
}

/// Per constraint: accumulated impulses and v_n (derived) after the pass; per body: velocity before → after.
namespace {

/// Velocity of B's material point at the contact, m/s: a dynamic B's v + ω × r_B,
/// else the kinematic surface velocity the solver recorded (zero for a plane).
Vec3 surfaceVelocityOfB(const World& world, const ContactStart& start) {
    if (start.refB.kind != BodyKind::Dynamic) return start.staticVelocity;
    const DynamicObject& b = world.dynamics()[start.refB.index];
    return b.velocity + glm::cross(b.angularVelocity, start.rB);
}

/// v_n of a constraint now: B's material point minus A's along the normal, m/s (< 0: approaching).
Real normalVelocityNow(const World& world, const SolverContact& c, const ContactStart& start) {
    const DynamicObject& bodyA = world.dynamics()[start.indexA];
    const Vec3 vA = bodyA.velocity + glm::cross(bodyA.angularVelocity, start.rA);
    return glm::dot(surfaceVelocityOfB(world, start) - vA, c.normal);
}

}  // namespace

void TraceObserver::writeSolve(const std::string& head, const World& world) {
    const auto& bodies = world.dynamics();
    for (std::size_t i = 0; i < world.solverContacts().size(); ++i) {
        const SolverContact& c = world.solverContacts()[i];
        const ContactStart& start = world.solverContactStarts()[i];
        const std::string& a = bodies[start.indexA].name;
        const std::string& b = objectName(world, start.refB);
        if (!objectSelected(a) && !objectSelected(b)) continue;
        line(head, a + "|" + b,
             contactFields(world, i) + "j " + num(c.normalImpulse) + " N*s  j_t " + num(std::hypot(c.tangentImpulse[0], c.tangentImpulse[1])) +
                 " N*s  j_max " + num(c.maxNormalImpulse) + " N*s  v_n " + num(normalVelocityNow(world, c, start)) + " m/s");
    }
    writeMotion(head, world);
}

/// Each joint's error after the pass (how far it is from its constraint), m, rad and rad/s.
void TraceObserver::writeJoints(const std::string& head, const World& world) {
    for (const Joint& joint : world.joints()) {
        if (joint.broken || !objectSelected(joint.name)) continue;
        const JointError e = measureJoint(joint, world.dynamics());
        line(head, "joint:" + joint.name,
             "error " + num(e.distance) + " m  angle " + num(e.angle) + " rad  speed " + num(e.speed) + " rad/s");
    }
}

/// The bounce decision per contact, the impulse of the whole step, and joints that broke.
void TraceObserver::writeRestitution(const std::string& head, const World& world) {
    const auto& bodies = world.dynamics();
    for (std::size_t i = 0; i < world.solverContacts().size(); ++i) {
        const SolverContact& c = world.solverContacts()[i];
        const ContactStart& start = world.solverContactStarts()[i];
        const std::string& a = bodies[start.indexA].name;
        const std::string& b = objectName(world, start.refB);
        if (!objectSelected(a) && !objectSelected(b)) continue;
        const char* decision = c.maxNormalImpulse <= 0                     ? "no (never pushed)"
                               : start.compression <= 0                     ? "no (no compression)"
                               : start.elasticity <= 0                      ? "no (e = 0)"
                                                                            : "yes";
        line(head, a + "|" + b,
             contactFields(world, i) + "v_c " + num(start.approachAtTouch) + " m/s  e " + num(start.elasticity) +
                 "  compression P " + num(start.compression) + " N*s  bounce " + decision + "  e*P " +
                 num(start.elasticity * start.compression) + " N*s  j " +
                 num(c.normalImpulse) + " N*s  j_max " + num(c.maxNormalImpulse) + " N*s  v_n " + num(normalVelocityNow(world, c, start)) + " m/s");
    }
    for (std::size_t i = 0; i < world.joints().size(); ++i) {
        const Joint& joint = world.joints()[i];
        if (!joint.broken || jointBrokenBefore_[i] || !objectSelected(joint.name)) continue;
        line(head, "joint:" + joint.name,
             "breaks  force " + num(joint.brokenForce) + " N > MaxForce " + num(joint.maxForce) + " N");
    }
}

/// The pressure stage: each awake soft body's gas after this substep of it (src/soft/); an asleep one
/// is not moved, and is left out as an asleep rigid body is from the integrate stage. A soft body
/// that an awake object could reach, or a rigid body that a soft body's nodes touched, wakes here.
void TraceObserver::writeSoftBodies(const std::string& head, const World& world) {
    for (std::size_t i = 0; i < world.softBodies().size(); ++i) {
        const SoftBody& b = world.softBodies()[i];
        if (b.asleep || !objectSelected(b.name)) continue;
        if (softAsleepBefore_[i]) line(head, b.name, "wakes (an awake object may reach it, or its island woke)");
        line(head, b.name, "V " + num(b.volume) + " m^3  P = nRT/V " + num(b.pressure) + " Pa  centre " +
                               vec(b.position) + " m  v " + vec(b.velocity) + " m/s");
    }
    const auto& bodies = world.dynamics();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (asleepBefore_[i] && !bodies[i].asleep && objectSelected(bodies[i].name)) {
            line(head, bodies[i].name, "wakes (a soft body's nodes touched its island)");
        }
    }
}

/// Per body: asleep or awake after the stage, and why.
void TraceObserver::writeSleep(const std::string& head, const World& world) {
    const WorldSettings& s = world.settings();
    const auto& bodies = world.dynamics();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const DynamicObject& b = bodies[i];
        if (!objectSelected(b.name)) continue;
        std::string fields;
        if (b.asleep) {
            fields = asleepBefore_[i] ? "asleep" : "falls asleep (its island was still for " + num(s.timeToSleep) + " s)";
        } else {
            const Real speed = glm::length(b.velocity);
            const Real spin = glm::length(b.angularVelocity);
            const IslandWorkspace& islands = world.islands();
            const bool measured = i < islands.linearAcceleration.size();
            fields = "awake  island " + std::to_string(islandOf(islands, std::uint32_t(i))) + "  still " +
                     num(b.stillTime) + " s of " + num(s.timeToSleep) + " s  |v| " + num(speed) + " m/s (still when < " +
                     num(s.sleepLinearSpeed) + " m/s)  |w| " + num(spin) + " rad/s (still when < " +
                     num(s.sleepAngularSpeed) + " rad/s)";
            if (measured) {
                fields += "  |dv|/h " + num(islands.linearAcceleration[i]) + " m/s^2 (still when < " +
                          num(s.sleepLinearAcceleration) + ")  |dw|/h " + num(islands.angularAcceleration[i]) +
                          " rad/s^2 (still when < " + num(s.sleepAngularAcceleration) + ")";
            }
        }
        line(head, b.name, fields);
    }
    // A soft body is still when every node is slow: its fastest node's speed (islands.hpp)
    const IslandWorkspace& islands = world.islands();
    for (std::size_t k = 0; k < world.softBodies().size(); ++k) {
        const SoftBody& b = world.softBodies()[k];
        if (!objectSelected(b.name)) continue;
        if (b.asleep) {
            line(head, b.name, softAsleepBefore_[k] ? "asleep"
                                                    : "falls asleep (its island was still for " + num(s.timeToSleep) + " s)");
            continue;
        }
        std::string fields = "awake  island " + std::to_string(islandOf(islands, std::uint32_t(bodies.size() + k))) +
                             "  still " + num(b.stillTime) + " s of " + num(s.timeToSleep) + " s";
        if (k < islands.softNodeSpeed.size()) {
            fields += "  fastest node |v| " + num(islands.softNodeSpeed[k]) + " m/s (still when < " +
                      num(s.sleepLinearSpeed) + " m/s)";
        }
        if (b.carried) fields += "  carried by a moving kinematic body";
        line(head, b.name, fields);
    }
}

namespace {

/// Steps @p world up to the last selected step with a TraceObserver on it; false when stopped early.
bool traceWorld(World& world, const TraceOptions& options, std::ostream& out, const std::function<bool()>& stopNow) {
    TraceObserver observer(out, options);
    world.setObserver(&observer);
    const std::uint64_t last = options.from - 1 + options.steps;
    bool finished = true;
    while (world.stepCount() < last) {
        if (stopNow && stopNow()) {
            finished = false;
            break;
        }
        world.step();
    }
    world.setObserver(nullptr);
    return finished;
}

}  // namespace

bool writeTrace(const Scene& scene, const TraceOptions& options, std::ostream& out,
                const std::function<bool()>& stopNow) {
    checkTraceObjects(options, scene);
    if (scene.spaces.empty()) {
        World world(scene);
        return traceWorld(world, options, out, stopNow);
    }
    // Spaces never touch (src/world/spaces.hpp): each is traced alone, in the order of `stepwise run`,
    // its own steps counted from 1, under a line that names it.
    for (auto& [space, part] : splitIntoSpaces(scene)) {
        out << "=== Space " << space.name << "\n";
        World world(std::move(part));
        if (!traceWorld(world, options, out, stopNow)) return false;
    }
    return true;
}

}  // namespace stepwise
