/// @file trajectory_csv.hpp
/// @brief Writes a World's trajectory as CSV, one row per object per sample.
#pragma once

#include <cstdio>
#include <string>

#include "world/world.hpp"

namespace stepwise {

/// @brief The CSV header: time, name, position, velocity, orientation (w first), angular velocity.
inline constexpr const char* kTrajectoryCsvHeader = "time,name,px,py,pz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz";

/// @brief The header of a scene with spaces: a `space` column after the time, which is the space's own.
inline constexpr const char* kSpacesTrajectoryCsvHeader = "time,space,name,px,py,pz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz";

/// @brief Writes the header line to @p out (kSpacesTrajectoryCsvHeader when @p withSpace).
void writeTrajectoryHeader(std::FILE* out, bool withSpace = false);

/// @brief Writes one row per dynamic, then per kinematic object, at the world's current time.
///
/// Numbers are printed with 17 significant digits (%.17g), enough to
/// read back the exact double, so two runs can be compared bit for bit.
void writeTrajectoryRows(std::FILE* out, const World& world);

/// @brief The same rows for a scene with spaces, with the space's name after the time.
void writeTrajectoryRows(std::FILE* out, const World& world, const std::string& space);

}  // namespace stepwise
