#include "geom/tubes/ring_stop.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepFeat_SplitShape.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "engine/core/vec3_ops.hpp"
#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {
namespace {

Vec3 vec(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

}  // namespace

Model split_wall(const Model& model, int wall, const Vec3& centre, const Vec3& axis) {
    const TopoDS_Face face = face_of(model, wall);
    BRepAlgoAPI_Section section(face, gp_Pln(gp_Pnt(centre.x, centre.y, centre.z), gp_Dir(axis.x, axis.y, axis.z)),
                                Standard_False);
    section.ComputePCurveOn1(Standard_True);
    section.Approximation(Standard_False);
    section.Build();
    std::vector<TopoDS_Edge> edges;
    for (TopExp_Explorer e(section.Shape(), TopAbs_EDGE); e.More(); e.Next()) edges.push_back(TopoDS::Edge(e.Current()));
    if (!section.IsDone() || edges.size() != 1 || !BRep_Tool::IsClosed(edges.front()))
        throw Error(Model::face_name(wall) + ": the cross-section where its ring would stop is not one closed edge (" +
                    std::to_string(edges.size()) + " edges)");
    BRepFeat_SplitShape split(solid_of(model));
    split.Add(edges.front(), face);
    split.Build();
    TopoDS_Solid solid;
    if (split.IsDone())
        if (TopExp_Explorer s(split.Shape(), TopAbs_SOLID); s.More()) solid = TopoDS::Solid(s.Current());
    if (solid.IsNull() || !BRepCheck_Analyzer(solid).IsValid())
        throw Error(Model::face_name(wall) + ": splitting it where its ring would stop gave no valid solid");
    return make_model(solid, model.report());
}

void stop_ring_at_edge(const Model& model, int edge_id_, TubeData& tube) {
    const TopoDS_Edge edge = edge_of(model, edge_id_);
    const std::string name = Model::edge_name(edge_id_);
    if (!BRep_Tool::IsClosed(edge) || tube.stations.size() < 2 || tube.ring1.size() < 4)
        throw Error(name + " cannot end a ring: it is not closed, or the tube has no stations or ring");
    // The wall faces reached from the first end without crossing the edge keep the ring.
    TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
    TopExp::MapShapesAndAncestors(solid_of(model), TopAbs_EDGE, TopAbs_FACE, edge_faces);
    const std::set<index_t> walls(tube.wall_faces.begin(), tube.wall_faces.end());
    std::set<index_t> kept;
    std::vector<index_t> todo;
    for (index_t f : tube.wall_faces) {
        TopTools_IndexedMapOfShape f_edges;
        TopExp::MapShapes(face_of(model, static_cast<int>(f)), TopAbs_EDGE, f_edges);
        for (index_t e : tube.loop1_edges)
            if (f_edges.Contains(edge_of(model, static_cast<int>(e))) && kept.insert(f).second) todo.push_back(f);
    }
    while (!todo.empty()) {
        const index_t f = todo.back();
        todo.pop_back();
        for (TopExp_Explorer e(face_of(model, static_cast<int>(f)), TopAbs_EDGE); e.More(); e.Next()) {
            if (e.Current().IsSame(edge)) continue;
            for (const TopoDS_Shape& g : edge_faces.FindFromKey(e.Current())) {
                const index_t id = static_cast<index_t>(face_id(model, g));
                if (walls.count(id) && kept.insert(id).second) todo.push_back(id);
            }
        }
    }
    index_t beyond = 0;
    bool borders_kept = false;
    for (const TopoDS_Shape& g : edge_faces.FindFromKey(edge)) {
        const index_t id = static_cast<index_t>(face_id(model, g));
        if (kept.count(id)) borders_kept = true;
        else if (walls.count(id)) beyond = id;
    }
    if (!borders_kept || beyond == 0 || kept.size() == walls.size())
        throw Error(name + " does not split the tube's wall between its first end and the rest");

    // The edge's plane: its centre and the tangent there, from the stations.
    const BRepAdaptor_Curve curve(edge);
    const double length = GCPnts_AbscissaPoint::Length(curve);
    const int n = static_cast<int>(tube.ring1.size());
    Vec3 centre{0, 0, 0};
    for (int k = 0; k < 64; ++k)
        centre += vec(curve.Value(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * k / 64));
    centre = centre / 64.0;
    // The station nearest the plane decides the tangent; stations past it leave.
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < tube.stations.size(); ++i)
        if (distance2(tube.stations[i].centre, centre) < distance2(tube.stations[nearest].centre, centre)) nearest = i;
    TubeStation last = tube.stations[nearest];
    const Vec3 tangent = last.tangent;
    const double step = norm(tube.stations[1].centre - tube.stations[0].centre);
    std::erase_if(tube.stations, [&](const TubeStation& s) { return dot(s.centre - centre, tangent) > -step / 2; });
    if (tube.stations.empty()) throw Error(name + " lies too close to the tube's first end for a ring");
    last.centre = centre;
    last.radius = norm(vec(curve.Value(curve.FirstParameter())) - centre);
    tube.stations.push_back(last);

    // Ring2 from the edge's vertex by arc length, turning about the tangent as ring1 does.
    const Vec3 c1 = tube.stations.front().centre;
    const double ring_turn = dot(cross(tube.ring1[0] - c1, tube.ring1[1] - c1), tube.stations.front().tangent);
    const double d = length / n;
    const double t0 = curve.FirstParameter();
    const gp_Pnt p0 = curve.Value(t0), p1 = curve.Value(GCPnts_AbscissaPoint(curve, d, t0).Parameter());
    const double edge_turn = dot(cross(vec(p0) - centre, vec(p1) - centre), tangent);
    const bool along = (ring_turn > 0) == (edge_turn > 0);
    tube.ring2.clear();
    std::vector<double> params;
    for (int k = 0; k <= n; ++k) {
        const double s = along ? k * d : length - k * d;
        const double t = k == 0 ? (along ? t0 : curve.LastParameter())
                         : k == n ? (along ? curve.LastParameter() : t0)
                                  : GCPnts_AbscissaPoint(curve, s, t0).Parameter();
        if (k < n) tube.ring2.push_back(k == 0 ? vec(p0) : vec(curve.Value(t)));
        params.push_back(t);
    }
    TopoDS_Vertex v0, v1;
    TopExp::Vertices(edge, v0, v1);
    TopTools_IndexedMapOfShape vertices;
    TopExp::MapShapes(solid_of(model), TopAbs_VERTEX, vertices);

    tube.wall_faces.assign(kept.begin(), kept.end());
    tube.host2 = beyond;
    tube.loop2_edges = {static_cast<index_t>(edge_id_)};
    tube.stops[1] = true;
    tube.stop_params[1] = std::move(params);
    tube.stop_vertex[1] = static_cast<index_t>(vertices.FindIndex(v0));
}

}  // namespace tubemesh::geom
