#pragma once
// Sweeping a circle along a centre line into a pipe solid. geom/ only.
#include <TopoDS_Solid.hxx>

#include "geom/builders/centre_line.hpp"

namespace tubemesh::geom {

// A closed solid: the swept wall (one face) and two flat end caps. Lines and arcs give an exact
// cylinder or torus; B-spline paths an approximated wall within 1e-3 of the radius (tighter in
// practice). Throws tubemesh::Error naming `pipe_number` when OpenCASCADE cannot sweep it.
TopoDS_Solid sweep_pipe(const CentreLine& line, double diameter, int pipe_number);

}  // namespace tubemesh::geom
