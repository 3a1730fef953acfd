/// @file free_rotation.cpp
/// @brief The torque-free tumble of a rigid body over one step: the splitting every integrator shares.
///
/// ## What is being solved
/// With no torque, the world-frame angular momentum L is constant and the
/// body turns with ω = I_world⁻¹·L = R·I_body⁻¹·Rᵀ·L. Because ω depends on
/// the orientation R, it changes as the body turns (that is the tumble, and
/// the Dzhanibekov flip): in the body frame, with Π = Rᵀ·L the body
/// components of L, Euler's equations read
/// \f[ \dot\Pi = \Pi \times \omega_\text{body}, \qquad \omega_\text{body} = I^{-1}\,\Pi . \f]
/// There is no closed form a student would want to code (it needs Jacobi
/// elliptic functions), and a naive step ("turn by ω·h") neither keeps the
/// kinetic energy nor the motion's character.
///
/// ## The splitting (McLachlan 1993; Dullweber, Leimkuhler & McLachlan 1997)
/// The energy of the free body is a sum of three terms, one per principal axis,
/// \f[ H = \frac{\Pi_1^2}{2 I_1} + \frac{\Pi_2^2}{2 I_2} + \frac{\Pi_3^2}{2 I_3}
///       = H_1 + H_2 + H_3 , \f]
/// and each term alone is a motion we *can* solve exactly: under H_i alone the
/// body spins about its own body axis e_i at the constant rate ω_i = Π_i/I_i
/// (Π_i does not change, because a rotation about e_i leaves the e_i component
/// of anything fixed). So the sub-flow "H_i for time Δt" is
/// \f[ q \leftarrow q \cdot \mathrm{angleAxis}\!\left(\frac{\Pi_i}{I_i}\,\Delta t,\; e_i\right), \f]
/// multiplied on the **right** because e_i is a body-frame axis. L in the
/// world never changes: the sub-flow turns the body, and with it Π = Rᵀ·L,
/// which is why Π is recomputed before each sub-flow.
///
/// Composing the sub-flows symmetrically (Strang splitting),
///
///     axis 1 for h/2 → axis 2 for h/2 → axis 3 for h → axis 2 for h/2 → axis 1 for h/2
///
/// gives a method that is
/// - **second order** (the error of the symmetric composition is O(h³) per step,
///   O(h²) over a fixed time: the odd error terms cancel by symmetry);
/// - **exactly |L|-conserving**: L is never touched, only the orientation;
/// - **Poisson (symplectic)**: each sub-flow is an exact Hamiltonian flow, and a
///   composition of such flows is again one. Consequence: the energy is not
///   exactly conserved (each sub-flow keeps its own H_i, not the sum) but its
///   error stays bounded, O(h²), for all time: no drift;
/// - **time-reversible**: running it with −h undoes a step.
///
/// The order of the sub-flows is one table, kSplitting below: change it and
/// see (lectures/04-inertia-and-rotation.md, exercises). Three sub-flows of
/// h each in sequence (Lie–Trotter splitting) is only first order.
///
/// A body whose three moments are equal (a sphere, a cube) has ω = L/I
/// constant: its exact motion is one rotation by |ω|·h about ω, and that is
/// what it gets (the sub-flows would approximate it with an O(h³) error).
///
/// A *symmetric top*, two moments equal (I₁ = I₂ = I⊥ about a symmetry
/// axis e₃ with moment I₃: a cylinder, a capsule, a square rod), has a
/// closed form too. Split ω = I⁻¹Π in the body frame as
/// \f[ \omega = \frac{\Pi}{I_\perp} + \Big(\frac{1}{I_3} - \frac{1}{I_\perp}\Big)\Pi_3\, e_3 : \f]
/// in the world the first part is L/I⊥, fixed, and the second turns with
/// the body about its own e₃, where Π₃ = e₃·Π does not change (a turn about
/// e₃ leaves it, and so does one about L). So the motion is a turn about L
/// by |L|·h/I⊥ on the left and a turn about e₃ by (1/I₃ − 1/I⊥)·Π₃·h on the
/// right,
/// \f[ q(h) = \mathrm{angleAxis}\big(|L| h / I_\perp,\ \hat L\big)\; q\;
///           \mathrm{angleAxis}\big((1/I_3 - 1/I_\perp)\,\Pi_3\, h,\ e_3\big) , \f]
/// exact for any h (the classic steady precession of the axis about L at
/// the rate |L|/I⊥; Goldstein, *Classical Mechanics*, §5.6; Landau &
/// Lifshitz, *Mechanics*, §33), with two turns where the splitting takes five.
///
/// References: R. I. McLachlan, "Explicit Lie–Poisson integration and the
/// Euler equations", Phys. Rev. Lett. 71 (1993) 3043; A. Dullweber,
/// B. Leimkuhler & R. McLachlan, "Symplectic splitting methods for rigid body
/// molecular dynamics", J. Chem. Phys. 107 (1997) 5840; Hairer, Lubich &
/// Wanner, *Geometric Numerical Integration*, §VII.5.
#include <algorithm>
#include <array>
#include <cmath>

