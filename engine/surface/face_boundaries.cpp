#include "engine/surface/face_boundaries.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_set>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh::surface {

EdgeNodes add_edge_nodes(std::span<const EdgePolyline> edges, HybridMesh& mesh, std::span<const FixedEdgeNodes> fixed) {
    EdgeNodes out;
    out.nodes.reserve(edges.size());
    std::unordered_map<index_t, const FixedEdgeNodes*> fixed_of;
    for (const FixedEdgeNodes& f : fixed) fixed_of.emplace(f.edge, &f);
    // A fixed edge's vertices are its end nodes, for every polyline that ends there.
    for (const EdgePolyline& e : edges) {
        const auto it = fixed_of.find(e.edge);
        if (it == fixed_of.end()) continue;
        const std::vector<index_t>& ids = it->second->ids;
        if (ids.size() != e.points.size() || ids.size() < 2)
            throw Error("edge_" + std::to_string(e.edge) + ": " + std::to_string(ids.size()) +
                        " fixed nodes for a polyline of " + std::to_string(e.points.size()) + " points");
        if (e.first_vertex != 0) out.vertex_node.emplace(e.first_vertex, ids.front());
        if (e.last_vertex != 0) out.vertex_node.emplace(e.last_vertex, ids.back());
    }
    const auto vertex_node = [&](index_t vertex, const Vec3& p) {
        if (vertex == 0) return mesh.add_point(p.x, p.y, p.z);  // 0 is never a B-rep id: no vertex
        auto [it, fresh] = out.vertex_node.try_emplace(vertex, 0);
        if (fresh) it->second = mesh.add_point(p.x, p.y, p.z);
        return it->second;
    };
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const EdgePolyline& e = edges[i];
        const std::size_t n = e.points.size();
        if (n < 2 || e.params.size() != n)
            throw Error("edge_" + std::to_string(e.edge) + ": its polyline has " + std::to_string(n) + " points and " +
                        std::to_string(e.params.size()) + " parameters (needs at least 2 of each, equally many)");
        out.polyline_of.emplace(e.edge, static_cast<index_t>(i));
        if (const auto it = fixed_of.find(e.edge); it != fixed_of.end()) {
            out.nodes.push_back(it->second->ids);
            continue;
        }
        std::vector<index_t> ids(n);
        ids.front() = vertex_node(e.first_vertex, e.points.front());
        for (std::size_t k = 1; k + 1 < n; ++k) ids[k] = mesh.add_point(e.points[k].x, e.points[k].y, e.points[k].z);
        ids.back() = vertex_node(e.last_vertex, e.points.back());
        out.nodes.push_back(std::move(ids));
    }
    return out;
}

