/// @file contact_rows.hpp
/// @brief A contact's three rows (normal, two tangents) as the solver's stages read them.
///
/// Used inside the contact solver's stages only (prepare_contacts.cpp,
/// warm_start_contacts.cpp, solve_contacts.cpp, restitution.cpp); the maths
/// of the rows is in contact_solver.hpp and solver_body.hpp.
#pragma once

#include "dynamics/contact_solver.hpp"

namespace stepwise {

/// The three rows of a round contact, computed from its normal, tangents and
/// levers (solver_body.hpp); the two friction rows together, as one impulse
/// vector in the tangent plane.
struct RoundRows {
    const SolverContact& c;  ///< The contact: its normal, tangents and levers.
    /// @brief v_n = J_n·v of the pair, m/s.
    Real normalVelocity(const SolverBody& a, const SolverBody& b) const { return roundNormalVelocity(a, b, c.normal); }
    /// @brief Applies the normal impulse @p lambda, N·s: Δv = M⁻¹·J_nᵀ·λ.
    void applyNormal(SolverBody& a, SolverBody& b, Real lambda) const { applyRoundNormalImpulse(a, b, c.normal, lambda); }
    /// @brief The two tangent velocities J_t·v into @p out, m/s.
    void tangentVelocities(const SolverBody& a, const SolverBody& b, Real (&out)[2]) const {
        roundFrictionVelocities(a, b, c.tangent, c.leverA, c.leverB, out);
    }
    /// @brief Applies the friction impulses @p lambda0, @p lambda1 along the two tangents, N·s.
    void applyTangents(SolverBody& a, SolverBody& b, Real lambda0, Real lambda1) const {
        applyRoundFrictionImpulse(a, b, c.tangent, c.leverA, c.leverB, lambda0, lambda1);
    }
};

/// The three rows of any other contact, read from SolverWorkspace::rows; a
/// kinematic B's own surface speed is part of J·v.
struct StoredRows {
    const SolverContact& c;  ///< The contact: its normal and tangents.
    const ContactRows& r;    ///< Its rows of J, made once a step by prepareContacts().
    /// @brief v_n = J_n·v of the pair plus a kinematic B's surface speed, m/s.
    Real normalVelocity(const SolverBody& a, const SolverBody& b) const {
        return rowVelocity(a, b, c.normal, r.normal) + r.normalSurfaceSpeed;
    }
    /// @brief Applies the normal impulse @p lambda, N·s: Δv = M⁻¹·J_nᵀ·λ.
    void applyNormal(SolverBody& a, SolverBody& b, Real lambda) const { applyRowImpulse(a, b, c.normal, r.normal, lambda); }
    /// @brief The two tangent velocities J_t·v (with the surface's own speed) into @p out, m/s.
    void tangentVelocities(const SolverBody& a, const SolverBody& b, Real (&out)[2]) const {
        for (int k = 0; k < 2; ++k) out[k] = rowVelocity(a, b, c.tangent[k], r.tangent[k]) + r.tangentSurfaceSpeed[k];
    }
    /// @brief Applies the friction impulses @p lambda0, @p lambda1 along the two tangents, N·s.
    void applyTangents(SolverBody& a, SolverBody& b, Real lambda0, Real lambda1) const {
        applyRowImpulse(a, b, c.tangent[0], r.tangent[0], lambda0);
        applyRowImpulse(a, b, c.tangent[1], r.tangent[1], lambda1);
    }
};

/// Calls @p work with contact @p c's rows, round or stored in @p stored (at index `c.rows`),
/// and returns what it returns: the one branch per contact a pass takes on the kind of contact.
template <class Work>
inline decltype(auto) withRows(const SolverContact& c, const std::vector<ContactRows>& stored, Work&& work) {
    if (c.rows == kRoundContact) return work(RoundRows{c});
    return work(StoredRows{c, stored[c.rows]});
}

/// withRows() with the stored rows of the workspace @p w.
template <class Work>
inline decltype(auto) withRows(const SolverContact& c, const SolverWorkspace& w, Work&& work) {
    return withRows(c, w.rows, work);
}

}  // namespace stepwise
