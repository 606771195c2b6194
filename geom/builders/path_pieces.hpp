#pragma once
// The curve pieces of a path that is not a single line or arc (polyline with rounded corners,
// interpolating spline, B-spline from control points), before make_centre_line joins them and
// their extensions into one curve. geom/ only.
#include <Geom_Curve.hxx>

#include <vector>

#include "geom/builders/block_spec.hpp"

namespace tubemesh::geom {

struct PathPieces {
    std::vector<Handle(Geom_Curve)> curves;  // end to end, tangent-continuous
    std::vector<bool> straight;              // per piece: a line segment
};

// Throws tubemesh::Error naming `pipe_number` when a corner cannot be rounded (no bend radius,
// a radius not above the pipe radius, a radius that does not fit its segments, a U-turn) or
// the spline cannot be interpolated.
PathPieces path_pieces(const PipeSpec& pipe, const HostSpec& host, int pipe_number);

}  // namespace tubemesh::geom
