/// @file broadphase_table.hpp
/// @brief The broadphase tracker's report as a text table (`stepwise bench broadphase`, bench/broadphase).
#pragma once

#include <cstdio>

#include "collision/broadphase_tracker.hpp"

namespace stepwise {

/// @brief Writes the ranked table of @p tracker and its differences from brute force to @p out.
///
/// One row per broadphase, fastest first: time per step, body pairs tested
/// per step, candidate pairs returned per step, the efficiency (pairs the
/// narrowphase finds touching per pair tested) and the number of differences
/// from brute force. Then each kept difference, with its step and its pair.
/// @param bodies the bodies the tracker watched, for their names
void writeBroadphaseTable(std::FILE* out, const BroadphaseTracker& tracker, const BodySet& bodies);

}  // namespace stepwise
