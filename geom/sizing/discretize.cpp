#include "geom/sizing/discretize.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "engine/core/types.hpp"
#include "engine/sweep/sweep.hpp"
#include "geom/sizing/discretize_edges.hpp"
#include "geom/sizing/ring_room.hpp"
#include "geom/tubes/ring_stop.hpp"
#include "geom/tubes/tubes_axis.hpp"
#include "geom/tubes/tubes_topology.hpp"
#include "geom/tubes/tubes_wall.hpp"

namespace tubemesh::geom {
namespace {

Vec3 to_vec(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

std::string tube_name(const TubeInfo& t) {
    std::string s = "tube on face";
    if (t.faces.size() > 1) s += "s";
    for (std::size_t i = 0; i < t.faces.size(); ++i) s += (i ? ", " : " ") + std::to_string(t.faces[i]);
    return s;
}

TubeStation station(const AxisSample& s) {
    return {to_vec(s.centre.XYZ()), to_vec(s.tangent.XYZ()), to_vec(s.reference.XYZ()), s.radius};
}

// n nodes by arc length from `start`, turning right-handed about the station's tangent.
std::vector<Vec3> ring(const LoopCurve& loop, const LoopPoint& start, int n, const AxisSample& at) {
    const double step = loop.length() / n;
    const gp_Vec a(at.centre, start.p);
    const gp_Vec b(at.centre, loop.at(start.s + step).p);
    const double turn = a.Crossed(b).Dot(at.tangent) >= 0 ? 1.0 : -1.0;
    std::vector<Vec3> nodes{to_vec(start.p.XYZ())};
    for (int k = 1; k < n; ++k) nodes.push_back(to_vec(loop.at(start.s + turn * k * step).p.XYZ()));
    return nodes;
}

TubeData discretize_tube(const TopologyIndex& index, const TubeInfo& info, double sweep, int ring_nodes) {
    std::string why;
    const auto wall = TubeWall::build(index, candidate_of(index, info), TubeOptions{}, why);
    if (!wall) throw Error(tube_name(info) + " is not a tube wall: " + why);
    const auto axis = TubeAxis::build(*wall, kGeneratorStartFraction);
    if (!axis) throw Error(tube_name(info) + ": no generator line of its wall leads from one end loop to the other");

    TubeData t;
    for (int f : info.faces) t.wall_faces.push_back(static_cast<index_t>(f));
    t.host1 = static_cast<index_t>(info.hosts[0]);
    t.host2 = static_cast<index_t>(info.hosts[1]);
    for (int e : info.loops[0]) t.loop1_edges.push_back(static_cast<index_t>(e));
    for (int e : info.loops[1]) t.loop2_edges.push_back(static_cast<index_t>(e));

    const int layers = std::max(1, static_cast<int>(std::lround(axis->length() / sweep)));
    for (const AxisSample& s : axis->stations(layers)) t.stations.push_back(station(s));

    const int n = tube_ring_nodes(info, sweep, ring_nodes);
    // Node 0 of both rings is where generator line 0 leaves E1 and reaches E2: the same
    // position around the axis, whatever the loops' own parametrisations.
    t.ring1 = ring(wall->loop(0), axis->generator(0).start(), n, axis->samples().front());
    t.ring2 = ring(wall->loop(1), axis->generator(0).end(), n, axis->samples().back());
    return t;
}

}  // namespace

int tube_ring_nodes(const TubeInfo& tube, double sweep_size, int ring_nodes) {
    return ring_nodes > 0 ? ring_nodes : circumferential_count((tube.radius_min + tube.radius_max) / 2, sweep_size);
}

DiscreteGeometry discretize(const Model& model, const std::vector<TubeInfo>& tubes, const SizePlan& plan,
                            const DiscretizeOptions& options) {
    if (!(plan.size > 0)) throw Error("cannot discretise the edges: the mesh size S is not positive");
    if (!tubes.empty() && !(plan.sweep_size > 0))
        throw Error("cannot discretise the tubes: the sweep size St is not positive");
    const TopologyIndex index(model);
    DiscreteGeometry out;
    out.size = plan.size;
    out.sweep_size = plan.sweep_size;
    std::set<int> tube_edges;
    const std::vector<RingRoom> rooms =
        plan.local_ring ? ring_rooms(model, tubes, plan.sweep_size) : std::vector<RingRoom>(tubes.size());
    for (std::size_t i = 0; i < tubes.size(); ++i) {
        const TubeInfo& info = tubes[i];
        const bool own = i < options.tube_sweep_size.size() && options.tube_sweep_size[i] > 0;
        // A ring that stops follows the whole wall, then is cut back to its stretch.
        out.tubes.push_back(discretize_tube(index, info.stop ? whole_tube(info) : info,
                                            own ? options.tube_sweep_size[i] : plan.sweep_size, options.ring_nodes));
        if (info.stop) stop_ring_at_edge(model, info.stop->edge, out.tubes.back());
        out.tubes.back().room = rooms[i];
        for (int f : info.faces)
            for (const FaceWire& w : index.face_wires[f])
                for (const LoopEdge& e : w.edges) tube_edges.insert(e.edge);
    }
    out.edges = discretize_edges(model, tube_edges, plan.size, options.chordal);
    return out;
}

}  // namespace tubemesh::geom
