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

/// @brief What a scene with soft bodies adds to the header: their rows carry two more values.
inline constexpr const char* kSoftBodyCsvColumns = ",volume,pressure";
/// @brief The header of `--csv-nodes`: one row per node of every soft body per sample.
inline constexpr const char* kNodeCsvHeader = "time,body,node,px,py,pz,vx,vy,vz";
/// @brief The header of `--csv-nodes` for a scene with spaces: the space's name after the time.
inline constexpr const char* kSpacesNodeCsvHeader = "time,space,body,node,px,py,pz,vx,vy,vz";

/// @brief Writes the header line to @p out (kSpacesTrajectoryCsvHeader when @p withSpace), with
/// kSoftBodyCsvColumns after it when @p withSoftBodies.
void writeTrajectoryHeader(std::FILE* out, bool withSpace = false, bool withSoftBodies = false);

/// @brief Writes one row per dynamic, then per kinematic object, then per soft body, at the world's current time.
///
/// A soft body's row has the centre of mass and its velocity, the orientation (1, 0, 0, 0) (a
/// soft body has no one rotation), the angular velocity ω = I⁻¹·L of its nodes about the centre of
/// mass, then its volume (m³) and pressure (Pa). The rigid rows are the same with soft bodies or without.
///
/// Numbers are printed with 17 significant digits (%.17g), enough to
/// read back the exact double, so two runs can be compared bit for bit.
void writeTrajectoryRows(std::FILE* out, const World& world);

/// @brief The same rows for a scene with spaces, with the space's name after the time (soft bodies' too).
void writeTrajectoryRows(std::FILE* out, const World& world, const std::string& space);

/// @brief Writes kNodeCsvHeader to @p out (kSpacesNodeCsvHeader when @p withSpace).
void writeNodeHeader(std::FILE* out, bool withSpace = false);

/// @brief Writes one row per node of every soft body: time, the body's name, the node's index, position, velocity.
void writeNodeRows(std::FILE* out, const World& world);

/// @brief The same rows for a scene with spaces, with the space's name after the time.
void writeNodeRows(std::FILE* out, const World& world, const std::string& space);

}  // namespace stepwise
