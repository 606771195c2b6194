#include "geom/model/model.hpp"

#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>

#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {

Model make_model(const TopoDS_Solid& solid, ImportReport report, std::optional<double> fixed_order_volume,
                 int scale_exponent) {
    auto impl = std::make_unique<Model::Impl>();
    impl->solid = solid;
    impl->fixed_order_volume = fixed_order_volume;
    impl->scale_exponent = scale_exponent;
    TopExp::MapShapes(solid, TopAbs_FACE, impl->faces);
    TopExp::MapShapes(solid, TopAbs_EDGE, impl->edges);
    impl->report = std::move(report);
    return Model(std::move(impl));
}

Model::Model(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Model::Model(Model&&) noexcept = default;
Model& Model::operator=(Model&&) noexcept = default;
Model::~Model() = default;

int Model::face_count() const { return impl_->faces.Extent(); }
int Model::edge_count() const { return impl_->edges.Extent(); }
std::string Model::face_name(int id) { return "face_" + std::to_string(id); }
std::string Model::edge_name(int id) { return "edge_" + std::to_string(id); }
const ImportReport& Model::report() const { return impl_->report; }
int Model::scale_exponent() const { return impl_->scale_exponent; }

double Model::volume() const {
    // The adaptive integration: the fixed-order default is far off a thin B-spline pipe's
    // volume (bench/results/tuning-notes.md).
    GProp_GProps props;
    BRepGProp::VolumeProperties(impl_->solid, props, 1e-6);
    return props.Mass();
}

BoundingBox Model::bounds() const {
    // Optimal mode: the plain box adds every edge's tolerance and pads B-spline control polygons,
    // which would make the box of a block with curved pipes visibly too big.
    Bnd_Box box;
    BRepBndLib::AddOptimal(impl_->solid, box, /*useTriangulation=*/false, /*useShapeTolerance=*/false);
    BoundingBox b;
    box.Get(b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z);
    // The optimal box still stands off by about Precision::Confusion() (1e-7) on every side: a
    // side within that of the outermost vertex is the vertex's plane (a block's side at 0, not
    // -1e-07).
    TopTools_IndexedMapOfShape vertices;
    TopExp::MapShapes(impl_->solid, TopAbs_VERTEX, vertices);
    if (vertices.IsEmpty()) return b;
    Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int i = 1; i <= vertices.Extent(); ++i) {
        const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(i)));
        lo = {std::min(lo.x, p.X()), std::min(lo.y, p.Y()), std::min(lo.z, p.Z())};
        hi = {std::max(hi.x, p.X()), std::max(hi.y, p.Y()), std::max(hi.z, p.Z())};
    }
    const double off = 2 * Precision::Confusion();
    const auto snap_low = [off](double& side, double vertex) {
        if (side < vertex && vertex - side <= off) side = vertex;
    };
    const auto snap_high = [off](double& side, double vertex) {
        if (side > vertex && side - vertex <= off) side = vertex;
    };
    snap_low(b.min.x, lo.x);
    snap_low(b.min.y, lo.y);
    snap_low(b.min.z, lo.z);
    snap_high(b.max.x, hi.x);
    snap_high(b.max.y, hi.y);
    snap_high(b.max.z, hi.z);
    return b;
}

}  // namespace tubemesh::geom
