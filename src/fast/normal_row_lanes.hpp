/// @file normal_row_lanes.hpp
/// @brief A contact's normal impulse on Lanes: the soft step's formula, four contacts at a time.
///
/// The same lines as solveContact()'s normal row (solve_contacts.cpp), for
/// every kind of contact in lanes (round_contact_lanes.hpp, box_contact_lanes.hpp):
/// \f[ \lambda = -K^{-1} s_m (v_n + b) - s_i \lambda_\text{acc}, \qquad
///     \lambda_\text{acc} \leftarrow \max(\lambda_\text{acc} + \lambda,\ 0), \f]
/// with, where the surfaces are still apart (C > 0), b = C/h_s, s_m = 1, s_i = 0 (the gap
/// may close in this substep, no further), and where they overlap the soft bias
/// b = max(β·C, −kMaxPushOutSpeed) and its scales s_m, s_i (softness.hpp), or, in a pass
/// without the push, b = 0, s_m = 1, s_i = 0. Each `if` of the scalar line on
/// a contact's own numbers becomes a select, lane by lane.
#pragma once

// These helpers pass Lanes by value too, always inlined (see lanes.hpp).
#if defined(__GNUC__)  // GCC, and clang, which reads GCC's pragmas
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

#include "dynamics/contact_solver.hpp"
#include "fast/lanes.hpp"

namespace stepwise {

/// @brief What a pass's formulas take from the settings, as Lanes, once per pass.
struct PassConstants {
    bool accumulate = true;    ///< ContactSolverSettings::accumulate.
    Lanes zero{};              ///< 0 in every lane.
    Lanes one{};               ///< 1 in every lane.
    Lanes inverseSubstep{};    ///< 1/h_s, 1/s.
    Lanes biasRate{};          ///< β (softness.hpp), 1/s.
    Lanes slowestPushOut{};    ///< −kMaxPushOutSpeed, m/s.
    Lanes softMassScale{};     ///< s_m where bodies overlap (softness.hpp; the pass without the push uses 1).
    Lanes softImpulseScale{};  ///< s_i where bodies overlap (the pass without the push uses 0).
};

/// @brief The constants of a pass with @p settings.
STEPWISE_LANES_INLINE PassConstants makePassConstants(const ContactSolverSettings& settings) {
    PassConstants k;
    k.accumulate = settings.accumulate;
    k.zero = splat(0);
    k.one = splat(1);
    k.inverseSubstep = splat(settings.inverseSubstep);
    k.biasRate = splat(settings.softness.biasRate);
    k.slowestPushOut = splat(-kMaxPushOutSpeed);
    k.softMassScale = splat(settings.softness.massScale);
    k.softImpulseScale = splat(settings.softness.impulseScale);
    return k;
}

/// @brief The normal row of four contacts at separation @p separation (m) and normal velocity @p vn
/// (m/s): updates the accumulated @p normalImpulse and @p maxNormalImpulse (N·s) and returns the
/// impulse to apply now. With @p PushOut false (the relax, or PositionCorrection=false) an overlap
/// has no bias and the scales are 1 and 0, so they are left out (the same bits).
template <bool PushOut>
STEPWISE_LANES_INLINE Lanes solveNormalImpulse(Lanes vn, Lanes separation, Lanes normalMass, Lanes& normalImpulse,
                                               Lanes& maxNormalImpulse, const PassConstants& k) {
    const auto gap = separation > k.zero;
    const Lanes gapBias = separation * k.inverseSubstep;
    Lanes impulse;
    if constexpr (PushOut) {
        const Lanes bias = select(gap, gapBias, maxLanes(k.biasRate * separation, k.slowestPushOut));
        const Lanes massScale = select(gap, k.one, k.softMassScale);
        const Lanes impulseScale = select(gap, k.zero, k.softImpulseScale);
        impulse = -normalMass * massScale * (vn + bias) - impulseScale * normalImpulse;
    } else {  // no push: s_m = 1, s_i = 0, and an overlap has no bias
        impulse = -normalMass * (vn + select(gap, gapBias, k.zero));
    }
    Lanes applied;
    if (k.accumulate) {
        const Lanes total = maxLanes(normalImpulse + impulse, k.zero);
        applied = total - normalImpulse;
        normalImpulse = total;
    } else {  // Box2D-Lite's switch: clamp each increment
        applied = maxLanes(impulse, k.zero);
        normalImpulse += applied;
    }
    maxNormalImpulse = maxLanes(maxNormalImpulse, normalImpulse);
    return applied;
}

}  // namespace stepwise

#if defined(__GNUC__)  // GCC, and clang, which reads GCC's pragmas
#pragma GCC diagnostic pop
#endif
