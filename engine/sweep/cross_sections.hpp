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
// summing w·depth over both ends. Node 0 of station `first` starts its wall projection at
// `start` (face -1: without a hint), the other nodes at their neighbour's or their previous
// station's foot.
double place_stations(const TubePlan& plan, int first, int last, const WallCursor& start, std::span<Vec3> nodes);

// Node 0's wall cursor at stations chunk, 2·chunk, ... (those before the last station), found
// by following node 0 along the tube from station 1, each foot the hint for the next: exactly
// the foot a run over all stations would find there, so a chunk that starts from it places its
// nodes as that run would. One hinted projection a station instead of a global search a chunk
// (on a long B-spline wall those cost milliseconds each).
std::vector<WallCursor> chunk_cursors(const TubePlan& plan, int chunk);

}  // namespace tubemesh::sweep
