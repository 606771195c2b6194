#pragma once
// SurfaceMap over OpenCASCADE for the faces of a geom::Model.
//
// Thread safety: BRepAdaptor_Surface / GeomAdaptor_Surface keep a mutable B-spline cache, and
// a surface of revolution or extrusion evaluates through a GeomAdaptor_Curve with the same kind
// of cache; ShapeAnalysis_Surface keeps projection state. None of them may be shared between
// threads. So each thread that calls a map gets its own deep copy of the surface, its
// uv curves, an adaptor and a projector, made on its first call (tbb::enumerable_thread_specific).
//
// No OpenCASCADE header here: the pipeline holds maps as SurfaceMap.
#include <memory>
#include <vector>

#include "engine/geometry/surface_map.hpp"
#include "geom/model/model.hpp"

namespace tubemesh::geom {

// The map of one face. It keeps its own handles to the geometry, so it may outlive the Model.
// Throws tubemesh::Error for an id that is not a face of the model.
std::unique_ptr<SurfaceMap> make_surface_map(const Model& model, int face_id);

// One map per face, element i for face id i + 1.
std::vector<std::unique_ptr<SurfaceMap>> make_surface_maps(const Model& model);

}  // namespace tubemesh::geom
