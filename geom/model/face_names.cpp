#include "geom/model/face_names.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopAbs_Orientation.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>

#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {

namespace {

std::string box_side(const BoundingBox& box, const TopoDS_Face& face) {
    const BRepAdaptor_Surface surface(face, /*restriction=*/false);
    if (surface.GetType() != GeomAbs_Plane) return "";
    gp_Dir n = surface.Plane().Axis().Direction();
    if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
    GProp_GProps props;
    BRepGProp::SurfaceProperties(face, props);
    const gp_Pnt c = props.CentreOfMass();
    const double size = std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z});
    const double tolerance = 1e-6 * size;
    struct Side {
        double nx, ny, nz, at, coordinate;
        const char* name;
    };
    const Side sides[] = {{0, 0, 1, box.max.z, c.Z(), "top"},       {0, 0, -1, box.min.z, c.Z(), "bottom"},
                          {0, -1, 0, box.min.y, c.Y(), "upstream"}, {0, 1, 0, box.max.y, c.Y(), "downstream"},
                          {-1, 0, 0, box.min.x, c.X(), "left"},     {1, 0, 0, box.max.x, c.X(), "right"}};
    for (const Side& s : sides)
        if (n.X() * s.nx + n.Y() * s.ny + n.Z() * s.nz > 1 - 1e-9 && std::abs(s.coordinate - s.at) <= tolerance)
            return s.name;
    return "";
}

}  // namespace

std::vector<std::string> box_sides(const Model& model) {
    const BoundingBox box = model.bounds();
    std::vector<std::string> out;
    for (int id = 1; id <= model.face_count(); ++id) out.push_back(box_side(box, face_of(model, id)));
    return out;
}

std::vector<std::string> face_names(const Model& model) {
    std::vector<std::string> names = model.report().face_names;
    names.resize(static_cast<std::size_t>(model.face_count()));
    // The box names the sides of built blocks only; an optimal box of a large imported solid
    // costs more than the tet step's boundary recovery.
    if (model.report().format != "built") return names;
    const std::vector<std::string> sides = box_sides(model);
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i].empty()) names[i] = sides[i];
    return names;
}

}  // namespace tubemesh::geom
