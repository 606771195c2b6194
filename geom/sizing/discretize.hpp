#pragma once
// Discretisation of the B-rep for the engine (paper §3.2): each tube's two end loops with the
// same node count and node 0 of both on one generator line of the wall, its centre line by
// arc length with tangents and reference directions, and every other B-rep edge by arc length
// at the overall size S (finer on a curved edge, by the chordal tolerance: discretize_edges.hpp),
// once per edge however many faces share it.
//
// No OpenCASCADE header here: the output is engine/geometry/tube_data.hpp's plain data.
#include <vector>

#include "engine/geometry/tube_data.hpp"
#include "geom/model/model.hpp"
#include "geom/sizing/sizing.hpp"
#include "geom/tubes/tubes.hpp"

namespace tubemesh::geom {

struct DiscretizeOptions {
    // Nodes around every tube; 0 picks circumferential_count() (engine/sweep/sweep.hpp) per tube.
    int ring_nodes = 0;
    // Curved edges' chords stray from the curve by at most this fraction of their length.
    double chordal = kDefaultChordal;
    // St of tube i where element i is > 0 (a thinner ring retried where the plan's found no room
    // for its pyramids); the plan's St elsewhere. Pass the same list to SweepOptions.
    std::vector<double> tube_sweep_size;
};

// n for one tube: `ring_nodes` when given (> 0), else circumferential_count at its mean radius.
int tube_ring_nodes(const TubeInfo& tube, double sweep_size, int ring_nodes);

// Stations along the centre line: St apart by arc length, at least two (one layer); St is the
// plan's or the tube's own (options.tube_sweep_size).
// Throws tubemesh::Error when a tube's wall cannot be followed from one loop to the other,
// or when the plan has no positive sizes.
DiscreteGeometry discretize(const Model& model, const std::vector<TubeInfo>& tubes, const SizePlan& plan,
                            const DiscretizeOptions& options = {});

}  // namespace tubemesh::geom
