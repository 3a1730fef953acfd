/// @file materials.hpp
/// @brief Materials shared between bodies, and how a contact mixes the two it touches.
///
/// A scene's `Material` record names a set of values (density, friction,
/// elasticity) that objects take with `Material=name`; the loader copies the
/// friction and elasticity onto each object (its own fields win) and turns the
/// density into a mass. What is left for the step is the *mixing*: a contact
/// touches two materials and needs one coefficient of friction μ and one of
/// restitution e. The World's `FrictionCombine` and `ElasticityCombine` pick
/// the rule, and a `MaterialPair` record may give a pair its own values, as
/// measured for that pair (rubber on ice), whatever the rule would say:
///
/// | rule            | μ (or e) of sides a and b | who uses it by default         |
/// |-----------------|---------------------------|--------------------------------|
/// | `Product`       | a·b                       | Bullet (friction, restitution) |
/// | `Min`           | min(a, b)                 |                                |
/// | `Max`           | max(a, b)                 | Box2D v3, Jolt (restitution)   |
/// | `Average`       | (a + b)/2                 |                                |
/// | `GeometricMean` | √(a·b)                    | Box2D v3, Jolt (friction)      |
///
/// docs/config-format.md ("How elasticity and friction combine") gives the
/// sources and what each rule does to a floor's default of 1.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "core/world_settings.hpp"
#include "objects/game_object.hpp"

namespace stepwise {

/// @brief One `Material` record: values objects share by naming it.
struct Material {
    std::string name;              ///< Unique among the scene's materials and objects.
    std::optional<Real> density;   ///< kg/m³; an object's mass is density × its volume when it gives no Mass.
    std::optional<Real> friction;  ///< Default `Friction` of the objects made of it.
    std::optional<Real> elasticity;///< Default `Elasticity` of the objects made of it.
};

/// @brief One `MaterialPair` record: the coefficients of contacts between two materials.
struct MaterialPair {
    std::uint32_t a = 0;            ///< Index of one material in Scene::materials.
    std::uint32_t b = 0;            ///< The other (may equal `a`: rubber on rubber).
    std::optional<Real> friction;   ///< μ of their contacts; nullopt: the World's rule decides.
    std::optional<Real> elasticity; ///< e of their contacts; nullopt: the World's rule decides.
};

/// @brief @p rule applied to the coefficients @p a and @p b of a contact's two sides.
///
/// Every rule is symmetric (which side is A does not matter) and keeps the
/// result between the two values, except Product, which gives less than both
/// when both are below 1.
inline Real combine(CombineRule rule, Real a, Real b) {
    switch (rule) {
        case CombineRule::Product: return a * b;
        case CombineRule::Min: return a < b ? a : b;
        case CombineRule::Max: return a < b ? b : a;
        case CombineRule::Average: return Real(0.5) * (a + b);
        case CombineRule::GeometricMean: return std::sqrt(a * b);
    }
    return a * b;
}

/// @brief μ and e of one contact.
struct ContactCoefficients {
    Real friction = 0;    ///< Coulomb's μ of the contact.
    Real elasticity = 0;  ///< Coefficient of restitution e of the contact, before the resting rule.
};

/// @brief The World's combine rules and its material pairs: what a contact's preparation asks once.
///
/// Built once when the World is made; read-only during the steps, so the
/// contacts prepared on several threads may ask it at once.
class ContactMaterials {
public:
    /// @brief The classic rules: products, no pairs (plain() is true).
    ContactMaterials() = default;
    /// @brief The rules of @p settings and the pairs @p pairs (indices below @p materialCount).
    ContactMaterials(const WorldSettings& settings, std::size_t materialCount, std::span<const MaterialPair> pairs);

    /// @brief True when every contact is the product of its sides: the rules are Product and no pair
    /// is given. The preparation then needs no look-up at all.
    bool plain() const { return plain_; }
    /// @brief True when some MaterialPair is given.
    bool hasPairs() const { return !pairs_.empty(); }

    /// @brief μ and e of a contact between a side of material @p materialA (kNoMaterial: none) with
    /// coefficients @p frictionA, @p elasticityA and a side of @p materialB with @p frictionB, @p elasticityB.
    ///
    /// A pair's own value wins; a value the pair leaves out comes from the rule.
    ContactCoefficients mix(std::uint32_t materialA, Real frictionA, Real elasticityA, std::uint32_t materialB,
                            Real frictionB, Real elasticityB) const;

private:
    /// One pair's entry, keyed by its two materials with the smaller index first.
    struct Entry {
        std::uint64_t key = 0;              ///< (min index) << 32 | (max index).
        std::optional<Real> friction;       ///< The pair's μ, if it gives one.
        std::optional<Real> elasticity;     ///< The pair's e, if it gives one.
    };
    static std::uint64_t keyOf(std::uint32_t a, std::uint32_t b);

    CombineRule frictionRule_ = CombineRule::Product;
    CombineRule elasticityRule_ = CombineRule::Product;
    std::vector<Entry> pairs_;  ///< Sorted by key: a binary search finds a pair in O(log pairs).
    bool plain_ = true;
};

}  // namespace stepwise
