/// @file prepare_contacts.cpp
/// @brief Stage 4 of the soft step: each contact becomes a constraint, once per step (the maths is in contact_solver.hpp).
#include "dynamics/contact_solver.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel_ranges.hpp"
#include "dynamics/contact_body.hpp"
#include "dynamics/contact_colours.hpp"
#include "dynamics/contact_rows.hpp"
#include "forces/conveyor.hpp"
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

/// Index of the fixed pose at the origin (the last one): a plane's "centre".
std::uint32_t planePose(const BodySet& bodies) {
    return static_cast<std::uint32_t>(bodies.dynamics.size() + bodies.kinematics.size());
}

/// A turning anchor split in two: the part the body's turn carries, and the rest, which stays fixed.
struct RoundedAnchor {
    Vec3 turning;  ///< From the body's centre to the anchor point that turns with it, m.
    Vec3 rest;     ///< From that point to the contact point, m; only its part along n is used.
};

/// For a capsule, the point of its axis segment nearest the contact turns with the body and the
/// radius is the fixed rest (the capsule is a segment grown by r: its surface under a contact is
/// always r from the axis); for any other shape the whole lever @p lever (centre to contact) turns.
template <class Body>
RoundedAnchor roundedAnchor(const Body& body, const Vec3& lever) {
    if (body.shape != Shape::Capsule) return {lever, Vec3(0)};
    const Vec3 axis = body.orientation * Vec3(0, 1, 0);
    const Real halfHeight = Real(0.5) * body.height;
    const Vec3 core = std::clamp(glm::dot(lever, axis), -halfHeight, halfHeight) * axis;
    return {core, lever - core};
}

