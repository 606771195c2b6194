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
// summing w·depth over both ends. Node 0's wall feet come from node0_feet; the other nodes'
// projections start from their neighbour's foot at a call's first station, from their own at
// the previous station after that.
struct WallStart {
    WallFoot foot;
    WallCursor cursor;  // after the projection
};
// `scales` (the tube's stations·n entries, or empty): where node column (i, k)'s share of the
// offsets goes (TubePlan::scale; 1 where the ring is full).
double place_stations(const TubePlan& plan, int first, int last, std::span<const WallStart> node0,
                      std::span<Vec3> nodes, std::span<double> scales = {});

// Node 0's wall foot at every station but the two ends (index = station), found by following
// node 0 along the tube from station 1, each foot the hint for the next. One hinted projection
// a station where a call of place_stations starting afresh would need a global search for
// its first (on a long B-spline wall those cost milliseconds each), and the nodes do not
// depend on how the stations are split between calls.
std::vector<WallStart> node0_feet(const TubePlan& plan);

}  // namespace tubemesh::sweep
