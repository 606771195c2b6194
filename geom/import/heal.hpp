#pragma once
// Safe shape healing before meshing. geom/ only.
#include <TopoDS_Shape.hxx>

#include <optional>
#include <string>
#include <vector>

namespace tubemesh::geom {

// ShapeFix_Shape with its default precision: fixes small defects (tolerances, edge
// parameterisation, wire order, face orientation) and never changes the geometry beyond them.
// Appends one line per kind of change to `changes` ("Wire: fixed gap between edges (x3)"),
// sorted so that the report is the same on every run. Empty when ShapeFix itself fails (it
// throws on some broken shapes); a line in `changes` then says so.
std::optional<TopoDS_Shape> heal_shape(const TopoDS_Shape& shape, std::vector<std::string>& changes);

}  // namespace tubemesh::geom
