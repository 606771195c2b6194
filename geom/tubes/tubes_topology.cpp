#include "geom/tubes/tubes_topology.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <set>
#include <sstream>

#include "engine/core/types.hpp"
#include "geom/model/model_occt.hpp"

namespace tubemesh::geom {
namespace {

// A candidate larger than this is not a bounded feature: the flood escaped into the body.
constexpr std::size_t kMaxTubeFaces = 256;

std::vector<LoopEdge> wire_edges(const Model& model, const TopoDS_Wire& wire, const TopoDS_Face& face) {
    std::vector<LoopEdge> out;
    for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next())
        out.push_back({edge_id(model, it.Current()), it.Orientation() != TopAbs_REVERSED});
    // The explorer needs a connected wire; a broken one still has edges worth knowing about.
    if (out.empty()) {
        for (TopoDS_Iterator it(wire); it.More(); it.Next())
            out.push_back({edge_id(model, it.Value()), it.Value().Orientation() != TopAbs_REVERSED});
    }
    return out;
}

// Faces reachable from `seeds` across edges that are not in any hole: a hole loop is where a
// tube meets its host, so it is the one place the flood must stop.
std::vector<int> flood(const TopologyIndex& index, const std::vector<int>& seeds) {
    std::set<int> group(seeds.begin(), seeds.end());
    std::vector<int> todo(seeds.begin(), seeds.end());
    while (!todo.empty() && group.size() <= kMaxTubeFaces) {
        const int f = todo.back();
        todo.pop_back();
        for (const FaceWire& w : index.face_wires[f])
            for (const LoopEdge& e : w.edges) {
                if (index.in_hole[e.edge]) continue;
                for (int g : index.edge_faces[e.edge])
                    if (group.insert(g).second) todo.push_back(g);
            }
    }
    return {group.begin(), group.end()};
}

double mean_outer_edge_length(const TopologyIndex& index, int face) {
    double sum = 0;
    int count = 0;
    for (const FaceWire& w : index.face_wires[face]) {
        if (!w.outer) continue;
        for (const LoopEdge& e : w.edges) {
            if (index.degenerate[e.edge]) continue;
            sum += index.edge_length[e.edge];
            ++count;
        }
    }
    return count ? sum / count : 0.0;
}

// Checks the group's boundary against rules 2-6. Returns an empty string and fills `loops`
// when it is two complete holes of outside faces that pass the length rule.
std::string check_boundary(const TopologyIndex& index, const std::vector<int>& group, const TubeOptions& options,
                           std::array<HoleLoop, 2>& loops, int& loop_count) {
    const auto inside = [&](int f) { return std::binary_search(group.begin(), group.end(), f); };
    std::set<int> boundary;
    for (int f : group)
        for (const FaceWire& w : index.face_wires[f])
            for (const LoopEdge& e : w.edges) {
                if (index.degenerate[e.edge]) continue;
                const auto& around = index.edge_faces[e.edge];
                const bool free_edge =
                    around.size() == 1 && !BRep_Tool::IsClosed(edge_of(index.model, e.edge), face_of(index.model, f));
                if (free_edge || std::any_of(around.begin(), around.end(), [&](int g) { return !inside(g); }))
                    boundary.insert(e.edge);
            }

    // Which wires of which outside faces the boundary edges belong to.
    std::set<std::pair<int, int>> wires;
    for (int e : boundary) {
        bool found = false;
        for (int g : index.edge_faces[e]) {
            if (inside(g)) continue;
            const auto& gw = index.face_wires[g];
            for (std::size_t k = 0; k < gw.size(); ++k)
                for (const LoopEdge& le : gw[k].edges)
                    if (le.edge == e) {
                        wires.insert({g, static_cast<int>(k)});
                        found = true;
                    }
        }
        if (!found) return "edge " + std::to_string(e) + " on its boundary belongs to no other face (open shell)";
    }
    loop_count = static_cast<int>(wires.size());
    if (wires.size() != 2) {
        return wires.size() == 1 ? "bounded by one loop (a blind hole or a pocket)"
                                 : "bounded by " + std::to_string(wires.size()) + " loops, a tube has two";
    }

    std::set<int> covered;
    int k = 0;
    for (const auto& [g, w] : wires) {
        const FaceWire& fw = index.face_wires[g][w];
        if (fw.outer)
            return "loop on face " + std::to_string(g) + " is that face's outer boundary, not a hole (an end cap)";
        HoleLoop& loop = loops[k++];
        loop.host = g;
        loop.wire = w;
        loop.edges = fw.edges;
        loop.length = 0;
        for (const LoopEdge& e : fw.edges) {
            covered.insert(e.edge);
            if (!index.degenerate[e.edge]) loop.length += index.edge_length[e.edge];
        }
        const double mean = mean_outer_edge_length(index, g);
        if (!(loop.length < options.max_loop_ratio * mean)) {
            std::ostringstream s;
            s << "hole in face " << g << " is too large for the tube rule: length " << loop.length
              << " >= " << options.max_loop_ratio << " x mean outer edge length " << mean;
            return s.str();
        }
    }
    if (covered != boundary) return "its boundary is not made of two complete holes";

    // Deterministic E1: smaller host id, then smaller first edge id.
    const auto first_edge = [](const HoleLoop& l) {
        int m = l.edges.empty() ? 0 : l.edges.front().edge;
        for (const LoopEdge& e : l.edges) m = std::min(m, e.edge);
        return m;
    };
    if (loops[1].host < loops[0].host ||
        (loops[1].host == loops[0].host && first_edge(loops[1]) < first_edge(loops[0])))
        std::swap(loops[0], loops[1]);
    return {};
}

}  // namespace

