#include "engine/surface/uv_insertion.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/vec3_ops.hpp"
#include "engine/surface/uv_predicates.hpp"

namespace tubemesh::surface {

Metric2 surface_metric(const SurfaceDerivatives& d) {
    const Vec3 &u = d.du, &v = d.dv;
    return {u.x * u.x + u.y * u.y + u.z * u.z, u.x * v.x + u.y * v.y + u.z * v.z, v.x * v.x + v.y * v.y + v.z * v.z};
}

MetricFactor::MetricFactor(const Metric2& m) {
    // A relative floor on both diagonal entries keeps U invertible at a singular point, where
    // one parameter direction has zero length, without changing regular metrics measurably.
    const double trace = m.a + m.c;
    if (!(trace > 0) || !std::isfinite(trace)) {
        u11 = 1, u12 = 0, u22 = 1;
        return;
    }
    const double floor = 1e-12 * trace;
    const double a = m.a + floor, c = m.c + floor;
    u11 = std::sqrt(a);
    u12 = m.b / u11;
    u22 = std::sqrt(std::max(c - u12 * u12, floor));
}

WalkResult locate(const UvMesh& mesh, index_t start, Uv p, index_t& found) {
    index_t t = start;
    // A walk that always tries the edges in the same order can circle forever in a triangulation
    // that is not Delaunay; varying the first edge tried (deterministically) breaks such cycles.
    std::uint32_t rotation = 0x9e3779b9u;
    const std::size_t limit = 4 * std::size_t{mesh.slot_count()} + 64;
    for (std::size_t step = 0; step < limit; ++step) {
        rotation = rotation * 1664525u + 1013904223u;
        const int first = static_cast<int>((rotation >> 16) % 3);
        int exit = -1;
        for (int r = 0; r < 3 && exit < 0; ++r) {
            const int i = (first + r) % 3;
            const index_t a = mesh.vertex(t, next3(i)), b = mesh.vertex(t, prev3(i));
            if (orient2d(mesh.uv[a], mesh.uv[b], p) < 0) exit = i;
        }
        if (exit < 0) {
            found = t;
            return WalkResult::Found;
        }
        if (mesh.constrained(t, exit) || mesh.neighbor(t, exit) == kNoIndex) return WalkResult::Blocked;
        t = mesh.neighbor(t, exit);
    }
    return WalkResult::Blocked;
}

namespace {

// p strictly inside the circumcircle of the counter-clockwise triangle (a, b, c), measured in
// the metric whose factor is f. Floating point: the caller checks the cavity's shape exactly.
bool in_circle(Uv a, Uv b, Uv c, Uv p, const MetricFactor& f) {
    const Uv A = f.apply(a.u - p.u, a.v - p.v);
    const Uv B = f.apply(b.u - p.u, b.v - p.v);
    const Uv C = f.apply(c.u - p.u, c.v - p.v);
    const double la = A.u * A.u + A.v * A.v, lb = B.u * B.u + B.v * B.v, lc = C.u * C.u + C.v * C.v;
    const double det = A.u * (B.v * lc - lb * C.v) - A.v * (B.u * lc - lb * C.u) + la * (B.u * C.v - B.v * C.u);
    return det > 0;
}

}  // namespace

bool Inserter::build_cavity(UvMesh& mesh, index_t t0, Uv p, const MetricFactor& f) {
    banned_.clear();
    while (true) {
        const std::uint32_t in = mesh.next_epoch(), out = in + 1;
        for (index_t t : banned_) mesh.mark[t] = out;
        cavity_.clear();
        cavity_.push_back(t0);
        mesh.mark[t0] = in;
        for (std::size_t k = 0; k < cavity_.size(); ++k) {
            const index_t t = cavity_[k];
            for (int i = 0; i < 3; ++i) {
                const index_t n = mesh.neighbor(t, i);
                if (n == kNoIndex || mesh.constrained(t, i) || mesh.mark[n] == in || mesh.mark[n] == out) continue;
                const index_t* w = &mesh.tv[3 * n];
                if (in_circle(mesh.uv[w[0]], mesh.uv[w[1]], mesh.uv[w[2]], p, f)) {
                    mesh.mark[n] = in;
                    cavity_.push_back(n);
                } else {
                    mesh.mark[n] = out;
                }
            }
        }
        rim_.clear();
        for (index_t t : cavity_) {
            for (int i = 0; i < 3; ++i) {
                const index_t n = mesh.neighbor(t, i);
                const bool c = mesh.constrained(t, i);
                if (n != kNoIndex && !c && mesh.mark[n] == in) continue;
                rim_.push_back({mesh.vertex(t, next3(i)), mesh.vertex(t, prev3(i)), mesh.adj[3 * t + i], t, c});
            }
        }
        // Star-shaped from p: every rim edge must see p strictly on its left. A rim edge that
        // does not disqualifies the cavity triangle it belongs to, and the cavity is grown
        // again without it; t0 holds p, so losing t0 means there is no valid cavity.
        const auto bad = std::find_if(rim_.begin(), rim_.end(),
                                      [&](const RimEdge& e) { return orient2d(mesh.uv[e.a], mesh.uv[e.b], p) <= 0; });
        if (bad == rim_.end()) return true;
        if (bad->owner == t0) return false;
        banned_.push_back(bad->owner);
    }
}

InsertStatus Inserter::insert(UvMesh& mesh, index_t start, const VertexData& v, double min_distance,
                              index_t& vertex) {
    created_.clear();
    duplicate_ = kNoIndex;
    index_t t0;
    if (locate(mesh, start, v.uv, t0) == WalkResult::Blocked) return InsertStatus::Blocked;
    for (int i = 0; i < 3; ++i) {
        const Uv q = mesh.uv[mesh.vertex(t0, i)];
        if (q.u == v.uv.u && q.v == v.uv.v) {
            duplicate_ = t0;
            return InsertStatus::Duplicate;
        }
    }
    if (!build_cavity(mesh, t0, v.uv, MetricFactor(v.metric))) return InsertStatus::NotStarShaped;
    if (min_distance > 0)
        for (const RimEdge& e : rim_)
            if (norm(mesh.xyz[e.a] - v.xyz) < min_distance) return InsertStatus::TooClose;

    const std::uint8_t inherited = mesh.flags[t0] & kInside;
    vertex = mesh.add_vertex(v);
    // rim_ holds as many edges as the cavity has triangles plus two (a disk around p): reuse the
    // cavity's slots, then take new ones.
    for (std::size_t k = 0; k < rim_.size(); ++k) {
        const RimEdge& e = rim_[k];
        index_t t;
        if (k < cavity_.size()) {
            t = cavity_[k];
            mesh.tv[3 * t] = e.a, mesh.tv[3 * t + 1] = e.b, mesh.tv[3 * t + 2] = vertex;
            ++mesh.gen[t];
            mesh.vtri[e.a] = mesh.vtri[e.b] = mesh.vtri[vertex] = t;
        } else {
            t = mesh.new_triangle(e.a, e.b, vertex);
        }
        mesh.flags[t] = static_cast<std::uint8_t>(inherited | (e.constrained ? kConstrainedEdge0 << 2 : 0));
        mesh.link(t, 2, e.outer);
        created_.push_back(t);
    }
    for (std::size_t k = rim_.size(); k < cavity_.size(); ++k) mesh.kill(cavity_[k]);
    // Around the new vertex: edge 0 of the triangle on rim edge (a, b) is b -> vertex, which is
    // edge 1 (vertex -> a') of the triangle whose rim edge starts at a' = b.
    if (fan_slot_.size() < mesh.vertex_count()) fan_slot_.resize(mesh.vertex_count());
    for (std::size_t k = 0; k < rim_.size(); ++k) fan_slot_[rim_[k].a] = created_[k];
    for (std::size_t k = 0; k < rim_.size(); ++k) mesh.link(created_[k], 0, fan_slot_[rim_[k].b], 1);
    return InsertStatus::Inserted;
}

}  // namespace tubemesh::surface
