#pragma once
// Does a shape pass OpenCASCADE's validity check, and if not, what failed where. geom/ only.
#include <TopoDS_Shape.hxx>

#include <string>

namespace tubemesh::geom {

// Empty when the shape passes BRepCheck_Analyzer. Otherwise one line naming the failures and
// the sub-shapes they were found on, e.g. "face_3: SelfIntersectingWire; edge_7:
// InvalidCurveOnSurface (and 4 more)", with ids as geom::Model numbers them (TopExp order).
std::string validity_problems(const TopoDS_Shape& shape);

}  // namespace tubemesh::geom