TopologyIndex::TopologyIndex(const Model& m) : model(m) {
    const int nf = m.face_count();
    const int ne = m.edge_count();
    edge_faces.assign(ne + 1, {});
    face_wires.assign(nf + 1, {});
    in_hole.assign(ne + 1, 0);
    degenerate.assign(ne + 1, 0);
    edge_length.assign(ne + 1, 0.0);

    TopTools_IndexedDataMapOfShapeListOfShape ancestors;
    TopExp::MapShapesAndAncestors(solid_of(m), TopAbs_EDGE, TopAbs_FACE, ancestors);
    for (int i = 1; i <= ancestors.Extent(); ++i) {
        const int e = edge_id(m, ancestors.FindKey(i));
        if (e == 0) continue;
        std::vector<int>& faces = edge_faces[e];
        for (const TopoDS_Shape& f : ancestors(i)) faces.push_back(face_id(m, f));
        std::sort(faces.begin(), faces.end());
        faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    }

    for (int e = 1; e <= ne; ++e) {
        const TopoDS_Edge edge = edge_of(m, e);
        degenerate[e] = BRep_Tool::Degenerated(edge);
        if (!degenerate[e]) {
            BRepAdaptor_Curve curve(edge);
            edge_length[e] = GCPnts_AbscissaPoint::Length(curve);
        }
    }

    for (int f = 1; f <= nf; ++f) {
        const TopoDS_Face face = face_of(m, f);
        const TopoDS_Wire outer = BRepTools::OuterWire(face);
        for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next()) {
            const TopoDS_Wire wire = TopoDS::Wire(it.Current());
            FaceWire fw{wire_edges(m, wire, face), wire.IsSame(outer)};
            if (!fw.outer)
                for (const LoopEdge& e : fw.edges) in_hole[e.edge] = 1;
            face_wires[f].push_back(std::move(fw));
        }
    }
}

CandidateSearch find_tube_candidates(const TopologyIndex& index, const TubeOptions& options) {
    CandidateSearch out;
    std::set<std::vector<int>> seen;
    for (int host = 1; host < static_cast<int>(index.face_wires.size()); ++host) {
        for (const FaceWire& w : index.face_wires[host]) {
            if (w.outer) continue;
            std::vector<int> seeds;
            for (const LoopEdge& e : w.edges)
                for (int g : index.edge_faces[e.edge])
                    if (g != host) seeds.push_back(g);
            if (seeds.empty()) continue;
            std::vector<int> group = flood(index, seeds);
            if (!seen.insert(group).second) continue;
            if (group.size() > kMaxTubeFaces) {
                out.rejected.push_back(
                    {{}, "the faces behind a hole in face " + std::to_string(host) + " are not a bounded feature"});
                continue;
            }
            TubeCandidate c;
            int loop_count = -1;
            const std::string why = check_boundary(index, group, options, c.loops, loop_count);
            if (!why.empty()) {
                out.rejected.push_back({group, why, loop_count});
                continue;
            }
            c.faces = std::move(group);
            out.candidates.push_back(std::move(c));
        }
    }
    return out;
}

TubeCandidate candidate_of(const TopologyIndex& index, const TubeInfo& tube) {
    TubeCandidate c;
    c.faces = tube.faces;
    for (int k = 0; k < 2; ++k) {
        const int host = tube.hosts[k];
        const bool valid = host >= 1 && host < static_cast<int>(index.face_wires.size()) && !tube.loops[k].empty();
        const auto& wires = valid ? index.face_wires[host] : std::vector<FaceWire>{};
        for (std::size_t w = 0; w < wires.size() && c.loops[k].edges.empty(); ++w)
            for (const LoopEdge& e : wires[w].edges)
                if (e.edge == tube.loops[k].front()) {
                    // A stretch of wall ends on a cut, one edge of the face beyond's wire.
                    std::vector<LoopEdge> edges;
                    for (const LoopEdge& le : wires[w].edges)
                        if (std::find(tube.loops[k].begin(), tube.loops[k].end(), le.edge) != tube.loops[k].end())
                            edges.push_back(le);
                    c.loops[k] = {host, static_cast<int>(w), edges, 0.0};
                    for (const LoopEdge& le : edges)
                        if (!index.degenerate[le.edge]) c.loops[k].length += index.edge_length[le.edge];
                    break;
                }
        if (c.loops[k].edges.empty())
            throw Error("tube on faces " + std::to_string(tube.faces.front()) + ", ... has no loop " +
                        std::to_string(k + 1) + " in face " + std::to_string(host) + " of this model");
    }
    return c;
}

}  // namespace tubemesh::geom
