#include "engine/surface/boundary_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "engine/surface/uv_predicates.hpp"

namespace tubemesh::surface {

namespace {

std::string face_label(const SurfaceMap& surface) { return "face_" + std::to_string(surface.face()); }

std::string uv_text(Uv p) { return "(" + std::to_string(p.u) + ", " + std::to_string(p.v) + ")"; }

// Two triangles covering a box well beyond the loops' uv extent: every boundary vertex is
// inserted strictly inside it, so the hull never needs special cases.
void start_with_box(const FaceBoundary& boundary, UvMesh& mesh) {
    double lo_u = std::numeric_limits<double>::max(), hi_u = -lo_u, lo_v = lo_u, hi_v = -lo_u;
    for (const Uv& p : boundary.loop_uv) {
        lo_u = std::min(lo_u, p.u), hi_u = std::max(hi_u, p.u);
        lo_v = std::min(lo_v, p.v), hi_v = std::max(hi_v, p.v);
    }
    const double mu = std::max(hi_u - lo_u, 1e-9 * (1 + std::abs(lo_u))) * 2;
    const double mv = std::max(hi_v - lo_v, 1e-9 * (1 + std::abs(lo_v))) * 2;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Vec3 nowhere{nan, nan, nan};
    mesh.add_vertex({{lo_u - mu, lo_v - mv}, nowhere});
    mesh.add_vertex({{hi_u + mu, lo_v - mv}, nowhere});
    mesh.add_vertex({{hi_u + mu, hi_v + mv}, nowhere});
    mesh.add_vertex({{lo_u - mu, hi_v + mv}, nowhere});
    const index_t t0 = mesh.new_triangle(0, 1, 2);
    const index_t t1 = mesh.new_triangle(0, 2, 3);
    mesh.link(t0, 1, t1, 2);  // the diagonal 2-0
}

void insert_occurrences(const SurfaceMap& surface, const FaceBoundary& boundary, const SizeField& size,
                        UvMesh& mesh, Inserter& inserter, std::vector<index_t>& loop_vertex) {
    loop_vertex.assign(boundary.loop_node.size(), kNoIndex);
    index_t start = 0;
    for (std::size_t k = 0; k < boundary.loop_node.size(); ++k) {
        const index_t node = boundary.loop_node[k];
        const Uv p = boundary.loop_uv[k];
        const SurfaceDerivatives d = surface.derivatives(p);
        const Vec3& x = boundary.xyz[node];
        index_t v = kNoIndex;
        const InsertStatus s = inserter.insert(mesh, start, vertex_data(p, d, x, size.at(x), node), 0, v);
        if (s == InsertStatus::Duplicate) {
            const index_t t = inserter.duplicate_of();
            for (int i = 0; i < 3; ++i) {
                const index_t w = mesh.vertex(t, i);
                if (mesh.uv[w].u == p.u && mesh.uv[w].v == p.v) v = w;
            }
            if (mesh.node[v] != node)
                throw Error(face_label(surface) + ": boundary nodes " + std::to_string(boundary.node_id[node]) + " and " +
                            std::to_string(boundary.node_id[mesh.node[v]]) + " have the same uv " + uv_text(p) +
                            "; the face's trimming loops touch there, which the surface mesher cannot respect");
        } else if (s != InsertStatus::Inserted) {
            throw Error(face_label(surface) + ": could not place boundary node " + std::to_string(boundary.node_id[node]) +
                        " at uv " + uv_text(p) + " (it lies on another boundary segment?)");
        } else {
            start = inserter.created().front();
        }
        loop_vertex[k] = v;
    }
}

[[noreturn]] void throw_on_segment(const SurfaceMap& surface, const FaceBoundary& boundary, const UvMesh& mesh,
                                   index_t a, index_t b, index_t w) {
    throw Error(face_label(surface) + ": boundary node " + std::to_string(boundary.node_id[mesh.node[w]]) + " at uv " +
                uv_text(mesh.uv[w]) + " lies on the boundary segment from node " +
                std::to_string(boundary.node_id[mesh.node[a]]) + " to node " +
                std::to_string(boundary.node_id[mesh.node[b]]) + ": the face's loops touch or overlap there");
}

// The edges the segment a-b crosses, in order from a, as (right, left) vertex pairs.
void crossing_edges(const SurfaceMap& surface, const FaceBoundary& boundary, const UvMesh& mesh, index_t a,
                    index_t b, std::vector<std::pair<index_t, index_t>>& out) {
    out.clear();
    const Uv pa = mesh.uv[a], pb = mesh.uv[b];
    // The triangle around a whose wedge holds the direction to b.
    index_t t = mesh.vtri[a];
    int k = -1;
    for (index_t turn = 0;; ++turn) {
        const int ka = mesh.local_index(t, a);
        const index_t x = mesh.vertex(t, next3(ka)), y = mesh.vertex(t, prev3(ka));
        const int ox = orient2d(pa, mesh.uv[x], pb), oy = orient2d(pa, mesh.uv[y], pb);
        const auto ahead = [&](index_t w) {
            return (mesh.uv[w].u - pa.u) * (pb.u - pa.u) + (mesh.uv[w].v - pa.v) * (pb.v - pa.v) > 0;
        };
        if (ox == 0 && ahead(x)) throw_on_segment(surface, boundary, mesh, a, b, x);
        if (ox > 0 && oy < 0) {
            k = ka;
            break;
        }
        t = mesh.neighbor(t, next3(ka));
        if (t == kNoIndex || turn > mesh.slot_count()) break;
    }
    if (k < 0)
        throw Error(face_label(surface) + ": the triangulation around boundary node " +
                    std::to_string(boundary.node_id[mesh.node[a]]) + " is corrupt (no wedge towards the next node)");
    index_t x = mesh.vertex(t, next3(k)), y = mesh.vertex(t, prev3(k));
    int edge = k;
    while (true) {
        out.emplace_back(x, y);
        const index_t packed = mesh.adj[3 * t + edge];
        const index_t n = packed / 3;
        const int j = static_cast<int>(packed % 3);
        const index_t w = mesh.vertex(n, j);
        if (w == b) return;
        const int ow = orient2d(pa, pb, mesh.uv[w]);
        if (ow == 0) throw_on_segment(surface, boundary, mesh, a, b, w);
        t = n;
        if (ow > 0) {
            y = w;
            edge = next3(j);
        } else {
            x = w;
            edge = prev3(j);
        }
    }
}

bool segments_cross(Uv a, Uv b, Uv c, Uv d) {
    return orient2d(a, b, c) * orient2d(a, b, d) < 0 && orient2d(c, d, a) * orient2d(c, d, b) < 0;
}

void mark_constrained(UvMesh& mesh, index_t a, index_t b) {
    auto [t, i] = mesh.find_edge(a, b);
    if (t == kNoIndex) std::tie(t, i) = mesh.find_edge(b, a);
    mesh.set_constrained(t, i, true);
    const index_t packed = mesh.adj[3 * t + i];
    if (packed != kNoIndex) mesh.set_constrained(packed / 3, static_cast<int>(packed % 3), true);
}

// Sloan's edge recovery: flip the edges that cross a-b until none does.
void recover_segment(const SurfaceMap& surface, const FaceBoundary& boundary, UvMesh& mesh, index_t a,
                     index_t b, BoundaryScratch& scratch) {
    if (mesh.find_edge(a, b).first != kNoIndex || mesh.find_edge(b, a).first != kNoIndex) {
        mark_constrained(mesh, a, b);
        return;
    }
    auto& queue = scratch.crossing;
    crossing_edges(surface, boundary, mesh, a, b, queue);
    const Uv pa = mesh.uv[a], pb = mesh.uv[b];
    const std::size_t limit = 64 * (queue.size() + 4) * (queue.size() + 4);
    for (std::size_t head = 0; head < queue.size(); ++head) {
        if (head > limit)
            throw Error(face_label(surface) + ": cannot recover the boundary segment from node " +
                        std::to_string(boundary.node_id[mesh.node[a]]) + " to node " +
                        std::to_string(boundary.node_id[mesh.node[b]]) +
                        ": another boundary segment crosses it (self-intersecting trimming loops?)");
        const auto [x, y] = queue[head];
        auto [t, i] = mesh.find_edge(x, y);
        if (t == kNoIndex) continue;  // cannot happen: crossing edges are interior edges
        if (!mesh.flip(t, i)) {
            queue.emplace_back(x, y);  // not convex yet: later flips will make it so
            continue;
        }
        const index_t c = mesh.vertex(t, 0), d = mesh.vertex(t, 2);  // t = (c, x, d) after the flip
        if (segments_cross(pa, pb, mesh.uv[c], mesh.uv[d])) queue.emplace_back(c, d);
    }
    mark_constrained(mesh, a, b);
}

// Inside = odd number of boundary crossings from the box corners.
void classify(UvMesh& mesh, std::vector<index_t>& queue) {
    const std::uint32_t even = mesh.next_epoch(), odd = even + 1;
    queue.clear();
    queue.push_back(mesh.vtri[0]);
    mesh.mark[mesh.vtri[0]] = even;
    for (std::size_t k = 0; k < queue.size(); ++k) {
        const index_t t = queue[k];
        const std::uint32_t parity = mesh.mark[t];
        if (parity == odd) mesh.flags[t] |= kInside;
        for (int i = 0; i < 3; ++i) {
            const index_t n = mesh.neighbor(t, i);
            if (n == kNoIndex || mesh.mark[n] == even || mesh.mark[n] == odd) continue;
            const bool flip = mesh.constrained(t, i);
            mesh.mark[n] = flip ? (parity == even ? odd : even) : parity;
            queue.push_back(n);
        }
    }
}

}  // namespace

void triangulate_boundary(const SurfaceMap& surface, const FaceBoundary& boundary, const SizeField& size,
                          UvMesh& mesh, Inserter& inserter, BoundaryScratch& scratch) {
    mesh.clear();
    start_with_box(boundary, mesh);
    insert_occurrences(surface, boundary, size, mesh, inserter, scratch.loop_vertex);
    for (index_t l = 0; l < boundary.loop_count(); ++l) {
        const index_t begin = boundary.loop_begin[l], end = boundary.loop_begin[l + 1];
        for (index_t k = begin; k < end; ++k) {
            const index_t a = scratch.loop_vertex[k], b = scratch.loop_vertex[k + 1 < end ? k + 1 : begin];
            if (a != b) recover_segment(surface, boundary, mesh, a, b, scratch);
        }
    }
    classify(mesh, scratch.queue);
}

}  // namespace tubemesh::surface
