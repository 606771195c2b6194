#include "geom/sizing/discretize_edges.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepLProp_CLProps.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <Precision.hxx>
#include <gp_Circ.hxx>
#include <gp_Elips.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <cmath>

#include "engine/core/types.hpp"
#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {
namespace {

Vec3 to_vec(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

// Curvature samples along a free-form edge (exact for lines, circles and ellipses).
constexpr int kCurvatureSamples = 64;
// Curvature never asks for more segments than this on one edge (a near-cusp of a free-form
// curve would otherwise ask for any number).
constexpr double kMaxTurnSegments = 1024;

double max_curvature(const BRepAdaptor_Curve& curve) {
    switch (curve.GetType()) {
        case GeomAbs_Line: return 0;
        case GeomAbs_Circle: return 1 / curve.Circle().Radius();
        case GeomAbs_Ellipse: {
            const gp_Elips e = curve.Ellipse();
            return e.MinorRadius() > 0 ? e.MajorRadius() / (e.MinorRadius() * e.MinorRadius()) : 0;
        }
        default: break;
    }
    const double t0 = curve.FirstParameter(), t1 = curve.LastParameter();
    BRepLProp_CLProps props(curve, 2, Precision::Confusion());
    double k = 0;
    for (int i = 0; i <= kCurvatureSamples; ++i) {
        props.SetParameter(t0 + (t1 - t0) * i / kCurvatureSamples);
        if (props.IsTangentDefined()) k = std::max(k, props.Curvature());
    }
    return std::isfinite(k) ? k : 0;
}

std::vector<double> uniform_params(const BRepAdaptor_Curve& curve, int segments) {
    const double t0 = curve.FirstParameter(), t1 = curve.LastParameter();
    GCPnts_UniformAbscissa split(curve, segments + 1, t0, t1);
    std::vector<double> params;
    if (split.IsDone() && split.NbPoints() == segments + 1) {
        for (int i = 1; i <= split.NbPoints(); ++i) params.push_back(split.Parameter(i));
    } else {
        // GCPnts gives up on some degenerate parametrisations; even parameter steps are still
        // a valid (if uneven) cut.
        for (int i = 0; i <= segments; ++i) params.push_back(t0 + (t1 - t0) * i / segments);
    }
    params.front() = t0;
    params.back() = t1;
    return params;
}

}  // namespace

std::vector<EdgePolyline> discretize_edges(const Model& model, const std::set<int>& skip, double size,
                                           double chordal) {
    if (!(chordal > 0)) throw Error("the chordal tolerance must be positive, got " + std::to_string(chordal));
    const double turn = chordal_turn(chordal);
    // geom::Model numbers faces and edges; vertices get TopExp::MapShapes order on the solid,
    // which is just as deterministic.
    TopTools_IndexedMapOfShape vertices;
    TopExp::MapShapes(solid_of(model), TopAbs_VERTEX, vertices);

    std::vector<EdgePolyline> out;
    for (int e = 1; e <= model.edge_count(); ++e) {
        if (skip.count(e)) continue;
        const TopoDS_Edge edge = TopoDS::Edge(edge_of(model, e).Oriented(TopAbs_FORWARD));
        if (BRep_Tool::Degenerated(edge)) continue;
        const BRepAdaptor_Curve curve(edge);
        const double length = GCPnts_AbscissaPoint::Length(curve);
        TopoDS_Vertex v0, v1;
        TopExp::Vertices(edge, v0, v1);
        const bool closed = v0.IsSame(v1);
        const int by_size = static_cast<int>(std::ceil(length / size - 1e-9));
        const int by_turn =
            static_cast<int>(std::ceil(std::min(kMaxTurnSegments, max_curvature(curve) * length / turn) - 1e-9));
        const int segments = std::max({closed ? 3 : 1, by_size, by_turn});

        EdgePolyline poly;
        poly.edge = static_cast<index_t>(e);
        poly.first_vertex = static_cast<index_t>(vertices.FindIndex(v0));
        poly.last_vertex = static_cast<index_t>(vertices.FindIndex(v1));
        poly.params = uniform_params(curve, segments);
        for (double t : poly.params) poly.points.push_back(to_vec(curve.Value(t)));
        // The vertices' own points, so edges meeting at a vertex share the coordinates exactly.
        if (!v0.IsNull()) poly.points.front() = to_vec(BRep_Tool::Pnt(v0));
        if (!v1.IsNull()) poly.points.back() = to_vec(BRep_Tool::Pnt(v1));
        out.push_back(std::move(poly));
    }
    return out;
}

}  // namespace tubemesh::geom
