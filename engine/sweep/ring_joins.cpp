#include "engine/sweep/ring_joins.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh {
namespace {

double distance(const HybridMesh& m, index_t a, index_t b) { return std::sqrt(distance2(m.point(a), m.point(b))); }

index_t end_station(const TubeRing& ring, int end) { return end == 0 ? 0 : ring.stations - 1; }

// tube_b's nodes on its joined end station (one block of ids) -> tube_a's.
struct StationMap {
    index_t first = 0;
    std::vector<index_t> to;
    index_t operator()(index_t v) const { return v >= first && v - first < to.size() ? to[v - first] : v; }
};

std::string pair_name(const RingJoin& j) {
    return "the rings of tube " + std::to_string(j.tube_a + 1) + " and tube " + std::to_string(j.tube_b + 1);
}

// Each node of b's end cross-section to the nearest of a's in the same radial layer, one to one.
StationMap match_station(const HybridMesh& mesh, const TubeRing& a, const TubeRing& b, const RingJoin& join,
                         double tolerance, double& gap) {
    if (a.circumferential != b.circumferential || a.radial_layers != b.radial_layers)
        throw Error(pair_name(join) + " meet on a face but have " + std::to_string(a.circumferential) + " and " +
                    std::to_string(b.circumferential) + " nodes around: give both pieces of the pipe one St");
    const index_t n = a.circumferential, layers = a.radial_layers;
    const index_t ia = end_station(a, join.end_a), ib = end_station(b, join.end_b);
    StationMap map{b.node(ib, 0, 0), std::vector<index_t>(std::size_t{layers + 1} * n)};
    for (index_t j = 0; j <= layers; ++j) {
        std::vector<char> taken(n, 0);
        for (index_t k = 0; k < n; ++k) {
            const index_t v = b.node(ib, j, k);
            index_t best = 0;
            double nearest = std::numeric_limits<double>::infinity();
            for (index_t ka = 0; ka < n; ++ka)
                if (const double d = distance(mesh, v, a.node(ia, j, ka)); d < nearest) {
                    nearest = d;
                    best = ka;
                }
            if (!(nearest <= tolerance) || taken[best])
                throw Error(pair_name(join) + " do not meet node for node where the pipe crosses from one into the "
                                              "other: a node lies " +
                            std::to_string(nearest) + " from the nearest of the other ring (more than " +
                            std::to_string(tolerance) + ")");
            taken[best] = 1;
            map.to[std::size_t{j} * n + k] = a.node(ia, j, best);
            gap = std::max(gap, nearest);
        }
    }
    return map;
}

void remap(std::vector<index_t>& ids, std::size_t first, std::size_t count, const StationMap& map) {
    for (std::size_t i = first; i < first + count; ++i) ids[i] = map(ids[i]);
}

// Every id of ring b that may name a node of the joined station.
void remap_ring(HybridMesh& mesh, SweepResult& sweep, TubeRing& b, const StationMap& map) {
    const std::size_t n = b.circumferential, layers = b.radial_layers, steps = b.stations - 1;
    remap(mesh.block(CellKind::Hex).nodes, 8 * std::size_t{b.first_hex}, 8 * std::size_t{b.hex_count}, map);
    remap(sweep.outer_quads, 4 * std::size_t{b.first_lateral_quad}, 4 * steps * n, map);
    remap(sweep.wall_quads, 4 * std::size_t{b.first_lateral_quad}, 4 * steps * n, map);
    remap(sweep.end_quads, 4 * std::size_t{b.first_end_quad}, 8 * layers * n, map);
    if (b.first_boundary_face != kNoIndex)
        remap(mesh.block(FaceKind::Quad).nodes, 4 * std::size_t{b.first_boundary_face}, 4 * (steps + 2 * layers) * n, map);
    for (RingEnd& end : b.ends)
        for (index_t& v : end.outer_nodes) v = map(v);
}

// Each chain of joined tubes takes the wall group of its first tube, named after its pipe; the
// wall groups left empty take the names after the last pipe's, so no two groups share a name.
void one_group_per_chain(HybridMesh& mesh, SweepResult& sweep, const std::vector<RingJoin>& joins) {
    const std::vector<index_t> pipe = pipe_of_tubes(sweep.rings.size(), joins);
    std::vector<index_t> first_tube, empty_groups;
    for (const TubeRing& ring : sweep.rings) {
        if (pipe[ring.tube] == first_tube.size()) first_tube.push_back(ring.tube);
        else empty_groups.push_back(ring.wall_group);
    }
    std::vector<index_t> named;
    for (index_t t : first_tube) named.push_back(sweep.rings[t].wall_group);
    named.insert(named.end(), empty_groups.begin(), empty_groups.end());
    for (std::size_t k = 0; k < named.size(); ++k)
        mesh.surface_group_names[named[k]] = "pipe_" + std::to_string(k + 1);
    FaceBlock& quads = mesh.block(FaceKind::Quad);
    for (TubeRing& ring : sweep.rings) {
        ring.wall_group = sweep.rings[first_tube[pipe[ring.tube]]].wall_group;
        if (ring.first_boundary_face == kNoIndex) continue;
        const std::size_t first = ring.first_boundary_face, count = std::size_t{ring.stations - 1} * ring.circumferential;
        std::fill(quads.group.begin() + first, quads.group.begin() + first + count, ring.wall_group);
    }
}

// The boundary quads marked in `drop` leave; the rings' first_boundary_face follow.
void drop_quads(HybridMesh& mesh, SweepResult& sweep, const std::vector<char>& drop) {
    FaceBlock& quads = mesh.block(FaceKind::Quad);
    std::vector<index_t> before(drop.size() + 1, 0);
    for (std::size_t f = 0; f < drop.size(); ++f) before[f + 1] = before[f] + drop[f];
    FaceBlock kept;
    for (std::size_t f = 0; f < drop.size(); ++f) {
        if (drop[f]) continue;
        kept.nodes.insert(kept.nodes.end(), quads.nodes.begin() + 4 * f, quads.nodes.begin() + 4 * f + 4);
        kept.group.push_back(quads.group[f]);
    }
    quads = std::move(kept);
    for (TubeRing& ring : sweep.rings)
        if (ring.first_boundary_face != kNoIndex) ring.first_boundary_face -= before[ring.first_boundary_face];
}

}  // namespace

