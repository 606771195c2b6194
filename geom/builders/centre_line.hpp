#pragma once
// From a PipeSpec to the one curve a pipe is swept along. geom/ only (OpenCASCADE types).
//
// Each pipe's centre line is a single curve, so that the pipe's wall is a single face with two
// end loops (the paper's rule for recognising a tubular hole, §3.1): lines and arcs stay exact
// (the wall is a cylinder or a torus), every other path becomes one C2 B-spline.
#include <Geom_Curve.hxx>

#include <vector>

#include "geom/builders/block_spec.hpp"

namespace tubemesh::geom {

struct CentreLine {
    Handle(Geom_Curve) curve;  // extended past both ends of the spec'd path
    bool exact = false;        // a line or circular arc: swept exactly, not approximated
    bool planar = false;       // lies in one plane (then `plane_normal` is its normal)
    Vec3 plane_normal{0, 0, 1};
    double extension = 0;      // how far the curve runs on past each end of the spec'd path
    double path_first = 0;     // curve parameters where the spec'd path starts and ends
    double path_last = 0;
};

// Throws tubemesh::Error when the spec is malformed (too few points, a bend radius that does
// not fit a corner, an arc through collinear points, ...); `pipe_number` (1-based) names it.
CentreLine make_centre_line(const PipeSpec& pipe, const HostSpec& host, int pipe_number);

// Points along the spec'd part of the centre line (not the extensions), at most `spacing` apart
// by arc length, in order; the first and last are the path's end points.
std::vector<Vec3> sample_path(const CentreLine& line, double spacing);

// Smallest radius of curvature along the spec'd part (infinity for a straight line).
double min_curvature_radius(const CentreLine& line);

}  // namespace tubemesh::geom
