/// @file contact.hpp
/// @brief What collision detection hands to collision response.
#pragma once

#include <cstdint>

#include "core/types.hpp"

namespace stepwise {

/// Two surfaces closer than this count as touching, m. It absorbs round-off
/// (a sphere pushed out to exactly touching may land a few ulps away), so a
/// resting body keeps its contact from step to step instead of flickering.
inline constexpr Real kTouchTolerance = Real(1e-6);

/// Box manifolds also keep points whose surfaces are still this far apart, m:
/// *speculative* points. A box resting on another rocks by a hair as the
/// impulse passes settle; with only touching points, a corner lifted by
/// 0.04 mm loses its contact, nothing holds that side, and the rocking grows.
/// The impulse stage lets a slow (resting) approach close such a gap within
/// the step but no further, and ignores gaps on fast approaches, so impacts
/// and bounces are unchanged. (Box2D keeps points within a few linear slops
/// for the same reason.) The sequential-impulse solver also asks the sphere
/// tests for contacts this far apart (findContacts() in narrowphase.hpp says why).
inline constexpr Real kSpeculativeDistance = Real(0.01);

/// @brief MurmurHash3's 32-bit finaliser (Appleby): spreads every bit of @p h over the result.
///
/// Feature ids that must also name a compound's parts or a mesh's triangle are mixed by it
/// (narrowphase.cpp, mesh_contacts.cpp): two different inputs give the same id with odds of
/// 2⁻³², so warm starting never matches a point of one part or triangle with another's.
constexpr std::uint32_t mixFeatureBits(std::uint32_t h) {
    constexpr std::uint32_t kMix1 = 0x85EBCA6Bu;  // the finaliser's two multipliers
    constexpr std::uint32_t kMix2 = 0xC2B2AE35u;
    h ^= h >> 16;
    h *= kMix1;
    h ^= h >> 13;
    h *= kMix2;
    h ^= h >> 16;
    return h;
}

/// 2³²/φ: an odd multiplier with well mixed bits, to spread a small index before mixFeatureBits().
inline constexpr std::uint32_t kGoldenRatioBits = 0x9E3779B9u;

/// @brief Which array a body lives in.
enum class BodyKind : std::uint8_t {
    Dynamic,    ///< World dynamics array.
    Kinematic,  ///< World kinematics array.
    Plane,      ///< World planes array.
};

/// @brief A reference to one object of the World: its kind and its index in that kind's array.
struct BodyRef {
    BodyKind kind = BodyKind::Dynamic;  ///< Which array.
    std::uint32_t index = 0;            ///< Index in that array.
};

/// @brief A pair the broadphase could not rule out. Body A is always dynamic.
struct CandidatePair {
    std::uint32_t a = 0;  ///< Index of the dynamic body A.
    BodyRef b;            ///< The other body.
};

/// @brief Contact::partA or partB of a body that is no compound (or of a part past the 65535th).
inline constexpr std::uint16_t kNoPart = 0xFFFF;

/// @brief One point of contact between dynamic body A and body B.
///
/// Convention (as in Box2D): the normal points from A towards B. A moves
/// along −normal and B along +normal to separate. The relative normal
/// velocity v_n = (v_B − v_A)·n is negative while the bodies approach.
struct Contact {
    std::uint32_t a = 0;  ///< Index of the dynamic body A.
    BodyRef b;            ///< The other body.
    Vec3 normal{0, 1, 0}; ///< Unit vector from A towards B.
    Vec3 point{0, 0, 0};  ///< World-space point midway through the overlap, m.
    Real depth = 0;       ///< Penetration depth along the normal, m (≥ 0 when touching).
    std::uint32_t featureId = 0; ///< Which features of A and B meet (from the pair test; stable while they stay in touch).
    std::uint16_t partA = kNoPart; ///< The part of compound A that touches (its material may differ from the body's).
    std::uint16_t partB = kNoPart; ///< The part of compound B that touches.
};

}  // namespace stepwise
