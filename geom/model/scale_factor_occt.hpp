#pragma once
// The OpenCASCADE side of geom/model/scale_factor.hpp. geom/ only.
#include <TopoDS_Shape.hxx>

namespace tubemesh::geom {

// working_scale_exponent of the shape's bounding-box diagonal (the fast box: tolerances and
// control polygons may enlarge it a little; it only picks a power of a thousand).
int working_scale_exponent(const TopoDS_Shape& shape);

// The shape scaled by 10^-k with its tolerances reset: OpenCASCADE's absolute precision
// (Precision::Confusion) everywhere, then raised where the geometry needs more
// (BRepLib::UpdateTolerances), so the tolerances a file carried at its own scale do not
// follow the shape into the working space. The shape itself for k = 0.
TopoDS_Shape scaled_to_working(const TopoDS_Shape& shape, int k);

}  // namespace tubemesh::geom
