#include "engine/surface/face_boundaries.hpp"

#include <algorithm>
#include <string>
#include <unordered_set>

namespace tubemesh::surface {

EdgeNodes add_edge_nodes(std::span<const EdgePolyline> edges, HybridMesh& mesh) {
    EdgeNodes out;
    out.nodes.reserve(edges.size());
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
        std::vector<index_t> ids(n);
        ids.front() = vertex_node(e.first_vertex, e.points.front());
        for (std::size_t k = 1; k + 1 < n; ++k) ids[k] = mesh.add_point(e.points[k].x, e.points[k].y, e.points[k].z);
        ids.back() = vertex_node(e.last_vertex, e.points.back());
        out.polyline_of.emplace(e.edge, static_cast<index_t>(i));
        out.nodes.push_back(std::move(ids));
    }
    return out;
}

namespace {

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
