#include "geom/describe_groups.hpp"

#include <BRepAdaptor_Surface.hxx>

#include <optional>
#include <string>

#include "geom/model/face_names.hpp"
#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {

namespace {

const char* surface_kind(GeomAbs_SurfaceType type) {
    switch (type) {
        case GeomAbs_Plane: return "plane";
        case GeomAbs_Cylinder: return "cylinder";
        case GeomAbs_Cone: return "cone";
        case GeomAbs_Sphere: return "sphere";
        case GeomAbs_Torus: return "torus";
        case GeomAbs_BezierSurface: return "Bezier";
        case GeomAbs_BSplineSurface: return "B-spline";
        case GeomAbs_SurfaceOfRevolution: return "surface of revolution";
        case GeomAbs_SurfaceOfExtrusion: return "surface of extrusion";
        case GeomAbs_OffsetSurface: return "offset surface";
        default: return "other";
    }
}

// The face id behind a group name: "face_<id>" is the face, "pipe_<k>" the k-th tube's first
// wall face.
std::optional<int> group_face(const std::string& name, const TubeSearch& tubes) {
    auto number = [&](const char* prefix) -> std::optional<int> {
        const std::string p(prefix);
        if (name.rfind(p, 0) != 0 || name.size() == p.size()) return std::nullopt;
        const std::string digits = name.substr(p.size());
        if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) return std::nullopt;
        return std::stoi(digits);
    };
    if (auto id = number("face_")) return id;
    if (auto k = number("pipe_"); k && *k >= 1 && static_cast<std::size_t>(*k) <= tubes.tubes.size()) {
        const TubeInfo& t = tubes.tubes[static_cast<std::size_t>(*k - 1)];
        if (!t.faces.empty()) return t.faces.front();
    }
    return std::nullopt;
}

}  // namespace

void describe_groups(const Model& model, const TubeSearch& tubes, const HybridMesh& mesh,
                     MeshDescription& description) {
    description.length_unit = model.report().length_unit;
    const std::vector<std::string> names = face_names(model);
    description.surface_groups.assign(mesh.surface_group_names.size(), {});
    for (std::size_t g = 0; g < mesh.surface_group_names.size(); ++g) {
        const std::optional<int> id = group_face(mesh.surface_group_names[g], tubes);
        if (!id || *id < 1 || *id > model.face_count()) continue;
        const TopoDS_Face face = face_of(model, *id);
        const BRepAdaptor_Surface surface(face, /*restriction=*/false);
        SurfaceGroupInfo& info = description.surface_groups[g];
        info.surface_kind = surface_kind(surface.GetType());
        if (mesh.surface_group_names[g].rfind("face_", 0) == 0) info.alias = names[static_cast<std::size_t>(*id - 1)];
    }
}

}  // namespace tubemesh::geom
