#include "geom/tubes/ring_stop.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
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

// The wall faces of `walls` reached from those bounded by `loop` without crossing `edge`.
std::set<index_t> faces_before(const Model& model, const std::set<index_t>& walls, const std::vector<index_t>& loop,
                               const TopoDS_Edge& edge, const TopTools_IndexedDataMapOfShapeListOfShape& edge_faces) {
    std::set<index_t> kept;
    std::vector<index_t> todo;
    for (index_t f : walls) {
        TopTools_IndexedMapOfShape f_edges;
        TopExp::MapShapes(face_of(model, static_cast<int>(f)), TopAbs_EDGE, f_edges);
        for (index_t e : loop)
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
    return kept;
}

// The mean of 64 points along a closed edge: its centre when it is a circle or near one.
Vec3 edge_centre(const BRepAdaptor_Curve& curve) {
    Vec3 centre{0, 0, 0};
    for (int k = 0; k < 64; ++k)
        centre += vec(curve.Value(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * k / 64));
    return centre / 64.0;
}

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
    std::vector<index_t> loop1(tube.loop1_edges.begin(), tube.loop1_edges.end());
    const std::set<index_t> kept = faces_before(model, walls, loop1, edge, edge_faces);
    index_t beyond = 0;
    bool borders_kept = false;
    for (const TopoDS_Shape& g : edge_faces.FindFromKey(edge)) {
        const index_t id = static_cast<index_t>(face_id(model, g));
        if (kept.count(id)) borders_kept = true;
        else if (walls.count(id)) beyond = id;
    }
    // A stretch that is a tube of its own (junction.hpp) ends on the edge already.
    const bool ends_there = tube.loop2_edges == std::vector<index_t>{static_cast<index_t>(edge_id_)};
    if (ends_there && beyond == 0 && kept.size() == walls.size()) beyond = tube.host2;
    else if (!borders_kept || beyond == 0 || kept.size() == walls.size())
        throw Error(name + " does not split the tube's wall between its first end and the rest");

    // The edge's plane: its centre and the tangent there, from the stations.
    const BRepAdaptor_Curve curve(edge);
    const double length = GCPnts_AbscissaPoint::Length(curve);
    const int n = static_cast<int>(tube.ring1.size());
    const Vec3 centre = edge_centre(curve);
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
    // Ring2's node 0 sits at the edge's vertex, wherever the split put it: the stations' reference
    // directions turn towards it bit by bit along the tube, so no layer takes the whole twist.
    {
        const Vec3 to_vertex = vec(curve.Value(curve.FirstParameter())) - centre;
        const Vec3 along_ref = last.reference, side = cross(last.tangent, last.reference);
        const double twist = std::atan2(dot(to_vertex, side), dot(to_vertex, along_ref));
        double total = 0;
        for (std::size_t i = 1; i < tube.stations.size(); ++i)
            total += norm(tube.stations[i].centre - tube.stations[i - 1].centre);
        double s = 0;
        for (std::size_t i = 0; i < tube.stations.size(); ++i) {
            if (i > 0) s += norm(tube.stations[i].centre - tube.stations[i - 1].centre);
            TubeStation& st = tube.stations[i];
            const double a = total > 0 ? twist * s / total : 0;
            st.reference = std::cos(a) * st.reference + std::sin(a) * cross(st.tangent, st.reference);
        }
    }

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

int wall_face_at(const Model& model, const std::vector<int>& faces, const Vec3& centre) {
    const TopoDS_Vertex v = BRepBuilderAPI_MakeVertex(gp_Pnt(centre.x, centre.y, centre.z));
    int best = 0;
    double nearest = 0;
    for (int f : faces) {
        BRepExtrema_DistShapeShape d(v, face_of(model, f));
        if (d.IsDone() && (best == 0 || d.Value() < nearest)) {
            best = f;
            nearest = d.Value();
        }
    }
    return best;
}

int stop_edge_at(const Model& model, const std::vector<int>& faces, const Vec3& centre, double reach) {
    TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
    TopExp::MapShapesAndAncestors(solid_of(model), TopAbs_EDGE, TopAbs_FACE, edge_faces);
    const std::set<int> walls(faces.begin(), faces.end());
    int best = 0;
    double nearest = reach;
    for (int f : faces)
        for (TopExp_Explorer e(face_of(model, f), TopAbs_EDGE); e.More(); e.Next()) {
            const TopoDS_Edge edge = TopoDS::Edge(e.Current());
            if (!BRep_Tool::IsClosed(edge) || BRep_Tool::IsClosed(edge, face_of(model, f))) continue;
            int on_walls = 0;
            for (const TopoDS_Shape& g : edge_faces.FindFromKey(edge)) on_walls += walls.count(face_id(model, g)) ? 1 : 0;
            if (on_walls != 2) continue;
            const double d = norm(edge_centre(BRepAdaptor_Curve(edge)) - centre);
            if (d < nearest) {
                nearest = d;
                best = edge_id(model, edge);
            }
        }
    return best;
}

TubeInfo stopped_tube(const Model& model, const TubeInfo& tube, int edge_id_, const Vec3& keep) {
    TubeInfo t = tube;
    if (t.centre_line.size() < 2) throw Error(Model::edge_name(edge_id_) + ": the tube has no centre line to stop");
    // The end nearer `keep` becomes E1.
    if (distance2(t.centre_line.back(), keep) < distance2(t.centre_line.front(), keep)) {
        std::swap(t.loops[0], t.loops[1]);
        std::swap(t.hosts[0], t.hosts[1]);
        std::swap(t.loop_lengths[0], t.loop_lengths[1]);
        std::reverse(t.centre_line.begin(), t.centre_line.end());
    }
    const TopoDS_Edge edge = edge_of(model, edge_id_);
    TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
    TopExp::MapShapesAndAncestors(solid_of(model), TopAbs_EDGE, TopAbs_FACE, edge_faces);
    const std::set<index_t> walls(t.faces.begin(), t.faces.end());
    const std::vector<index_t> loop1(t.loops[0].begin(), t.loops[0].end());
    const std::set<index_t> kept = faces_before(model, walls, loop1, edge, edge_faces);
    int beyond = 0;
    for (const TopoDS_Shape& g : edge_faces.FindFromKey(edge)) {
        const int id = face_id(model, g);
        if (walls.count(static_cast<index_t>(id)) && !kept.count(static_cast<index_t>(id))) beyond = id;
    }
    if (beyond == 0 || kept.empty() || kept.size() == walls.size())
        throw Error(Model::edge_name(edge_id_) + " does not split the tube's wall between its ends");

    TubeInfo::Stop stop;
    stop.edge = edge_id_;
    stop.wall = t.faces;
    for (int f : t.faces)
        if (!kept.count(static_cast<index_t>(f))) stop.beyond.push_back(f);
    stop.loop = t.loops[1];
    stop.host = t.hosts[1];
    stop.loop_length = t.loop_lengths[1];
    stop.length = t.length;
    stop.centre_line = t.centre_line;

    const BRepAdaptor_Curve curve(edge);
    const Vec3 centre = edge_centre(curve);
    // The centre line up to the plane of the edge, walking from E1; then the edge's centre.
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < t.centre_line.size(); ++i)
        if (distance2(t.centre_line[i], centre) < distance2(t.centre_line[nearest], centre)) nearest = i;
    const std::size_t j = std::min(nearest + 1, t.centre_line.size() - 1), i = j - 1;
    const Vec3 tangent = t.centre_line[j] - t.centre_line[i];
    std::vector<Vec3> line;
    for (const Vec3& p : t.centre_line) {
        if (dot(p - centre, tangent) >= -1e-9 * norm(tangent) * norm(tangent)) break;
        line.push_back(p);
    }
    if (line.empty()) throw Error(Model::edge_name(edge_id_) + " lies at the tube's first end: no stretch for a ring");
    line.push_back(centre);
    t.centre_line = std::move(line);
    t.length = 0;
    for (std::size_t k = 1; k < t.centre_line.size(); ++k) t.length += norm(t.centre_line[k] - t.centre_line[k - 1]);
    t.faces.clear();
    for (index_t f : kept) t.faces.push_back(static_cast<int>(f));
    t.loops[1] = {edge_id_};
    t.hosts[1] = beyond;
    t.loop_lengths[1] = GCPnts_AbscissaPoint::Length(curve);
    t.stop = std::move(stop);
    return t;
}

