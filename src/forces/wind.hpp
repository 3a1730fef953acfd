/// @file wind.hpp
/// @brief Wind: drag in air that moves (Effect=Wind).
///
/// Wind is drag with the air's velocity w in place of a still fluid's: the
/// force depends on the body's velocity relative to the air, v − w. A body
/// the wind carries approaches the wind's speed, where the relative velocity
/// and so the force vanish: under the linear law, with no other force,
/// v(t) = w + (v₀ − w)·e^(−c·t/m). A falling body in a horizontal wind drifts
/// towards the wind's speed sideways while it falls.
#pragma once

#include "forces/region.hpp"

namespace stepwise {

/// @brief Adds the wind's push on @p body (drag.hpp's law with the fluid moving at region.velocity).
void addWind(DynamicObject& body, const Region& region, Real substepTime);

}  // namespace stepwise