#include "integrators/integrators.hpp"

namespace stepwise {

namespace {

/// One exactly solvable piece of the free motion: spin about body axis
/// `axis` (0, 1, 2 = x, y, z) for `fraction`·h seconds.
struct SubFlow {
    int axis;
    Real fraction;
};

/// The Strang splitting 1(h/2) 2(h/2) 3(h) 2(h/2) 1(h/2). The fractions of
/// each axis sum to 1, so each H_i acts for h in total. Symmetric ⇒ second order.
constexpr std::array<SubFlow, 5> kSplitting = {{
    {0, Real(0.5)},
    {1, Real(0.5)},
    {2, Real(1)},
    {1, Real(0.5)},
    {0, Real(0.5)},
}};

/// The body's principal axes in its own frame.
const std::array<Vec3, 3> kBodyAxes = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};

/// Relative spread of the three moments below which a body counts as
/// isotropic (sphere, cube): ω = L/I is then constant, and treating a
/// spread of 1e-12 as none changes ω by at most 1e-12 relative.
constexpr Real kIsotropicTolerance = Real(1e-12);

/// Two inverse moments that differ by at most kIsotropicTolerance of the larger count as equal.
bool sameMoment(Real a, Real b) { return std::abs(a - b) <= kIsotropicTolerance * std::max(a, b); }

bool isIsotropic(const Vec3& inverseInertiaBody) {
    const Real largest = std::max({inverseInertiaBody.x, inverseInertiaBody.y, inverseInertiaBody.z});
    const Real smallest = std::min({inverseInertiaBody.x, inverseInertiaBody.y, inverseInertiaBody.z});
    return sameMoment(largest, smallest);
}

/// The symmetry axis (0, 1, 2) of a symmetric top, whose other two inverse moments are equal
/// (sameMoment()), or −1 when no two are.
int symmetryAxis(const Vec3& inverseInertiaBody) {
    for (int axis = 0; axis < 3; ++axis) {
        if (sameMoment(inverseInertiaBody[(axis + 1) % 3], inverseInertiaBody[(axis + 2) % 3])) return axis;
    }
    return -1;
}

/// The exact turn of a symmetric top with symmetry axis @p axis (the file's header derives it).
Quat rotateSymmetricTop(const Quat& orientation, const Vec3& angularMomentum, const Vec3& inverseInertiaBody,
                        int axis, Real h) {
    const auto i = static_cast<std::size_t>(axis);
    const Real inversePerpendicular = inverseInertiaBody[(axis + 1) % 3];  // 1/I⊥, 1/(kg·m²)
    const Real spin = (glm::conjugate(orientation) * angularMomentum)[axis];  // Π₃, kg·m²/s
    // About L by |L|·h/I⊥ (world frame: on the left); rotateByAngularVelocity() turns by |ω|·h about ω.
    const Quat precession = rotateByAngularVelocity(orientation, angularMomentum * inversePerpendicular, h);
    // About e₃ by (1/I₃ − 1/I⊥)·Π₃·h (body frame: on the right)
    const Quat q = precession * glm::angleAxis((inverseInertiaBody[axis] - inversePerpendicular) * spin * h, kBodyAxes[i]);
    return glm::normalize(q);
}

}  // namespace

Quat rotateTorqueFree(const Quat& orientation, const Vec3& angularMomentum, const Vec3& inverseInertiaBody, Real h) {
    if (isIsotropic(inverseInertiaBody)) {
        // ω = L/I is constant: the exact motion is one rotation by |ω|·h about ω.
        return rotateByAngularVelocity(orientation, angularMomentum * inverseInertiaBody.x, h);
    }
    if (const int axis = symmetryAxis(inverseInertiaBody); axis >= 0) {
        return rotateSymmetricTop(orientation, angularMomentum, inverseInertiaBody, axis, h);
    }
    Quat q = orientation;
    for (const SubFlow& sub : kSplitting) {
        const auto i = static_cast<std::size_t>(sub.axis);
        // Π = Rᵀ·L: the world's fixed L seen from the body as it is now.
        const Vec3 bodyMomentum = glm::conjugate(q) * angularMomentum;
        const Real rate = bodyMomentum[sub.axis] * inverseInertiaBody[sub.axis];  // ω_i = Π_i / I_i, rad/s
        // Body-frame axis ⇒ the turn multiplies on the right.
        q = q * glm::angleAxis(rate * sub.fraction * h, kBodyAxes[i]);
    }
    // Each product rounds; without this the quaternion creeps off the unit
    // sphere, and a q with |q| ≠ 1 stretches what it rotates (q·v·q* has length |q|²·|v|).
    return glm::normalize(q);
}

}  // namespace stepwise