namespace {

// A segment up to this factor times h(x) is left alone: the face mesher accepts triangles with
// a circumradius up to 1.3 times the ideal one, so such a segment is no worse than they are.
constexpr double kLongSegment = 1.1;
// Edge nodes whose segments are shorter than this factor times h(x) become size sources.
constexpr double kShortSegment = 0.8;
// The integral of ds / t(s) is taken in steps of at most this fraction of t: h changes by at
// most g (0.25) times a step, so t is nearly constant over one.
constexpr double kStepFraction = 0.25;

// A point of the integration along a polyline: position = segment index + fraction along it.
struct Station {
    double position;
    double integral;  // of ds / t(s) from the polyline's start
};

EdgePolyline follow_one(const EdgePolyline& e, const EdgeOnFace* on_face, const SizeField& size,
                        std::vector<Station>& stations) {
    const std::size_t m = e.points.size() - 1;
    stations.clear();
    stations.push_back({0, 0});
    bool too_long = false;
    double integral = 0;
    for (std::size_t i = 0; i < m; ++i) {
        const Vec3 a = e.points[i], d = e.points[i + 1] - a;
        const double len = norm(d);
        if (!(len > 0)) {
            stations.push_back({double(i + 1), integral});
            continue;
        }
        // Trapezoids on 1 / t along the chord (close to the curve: its sagitta is small).
        double s = 0;
        double h = size.at(a);
        too_long = too_long || len > kLongSegment * h;
        double inv = 1 / std::min(h, len);
        while (s < len) {
            const double ds = std::min(kStepFraction * std::min(h, len), len - s);
            const double s1 = s + ds < len ? s + ds : len;
            const Vec3 x = s1 < len ? a + (s1 / len) * d : e.points[i + 1];
            h = size.at(x);
            too_long = too_long || len > kLongSegment * h;
            const double inv1 = 1 / std::min(h, len);
            integral += 0.5 * (inv + inv1) * (s1 - s);
            inv = inv1;
            s = s1;
            stations.push_back({s1 < len ? double(i) + s1 / len : double(i + 1), integral});
        }
    }
    if (!too_long) return e;
    if (on_face == nullptr || on_face->surface == nullptr)
        throw Error("edge_" + std::to_string(e.edge) + ": no face uses it, so it cannot be cut to the size field");

    const std::size_t min_segments = e.first_vertex == e.last_vertex ? 3 : 1;
    const std::size_t n = std::max(min_segments, static_cast<std::size_t>(std::ceil(integral - 1e-9)));
    EdgePolyline out;
    out.edge = e.edge;
    out.first_vertex = e.first_vertex;
    out.last_vertex = e.last_vertex;
    out.points.push_back(e.points.front());
    out.params.push_back(e.params.front());
    const SurfaceMap& surface = *on_face->surface;
    std::size_t k = 0;
    for (std::size_t j = 1; j < n; ++j) {
        const double target = integral * double(j) / double(n);
        while (k + 2 < stations.size() && stations[k + 1].integral < target) ++k;
        const Station &lo = stations[k], &hi = stations[k + 1];
        const double f = hi.integral > lo.integral ? (target - lo.integral) / (hi.integral - lo.integral) : 0.5;
        const double position = lo.position + std::clamp(f, 0.0, 1.0) * (hi.position - lo.position);
        const std::size_t i = std::min(static_cast<std::size_t>(position), m - 1);
        const double t = e.params[i] + (position - double(i)) * (e.params[i + 1] - e.params[i]);
        out.points.push_back(surface.point(surface.edge_uv(on_face->use, t)));
        out.params.push_back(t);
    }
    out.points.push_back(e.points.back());
    out.params.push_back(e.params.back());
    return out;
}

class BoundaryWriter {
public:
    BoundaryWriter(const HybridMesh& mesh, FaceBoundary& b) : mesh_(mesh), b_(b) {}
    void add(index_t id, Uv uv) {
        auto [it, fresh] = local_.try_emplace(id, b_.node_count());
        if (fresh) b_.add_node(id, mesh_.point(id));
        b_.add_loop_point(it->second, uv);
    }

private:
    const HybridMesh& mesh_;
    FaceBoundary& b_;
    std::unordered_map<index_t, index_t> local_;  // mesh point id -> boundary node
};

std::string face_label(const SurfaceMap& surface) { return "face_" + std::to_string(surface.face()); }

}  // namespace

void add_edge_faces(const SurfaceMap& surface, std::unordered_map<index_t, EdgeOnFace>& out) {
    for (const TrimLoop& loop : surface.trimming_loops(0))
        for (const EdgeUse& use : loop.edges) out.try_emplace(use.edge, EdgeOnFace{&surface, use});
}

std::vector<EdgePolyline> follow_size_field(std::span<const EdgePolyline> edges,
                                            const std::unordered_map<index_t, EdgeOnFace>& on_face,
                                            const SizeField& size) {
    std::vector<EdgePolyline> out;
    out.reserve(edges.size());
    std::vector<Station> stations;
    for (const EdgePolyline& e : edges) {
        if (e.points.size() < 2 || e.params.size() != e.points.size()) {
            out.push_back(e);  // add_edge_nodes reports it
            continue;
        }
        const auto it = on_face.find(e.edge);
        out.push_back(follow_one(e, it == on_face.end() ? nullptr : &it->second, size, stations));
    }
    return out;
}

