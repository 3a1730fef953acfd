/// @file impulse_resolver.cpp
/// @brief Stages 6 and 7: impulses at contact points, then position correction
/// (the derivations are in impulse_resolver.hpp).
#include "dynamics/impulse_resolver.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/contact_body.hpp"
#include "objects/inertia.hpp"
#include "dynamics/point_impulse.hpp"
#include "forces/conveyor.hpp"
#include "integrators/integrators.hpp"

namespace stepwise {

namespace {

/// |n·x| above this means x is too close to n to build a tangent from.
constexpr Real kAlmostParallel = Real(0.57735);  // 1/√3: some axis always has |n_i| ≤ 1/√3

}  // namespace

void tangentBasis(const Vec3& n, Vec3 (&t)[2]) {
    const Vec3 helper = std::abs(n.x) < kAlmostParallel ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    t[0] = glm::normalize(glm::cross(n, helper));
    t[1] = glm::cross(n, t[0]);
}

ContactKey keyOf(const Contact& contact) {
    constexpr unsigned kKindShift = 30;  // two bits of kind above a 30-bit index
    return {contact.a, (static_cast<std::uint32_t>(contact.b.kind) << kKindShift) | contact.b.index, contact.featureId};
}

namespace {

/// How far behind the last match a lookup first searches: more than the points of one pair's
/// manifold (at most 8, a box's face clipped against a face).
constexpr std::size_t kCacheLookBack = 16;

}  // namespace

const CachedImpulse* findCachedImpulse(const std::vector<CachedImpulse>& cache, const ContactKey& key,
                                       std::size_t& next) {
    if (next < cache.size() && cache[next].key == key) return &cache[next++];
    const bool ahead = next < cache.size() && cache[next].key < key;
    // A key just behind: a point of the same pair, whose feature ids need not ascend (a box's
    // manifold). Its entry lies within a manifold's few points before `next`.
    const std::size_t back = next > kCacheLookBack ? next - kCacheLookBack : 0;
    const bool justBehind = !ahead && back < cache.size() && cache[back].key <= key;
    // Not ahead: the key sorts before cache[next] (or next is past the end), so its entry, if any, does too.
    const auto from = ahead ? cache.begin() + static_cast<std::ptrdiff_t>(next)
                      : justBehind ? cache.begin() + static_cast<std::ptrdiff_t>(back)
                                   : cache.begin();
    const auto to = ahead ? cache.end() : cache.begin() + static_cast<std::ptrdiff_t>(std::min(next, cache.size()));
    const auto found = std::lower_bound(from, to, key,
                                        [](const CachedImpulse& entry, const ContactKey& k) { return entry.key < k; });
    if (found == to || found->key != key) return nullptr;
    next = static_cast<std::size_t>(found - cache.begin()) + 1;
    return &*found;
}

const CachedImpulse* findCachedImpulse(const std::vector<CachedImpulse>& cache, const ContactKey& key) {
    std::size_t start = 0;  // from the first entry: a search of the whole cache
    return findCachedImpulse(cache, key, start);
}

namespace {

/// Sets up one contact: lever arms, effective masses, and the bounce it aims for.
ContactConstraint prepare(const BodySet& bodies, const Contact& contact, Real h, ImpulseReport& report) {
    ContactConstraint c;
    DynamicObject& a = bodies.dynamics[contact.a];
    const ContactBody other = contactBody(bodies, contact.b, contact.point);
    c.a = &a;
    c.b = other.dynamic;
    c.staticVelocity = other.velocity;
    c.inverseMassA = a.inverseMass;
    c.inverseInertiaA = worldInverseInertia(a.orientation, a.inverseInertiaBody);
    c.rA = contact.point - a.position;
    if (c.b) {
        c.inverseMassB = c.b->inverseMass;
        c.inverseInertiaB = worldInverseInertia(c.b->orientation, c.b->inverseInertiaBody);
        c.rB = contact.point - c.b->position;
    } else {
        c.inverseInertiaB = Mat3(0);
    }
    c.normal = contact.normal;
    tangentBasis(c.normal, c.tangent);
    c.normalMass = Real(1) / inverseEffectiveMass(c, c.normal);
    c.tangentMass[0] = c.tangentMass[1] =
        frictionPairMass(inverseEffectiveMass(c, c.tangent[0]), inverseEffectiveMass(c, c.tangent[1]));
    // μ and e of the pair: the World's combine rules (products by default), or a MaterialPair's.
    const ContactCoefficients material = contactCoefficients(bodies, contact, a, other);
    c.friction = material.friction;

    // The bounce is decided once, from the velocities before any impulse:
    // restitution is a property of the impact, not of the passes.
    const Real vn = glm::dot(relativeVelocity(c), c.normal);
    const Real an = glm::dot(other.acceleration - a.acceleration, c.normal);
    const Real depth = std::max(contact.depth, Real(0));
    const Real approachAtTouch = vn < 0 ? std::sqrt(std::max(Real(0), vn * vn + Real(2) * an * depth)) : Real(0);
    // The speed a step's acceleration builds along the normal: the contact's
    // relative one (a_n), or, for two bodies falling alike onto each other (a
    // stack, where a_n = 0), what either feels along n. A wall's horizontal
    // normal sees no gravity, so a slow ball rolling into it still bounces.
    const Real stepAcceleration = std::max({std::abs(an), std::abs(glm::dot(a.acceleration, c.normal)),
                                            std::abs(glm::dot(other.acceleration, c.normal))});
    c.resting = approachAtTouch <= kRestingContactSteps * stepAcceleration * h;
    const Real e = c.resting ? Real(0) : material.elasticity;
    c.targetSeparation = e * approachAtTouch;
    if (contact.depth < -kTouchTolerance) {  // closer than that is touching, as in the narrowphase
        // A speculative point, still a gap g apart: a slow approach may close
        // it within the step (v_n ≥ −g/h) but not go further; a fast one is
        // left alone until the surfaces meet, so its bounce is computed then.
        c.targetSeparation = contact.depth / h;
        c.speculative = true;
        c.active = c.resting;
    }
    report = {std::max(-vn, Real(0)), approachAtTouch, e, 0, 0, c.normalMass, c.resting};
    return c;
}

/// One pass at one contact: the normal impulse, then friction within the new bound.
void solve(ContactConstraint& c) {
    if (!c.active) return;
    // Normal: drive v_n to the target separation speed, keep the total j ≥ 0.
    const Real vn = glm::dot(relativeVelocity(c), c.normal);
    const Real previous = c.normalImpulse;
    const Real wanted = previous + c.normalMass * (c.targetSeparation - vn);
    c.normalClamped = c.normalClamped || wanted < 0;  // reported only: a trace shows where j = 0 held
    c.normalImpulse = std::max(wanted, Real(0));
    applyImpulse(c, (c.normalImpulse - previous) * c.normal);

    // Friction: recompute the relative velocity, because the normal impulse
    // just changed it; friction acts on what is left sliding, and its total
    // may not leave Coulomb's cone |j_t| ≤ μ·j.
    const Vec3 relative = relativeVelocity(c);
    const Real limit = c.friction * c.normalImpulse;
    Real total[2];
    for (int k = 0; k < 2; ++k) {
        total[k] = c.tangentImpulse[k] - c.tangentMass[k] * glm::dot(relative, c.tangent[k]);
    }
    const Real magnitude = std::sqrt(total[0] * total[0] + total[1] * total[1]);
    if (magnitude > limit) {  // sliding: kinetic friction at the full μ·j, along the sliding direction
        const Real scale = magnitude > 0 ? limit / magnitude : Real(0);
        c.frictionClamped = true;
        total[0] *= scale;
        total[1] *= scale;
    }
    const Vec3 change = (total[0] - c.tangentImpulse[0]) * c.tangent[0] + (total[1] - c.tangentImpulse[1]) * c.tangent[1];
    c.tangentImpulse[0] = total[0];
    c.tangentImpulse[1] = total[1];
    applyImpulse(c, change);
}

/// Applies last step's impulses of the same contact point, if it had one.
void warmStartFromCache(ContactConstraint& c, const ContactKey& key, const std::vector<CachedImpulse>& cache) {
    const CachedImpulse* found = findCachedImpulse(cache, key);
    if (found == nullptr || !c.active) return;
    c.normalImpulse = found->normalImpulse;
    // The tangent axes are rebuilt each step; carry the friction over as a world vector.
    for (int k = 0; k < 2; ++k) c.tangentImpulse[k] = glm::dot(found->frictionImpulse, c.tangent[k]);
    applyImpulse(c, c.normalImpulse * c.normal + c.tangentImpulse[0] * c.tangent[0] + c.tangentImpulse[1] * c.tangent[1]);
}

/// Keeps this step's impulses, sorted by key, for the next step's warm start.
void rememberImpulses(std::span<const Contact> contacts, const std::vector<ContactConstraint>& constraints,
                      ContactWorkspace& workspace) {
    workspace.currentImpulses.clear();
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const ContactConstraint& c = constraints[i];
        workspace.currentImpulses.push_back(
            {keyOf(contacts[i]), c.normalImpulse, c.tangentImpulse[0] * c.tangent[0] + c.tangentImpulse[1] * c.tangent[1]});
    }
    std::sort(workspace.currentImpulses.begin(), workspace.currentImpulses.end(),
              [](const CachedImpulse& x, const CachedImpulse& y) { return x.key < y.key; });
    std::swap(workspace.previousImpulses, workspace.currentImpulses);
}

}  // namespace

