#pragma once
// Quality of a ring's hexes while its nodes are still the tube's own array: the statistics the
// sweep reports and the fold check it makes before anything reaches the mesh.
#include <limits>
#include <span>

#include "engine/sweep/tube_plan.hpp"

namespace tubemesh::sweep {

struct RingQuality {
    double min_jacobian = std::numeric_limits<double>::infinity();
    double sum_jacobian = 0;
    double max_condition = 0;
    double sum_condition = 0;
    int folded_layer = -1;  // first hex layer holding a hex with J_m <= 0; -1: none

    // Adds a later part of the same ring (the sums stay reproducible when parts are added in
    // a fixed order).
    void add(const RingQuality& later);
};

// J_m and condition number of the hexes of layers [first, last) of the plan's ring (layer i lies
// between stations i and i+1).
RingQuality measure_layers(const TubePlan& plan, std::span<const Vec3> nodes, int first, int last);

}  // namespace tubemesh::sweep
