#pragma once
// OpenCASCADE solids for the tube, sizing, discretisation and surface map tests: boxes with
// pipes cut through them, the not-a-tube features, face splitting and a STEP round trip.
// Built here with OCCT directly, so these tests do not depend on geom/builders.
#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pnt.hxx>

#include <vector>

#include "geom/model/model.hpp"

namespace tubemesh::test {

TopoDS_Wire straight_spine(const gp_Pnt& a, const gp_Pnt& b);
// Arc of a circle in the plane z = centre.Z(), from angle a0 to a1 (degrees, counter-clockwise).
TopoDS_Wire arc_spine(const gp_Pnt& centre, double radius, double a0_deg, double a1_deg);
// Line from a towards `corner`, a circular arc of radius `bend` tangent to both legs, line on
// to b: three edges, so the pipe's wall is three faces along its axis. bend = 0 gives two
// lines meeting at the corner (a mitred pipe).
TopoDS_Wire corner_spine(const gp_Pnt& a, const gp_Pnt& corner, const gp_Pnt& b, double bend);
// Interpolating B-spline through the points.
TopoDS_Wire spline_spine(const std::vector<gp_Pnt>& points);

// The axis-aligned box [lo, hi] minus a circular pipe of radius r along each spine (each spine
// must start and end outside the box).
TopoDS_Solid box_with_pipes(const gp_Pnt& lo, const gp_Pnt& hi, const std::vector<TopoDS_Wire>& spines, double r);

// Not tubes: a blind hole, a through slot with flat sides, a rectangular pocket, in the unit box.
TopoDS_Solid box_with_blind_hole(double r, double depth);
TopoDS_Solid box_with_slot(double width, double length);
TopoDS_Solid box_with_pocket(double width, double depth);

// A pipe solid on its own (its circles are the outer wires of its end caps).
TopoDS_Solid pipe_solid(const TopoDS_Wire& spine, double r);

// Every face closed around the axis split in two (ShapeUpgrade_ShapeDivideClosed).
TopoDS_Solid split_closed_faces(const TopoDS_Shape& shape);
// Written to a STEP file and read back.
TopoDS_Solid step_round_trip(const TopoDS_Shape& shape);

geom::Model model_of(const TopoDS_Solid& solid);

}  // namespace tubemesh::test