/// The contact's pass record (returned) and its start record @p start; its stored rows and turning
/// anchors, if it has them, go to @p out, and the record holds their indices there. @p beltVelocities
/// are the dynamic bodies' conveyor belts (prepareContacts()), empty in a scene without one.
SolverContact prepareOne(const BodySet& bodies, const Contact& contact, Real h, const SolverWorkspace& w,
                         std::span<const Vec3> beltVelocities, ContactStart& start, PreparedSideArrays& out) {
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
            start.rB = contact.point - k.position;
            // A kinematic body at rest neither moves nor turns this step: its anchor stays where the
            // contact found it, a fixed point, exactly as a plane's does. So it is measured as a
            // plane's is, from the fixed pose at the origin, and the contact is round if A is a ball.
            if (!k.atRest()) {
                c.poseB = static_cast<std::uint32_t>(bodies.dynamics.size() + contact.b.index);
                centreB = k.position;
                orientationB = &k.orientation;
                turnsB = k.shape != Shape::Sphere;
            }
        }
    }
    const Vec3 offsetB = contact.point - centreB;
    if (other.dynamic != nullptr) start.rB = offsetB;
    c.separationOffset = start.startSeparation + (turnsB ? Real(0) : glm::dot(offsetB, c.normal)) -
                         (turnsA ? Real(0) : glm::dot(rA, c.normal));
    if (turnsA || turnsB) {
        // A turning anchor is a point of the body, carried by its turn through the substeps. A
        // capsule's is the point of its axis under the contact, with the rest of the way to the
        // contact, along n, kept fixed (roundedAnchor()): a capsule rolling about its axis keeps
        // the point under it touching, as a ball does, instead of lifting its surface point by
        // r·(1 − cos ωh) in a step.
        const RoundedAnchor anchorA = turnsA ? roundedAnchor(a, rA) : RoundedAnchor{rA, Vec3(0)};
        const RoundedAnchor anchorB =
            turnsB && other.dynamic != nullptr ? roundedAnchor(*other.dynamic, offsetB)
            : turnsB && contact.b.kind == BodyKind::Kinematic ? roundedAnchor(bodies.kinematics[contact.b.index], offsetB)
                                                              : RoundedAnchor{offsetB, Vec3(0)};
        c.separationOffset += glm::dot(anchorB.rest, c.normal) - glm::dot(anchorA.rest, c.normal);
        TurningAnchors anchors;
        if (turnsA) anchors.localA = glm::conjugate(a.orientation) * anchorA.turning;
        if (turnsB) anchors.localB = glm::conjugate(*orientationB) * anchorB.turning;
        c.turningAnchors = static_cast<std::uint32_t>(out.turningAnchors.size());
        out.turningAnchors.push_back(anchors);
    }

    const SolverBody& bodyA = w.bodies[c.bodyA];
    const SolverBody& bodyB = w.bodies[c.bodyB];
    tangentBasis(c.normal, c.tangent);
    // J's angular parts and K, once per step: r, d and I⁻¹ are fixed through it (solver_body.hpp).
    // A ball on a ball, a plane or a kinematic body at rest (no anchor turns, no surface moves):
    // levers along n, rows computed by the pass. A surface under a conveyor belt moves: stored rows.
    const Vec3* belt = beltUnder(beltVelocities, contact.a, other.dynamic != nullptr);
    const bool surfaceMovesB =
        belt != nullptr || (contact.b.kind == BodyKind::Kinematic && !bodies.kinematics[contact.b.index].atRest());
    if (!turnsA && !turnsB && !surfaceMovesB) {
        // The levers from the local vectors: read back from `start`, a 16-byte load of a vector
        // just written as 8-byte stores waits for them (the processor cannot forward it).
        c.leverA = glm::dot(rA, c.normal);
        c.leverB = other.dynamic != nullptr ? glm::dot(offsetB, c.normal) : Real(0);  // a static B has no lever
        c.normalMass = Real(1) / (bodyA.inverseMass + bodyB.inverseMass);
        c.tangentMass[0] = c.tangentMass[1] = Real(1) / roundTangentInverseMass(bodyA, bodyB, c.leverA, c.leverB);
    } else {
        const SolverBodyInertia& inertiaA = w.inertias[c.bodyA];
        const SolverBodyInertia& inertiaB = w.inertias[c.bodyB];
        ContactRows rows;
        rows.normal = makeContactRow(inertiaA, inertiaB, start.rA, start.rB, c.normal);
        c.normalMass = Real(1) / inverseEffectiveMass(bodyA, bodyB, rows.normal);
        rows.normalSurfaceSpeed = glm::dot(start.staticVelocity, c.normal);
        // Friction's target: the surface's velocity in the tangent plane, a belt's included (conveyor.hpp).
        // The belt has no part along n, so the normal row and the bounce never see it.
        Vec3 tangentialSurface = start.staticVelocity;
        if (belt != nullptr) tangentialSurface += conveyorSurfaceVelocity(*belt, c.normal);
        Real tangentInverseMass[2];
        for (int k = 0; k < 2; ++k) {
            rows.tangent[k] = makeContactRow(inertiaA, inertiaB, start.rA, start.rB, c.tangent[k]);
            tangentInverseMass[k] = inverseEffectiveMass(bodyA, bodyB, rows.tangent[k]);
            rows.tangentSurfaceSpeed[k] = glm::dot(tangentialSurface, c.tangent[k]);
        }
        // One mass for the pair, or a sliding box's friction is not against its sliding (frictionPairMass())
        c.tangentMass[0] = c.tangentMass[1] = frictionPairMass(tangentInverseMass[0], tangentInverseMass[1]);
        c.rows = static_cast<std::uint32_t>(out.rows.size());
        out.rows.push_back(rows);
    }
    // μ and e of the pair, once per contact: the World's combine rules (products by default), or a
    // MaterialPair's. The fast path reads them from here too.
    const ContactCoefficients material = contactCoefficients(bodies, contact, a, other);
    c.friction = material.friction;

    // The bounce, decided before any impulse (contact_solver.hpp): the
    // approach speed when the surfaces meet, v_c² = v_n² + 2·a·C, with a the
    // approach acceleration −(a_B − a_A)·n.
    const Real vn = withRows(c, out.rows, [&](const auto& rows) { return rows.normalVelocity(bodyA, bodyB); });
    const Real approachAcceleration = -glm::dot(other.acceleration - a.acceleration, c.normal);
    if (vn < 0) {
        start.approachAtTouch =
            std::sqrt(std::max(Real(0), vn * vn + Real(2) * approachAcceleration * start.startSeparation));
    }
    const Real stepAcceleration = std::max({std::abs(approachAcceleration), std::abs(glm::dot(a.acceleration, c.normal)),
                                            std::abs(glm::dot(other.acceleration, c.normal))});
    const bool resting = start.approachAtTouch <= kRestingContactSteps * stepAcceleration * h;
    start.elasticity = material.elasticity;
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

}  // namespace

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
                     bool warmStart, SolverWorkspace& workspace, ThreadPool* pool, std::span<const Vec3> beltVelocities) {
    SolverWorkspace& w = workspace;
    w.dynamics = bodies.dynamics;
    makeBodyRecords(bodies, contacts, links, w);  // last step's records are dropped
    w.contacts.resize(contacts.size());
    w.starts.resize(contacts.size());

    // 1. Each contact on its own numbers: in ranges of contacts, on the pool's threads when there
    //    are enough (core/parallel_ranges.hpp). A range keeps its stored rows and turning anchors
    //    in side arrays of its own.
    const std::size_t count = contacts.size();
    const RangeSplit split = splitRanges(pool, 0, count, kParallelPrepareContacts);
    w.preparedRanges.resize(std::max(split.count, w.preparedRanges.size()));
    runRanges(pool, split, [&](std::size_t r, std::size_t first, std::size_t last) {
        PreparedSideArrays& out = w.preparedRanges[r];
        out.rows.clear();
        out.turningAnchors.clear();
        std::size_t nextCached = 0;  // the contacts come in key order, mostly: each lookup starts where the last ended
        for (std::size_t i = first; i < last; ++i) {
            SolverContact& c = w.contacts[i];
            c = prepareOne(bodies, contacts[i], h, w, beltVelocities, w.starts[i], out);
            if (!warmStart) continue;
            if (const CachedImpulse* cached = findCachedImpulse(w.previousImpulses, keyOf(contacts[i]), nextCached)) {
                c.normalImpulse = cached->normalImpulse;
                // Tangent axes are rebuilt each step: the friction is carried as a world vector.
                for (int k = 0; k < 2; ++k) c.tangentImpulse[k] = glm::dot(cached->frictionImpulse, c.tangent[k]);
            }
        }
    });

    // 2. The side arrays joined in range order, so every index is the one a single range gives.
    if (split.count == 1) {
        std::swap(w.rows, w.preparedRanges[0].rows);
        std::swap(w.turningAnchors, w.preparedRanges[0].turningAnchors);
    } else {
        w.rows.clear();
        w.turningAnchors.clear();
        for (std::size_t r = 0; r < split.count; ++r) {
            const auto rowsFrom = static_cast<std::uint32_t>(w.rows.size());
            const auto anchorsFrom = static_cast<std::uint32_t>(w.turningAnchors.size());
            const PreparedSideArrays& part = w.preparedRanges[r];
            w.rows.insert(w.rows.end(), part.rows.begin(), part.rows.end());
            w.turningAnchors.insert(w.turningAnchors.end(), part.turningAnchors.begin(), part.turningAnchors.end());
            for (std::size_t i = split.first(r); i < split.last(r); ++i) {
                SolverContact& c = w.contacts[i];
                if (c.rows != kRoundContact) c.rows += rowsFrom;
                if (c.turningAnchors != kNoTurningAnchors) c.turningAnchors += anchorsFrom;
            }
        }
    }

    // 3. The pass lists, and the impacts
    w.roundContacts.clear();
    w.otherContacts.clear();
    w.bouncing.clear();
    for (std::uint32_t i = 0; i < count; ++i) {
        (w.contacts[i].rows == kRoundContact ? w.roundContacts : w.otherContacts).push_back(i);
        if (w.starts[i].touchVelocity < Real(0)) w.bouncing.push_back(i);
    }

    // 4. The order of the passes (contact_colours.hpp)
    if (w.colourOrder) {
        orderByColour(w, w.roundContacts, w.colouring.roundColourEnds);
        orderByColour(w, w.otherContacts, w.colouring.otherColourEnds);
    } else {
        w.colouring.roundColourEnds.clear();
        w.colouring.otherColourEnds.clear();
    }
}

}  // namespace stepwise
