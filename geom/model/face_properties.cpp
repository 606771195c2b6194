#include "geom/model/face_properties.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <string>

#include "engine/core/types.hpp"
#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {

FaceProperties face_properties(const Model& model, int face_id) {
    if (face_id < 1 || face_id > model.face_count())
        throw Error("face_" + std::to_string(face_id) + " is not a face of the model (it has " +
                    std::to_string(model.face_count()) + ")");
    const TopoDS_Face face = face_of(model, face_id);
    FaceProperties p;
    // The adaptive integration, for the same reason as Model::volume: the fixed-order default
    // is far off on thin B-spline faces (the tube walls).
    GProp_GProps props;
    BRepGProp::SurfaceProperties(face, props, 1e-9);
    p.area = props.Mass();
    p.planar = BRepAdaptor_Surface(face, /*restriction=*/false).GetType() == GeomAbs_Plane;
    return p;
}

RoughMeasures rough_measures(const Model& model, const std::vector<int>& skip) {
    RoughMeasures m;
    if (model.impl().fixed_order_volume) {
        m.volume = *model.impl().fixed_order_volume;
    } else {
        GProp_GProps volume;
        BRepGProp::VolumeProperties(model.impl().solid, volume);
        m.volume = volume.Mass();
    }
    std::vector<char> skipped(static_cast<std::size_t>(model.face_count()) + 1, 0);
    for (int f : skip)
        if (f >= 1 && f <= model.face_count()) skipped[static_cast<std::size_t>(f)] = 1;
    for (int f = 1; f <= model.face_count(); ++f) {
        if (skipped[static_cast<std::size_t>(f)]) continue;
        GProp_GProps area;
        BRepGProp::SurfaceProperties(face_of(model, f), area);
        m.area += area.Mass();
    }
    return m;
}

}  // namespace tubemesh::geom
