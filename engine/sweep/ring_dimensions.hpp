#pragma once
// The ring's cross-section and its axial step: how thick each radial layer is and how far
// apart the stations are (the defaults' rationale is in sweep.hpp, SweepOptions).
#include <vector>

namespace tubemesh::sweep {

// Distance of radial node j (j = 0..layers) from the wall: St·(g^j − 1)/(g^L − 1), so layer
// j+1 is g times as thick as layer j; uniform for g = 1. offsets[0] = 0, offsets[L] = St.
std::vector<double> radial_offsets(double sweep_size, int layers, double grading);

// Centre-line distance between stations: `axial_aspect` times the side of the outer polygon,
// 2 (r + St) sin(π/n), shortened while the ring's hexes on a straight pipe of radius r have a
// condition number above `max_condition` (<= 0: never), by 5% steps to a quarter, or further
// down to kMinAxialAspect sides for a wanted step longer than 4 sides. Where no step in that
// reach meets the cap and the ring has more than 2 layers or more nodes around than
// circumferential_count gives, the step is not shortened below kMinAxialAspect sides (nor the
// wanted step): the pyramids need room along the pipe more than those hexes need the little a
// shorter step gives them.
double axial_step(double radius, const std::vector<double>& offsets, int n, double axial_aspect,
                  double max_condition);

// Worst condition number of the ring's hexes on a straight pipe of radius r with this axial
// step: one hex per radial layer, between two nodes 2π/n apart.
double straight_ring_condition(double radius, const std::vector<double>& offsets, int n, double step);

}  // namespace tubemesh::sweep