void resolveImpulses(const BodySet& bodies, std::span<const Contact> contacts, Real h, int iterations,
                     bool warmStart, ContactWorkspace& workspace, std::span<ImpulseReport> reports,
                     std::span<const Vec3> beltVelocities) {
    std::vector<ContactConstraint>& constraints = workspace.constraints;
    constraints.resize(contacts.size());
    ImpulseReport unused;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        constraints[i] = prepare(bodies, contacts[i], h, reports.empty() ? unused : reports[i]);
        // A conveyor belt under A moves B's surface along itself (src/forces/conveyor.hpp): the friction of
        // the passes compares against it. It lies in the tangent plane, so v_n changes by rounding only,
        // and the bounce, decided in prepare(), not at all.
        if (const Vec3* belt = beltUnder(beltVelocities, contacts[i].a, constraints[i].b != nullptr)) {
            constraints[i].staticVelocity += conveyorSurfaceVelocity(*belt, constraints[i].normal);
        }
    }
    // Warm start after every contact is prepared: the bounce targets were
    // taken from the velocities before any impulse.
    if (warmStart) {
        for (std::size_t i = 0; i < contacts.size(); ++i) warmStartFromCache(constraints[i], keyOf(contacts[i]), workspace.previousImpulses);
    }
    for (int pass = 0; pass < iterations; ++pass) {
        for (ContactConstraint& c : constraints) solve(c);
    }
    rememberImpulses(contacts, constraints, workspace);
    // Angular momentum was updated alongside ω; refresh ω from L once so the
    // two stay exactly consistent (ω = I⁻¹L) for the next stage.
    for (ContactConstraint& c : constraints) {
        updateAngularVelocity(*c.a);
        if (c.b) updateAngularVelocity(*c.b);
    }

    // What the resting contacts did to each body, for stage 7: the velocity
    // change Δv = ±P/m of their impulses P.
    const std::size_t bodyCount = bodies.dynamics.size();
    workspace.supportVelocityChange.assign(bodyCount, Vec3(0));
    for (std::size_t i = 0; i < constraints.size(); ++i) {
        const ContactConstraint& c = constraints[i];
        if (!c.resting || c.speculative) continue;  // only touching supports held the body during the step
        const Vec3 P = c.normalImpulse * c.normal + c.tangentImpulse[0] * c.tangent[0] + c.tangentImpulse[1] * c.tangent[1];
        workspace.supportVelocityChange[contacts[i].a] -= P * c.a->inverseMass;
        if (c.b) {
            workspace.supportVelocityChange[contacts[i].b.index] += P * c.inverseMassB;
        }
    }
    if (!reports.empty()) {
        for (std::size_t i = 0; i < contacts.size(); ++i) {
            const ContactConstraint& c = constraints[i];
            reports[i].normalImpulse = c.normalImpulse;
            reports[i].frictionImpulse = std::hypot(c.tangentImpulse[0], c.tangentImpulse[1]);
            reports[i].normalClamped = c.normalClamped;
            reports[i].frictionClamped = c.frictionClamped;
        }
    }
}

