#pragma once
// B-rep edges cut by arc length (GCPnts_UniformAbscissa) into segments of at most a given
// size, and on a curved edge into enough segments that no chord strays from the curve by more
// than `chordal` times its length (kDefaultChordal: a turn of 0.065 rad per segment), skipping
// the edges a tube owns.
#include <cmath>
#include <set>
#include <vector>

#include "engine/geometry/tube_data.hpp"
#include "geom/model/model.hpp"

namespace tubemesh::geom {

// The turn of a circular arc's segment whose chord strays from it by `chordal` times the chord's
// length (the sagitta of a chord turning by t is tan(t / 4) / 2 of its length).
inline double chordal_turn(double chordal) { return 4 * std::atan(2 * chordal); }

// One polyline per non-degenerate edge not in `skip`, by increasing edge id. A closed edge
// gets at least 3 segments, so it stays a polygon. Throws tubemesh::Error when `chordal` is not
// positive.
std::vector<EdgePolyline> discretize_edges(const Model& model, const std::set<int>& skip, double size,
                                           double chordal = kDefaultChordal);

}  // namespace tubemesh::geom
