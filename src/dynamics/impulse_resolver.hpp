/// @file impulse_resolver.hpp
/// @brief Stages 6 and 7 of the step: collision response by impulses, then position correction.
#pragma once

#include <span>
#include <vector>

#include "collision/contact.hpp"
#include "dynamics/contact_body.hpp"
#include "objects/body_set.hpp"

namespace stepwise {

/// @brief Restitution of a pair of materials by the default rule: the product e = e_A · e_B.
///
/// With the product, an object of elasticity 1 (the default for planes and
/// kinematic objects) lets the other object's value decide, which is how
/// the classic assignment format (elasticity on dynamic objects only) reads.
/// Bullet combines restitution the same way. `World, ElasticityCombine=…`
/// picks another rule (src/objects/materials.hpp).
inline Real combineElasticity(Real a, Real b) { return a * b; }

/// @brief Friction of a pair of materials by the default rule: the product μ = μ_A · μ_B (same reasoning).
inline Real combineFriction(Real a, Real b) { return a * b; }

/// @brief The part of @p shape that Contact::partA or partB names when it has a `Material` of its
/// own; nullptr for a body that is no compound, or a part that takes the body's.
inline const CompoundPart* partWithMaterial(const CompoundShape* shape, std::uint16_t part) {
    if (shape == nullptr || part >= shape->parts.size()) return nullptr;
    const CompoundPart& p = shape->parts[part];
    return p.material != kNoMaterial ? &p : nullptr;
}

/// @brief μ and e of @p contact between body @p a and the other side @p other, decided once per
/// contact when it is prepared (by both solvers, so the fast path reads the same μ and e).
///
/// Each side is the surface that touches: the body's, or, where a compound's part with a
/// `Material` of its own touches, that part's (a rubber tyre on a steel wheel). A scene without
/// materials, or whose rules are both Product, takes the products above and looks up nothing;
/// otherwise the World's rules or a MaterialPair decide (ContactMaterials::mix()).
inline ContactCoefficients contactCoefficients(const BodySet& bodies, const Contact& contact, const DynamicObject& a,
                                               ContactBody other) {
    std::uint32_t materialA = a.material;
    Real frictionA = a.friction;
    Real elasticityA = a.elasticity;
    if (const CompoundPart* part = partWithMaterial(a.compound.get(), contact.partA)) {
        materialA = part->material;
        frictionA = part->friction;
        elasticityA = part->elasticity;
    }
    const CompoundShape* shapeB = contact.b.kind == BodyKind::Dynamic     ? bodies.dynamics[contact.b.index].compound.get()
                                  : contact.b.kind == BodyKind::Kinematic ? bodies.kinematics[contact.b.index].compound.get()
                                                                          : nullptr;
    if (const CompoundPart* part = partWithMaterial(shapeB, contact.partB)) {
        other.material = part->material;
        other.friction = part->friction;
        other.elasticity = part->elasticity;
    }
    if (bodies.materials == nullptr || bodies.materials->plain()) {
        return {combineFriction(frictionA, other.friction), combineElasticity(elasticityA, other.elasticity)};
    }
    return bodies.materials->mix(materialA, frictionA, elasticityA, other.material, other.friction, other.elasticity);
}

/// Passes of the position correction over all contacts. Like the impulse
/// passes, they let several contacts on one body (a box's corners) agree.
inline constexpr int kPositionPasses = 4;

/// Contacts approaching slower than the speed a step's acceleration builds in
/// this many steps do not bounce: that speed is gravity pulling a resting
/// body into its support during one step, not an impact. Without it a
/// resting ball with e > 0 hops forever. The acceleration is the largest of
/// the contact's relative one, |a_n|, and each body's own along the normal,
/// |a_A·n| and |a_B·n|: two boxes of a stack fall alike (a_n = 0), yet the
/// solver's passes leave them approaching by about g·h, and that must not
/// count as an impact either; a wall's horizontal normal sees no gravity, so
/// a ball rolling slowly into it still bounces.
inline constexpr Real kRestingContactSteps = Real(2);

/// @brief What happened at one contact, for tests, traces and debuggers.
struct ImpulseReport {
    Real approachSpeed = 0;       ///< −v_n before the impulses, m/s (> 0 when approaching).
    Real approachAtTouch = 0;     ///< Approach speed reconstructed at the moment of touching, m/s.
    Real restitution = 0;         ///< e used (0 for a resting contact).
    Real normalImpulse = 0;       ///< Total normal impulse j over all passes, N·s (≥ 0).
    Real frictionImpulse = 0;     ///< Magnitude of the total friction impulse, N·s (≤ μ·j).
    Real normalMass = 0;          ///< Effective mass along the normal, 1/(J M⁻¹ Jᵀ), kg (foundation solver).
    bool resting = false;         ///< Support, not impact: no bounce (foundation solver).
    bool normalClamped = false;   ///< A pass wanted a pulling total (j < 0) and was held at j = 0 (foundation solver).
    bool frictionClamped = false; ///< The friction total reached Coulomb's bound μ·j: sliding (foundation solver).
};

/// @brief One contact prepared for the impulse passes: geometry, effective
/// masses and the impulses accumulated so far. Filled by resolveImpulses;
/// kept in a reusable array so a step allocates nothing.
struct ContactConstraint {
    DynamicObject* a = nullptr;    ///< Body A (always dynamic).
    DynamicObject* b = nullptr;    ///< Body B when dynamic, else nullptr.
    Vec3 staticVelocity{0, 0, 0};  ///< Velocity of B's surface at the contact when B is kinematic or a plane (with a belt's, conveyor.hpp), m/s.
    Mat3 inverseInertiaA{1};       ///< A's world inverse inertia (fixed during the passes), 1/(kg·m²).
    Mat3 inverseInertiaB{0};       ///< B's, or zero.
    Real inverseMassA = 0;         ///< A's 1/m, 1/kg.
    Real inverseMassB = 0;         ///< B's 1/m, or zero.
    Vec3 rA{0, 0, 0};              ///< From A's centre to the contact point, m.
    Vec3 rB{0, 0, 0};              ///< From B's centre to the contact point, m (zero for static B).
    Vec3 normal{0, 1, 0};          ///< From A towards B.
    Vec3 tangent[2];               ///< Two unit vectors across the normal, for friction.
    Real normalMass = 0;           ///< 1 / (effective inverse mass along n), kg.
    Real tangentMass[2] = {0, 0};  ///< Along each tangent: one mass for both, frictionPairMass(), kg.
    Real targetSeparation = 0;     ///< e·v_c: the normal speed the passes aim for, m/s.
    bool resting = false;          ///< Support, not impact: v_c below kRestingContactSteps·h·max(|a_n|, |a_A·n|, |a_B·n|).
    bool speculative = false;      ///< The surfaces are still a gap apart (Contact::depth < −kTouchTolerance).
    bool active = true;            ///< False for a speculative point approached fast: it waits for the impact.
    Real friction = 0;             ///< μ of the pair.
    Real normalImpulse = 0;        ///< Accumulated j, N·s.
    Real tangentImpulse[2] = {0, 0}; ///< Accumulated friction impulse along each tangent, N·s.
    bool normalClamped = false;    ///< Some pass clamped the accumulated j at 0 (for ImpulseReport).
    bool frictionClamped = false;  ///< Some pass scaled the friction back to μ·j (for ImpulseReport).
};

/// @brief Names one contact point from step to step: body A, body B and the
/// features that touch (the pair test's feature id). Two steps' contacts with
/// the same key are the same contact, so last step's impulse is a good guess.
struct ContactKey {
    std::uint32_t a = 0;        ///< Index of dynamic body A.
    std::uint32_t b = 0;        ///< Body B: its kind in the top two bits, its index below.
    std::uint32_t feature = 0;  ///< Feature id from the narrowphase.
    /// @brief Keys order lexicographically (a, b, feature), so a sorted array can be searched.
    auto operator<=>(const ContactKey&) const = default;
};

/// @brief A contact point's accumulated impulses at the end of a step, kept for warm starting the next.
struct CachedImpulse {
    ContactKey key;              ///< Which contact point.
    Real normalImpulse = 0;      ///< Its total normal impulse j, N·s.
    Vec3 frictionImpulse{0, 0, 0}; ///< Its total friction impulse as a world vector, N·s (tangent axes change between steps).
};

/// @brief Two unit vectors t₁, t₂ that complete the unit normal @p n to a right-handed orthonormal basis (n, t₁, t₂).
void tangentBasis(const Vec3& n, Vec3 (&t)[2]);

/// @brief The one effective mass both friction rows of a contact point share, kg:
/// 2 / (K₁₁ + K₂₂), from the inverse masses @p inverseMass0, @p inverseMass1 along t₁ and t₂.
///
/// The two tangent rows are solved together and clamped to Coulomb's circle. With a
/// mass of its own on each row, a pass sets the friction impulse to P − diag(m₁, m₂)·u
/// for the sliding velocity u, and at a sliding point the clamped impulse then points
/// along −diag(m₁, m₂)·u instead of −u: not against the sliding, and turned by how the
/// tangents happen to lie. A box's contact point has different inverse masses along
/// the two tangents (its lever arms turn it differently), so a box sliding down an
/// incline whose slope lay between t₁ and t₂ slid up to 7 % too fast and drifted
/// sideways. One mass for both, from the trace of K's tangent block (the same in
/// every basis of the tangent plane), makes each increment −m·u: against the sliding,
/// in any basis. A sticking point still converges: a pass multiplies its error by
/// I − m·K_t, whose eigenvalues 1 − λᵢ/λ̄ (λ̄ the mean of K_t's two) lie in (−1, 1).
/// A ball's two inverse masses are equal, and this is then exactly 1/K₁₁.
inline Real frictionPairMass(Real inverseMass0, Real inverseMass1) { return Real(2) / (inverseMass0 + inverseMass1); }

/// @brief The warm-start key of @p contact: body A, body B (kind in the top two bits, index below), feature id.
ContactKey keyOf(const Contact& contact);

/// @brief The entry of @p cache (sorted by key) for @p key, or nullptr when that point is new this step.
const CachedImpulse* findCachedImpulse(const std::vector<CachedImpulse>& cache, const ContactKey& key);

/// @brief The same search for contacts looked up in (mostly) ascending key order,
/// the narrowphase's order: @p next is where the last lookup ended (0 before the first).
///
/// Each contact found again is usually the entry right after the last one
/// found, so that entry is compared first, and a search is needed only for a
/// new contact or one out of order (then from @p next on when the key lies
/// ahead, among the few entries just behind @p next when it lies there, as
/// another point of the same pair does, and over the whole cache otherwise). Finds exactly what the plain
/// search finds, in O(1) instead of O(log n) for most contacts.
const CachedImpulse* findCachedImpulse(const std::vector<CachedImpulse>& cache, const ContactKey& key,
                                       std::size_t& next);

/// @brief Scratch arrays of stages 6 and 7, owned by the World and reused every step.
struct ContactWorkspace {
    std::vector<CachedImpulse> previousImpulses; ///< Last step's impulses, sorted by key (warm starting).
    std::vector<CachedImpulse> currentImpulses;  ///< This step's, becoming the next step's previous.
    std::vector<ContactConstraint> constraints;  ///< One per contact, rebuilt each step.
    std::vector<Vec3> supportVelocityChange;     ///< Per dynamic body: Δv from its resting contacts, m/s.
    std::vector<Vec3> shift;                     ///< Per dynamic body: stage 7's displacement, m.
    std::vector<Vec3> turn;                      ///< Per dynamic body: stage 7's rotation vector, rad.
};

/// @brief Applies normal impulses with restitution and Coulomb friction impulses at every contact point.
///
/// **One contact.** For contact normal n (from A to B), lever arms r_A and
/// r_B from the centres of mass to the contact point, the relative velocity
/// of the two surfaces there is
/// \f[ v_\text{rel} = (v_B + \omega_B \times r_B) - (v_A + \omega_A \times r_A), \qquad v_n = v_\text{rel}\cdot n \f]
/// (v_n < 0: approaching). An impulse j·n at the point (−j·n on A) changes
/// v_n by j/m_eff, where the *effective mass* along n includes turning:
/// \f[ \frac{1}{m_\text{eff}} = m_A^{-1} + m_B^{-1}
///      + (r_A\times n)\cdot I_A^{-1}(r_A\times n) + (r_B\times n)\cdot I_B^{-1}(r_B\times n). \f]
/// A push through the centre (r × n = 0) only moves; off centre, part of it
/// turns the body instead, so the body "feels lighter". The impulse that
/// makes the bodies separate at speed e·v_c is
/// \f[ j = m_\text{eff}\,(e\,v_c - v_n), \f]
/// applied as Δv = ±j·n/m and ΔL = ±r × j·n (momentum is conserved). With
/// v_c = −v_n and no turning this is the textbook j = −(1+e)·v_n/(m_A⁻¹+m_B⁻¹).
///
/// **Why v_c and not −v_n.** The contact is found only after the step has
/// carried the bodies a depth d into each other. Under their relative normal
/// acceleration a_n = (a_B − a_A)·n the approach speed grew over that
/// distance, v_n² = v_c² − 2·a_n·d, so the speed at the moment of touching is
/// \f[ v_c = \sqrt{\max(0,\; v_n^2 + 2\,a_n\,d)}. \f]
/// Bouncing with the end-of-step speed instead, and then pushing the body
/// back to the surface, adds m·g·d of energy per bounce: the well-known
/// "ball that bounces higher than it fell". With v_c, a ball of restitution
/// e dropped from height h peaks at e²ⁿ·h after n bounces at any time step.
/// Below kRestingContactSteps·h·max(|a_n|, |a_A·n|, |a_B·n|) the contact is resting: e = 0.
///
/// **Friction** acts on the tangential part of v_rel *after* the normal
/// impulse (the normal impulse sets its bound): the impulse that would stop
/// the sliding, with effective masses along two tangents t₁, t₂, clamped to
/// Coulomb's cone |j_t| ≤ μ·j.
///
/// **Many contacts.** A box on a plane has four contacts on one body, and
/// an impulse at one corner changes the velocity at the others. The stage
/// therefore makes `settings.impulseIterations` passes over all contacts,
/// each pass correcting what is left, and *accumulates* each contact's
/// impulses: a pass may reduce an earlier impulse, but the total j stays
/// ≥ 0 (contacts push, never pull) and the total friction stays inside
/// μ·j. This is Catto's sequential impulses (GDC 2006).
///
/// **Warm starting.** A stack's contacts carry nearly the same impulses
/// every step, and a few passes from zero cannot rebuild them: the weight of
/// twenty boxes has to travel down the stack one pass per box. With
/// @p warmStart, each contact found again (same ContactKey as last step)
/// starts from last step's impulses, applied before the first pass; the
/// passes then only correct the change. This is what lets a tall stack stand.
///
/// After the passes, the velocity change each body received from its
/// touching *resting* contacts is recorded in the workspace for stage 7.
///
/// References: Catto, "Fast and Simple Physics using Sequential Impulses",
/// GDC 2006; Millington, *Game Physics Engine Development*, ch. 14;
/// Mirtich, *Impulse-based Dynamic Simulation of Rigid Body Systems* (1996).
/// @param bodies      the world's objects (dynamic velocities change)
/// @param contacts    this step's contacts
/// @param h           time step, s (sets the resting-contact speed)
/// @param iterations  passes over the contacts, ≥ 1
/// @param warmStart   start each contact found again from last step's impulses
/// @param workspace   scratch arrays, reused between steps
/// @param reports     optional, one report per contact (size must match), may be empty
/// @param beltVelocities each dynamic body's conveyor belt u, m/s (conveyorVelocities(), src/forces/conveyor.hpp):
///                    a contact with a static or kinematic surface adds u's part in its tangent plane to the
///                    surface's velocity, after the bounce is decided; empty: no belt in the scene
void resolveImpulses(const BodySet& bodies, std::span<const Contact> contacts, Real h, int iterations,
                     bool warmStart, ContactWorkspace& workspace, std::span<ImpulseReport> reports = {},
                     std::span<const Vec3> beltVelocities = {});

/// @brief Stage 7: moves supported bodies as their integrator would have, then pushes overlapping bodies apart.
///
/// **Support.** A resting contact stands for a continuous support force. Over
/// the step it changed the body's velocity by Δv, which the integrator, had
/// it been a force, would have turned into a displacement s·h·Δv (s from
/// positionShareOfVelocityChange: 0, 1 or ½). Applying it here undoes
/// exactly the sag *and* the slide that gravity's
/// drift put into this step's integration: a ball at rest does not sink, a box
/// on a slope with enough friction does not creep, and every box of a stack
/// is held up by its own support in the same step (position correction alone
/// would have to pass the sag down the stack one box per step). One limit: a
/// force can cancel at most what the acceleration a added in the step, so
/// the part of Δv that opposes a is capped at |a|·h; beyond that it is the
/// last of an impact (a ball ending its bouncing), which the overlap removal
/// handles and which would otherwise lift the ball clear of the floor.
/// Impacts are left out: a bounce is instantaneous. The support's *turn* is
/// not applied: a resting body's support impulses balance, and turning it by
/// the small imbalance the passes leave makes a stack rock.
///
/// **Overlap.** What remains is removed by non-linear Gauss–Seidel on
/// positions (Catto; Box2D's position solver), without Baumgarte's fraction.
/// A point of a body at lever arm r moves by Δx + Δθ × r when the body is
/// shifted by Δx and turned by the small rotation Δθ, so a contact's remaining
/// overlap is
/// \f[ d_\text{now} = d - \big((\Delta x_B + \Delta\theta_B\times r_B)
///                           - (\Delta x_A + \Delta\theta_A\times r_A)\big)\cdot n, \f]
/// and the position impulse λ = d_now·m_eff (the effective mass of the
/// velocity impulses, with its r×n terms) shifts and turns both bodies just
/// enough to close it: Δx = ±λn/m, Δθ = ±I⁻¹(r × λn). kPositionPasses passes let
/// the contacts of one body agree. Turning matters: a tilted box is turned
/// flat rather than lifted bodily by its deepest corner, which would raise its
/// centre of mass and feed it energy. Only positions and orientations change;
/// no velocity is added, so the correction puts no energy into the motion.
/// @param bodies     the world's objects (dynamic positions and orientations change)
/// @param contacts   this step's contacts
/// @param h          time step, s (bounds what a support force can do in a step)
/// @param supportStep s·h: the integrator's share of the step, s
/// @param workspace  the arrays stage 6 filled (support changes) and scratch
void correctPositions(const BodySet& bodies, std::span<const Contact> contacts, Real h, Real supportStep,
                      ContactWorkspace& workspace);

}  // namespace stepwise
