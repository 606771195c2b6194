#include "engine/tets/recovery/recovery_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

#include "engine/mesh/edge_key.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/mesh/topology.hpp"
#include "engine/predicates/predicates.hpp"

namespace tubemesh::tets {

using predicates::orient3d;

namespace {

// A point well off the plane through a, b, c (not collinear): a moved along the axis the
// plane's normal is closest to, by more than the points' spread. Exact side tests in the plane
// then reduce to orient3d with this point (the plane through a line of the plane and e meets
// the plane exactly in that line).
void off_plane_point(const double* a, const double* b, const double* c, double* e) {
    const Vec3 u = vec3_at(b) - vec3_at(a), v = vec3_at(c) - vec3_at(a), n = cross(u, v);
    const double an[3] = {std::abs(n.x), std::abs(n.y), std::abs(n.z)};
    int k = 0;
    for (int i = 1; i < 3; ++i)
        if (an[i] > an[k]) k = i;
    const double span = std::abs(u.x) + std::abs(u.y) + std::abs(u.z) + std::abs(v.x) + std::abs(v.y) +
                        std::abs(v.z) + 1.0;
    e[0] = a[0];
    e[1] = a[1];
    e[2] = a[2];
    e[k] += span;
}

// Point w on the open segment ab (a != b).
bool on_open_segment(const double* a, const double* b, const double* w) {
    const Vec3 d = vec3_at(b) - vec3_at(a);
    const double ad[3] = {std::abs(d.x), std::abs(d.y), std::abs(d.z)};
    int k = 0;
    for (int i = 1; i < 3; ++i)
        if (ad[i] > ad[k]) k = i;
    const double span = ad[0] + ad[1] + ad[2] + 1.0;
    // Two planes through ab, spanned with the two other axes: they meet exactly in line ab.
    double e1[3] = {a[0], a[1], a[2]}, e2[3] = {a[0], a[1], a[2]};
    e1[(k + 1) % 3] += span;
    e2[(k + 2) % 3] += span;
    if (orient3d(a, b, e1, w) != 0 || orient3d(a, b, e2, w) != 0) return false;
    return (a[k] < w[k] && w[k] < b[k]) || (b[k] < w[k] && w[k] < a[k]);
}

}  // namespace

bool segments_cross(const double* p, const double* q, const double* a, const double* b) {
    if (orient3d(p, q, a, b) != 0) return false;
    // The plane: through a, b and whichever of p, q is off line ab.
    double e[3];
    off_plane_point(a, b, p, e);
    if (orient3d(a, b, p, e) == 0) off_plane_point(a, b, q, e);
    const int sp = orient3d(a, b, e, p), sq = orient3d(a, b, e, q);
    if (sp == 0 || sq == 0 || sp == sq) return false;
    const int sa = orient3d(p, q, e, a), sb = orient3d(p, q, e, b);
    return sa != 0 && sb != 0 && sa != sb;
}

bool edge_crosses(const RecoveryMesh& m, const Target& g, index_t u, index_t v) {
    if (g.has(u) || g.has(v)) return false;
    if (g.is_edge()) return segments_cross(m.point(u), m.point(v), m.point(g.a), m.point(g.b));
    return predicates::segment_triangle(m.point(u), m.point(v), m.point(g.a), m.point(g.b), m.point(g.c)) ==
           predicates::Contact::Crossing;
}

bool face_crossed(const RecoveryMesh& m, const Target& g, index_t x, index_t y, index_t z) {
    if (!g.is_edge() || g.has(x) || g.has(y) || g.has(z)) return false;
    return predicates::segment_triangle(m.point(g.a), m.point(g.b), m.point(x), m.point(y), m.point(z)) ==
           predicates::Contact::Crossing;
}

bool point_on_target(const RecoveryMesh& m, const Target& g, index_t w) {
    return !g.has(w) && point_on_target(m, g, m.point(w));
}

bool point_on_target(const RecoveryMesh& m, const Target& g, const double* p) {
    const double *a = m.point(g.a), *b = m.point(g.b);
    if (g.is_edge()) return on_open_segment(a, b, p);
    const double* c = m.point(g.c);
    if (orient3d(a, b, c, p) != 0) return false;
    double e[3];
    off_plane_point(a, b, c, e);
    const int s1 = orient3d(a, b, e, p), s2 = orient3d(b, c, e, p), s3 = orient3d(c, a, e, p);
    const int s = orient3d(a, b, e, c);
    return s1 == s && s2 == s && s3 == s;
}

void find_crossings(RecoveryMesh& m, const Target& g, Crossings& out) {
    out.faces.clear();
    out.edges.clear();
    out.vertex_on_target = kNoIndex;
    std::vector<index_t> queue, around, ring;
    std::unordered_set<index_t> seen;
    std::unordered_set<std::uint64_t> seen_edges, seen_faces;
    for (index_t v : {g.a, g.b, g.c}) {
        if (v == kNoIndex) continue;
        m.ball(v, around);
        for (index_t t : around)
            if (seen.insert(t).second) queue.push_back(t);
    }
    for (std::size_t k = 0; k < queue.size(); ++k) {
        const index_t t = queue[k];
        const Tet tv = m.tet(t);
        for (int i = 0; i < 4; ++i)
            if (out.vertex_on_target == kNoIndex && point_on_target(m, g, tv[i])) out.vertex_on_target = tv[i];
        if (g.is_edge()) {
            for (int f = 0; f < 4; ++f) {
                const index_t code = 4 * t + static_cast<index_t>(f);
                const index_t nb = m.neighbour(code);
                const std::uint64_t key = nb == kNoIndex ? code : std::min(code, nb);
                if (seen_faces.count(key)) continue;
                const auto fv = m.face(t, f);
                if (!face_crossed(m, g, fv[0], fv[1], fv[2])) continue;
                seen_faces.insert(key);
                out.faces.emplace_back(t, f);
                if (nb != kNoIndex && seen.insert(nb >> 2).second) queue.push_back(nb >> 2);
            }
        }
        for (int e = 0; e < 6; ++e) {
            const index_t u = tv[kTetTopology.edge[e].a], v = tv[kTetTopology.edge[e].b];
            const std::uint64_t key = edge_key(u, v);
            if (seen_edges.count(key)) continue;
            if (!edge_crosses(m, g, u, v)) continue;
            seen_edges.insert(key);
            out.edges.emplace_back(std::min(u, v), std::max(u, v));
            std::vector<index_t> tets;
            if (!m.edge_ring(u, v, tets, ring)) continue;
            for (index_t s : tets)
                if (seen.insert(s).second) queue.push_back(s);
        }
    }
}

}  // namespace tubemesh::tets
