#include "engine/surface/uv_mesh.hpp"

#include <cmath>

#include "engine/surface/uv_predicates.hpp"

namespace tubemesh::surface {

void UvMesh::clear() {
    uv.clear();
    xyz.clear();
    size.clear();
    metric.clear();
    normal.clear();
    node.clear();
    vtri.clear();
    tv.clear();
    adj.clear();
    flags.clear();
    gen.clear();
    mark.clear();
    free_slots.clear();
    epoch = 0;
}

VertexData vertex_data(Uv uv, const SurfaceDerivatives& d, const Vec3& xyz, double size, index_t node) {
    const Vec3 &u = d.du, &v = d.dv;
    Vec3 n{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
    const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    const double uu = u.x * u.x + u.y * u.y + u.z * u.z, vv = v.x * v.x + v.y * v.y + v.z * v.z;
    // Singular where du x dv vanishes against |du||dv| (a pole, an apex): no direction there.
    if (!(len > 1e-6 * std::sqrt(uu * vv))) n = {0, 0, 0};
    else n = {n.x / len, n.y / len, n.z / len};
    return {uv, xyz, size, node, {uu, u.x * v.x + u.y * v.y + u.z * v.z, vv}, n};
}

index_t UvMesh::add_vertex(const VertexData& v) {
    uv.push_back(v.uv);
    xyz.push_back(v.xyz);
    size.push_back(v.size);
    metric.push_back(v.metric);
    normal.push_back(v.normal);
    node.push_back(v.node);
    vtri.push_back(kNoIndex);
    return static_cast<index_t>(uv.size() - 1);
}

index_t UvMesh::new_triangle(index_t a, index_t b, index_t c) {
    index_t t;
    if (!free_slots.empty()) {
        t = free_slots.back();
        free_slots.pop_back();
        ++gen[t];
    } else {
        t = static_cast<index_t>(flags.size());
        tv.resize(tv.size() + 3);
        adj.resize(adj.size() + 3);
        flags.push_back(0);
        gen.push_back(0);
        mark.push_back(0);
    }
    tv[3 * t] = a;
    tv[3 * t + 1] = b;
    tv[3 * t + 2] = c;
    adj[3 * t] = adj[3 * t + 1] = adj[3 * t + 2] = kNoIndex;
    flags[t] = 0;
    vtri[a] = vtri[b] = vtri[c] = t;
    return t;
}

void UvMesh::kill(index_t t) {
    flags[t] = kDead;
    ++gen[t];
    free_slots.push_back(t);
}

void UvMesh::set_constrained(index_t t, int i, bool on) {
    const auto bit = static_cast<std::uint8_t>(kConstrainedEdge0 << i);
    flags[t] = static_cast<std::uint8_t>(on ? flags[t] | bit : flags[t] & ~bit);
}

bool UvMesh::faces_out(index_t a, index_t b, index_t c, const Vec3& xa, const Vec3& xb, const Vec3& xc) const {
    const Vec3 e{xb.x - xa.x, xb.y - xa.y, xb.z - xa.z}, f{xc.x - xa.x, xc.y - xa.y, xc.z - xa.z};
    const Vec3 n{e.y * f.z - e.z * f.y, e.z * f.x - e.x * f.z, e.x * f.y - e.y * f.x};
    for (index_t v : {a, b, c}) {
        const Vec3& s = normal[v];
        if (n.x * s.x + n.y * s.y + n.z * s.z < 0) return false;
    }
    return true;
}

int UvMesh::local_index(index_t t, index_t v) const {
    for (int i = 0; i < 3; ++i)
        if (tv[3 * t + i] == v) return i;
    return -1;
}

void UvMesh::link(index_t t, int i, index_t n, int j) {
    if (n == kNoIndex) {
        adj[3 * t + i] = kNoIndex;
        return;
    }
    adj[3 * t + i] = 3 * n + static_cast<index_t>(j);
    adj[3 * n + j] = 3 * t + static_cast<index_t>(i);
}

std::uint32_t UvMesh::next_epoch() {
    epoch += 2;
    if (epoch < 2) {  // wrapped: old marks could collide with new epochs
        std::fill(mark.begin(), mark.end(), 0u);
        epoch = 2;
    }
    return epoch;
}

std::pair<index_t, int> UvMesh::find_edge(index_t a, index_t b) const {
    const index_t start = vtri[a];
    if (start == kNoIndex) return {kNoIndex, -1};
    // Counter-clockwise around a; if the hull stops us, clockwise from the start.
    index_t t = start;
    do {
        const int k = local_index(t, a);
        if (tv[3 * t + next3(k)] == b) return {t, prev3(k)};
        t = neighbor(t, next3(k));
    } while (t != kNoIndex && t != start);
    if (t == start) return {kNoIndex, -1};
    t = start;
    while (true) {
        const int k = local_index(t, a);
        t = neighbor(t, prev3(k));
        if (t == kNoIndex) return {kNoIndex, -1};
        const int k2 = local_index(t, a);
        if (tv[3 * t + next3(k2)] == b) return {t, prev3(k2)};
    }
}

bool UvMesh::flip(index_t t, int i) {
    if (constrained(t, i) || adj[3 * t + i] == kNoIndex) return false;
    const index_t n = adj[3 * t + i] / 3;
    const int j = static_cast<int>(adj[3 * t + i] % 3);
    const index_t c = tv[3 * t + i], a = tv[3 * t + next3(i)], b = tv[3 * t + prev3(i)];
    const index_t d = tv[3 * n + j];
    if (orient2d(uv[c], uv[a], uv[d]) <= 0 || orient2d(uv[d], uv[b], uv[c]) <= 0) return false;
    flip_unchecked(t, i);
    return true;
}

void UvMesh::flip_unchecked(index_t t, int i) {
    const index_t n = adj[3 * t + i] / 3;
    const int j = static_cast<int>(adj[3 * t + i] % 3);
    const index_t c = tv[3 * t + i], a = tv[3 * t + next3(i)], b = tv[3 * t + prev3(i)];
    const index_t d = tv[3 * n + j];
    // The four outer edges with their neighbours and constraint bits (see uv_mesh.hpp for the
    // edge numbering): b-c and c-a from t, a-d and d-b from n.
    const index_t bc = adj[3 * t + next3(i)], ca = adj[3 * t + prev3(i)];
    const index_t ad = adj[3 * n + next3(j)], db = adj[3 * n + prev3(j)];
    const bool cbc = constrained(t, next3(i)), cca = constrained(t, prev3(i));
    const bool cad = constrained(n, next3(j)), cdb = constrained(n, prev3(j));
    const std::uint8_t keep = static_cast<std::uint8_t>(kInside | kAccepted);
    const std::uint8_t ft = static_cast<std::uint8_t>(flags[t] & keep);
    const std::uint8_t fn = static_cast<std::uint8_t>(flags[n] & keep);

    // t = (c, a, d), n = (d, b, c); their edge 1 is the new edge c-d.
    tv[3 * t] = c, tv[3 * t + 1] = a, tv[3 * t + 2] = d;
    tv[3 * n] = d, tv[3 * n + 1] = b, tv[3 * n + 2] = c;
    flags[t] = ft;
    flags[n] = fn;
    link(t, 0, ad);
    link(t, 2, ca);
    link(n, 0, bc);
    link(n, 2, db);
    link(t, 1, n, 1);
    set_constrained(t, 0, cad);
    set_constrained(t, 2, cca);
    set_constrained(n, 0, cbc);
    set_constrained(n, 2, cdb);
    ++gen[t];
    ++gen[n];
    vtri[a] = vtri[c] = t;
    vtri[b] = vtri[d] = n;
}

void UvMesh::collapse_unchecked(index_t v, std::span<const index_t> ring, std::span<const index_t> fan,
                                std::size_t k) {
    const std::size_t n = ring.size();
    const index_t w = ring[k];
    const index_t gone_a = fan[(k + n - 1) % n], gone_b = fan[k];  // (v, r[k-1], w) and (v, w, r[k+1])
    const index_t keep_a = fan[(k + n - 2) % n], keep_b = fan[(k + 1) % n];
    const index_t r_prev = ring[(k + n - 1) % n], r_next = ring[(k + 1) % n];
    // The outer edges of the two triangles that go: r[k-1]-w and w-r[k+1].
    const int ea = local_index(gone_a, v), eb = local_index(gone_b, v);
    const index_t outer_a = adj[3 * gone_a + ea], outer_b = adj[3 * gone_b + eb];
    const bool ca = constrained(gone_a, ea), cb = constrained(gone_b, eb);
    for (std::size_t j = 0; j < n; ++j) {
        if (j == (k + n - 1) % n || j == k) continue;
        const index_t t = fan[j];
        tv[3 * t + local_index(t, v)] = w;
        ++gen[t];
    }
    // keep_a now has the edge w-r[k-1] (across from its third vertex r[k-2]); keep_b has
    // w-r[k+1] (across from r[k+2]). With n == 3 they are one triangle and both apply.
    const int ia = local_index(keep_a, ring[(k + n - 2) % n]);
    link(keep_a, ia, outer_a);
    set_constrained(keep_a, ia, ca);
    const int ib = local_index(keep_b, ring[(k + 2) % n]);
    link(keep_b, ib, outer_b);
    set_constrained(keep_b, ib, cb);
    vtri[w] = keep_b;
    vtri[r_prev] = keep_a;
    vtri[r_next] = keep_b;
    vtri[v] = kNoIndex;
    kill(gone_a);
    kill(gone_b);
}

}  // namespace tubemesh::surface
