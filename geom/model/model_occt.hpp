#pragma once
// The OpenCASCADE side of geom::Model. For geom/ sources only: it includes OCCT headers, which
// the engine and the tools never see.
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>

#include <optional>

#include "geom/model/model.hpp"

namespace tubemesh::geom {

struct Model::Impl {
    TopoDS_Solid solid;
    // Built once by make_model; index i is id i (1-based, like the maps themselves).
    TopTools_IndexedMapOfShape faces;
    TopTools_IndexedMapOfShape edges;
    ImportReport report;
    // The fixed-order volume integration of `solid` (BRepGProp::VolumeProperties' defaults),
    // when whoever made the model already ran it: import does, to refuse solids without a
    // positive volume, and rough_measures reuses it (on a block with curved B-spline holes
    // it costs as much as a good part of the tet step).
    std::optional<double> fixed_order_volume;
    // The solid is the source's scaled by 10^-scale_exponent (geom/working_scale.hpp).
    int scale_exponent = 0;
};

// Wraps one solid, numbering its faces and edges in TopExp::MapShapes order (deterministic for
// a given shape). The caller has already checked the solid (see check_solid in geom/import).
// `scale_exponent`: the solid is the source's scaled by 10^-scale_exponent.
Model make_model(const TopoDS_Solid& solid, ImportReport report,
                 std::optional<double> fixed_order_volume = std::nullopt, int scale_exponent = 0);

inline const TopoDS_Solid& solid_of(const Model& m) { return m.impl().solid; }
inline TopoDS_Face face_of(const Model& m, int id) { return TopoDS::Face(m.impl().faces.FindKey(id)); }
inline TopoDS_Edge edge_of(const Model& m, int id) { return TopoDS::Edge(m.impl().edges.FindKey(id)); }
// 0 when the face (or edge) is not one of the model's, whatever its orientation.
inline int face_id(const Model& m, const TopoDS_Shape& face) { return m.impl().faces.FindIndex(face); }
inline int edge_id(const Model& m, const TopoDS_Shape& edge) { return m.impl().edges.FindIndex(edge); }

}  // namespace tubemesh::geom
