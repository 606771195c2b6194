#include "geom/sizing/junction.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <gp_Cylinder.hxx>

#include <algorithm>
#include <cmath>

#include "engine/core/vec3_ops.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/tubes/ring_stop.hpp"
#include "geom/tubes/tubes_topology.hpp"

namespace tubemesh::geom {
namespace {

Vec3 vec(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

// Two cylinders are one pipe when their axes and radii agree within this share of the radius.
constexpr double kSameAxis = 1e-6;

}  // namespace

std::vector<JunctionPipe> junction_pipes(const Model& model, const std::vector<int>& group, const std::set<int>& walls) {
    std::vector<JunctionPipe> pipes;
    for (int f : group) {
        const BRepAdaptor_Surface surface(face_of(model, f));
        if (surface.GetType() != GeomAbs_Cylinder) continue;
        const gp_Cylinder c = surface.Cylinder();
        const Vec3 o = vec(c.Location().XYZ()), d = vec(c.Axis().Direction().XYZ());
        const double r = c.Radius();
        const auto same = std::find_if(pipes.begin(), pipes.end(), [&](const JunctionPipe& p) {
            const Vec3 off = o - p.origin;
            return std::abs(r - p.radius) <= kSameAxis * r && norm(cross(d, p.axis)) <= kSameAxis &&
                   norm(off - dot(off, p.axis) * p.axis) <= kSameAxis * r;
        });
        if (same != pipes.end())
            same->faces.push_back(f);
        else
            pipes.push_back({{f}, o, d, r, {}, {}});
    }
    const TopologyIndex index(model);
    for (JunctionPipe& p : pipes) {
        const auto own = [&](int g) { return std::binary_search(p.faces.begin(), p.faces.end(), g); };
        for (int f : p.faces)
            for (const FaceWire& w : index.face_wires[static_cast<std::size_t>(f)])
                for (const LoopEdge& e : w.edges) {
                    if (index.degenerate[static_cast<std::size_t>(e.edge)]) continue;
                    const std::vector<int>& around = index.edge_faces[static_cast<std::size_t>(e.edge)];
                    const auto other = std::find_if_not(around.begin(), around.end(), own);
                    if (other == around.end()) continue;  // a seam, or between two of its faces
                    const bool wall = walls.count(*other) || std::binary_search(group.begin(), group.end(), *other);
                    for (const Vec3& q : edge_points(model, {e.edge}))
                        (wall ? p.junction : p.open).push_back(dot(q - p.origin, p.axis));
                }
    }
    return pipes;
}

std::vector<RingCut> junction_cuts(const JunctionPipe& pipe, double margin_diameters) {
    if (pipe.junction.empty() || pipe.open.empty()) return {};
    const auto [jlo, jhi] = std::minmax_element(pipe.junction.begin(), pipe.junction.end());
    const double margin = margin_diameters * 2 * pipe.radius, shortest = kShortestStoppedRing * 2 * pipe.radius;
    std::vector<RingCut> cuts;
    // The open end before the junctions (its point nearest them), then the one after.
    double before = -HUGE_VAL, after = HUGE_VAL;
    for (double t : pipe.open) {
        if (t < *jlo) before = std::max(before, t);
        if (t > *jhi) after = std::min(after, t);
    }
    if (std::isfinite(before) && *jlo - margin - before >= shortest) {
        RingCut c;
        c.centre = pipe.origin + (*jlo - margin) * pipe.axis;
        c.tangent = pipe.axis;
        c.keep = pipe.origin + before * pipe.axis;
        c.kept_length = *jlo - margin - before;
        c.spot = *jlo - before;
        cuts.push_back(c);
    }
    if (std::isfinite(after) && after - (*jhi + margin) >= shortest) {
        RingCut c;
        c.centre = pipe.origin + (*jhi + margin) * pipe.axis;
        c.tangent = pipe.axis;
        c.keep = pipe.origin + after * pipe.axis;
        c.kept_length = after - (*jhi + margin);
        c.spot = after - *jhi;
        cuts.push_back(c);
    }
    return cuts;
}

std::optional<TubeInfo> stretch_tube(const Model& model, const std::vector<int>& group, int cut, const Vec3& keep) {
    const TopologyIndex index(model);
    if (cut <= 0 || cut >= static_cast<int>(index.edge_faces.size())) return std::nullopt;
    const auto in_group = [&](int f) { return std::binary_search(group.begin(), group.end(), f); };
    std::vector<int> sides;
    for (int f : index.edge_faces[static_cast<std::size_t>(cut)])
        if (in_group(f)) sides.push_back(f);
    if (sides.size() != 2) return std::nullopt;
    const int start = wall_face_at(model, sides, keep);
    const int beyond = sides[0] == start ? sides[1] : sides[0];
    // The group's faces reached from `start` without crossing the cut or a hole loop.
    std::set<int> faces{start};
    std::vector<int> todo{start};
    while (!todo.empty()) {
        const int f = todo.back();
        todo.pop_back();
        for (const FaceWire& w : index.face_wires[static_cast<std::size_t>(f)])
            for (const LoopEdge& e : w.edges) {
                if (e.edge == cut || index.in_hole[static_cast<std::size_t>(e.edge)]) continue;
                for (int g : index.edge_faces[static_cast<std::size_t>(e.edge)])
                    if (in_group(g) && faces.insert(g).second) todo.push_back(g);
            }
    }
    if (faces.count(beyond)) return std::nullopt;

    TubeCandidate c;
    c.faces.assign(faces.begin(), faces.end());
    // Loop 2: the cut, on the face beyond.
    for (std::size_t w = 0; w < index.face_wires[static_cast<std::size_t>(beyond)].size(); ++w)
        for (const LoopEdge& e : index.face_wires[static_cast<std::size_t>(beyond)][w].edges)
            if (e.edge == cut)
                c.loops[1] = {beyond, static_cast<int>(w), {e}, index.edge_length[static_cast<std::size_t>(cut)]};
    if (c.loops[1].edges.empty()) return std::nullopt;
    // Loop 1: the one hole of another face every other edge on the stretch's boundary lies in.
    std::set<std::pair<int, int>> wires;
    for (int f : c.faces)
        for (const FaceWire& w : index.face_wires[static_cast<std::size_t>(f)])
            for (const LoopEdge& e : w.edges) {
                if (e.edge == cut || index.degenerate[static_cast<std::size_t>(e.edge)]) continue;
                for (int g : index.edge_faces[static_cast<std::size_t>(e.edge)]) {
                    if (faces.count(g)) continue;
                    const std::vector<FaceWire>& gw = index.face_wires[static_cast<std::size_t>(g)];
                    for (std::size_t k = 0; k < gw.size(); ++k)
                        for (const LoopEdge& le : gw[k].edges)
                            if (le.edge == e.edge) wires.insert({g, static_cast<int>(k)});
                }
            }
    if (wires.size() != 1) return std::nullopt;
    const auto [host, wire] = *wires.begin();
    const FaceWire& open = index.face_wires[static_cast<std::size_t>(host)][static_cast<std::size_t>(wire)];
    if (open.outer) return std::nullopt;
    c.loops[0] = {host, wire, open.edges, 0.0};
    for (const LoopEdge& e : open.edges)
        if (!index.degenerate[static_cast<std::size_t>(e.edge)]) c.loops[0].length += index.edge_length[static_cast<std::size_t>(e.edge)];
    std::string why;
    return candidate_tube(index, c, why);
}

}  // namespace tubemesh::geom
