/// @file trajectory_csv.hpp
/// @brief Writes a World's trajectory as CSV, one row per object per sample.
#pragma once

#include <cstdio>

#include "world/world.hpp"

namespace stepwise {

/// @brief The CSV header: time, name, position, velocity, orientation (w first), angular velocity.
inline constexpr const char* kTrajectoryCsvHeader = "time,name,px,py,pz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz";

/// @brief Writes the header line to @p out.
void writeTrajectoryHeader(std::FILE* out);

/// @brief Writes one row per dynamic, then per kinematic object, at the world's current time.
///
/// Numbers are printed with 17 significant digits (%.17g), enough to
/// read back the exact double, so two runs can be compared bit for bit.
void writeTrajectoryRows(std::FILE* out, const World& world);

}  // namespace stepwise