std::vector<index_t> pipe_of_tubes(std::size_t tubes, const std::vector<RingJoin>& joins) {
    std::vector<index_t> head(tubes);
    std::iota(head.begin(), head.end(), index_t{0});
    const auto find = [&](index_t t) {
        while (head[t] != t) t = head[t] = head[head[t]];
        return t;
    };
    for (const RingJoin& j : joins) {
        const index_t a = find(j.tube_a), b = find(j.tube_b);
        head[std::max(a, b)] = std::min(a, b);
    }
    std::vector<index_t> pipe(tubes, kNoIndex);
    index_t pipes = 0;
    for (index_t t = 0; t < tubes; ++t) {
        const index_t h = find(t);  // a chain's first tube, so h <= t: its number is known
        pipe[t] = h == t ? pipes++ : pipe[h];
    }
    return pipe;
}

double join_ring_ends(HybridMesh& mesh, SweepResult& sweep, const std::vector<RingJoin>& joins, double tolerance) {
    double gap = 0;
    std::vector<char> drop(mesh.face_count(FaceKind::Quad), 0);
    for (const RingJoin& j : joins) {
        if (j.tube_a >= sweep.rings.size() || j.tube_b >= sweep.rings.size() || j.tube_a == j.tube_b)
            throw Error("a ring join names tube " + std::to_string(j.tube_b + 1) + " and tube " +
                        std::to_string(j.tube_a + 1) + " of " + std::to_string(sweep.rings.size()));
        TubeRing& b = sweep.rings[j.tube_b];
        const StationMap map = match_station(mesh, sweep.rings[j.tube_a], b, j, tolerance, gap);
        remap_ring(mesh, sweep, b, map);
        b.ends[static_cast<std::size_t>(j.end_b)].host = 0;
        if (b.first_boundary_face == kNoIndex) continue;
        const std::size_t n = b.circumferential, layers = b.radial_layers;
        const std::size_t first = b.first_boundary_face + std::size_t{b.stations - 1} * n + j.end_b * layers * n;
        std::fill(drop.begin() + first, drop.begin() + first + layers * n, 1);
    }
    one_group_per_chain(mesh, sweep, joins);
    drop_quads(mesh, sweep, drop);
    return gap;
}

}  // namespace tubemesh