void add_short_edge_sources(std::span<const EdgePolyline> edges, const SizeField& size, std::vector<SizeSource>& out) {
    for (const EdgePolyline& e : edges) {
        const std::size_t n = e.points.size();
        if (n < 2) continue;
        for (std::size_t k = 0; k < n; ++k) {
            const double before = k > 0 ? norm(e.points[k] - e.points[k - 1]) : 0;
            const double after = k + 1 < n ? norm(e.points[k + 1] - e.points[k]) : 0;
            const double local = k == 0 ? after : k + 1 == n ? before : 0.5 * (before + after);
            if (local > 0 && local < kShortSegment * size.at(e.points[k])) out.push_back({e.points[k], local});
        }
    }
}

FaceBoundary face_boundary(const SurfaceMap& surface, std::span<const EdgePolyline> edges,
                           const EdgeNodes& edge_nodes, std::span<const index_t> tube_loop_edges,
                           std::span<const HolePolygon> rings, const HybridMesh& mesh, double max_step) {
    const std::unordered_set<index_t> tube(tube_loop_edges.begin(), tube_loop_edges.end());
    FaceBoundary b;
    BoundaryWriter out(mesh, b);
    for (const TrimLoop& loop : surface.trimming_loops(max_step)) {
        const std::size_t uses = loop.edges.size();
        if (uses == 0) continue;
        if (std::all_of(loop.edges.begin(), loop.edges.end(), [&](const EdgeUse& u) { return tube.count(u.edge) > 0; }))
            continue;  // a tube's end: the ring's outer polygon stands in for it
        const auto polyline = [&](std::size_t u) {
            const auto it = edge_nodes.polyline_of.find(loop.edges[u].edge);
            return it == edge_nodes.polyline_of.end() ? kNoIndex : it->second;
        };
        // Start at an edge with a polyline, so a degenerate edge always follows the vertex it
        // collapses to.
        std::size_t first = 0;
        while (first < uses && polyline(first) == kNoIndex) ++first;
        if (first == uses)
            throw Error(face_label(surface) + ": a trimming loop has no discretised edge (only degenerate or unknown ones)");
        index_t last_node = kNoIndex;
        for (std::size_t r = 0; r < uses; ++r) {
            const std::size_t u = (first + r) % uses;
            const EdgeUse use = loop.edges[u];
            if (tube.count(use.edge))
                throw Error(face_label(surface) + ": edge_" + std::to_string(use.edge) +
                            " belongs to a tube's end loop but shares its trimming loop with other edges");
            const index_t p = polyline(u);
            if (p == kNoIndex) {
                // A degenerate edge: its uv samples all sit on the vertex before it.
                const std::size_t begin = loop.edge_begin[u];
                const std::size_t end = u + 1 < uses ? loop.edge_begin[u + 1] : loop.uv.size();
                if (begin >= end)
                    throw Error(face_label(surface) + ": edge_" + std::to_string(use.edge) +
                                " has no polyline and no uv samples: is it a degenerate edge?");
                for (std::size_t k = begin; k < end; ++k) out.add(last_node, loop.uv[k]);
                continue;
            }
            const EdgePolyline& e = edges[p];
            const std::vector<index_t>& ids = edge_nodes.nodes[p];
            const std::size_t n = ids.size();
            for (std::size_t k = 0; k + 1 < n; ++k) {
                const std::size_t i = use.forward ? k : n - 1 - k;
                out.add(ids[i], surface.edge_uv(use, e.params[i]));
            }
            last_node = use.forward ? ids.back() : ids.front();
        }
        b.close_loop();
    }
    for (const HolePolygon& ring : rings) {
        if (ring.nodes.size() != ring.uv.size() || ring.nodes.size() < 3)
            throw Error(face_label(surface) + ": a ring polygon has " + std::to_string(ring.nodes.size()) + " nodes and " +
                        std::to_string(ring.uv.size()) + " uv points (needs at least 3, equally many)");
        for (std::size_t k = 0; k < ring.nodes.size(); ++k) out.add(ring.nodes[k], ring.uv[k]);
        b.close_loop();
    }
    return b;
}

}  // namespace tubemesh::surface