namespace {

/// The part of a resting body's velocity change that a support *force* can
/// account for: against the body's acceleration a, at most what a added in
/// this step, |a|·h. Anything beyond is the last of an impact (a ball that
/// ends its bouncing arrives a little faster than gravity's one-step kick),
/// whose position the overlap removal handles; moving by it would lift the
/// body clear of its support.
Vec3 supportedVelocityChange(const Vec3& dv, const Vec3& acceleration, Real h) {
    const Real a = glm::length(acceleration);
    if (a == Real(0)) return Vec3(0);  // weightless: there is no sag to undo, only impacts
    const Vec3 down = acceleration / a;
    const Real against = -glm::dot(dv, down);  // how much dv opposes the acceleration, m/s
    const Real excess = against - a * h;
    return excess > 0 ? dv + excess * down : dv;
}

}  // namespace

void correctPositions(const BodySet& bodies, std::span<const Contact> contacts, Real h, Real supportStep,
                      ContactWorkspace& workspace) {
    // Every body's correction is gathered as a displacement Δx and a small
    // rotation Δθ (a rotation vector, rad), applied once at the end. Stage 6
    // left, per contact, the lever arms, inverse inertias and normal mass of
    // this very configuration: the passes below reuse them.
    const std::size_t bodyCount = bodies.dynamics.size();
    std::vector<Vec3>& shift = workspace.shift;
    std::vector<Vec3>& turn = workspace.turn;
    shift.assign(bodyCount, Vec3(0));
    turn.assign(bodyCount, Vec3(0));

    // Support: the displacement the integrator would have given the support force.
    if (workspace.supportVelocityChange.size() == bodyCount) {
        for (std::size_t i = 0; i < bodyCount; ++i) {
            shift[i] = supportStep * supportedVelocityChange(workspace.supportVelocityChange[i],
                                                             bodies.dynamics[i].acceleration, h);
        }
    }

    // Overlap: whatever the support did not already remove, by non-linear
    // Gauss–Seidel on positions. A material point at lever arm r moves by
    // Δx + Δθ × r, so a contact's remaining overlap is
    //   d_now = d − ((Δx_B + Δθ_B × r_B) − (Δx_A + Δθ_A × r_A))·n,
    // and the "position impulse" λ = d_now·m_eff along n (the same effective
    // mass as the velocity impulses) moves and turns both bodies just enough
    // to close it. A tilted box is thereby turned flat, not lifted bodily by
    // its deepest corner, which would raise its centre of mass and feed it
    // energy. Several passes let the contacts of one body agree.
    const std::vector<ContactConstraint>& constraints = workspace.constraints;
    for (int pass = 0; pass < kPositionPasses; ++pass) {
        for (std::size_t i = 0; i < contacts.size(); ++i) {
            const Contact& contact = contacts[i];
            const ContactConstraint& c = constraints[i];
            if (!c.active) continue;
            const bool dynamicB = contact.b.kind == BodyKind::Dynamic;
            const std::uint32_t a = contact.a;
            const std::uint32_t b = contact.b.index;
            const Vec3 movedA = shift[a] + glm::cross(turn[a], c.rA);
            const Vec3 movedB = dynamicB ? shift[b] + glm::cross(turn[b], c.rB) : Vec3(0);
            const Real remaining = contact.depth - glm::dot(movedB - movedA, contact.normal);
            if (remaining <= Real(0)) continue;

            const Vec3 P = (remaining * c.normalMass) * contact.normal;
            shift[a] -= P * bodies.dynamics[a].inverseMass;
            turn[a] -= c.inverseInertiaA * glm::cross(c.rA, P);
            if (dynamicB) {
                shift[b] += P * c.inverseMassB;
                turn[b] += c.inverseInertiaB * glm::cross(c.rB, P);
            }
        }
    }

    for (std::size_t i = 0; i < bodyCount; ++i) {
        DynamicObject& body = bodies.dynamics[i];
        body.position += shift[i];
        if (turn[i] != Vec3(0)) {
            body.orientation = rotateByAngularVelocity(body.orientation, turn[i], Real(1));
            updateAngularVelocity(body);  // I_world turned with the body: ω = I_world⁻¹·L
        }
    }
}

}  // namespace stepwise
