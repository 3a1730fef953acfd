/// @file lanes.hpp
/// @brief Four numbers handled as one: the same formula on four contacts at once (SIMD lanes).
///
/// A `Lanes` value holds four `Real`s, and `+ − × ÷` and comparisons work on
/// all four, lane by lane. It is GCC's and Clang's vector extension
/// (`__attribute__((vector_size))`): the compiler turns one operation on
/// Lanes into the processor's vector instructions — two SSE2 instructions
/// for four doubles on any x86-64, one AVX instruction where the build
/// targets it — and into four ordinary ones where there are none.
/// Each lane is rounded exactly as the scalar operation would be (IEEE 754
/// does not depend on the width of the register), so a formula written on
/// Lanes gives, lane by lane, the numbers the same formula gives on Reals.
///
/// `Vec3Lanes` is four 3-vectors stored as three Lanes (x of all four, y of
/// all four, z of all four: "structure of arrays"), so that a dot product of
/// four pairs of vectors is three multiplications and two additions of Lanes.
///
/// Reference: GCC manual, "Using Vector Instructions through Built-in
/// Functions"; Catto, Box2D v3 `contact_solver.c` (contacts solved in SIMD
/// lanes, 2024).
#pragma once

// GCC warns that passing a 32-byte vector by value would use another calling
// convention with AVX than without. These functions are always inlined and
// never cross a library boundary, so no two builds ever call each other with
// them. Silenced here only, not for the files that include this one.
#if defined(__GNUC__)  // GCC, and clang, which reads GCC's pragmas
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "core/types.hpp"

/// Every function on Lanes is inlined into its caller: a caller compiled for
/// AVX (a `target_clones` function, round_contact_lanes.cpp) must never call an
/// out-of-line copy compiled without it, which would expect its arguments elsewhere.
#define STEPWISE_LANES_INLINE inline __attribute__((always_inline))

/// A function on Lanes marked with this is compiled three times: for
/// processors with AVX-512 (x86-64-v4), with AVX2 (both four doubles per
/// instruction), and for any x86-64 (SSE2, two); the program picks the copy
/// for the processor it runs on when it starts. The AVX-512 copy still works
/// on four doubles; what it gains is 32 vector registers instead of 16, so a
/// contact's two bodies, its axes and its impulses stay in registers instead
/// of being spilled to the stack and read back. All
/// copies give the same numbers (the file is built with -ffp-contract=off, so
/// no copy fuses a·b + c into one rounding). Define STEPWISE_NO_AVX_COPY to
/// build only the last (to compare them, or for a compiler without `target_clones`).
#if defined(__x86_64__) && !defined(STEPWISE_NO_AVX_COPY)
#define STEPWISE_LANES_COPIES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define STEPWISE_LANES_COPIES
#endif

