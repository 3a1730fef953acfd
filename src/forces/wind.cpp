/// @file wind.cpp
/// @brief Effect=Wind: F = −c·(v − w), or −c·|v − w|·(v − w).
#include "forces/wind.hpp"

#include "forces/drag.hpp"

namespace stepwise {

void addWind(DynamicObject& body, const Region& region, Real substepTime) {
    addDrag(body, region, region.velocity, Real(1), substepTime);
}

}  // namespace stepwise
