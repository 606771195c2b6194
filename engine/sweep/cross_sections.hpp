#pragma once
// Node positions of a tube's ring, station by station.
#include <span>

#include "engine/sweep/tube_plan.hpp"

namespace tubemesh::sweep {

// Writes the (L+1)·n nodes of stations [first, last) into `nodes` (the tube's whole node array,
// station-major as in TubeRing::node) and returns the largest distance, over the tube's
// radius, by which a wall node moved onto the wall. The end stations copy the plan's end
// sections; the others place node (j, k) at
//   wall foot of (centre + radius·dir_k + w·depth_0k·tangent), + offsets[j]·dir_k
//   + w·(depth_jk − depth_0k)·tangent,
// summing w·depth over both ends. A call starts its wall projections afresh, so the result
// does not depend on how the stations are split between calls.
double place_stations(const TubePlan& plan, int first, int last, std::span<Vec3> nodes);

}  // namespace tubemesh::sweep
