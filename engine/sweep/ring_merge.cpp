#include "engine/sweep/ring_merge.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "engine/core/vec3_ops.hpp"
#include "engine/sweep/ring_cells.hpp"

namespace tubemesh::sweep {
namespace {

RingCells cells_of(const TubePlan& p, index_t first) {
    return {first, static_cast<index_t>(p.n), static_cast<index_t>(p.layers), p.turn};
}

// The outer polygon of end e, as a hole of the host face (see RingEnd).
RingEnd outer_polygon(const TubePlan& p, const TubeData& tube, int e, index_t first_node) {
    const std::size_t ee = static_cast<std::size_t>(e);
    const EndSection& end = p.ends[ee];
    const Station& st = e == 0 ? p.line.stations.front() : p.line.stations.back();
    const std::size_t n = static_cast<std::size_t>(p.n), outer = static_cast<std::size_t>(p.layers) * n;
    // The solid's outward normal on the host points back along the tube at its first end and
    // onwards at its last (the tube runs into the solid from ring1's face to ring2's).
    const Vec3 outward = e == 0 ? -st.tangent : st.tangent;
    Vec3 normal{0, 0, 0};
    for (std::size_t k = 0; k < n; ++k)
        normal += cross(end.node[outer + k] - st.centre, end.node[outer + (k + 1) % n] - st.centre);
    const bool reverse = dot(normal, outward) > 0;  // counter-clockwise seen from outside

    RingEnd r;
    r.host = tube.stops[ee] ? 0 : e == 0 ? tube.host1 : tube.host2;
    r.station = e == 0 ? 0 : static_cast<index_t>(p.stations() - 1);
    const RingCells cells = cells_of(p, first_node);
    for (std::size_t q = 0; q < n; ++q) {
        const std::size_t k = reverse ? (n - q) % n : q;
        r.outer_nodes.push_back(cells.node(r.station, static_cast<index_t>(p.layers), static_cast<index_t>(k)));
        r.outer_xyz.push_back(end.node[outer + k]);
        r.outer_uv.push_back(end.uv[outer + k]);
    }
    // Continuous across a periodic host's seam: each uv within half a period of the one before.
    const ParamRange u = p.hosts[ee]->u_range(), v = p.hosts[ee]->v_range();
    for (std::size_t q = 1; q < n; ++q) {
        Uv& uv = r.outer_uv[q];
        const Uv& before = r.outer_uv[q - 1];
        if (u.period > 0) uv.u = before.u + std::remainder(uv.u - before.u, u.period);
        if (v.period > 0) uv.v = before.v + std::remainder(uv.v - before.v, v.period);
    }
    return r;
}

template <class Ids>
void put(std::vector<index_t>& to, std::size_t at, const Ids& ids) {
    std::copy(ids.begin(), ids.end(), to.begin() + static_cast<std::ptrdiff_t>(at));
}

// Numbers every tube's nodes, hexes and quads after those before it, names its groups, and
// fills in everything about it but the mesh arrays. Returns the mesh's new quad count.
std::size_t describe(HybridMesh& mesh, const std::vector<TubeData>& tubes, std::span<const TubePlan> plans,
                     const std::vector<std::vector<Vec3>>& nodes, std::span<const RingQuality> quality,
                     const SweepOptions& options, SweepResult& result) {
    SweepStats& stats = result.stats;
    stats.tubes = static_cast<index_t>(tubes.size());
    stats.min_scaled_jacobian = tubes.empty() ? 0.0 : std::numeric_limits<double>::infinity();
    double sum_jacobian = 0, sum_condition = 0;
    std::size_t node = mesh.x.size(), hex = mesh.cell_count(CellKind::Hex), face = mesh.face_count(FaceKind::Quad);
    std::size_t lateral = 0, end = 0, stop = 0;
    result.rings.resize(tubes.size());
    for (std::size_t t = 0; t < tubes.size(); ++t) {
        const TubePlan& p = plans[t];
        TubeRing& ring = result.rings[t];
        const index_t n = static_cast<index_t>(p.n), layers = static_cast<index_t>(p.layers);
        const index_t steps = static_cast<index_t>(p.stations() - 1);
        ring.tube = static_cast<index_t>(t);
        ring.circumferential = n;
        ring.radial_layers = layers;
        ring.stations = steps + 1;
        ring.sweep_size = p.sweep_size;
        ring.axial_step = p.line.length / steps;
        ring.twist = p.twist;
        ring.frame_fallback = p.line.frame_fallback;
        ring.centres.clear();
        for (const Station& s : p.line.stations) ring.centres.push_back(s.centre);
        ring.first_node = static_cast<index_t>(node);
        ring.first_hex = static_cast<index_t>(hex);
        ring.hex_count = steps * layers * n;
        ring.first_lateral_quad = static_cast<index_t>(lateral);
        ring.first_end_quad = static_cast<index_t>(end);
        ring.wall_group = mesh.surface_group_id("pipe_" + std::to_string(t + 1));
        ring.stopped = tubes[t].stops;
        const int stopped = int(ring.stopped[0]) + int(ring.stopped[1]);
        for (std::size_t e = 0; e < 2; ++e)
            if (!ring.stopped[e])
                ring.host_group[e] = mesh.surface_group_id("face_" + std::to_string(e == 0 ? tubes[t].host1 : tubes[t].host2));
        ring.first_stop_quad = static_cast<index_t>(stop);
        stop += std::size_t(stopped) * layers * n;
        if (options.store_boundary_faces) {
            ring.first_boundary_face = static_cast<index_t>(face);
            face += std::size_t{steps} * n + std::size_t(2 - stopped) * layers * n;
        }
        for (int e = 0; e < 2; ++e) ring.ends[static_cast<std::size_t>(e)] = outer_polygon(p, tubes[t], e, ring.first_node);
        const RingQuality& q = quality[t];
        ring.min_scaled_jacobian = q.min_jacobian;
        ring.mean_scaled_jacobian = q.sum_jacobian / ring.hex_count;
        ring.max_condition = q.max_condition;

        node += nodes[t].size();
        hex += ring.hex_count;
        lateral += std::size_t{steps} * n;
        end += 2 * std::size_t{layers} * n;
        stats.nodes += static_cast<index_t>(nodes[t].size());
        stats.hexes += ring.hex_count;
        stats.min_scaled_jacobian = std::min(stats.min_scaled_jacobian, q.min_jacobian);
        stats.max_condition = std::max(stats.max_condition, q.max_condition);
        sum_jacobian += q.sum_jacobian;
        sum_condition += q.sum_condition;
    }
    stats.outer_quads = stats.wall_quads = static_cast<index_t>(lateral);
    stats.end_quads = static_cast<index_t>(end);
    result.stop_quads.resize(4 * stop);
    if (stats.hexes > 0) {
        stats.mean_scaled_jacobian = sum_jacobian / stats.hexes;
        stats.mean_condition = sum_condition / stats.hexes;
    }
    return face;
}

// One chunk's part of the mesh arrays and of the result's quad arrays: the nodes of its
// stations, the hex layers and lateral quads starting there, and the end quads of an end
// station it holds.
void write(HybridMesh& mesh, const TubePlan& p, const std::vector<Vec3>& nodes, const StationChunk& chunk,
           const SweepOptions& options, SweepResult& result) {
    const TubeRing& ring = result.rings[chunk.tube];
    const index_t n = ring.circumferential, layers = ring.radial_layers, steps = ring.stations - 1;
    const std::size_t per_station = (std::size_t{layers} + 1) * n;
    for (std::size_t v = per_station * static_cast<std::size_t>(chunk.first);
         v < per_station * static_cast<std::size_t>(chunk.last); ++v) {
        mesh.x[ring.first_node + v] = nodes[v].x;
        mesh.y[ring.first_node + v] = nodes[v].y;
        mesh.z[ring.first_node + v] = nodes[v].z;
    }
    const RingCells cells = cells_of(p, ring.first_node);
    CellBlock& hexes = mesh.block(CellKind::Hex);
    FaceBlock& quads = mesh.block(FaceKind::Quad);
    const index_t first = static_cast<index_t>(chunk.first), last = std::min(static_cast<index_t>(chunk.last), steps);
    for (index_t i = first; i < last; ++i) {
        for (index_t j = 0; j < layers; ++j)
            for (index_t k = 0; k < n; ++k)
                put(hexes.nodes, 8 * (std::size_t{ring.first_hex} + (i * layers + j) * n + k), cells.hex(i, j, k));
        for (index_t k = 0; k < n; ++k) {
            const std::size_t q = std::size_t{ring.first_lateral_quad} + i * n + k;
            put(result.outer_quads, 4 * q, cells.outer_quad(i, k));
            put(result.wall_quads, 4 * q, cells.wall_quad(i, k));
            if (!options.store_boundary_faces) continue;
            const std::size_t f = std::size_t{ring.first_boundary_face} + i * n + k;
            put(quads.nodes, 4 * f, cells.wall_quad(i, k));
            quads.group[f] = ring.wall_group;
        }
    }
    for (index_t e = 0; e < 2; ++e) {
        const index_t station = e == 0 ? 0 : steps;
        if (station < static_cast<index_t>(chunk.first) || station >= static_cast<index_t>(chunk.last)) continue;
        for (index_t j = 0; j < layers; ++j)
            for (index_t k = 0; k < n; ++k) {
                const auto quad = cells.end_quad(station, e == 1, j, k);
                put(result.end_quads, 4 * (std::size_t{ring.first_end_quad} + (e * layers + j) * n + k), quad);
                // The ends before this one that have boundary quads, or that stop.
                const index_t slot = e == 1 && ring.stopped[0] == ring.stopped[1] ? 1 : 0;
                if (ring.stopped[e]) {
                    put(result.stop_quads, 4 * (std::size_t{ring.first_stop_quad} + (slot * layers + j) * n + k), quad);
                    continue;
                }
                if (!options.store_boundary_faces) continue;
                const std::size_t f = std::size_t{ring.first_boundary_face} + std::size_t{steps} * n + (slot * layers + j) * n + k;
                put(quads.nodes, 4 * f, quad);
                quads.group[f] = ring.host_group[e];
            }
    }
}

}  // namespace

SweepResult merge_rings(HybridMesh& mesh, const std::vector<TubeData>& tubes, std::span<const TubePlan> plans,
                        const std::vector<std::vector<Vec3>>& nodes, std::span<const RingQuality> quality,
                        std::span<const StationChunk> chunks, const SweepOptions& options) {
    std::size_t new_nodes = 0;
    for (const auto& v : nodes) new_nodes += v.size();
    if (mesh.x.size() + new_nodes > kNoIndex) throw Error("the hex rings would take the mesh past 2^32 nodes");

    SweepResult result;
    const index_t region = mesh.region_id("hex_ring");
    const std::size_t faces = describe(mesh, tubes, plans, nodes, quality, options, result);
    const std::size_t node_total = mesh.x.size() + new_nodes;
    const std::size_t hex_total = mesh.cell_count(CellKind::Hex) + result.stats.hexes;
    mesh.x.resize(node_total);
    mesh.y.resize(node_total);
    mesh.z.resize(node_total);
    mesh.block(CellKind::Hex).nodes.resize(8 * hex_total);
    mesh.block(CellKind::Hex).region.resize(hex_total, region);
    mesh.block(FaceKind::Quad).nodes.resize(4 * faces);
    mesh.block(FaceKind::Quad).group.resize(faces);
    result.outer_quads.resize(4 * std::size_t{result.stats.outer_quads});
    result.wall_quads.resize(4 * std::size_t{result.stats.wall_quads});
    result.end_quads.resize(4 * std::size_t{result.stats.end_quads});

    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t c = r.begin(); c != r.end(); ++c) {
            const StationChunk& chunk = chunks[c];
            write(mesh, plans[chunk.tube], nodes[chunk.tube], chunk, options, result);
        }
    });
    return result;
}

}  // namespace tubemesh::sweep