namespace stepwise {

/// How many contacts a Lanes value carries.
inline constexpr int kLanes = 4;

/// Bytes in a cache line (x86-64, and most ARM cores): what memory moves in, and what a
/// record streamed by every pass is aligned to (RoundBatch), so that it spans no extra line.
inline constexpr std::size_t kCacheLine = 64;

/// @brief Four Reals, operated on together. Aligned to their whole size: a
/// build without AVX would align four doubles to 16 bytes only, while the AVX
/// copy of a function reads them as one aligned 32-byte load.
using Lanes = Real __attribute__((vector_size(kLanes * sizeof(Real)), aligned(kLanes * sizeof(Real))));

/// @brief The same value in all four lanes.
STEPWISE_LANES_INLINE Lanes splat(Real x) { return Lanes{x, x, x, x}; }

/// @brief Lane by lane, `keep ? a : b` (keep from a comparison of Lanes).
template <class Mask>
STEPWISE_LANES_INLINE Lanes select(Mask keep, Lanes a, Lanes b) {
    return keep ? a : b;
}

/// @brief Lane by lane std::max(a, b): (a < b) ? b : a, the same NaN behaviour.
STEPWISE_LANES_INLINE Lanes maxLanes(Lanes a, Lanes b) { return a < b ? b : a; }

/// @brief Lanes picked from @p a (indices 0–3) and @p b (4–7): lane i of the result is lane I_i of [a b].
template <int I0, int I1, int I2, int I3>
STEPWISE_LANES_INLINE Lanes shuffleLanes(Lanes a, Lanes b) {
#if defined(__clang__)
    return __builtin_shufflevector(a, b, I0, I1, I2, I3);
#else
    using Index = std::conditional_t<sizeof(Real) == 8, std::int64_t, std::int32_t>;
    using Indices = Index __attribute__((vector_size(kLanes * sizeof(Real))));
    return __builtin_shuffle(a, b, Indices{I0, I1, I2, I3});
#endif
}

/// @brief kLanes Reals from memory (any alignment) as one Lanes.
STEPWISE_LANES_INLINE Lanes load(const Real* from) {
    Lanes lanes;
    std::memcpy(&lanes, from, sizeof lanes);
    return lanes;
}

/// @brief One Lanes to kLanes Reals in memory (any alignment).
STEPWISE_LANES_INLINE void store(Real* to, const Lanes& lanes) { std::memcpy(to, &lanes, sizeof lanes); }

/// @brief Rows r₀…r₃ of a 4×4 matrix in, its columns out (in place): lane i of
/// column j is element j of row i. Its own inverse.
STEPWISE_LANES_INLINE void transpose(Lanes& r0, Lanes& r1, Lanes& r2, Lanes& r3) {
    const Lanes t0 = shuffleLanes<0, 4, 2, 6>(r0, r1);  // [r0₀ r1₀ r0₂ r1₂]
    const Lanes t1 = shuffleLanes<1, 5, 3, 7>(r0, r1);  // [r0₁ r1₁ r0₃ r1₃]
    const Lanes t2 = shuffleLanes<0, 4, 2, 6>(r2, r3);
    const Lanes t3 = shuffleLanes<1, 5, 3, 7>(r2, r3);
    r0 = shuffleLanes<0, 1, 4, 5>(t0, t2);  // [r0₀ r1₀ r2₀ r3₀]
    r1 = shuffleLanes<0, 1, 4, 5>(t1, t3);
    r2 = shuffleLanes<2, 3, 6, 7>(t0, t2);
    r3 = shuffleLanes<2, 3, 6, 7>(t1, t3);
}

/// @brief Lane by lane square root.
STEPWISE_LANES_INLINE Lanes sqrtLanes(Lanes x) {
    Lanes r;
    for (int i = 0; i < kLanes; ++i) r[i] = std::sqrt(x[i]);
    return r;
}

/// @brief Four 3-vectors, stored by component.
struct Vec3Lanes {
    Lanes x;  ///< The four x components.
    Lanes y;  ///< The four y components.
    Lanes z;  ///< The four z components.
    /// Sets lane @p i to @p v.
    STEPWISE_LANES_INLINE void setLane(int i, const Vec3& v) {
        x[i] = v.x;
        y[i] = v.y;
        z[i] = v.z;
    }
};

/// a + b, lane by lane.
STEPWISE_LANES_INLINE Vec3Lanes operator+(const Vec3Lanes& a, const Vec3Lanes& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
/// a − b, lane by lane.
STEPWISE_LANES_INLINE Vec3Lanes operator-(const Vec3Lanes& a, const Vec3Lanes& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
/// −a, lane by lane.
STEPWISE_LANES_INLINE Vec3Lanes operator-(const Vec3Lanes& a) { return {-a.x, -a.y, -a.z}; }
/// Each lane's vector scaled by that lane's number.
STEPWISE_LANES_INLINE Vec3Lanes operator*(Lanes s, const Vec3Lanes& v) { return {s * v.x, s * v.y, s * v.z}; }
/// a = a + b.
STEPWISE_LANES_INLINE Vec3Lanes& operator+=(Vec3Lanes& a, const Vec3Lanes& b) { return a = a + b; }
/// a = a − b.
STEPWISE_LANES_INLINE Vec3Lanes& operator-=(Vec3Lanes& a, const Vec3Lanes& b) { return a = a - b; }
/// a × b in each lane, each component formed as glm::cross forms it (so a lane is glm::cross, to the bit).
STEPWISE_LANES_INLINE Vec3Lanes cross(const Vec3Lanes& a, const Vec3Lanes& b) {
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}
/// a·b in each lane, summed as glm::dot sums: (x + y) + z.
STEPWISE_LANES_INLINE Lanes dot(const Vec3Lanes& a, const Vec3Lanes& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

}  // namespace stepwise

#if defined(__GNUC__)  // GCC, and clang, which reads GCC's pragmas
#pragma GCC diagnostic pop
#endif