TubeInfo whole_tube(const TubeInfo& stopped) {
    TubeInfo t = stopped;
    if (!stopped.stop || stopped.stop->stretch_only) {
        t.stop.reset();
        return t;
    }
    const TubeInfo::Stop& s = *stopped.stop;
    t.faces = s.wall;
    t.loops[1] = s.loop;
    t.hosts[1] = s.host;
    t.loop_lengths[1] = s.loop_length;
    t.length = s.length;
    t.centre_line = s.centre_line;
    t.stop.reset();
    return t;
}

std::vector<Vec3> edge_points(const Model& model, const std::vector<int>& edges) {
    std::vector<Vec3> out;
    for (int e : edges) {
        const TopoDS_Edge edge = edge_of(model, e);
        if (BRep_Tool::Degenerated(edge)) continue;
        const BRepAdaptor_Curve curve(edge);
        for (int k = 0; k <= 16; ++k)
            out.push_back(vec(curve.Value(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * k / 16)));
    }
    return out;
}

std::vector<int> same_faces_in(const Model& from, const Model& to) {
    std::vector<int> out;
    for (int f = 1; f <= from.face_count(); ++f) out.push_back(to.impl().faces.FindIndex(face_of(from, f)));
    return out;
}

}  // namespace tubemesh::geom
