#include "engine/tets/recovery/recovery_flips.hpp"

#include <algorithm>
#include <limits>

#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/mesh/topology.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/predicates/predicates.hpp"
#include "engine/quality/quality.hpp"
#include "engine/tets/domain/ring_triangulation.hpp"

namespace tubemesh::tets {

using predicates::orient3d;

namespace {

// The apex id of a cone that is a new point, not yet in the mesh (swap_shell_to_segment).
constexpr index_t kNewPoint = kNoIndex;

// Tet t is positive; a vertex kNewPoint stands for the point `at`.
bool positive(const RecoveryMesh& m, const Tet& t, const double* at = nullptr) {
    std::array<const double*, 4> x;
    for (int i = 0; i < 4; ++i) x[i] = t[i] == kNewPoint ? at : m.point(t[i]);
    return orient3d(x[0], x[1], x[2], x[3]) > 0;
}

double collapse(const RecoveryMesh& m, const Tet& t) {
    std::array<Vec3, 4> p;
    for (int i = 0; i < 4; ++i) p[i] = {m.point(t[i])[0], m.point(t[i])[1], m.point(t[i])[2]};
    return tet_collapse(p);
}

}  // namespace

bool FrontLocks::edge(index_t u, index_t v) const {
    return std::binary_search(front_.edges.begin(), front_.edges.end(), std::pair{std::min(u, v), std::max(u, v)});
}

bool FrontLocks::face(index_t x, index_t y, index_t z) const {
    return lock_faces && std::binary_search(front_.triangles.begin(), front_.triangles.end(), sorted3(x, y, z));
}

bool flip23(RecoveryMesh& m, index_t t, int f, const Target* target, const FrontLocks& locks, FlipCounters& c) {
    const index_t nb = m.neighbour(4 * t + static_cast<index_t>(f));
    if (nb == kNoIndex) return false;
    const auto fv = m.face(t, f);  // normal towards q
    if (locks.face(fv[0], fv[1], fv[2])) return false;
    const index_t p = m.vertex(t)[f], q = m.vertex(nb >> 2)[nb & 3];
    const std::array<Tet, 3> tets = {Tet{fv[0], fv[1], p, q}, Tet{fv[1], fv[2], p, q}, Tet{fv[2], fv[0], p, q}};
    for (const Tet& n : tets)
        if (!positive(m, n)) return false;
    if (target) {
        if (edge_crosses(m, *target, p, q)) return false;
        for (int k = 0; k < 3; ++k)
            if (face_crossed(m, *target, p, q, fv[k])) return false;
    }
    const std::array<index_t, 2> old = {t, nb >> 2};
    if (!m.replace(old, tets)) return false;
    ++c.flips23;
    return true;
}

bool remove_edge(RecoveryMesh& m, index_t u, index_t v, const Target* target, const FrontLocks& locks,
                 int max_ring, FlipCounters& c) {
    if (locks.edge(u, v)) return false;
    std::vector<index_t> tets, ring;
    if (!m.edge_ring(u, v, tets, ring)) return false;
    const int n = static_cast<int>(ring.size());
    if (n < 3 || n > std::min(max_ring, kMaxRecoveryRing)) return false;
    for (int i = 0; i < n; ++i)
        if (locks.face(u, v, ring[i])) return false;

    // Chords the new tets may use: (i, j) not crossing the target (nor its faces to u, v).
    std::vector<std::uint8_t> chord_ok(static_cast<std::size_t>(n * n), 1);
    if (target) {
        for (int i = 0; i < n; ++i)
            for (int j = i + 2; j < n; ++j) {
                if (i == 0 && j == n - 1) continue;
                const index_t a = ring[i], b = ring[j];
                const bool bad = edge_crosses(m, *target, a, b) || face_crossed(m, *target, u, a, b) ||
                                 face_crossed(m, *target, v, a, b);
                chord_ok[i * n + j] = !bad;
            }
    }
    // Triangle (i, k, j) of the ring makes the tets (ri, rk, rj, v) and (ri, rj, rk, u); it is
    // out when either is not positive or the triangle crosses the target.
    const auto score = [&](int i, int k, int j, double) {
        const Tet t1{ring[i], ring[k], ring[j], v}, t2{ring[i], ring[j], ring[k], u};
        constexpr double kOut = -std::numeric_limits<double>::infinity();
        if (!positive(m, t1) || !positive(m, t2)) return RingTriangle{kOut, kOut, kOut};
        if (target && face_crossed(m, *target, ring[i], ring[k], ring[j])) return RingTriangle{kOut, kOut, kOut};
        const double first = collapse(m, t1), second = collapse(m, t2);
        return RingTriangle{std::min(first, second), first, second};
    };
    RingTriangulation<kMaxRecoveryRing> search;
    if (!search.solve(n, -std::numeric_limits<double>::infinity(), score,
                      [&](int i, int j) { return chord_ok[i * n + j] != 0; }))
        return false;
    std::vector<Tet> out;
    search.for_each_triangle([&](int i, int k, int j, double, double) {
        out.push_back({ring[i], ring[k], ring[j], v});
        out.push_back({ring[i], ring[j], ring[k], u});
    });
    if (!m.replace(tets, out)) return false;
    ++c.edge_removals;
    c.flips32 += n == 3;
    c.flips44 += n == 4;
    return true;
}

index_t insert_point(RecoveryMesh& m, std::span<const index_t> cavity, const double* p, const FrontLocks& locks) {
    const std::uint32_t e = m.next_epoch();
    for (index_t t : cavity) m.set_mark(t, e);
    std::vector<std::array<index_t, 3>> faces;
    for (index_t t : cavity)
        for (int f = 0; f < 4; ++f) {
            const index_t nb = m.neighbour(4 * t + static_cast<index_t>(f));
            const auto fv = m.face(t, f);
            if (nb != kNoIndex && m.marked(nb >> 2, e)) {
                if (locks.face(fv[0], fv[1], fv[2])) return kNoIndex;
                continue;
            }
            // Outward face (x, y, z) with p inside: (y, x, z, p) is positive.
            if (orient3d(m.point(fv[1]), m.point(fv[0]), m.point(fv[2]), p) <= 0) return kNoIndex;
            faces.push_back(fv);
        }
    const index_t s = m.add_point(p);
    std::vector<Tet> out;
    out.reserve(faces.size());
    for (const auto& fv : faces) out.push_back({fv[1], fv[0], fv[2], s});
    if (!m.replace(cavity, out)) throw Error("boundary recovery: internal error, a cavity is not a ball");
    return s;
}

namespace {

// One half of the shell of edge pq in swap_shell_to_segment: the tets (p, q, arc[i], arc[i+1]),
// arc running along pq's ring from one end of the segment (arc.front()) to the other. Appends
// the tets coning the half's boundary from apex c (a point of the arc, or kNewPoint at `at`):
// its faces at p and at q (c in place of q, then of p, in the old tets), and the triangles
// (s, t, p) and (s, t, q) of the segment st that cut the shell in two, oriented to pair with
// the faces at p and q. False when a tet is not positive (c outside the half's kernel),
// leaving `out` as it was.
bool cone_half(const RecoveryMesh& m, index_t p, index_t q, std::span<const index_t> arc, index_t c,
               const double* at, std::vector<Tet>& out) {
    const std::size_t size = out.size();
    for (std::size_t i = 0; i + 1 < arc.size(); ++i) {
        if (arc[i] == c || arc[i + 1] == c) continue;
        out.push_back({p, c, arc[i], arc[i + 1]});
        out.push_back({c, q, arc[i], arc[i + 1]});
    }
    out.push_back({arc.back(), arc.front(), p, c});
    out.push_back({arc.front(), arc.back(), q, c});
    for (std::size_t i = size; i < out.size(); ++i)
        if (!positive(m, out[i], at)) {
            out.resize(size);
            return false;
        }
    return true;
}

// Cones the half from one of its own ring points when that works (no new point), else from a
// new point off the cut, on the half's side: first from the cut's centre towards the half's
// ring points (a well-shaped apex), then ever closer to the cut, above the middle of pq (tets
// (p, q, ...) are positive, so points near pq see every face at p and q) and above the cut's
// centre. The apex, or kNewPoint with its coordinates in `at`; false when none works.
bool cone_half_somewhere(const RecoveryMesh& m, index_t p, index_t q, std::span<const index_t> arc,
                         std::vector<Tet>& out, index_t& apex, std::array<double, 3>& at) {
    apex = kNewPoint;
    for (std::size_t i = 1; i + 1 < arc.size(); ++i)
        if (cone_half(m, p, q, arc, arc[i], nullptr, out)) {
            apex = arc[i];
            return true;
        }
    const auto vec = [&](index_t v) {
        const double* x = m.point(v);
        return Vec3{x[0], x[1], x[2]};
    };
    const Vec3 s = vec(arc.front()), t = vec(arc.back()), ps = vec(p), qs = vec(q);
    const Vec3 centre = 0.25 * (s + t + ps + qs), mid = 0.5 * (ps + qs);
    Vec3 towards{0, 0, 0};
    for (std::size_t i = 1; i + 1 < arc.size(); ++i) towards = towards + vec(arc[i]);
    towards = (1.0 / static_cast<double>(arc.size() - 2)) * towards - centre;
    // The cut's normal (st x pq), towards the half, as long as st.
    Vec3 normal = cross(t - s, qs - ps);
    const double len = norm(normal);
    if (len == 0) return false;
    normal = ((dot(normal, towards) < 0 ? -norm(t - s) : norm(t - s)) / len) * normal;
    std::vector<Vec3> cands = {centre + 0.5 * towards, centre + 0.25 * towards};
    for (double h : {0.25, 0.1, 0.02, 0.005})
        for (const Vec3& x : {mid, centre}) cands.push_back(x + h * normal);
    for (const Vec3& c : cands) {
        const double x[3] = {c.x, c.y, c.z};
        if (cone_half(m, p, q, arc, kNewPoint, x, out)) {
            at = {c.x, c.y, c.z};
            return true;
        }
    }
    return false;
}

}  // namespace

bool swap_shell_to_segment(RecoveryMesh& m, index_t p, index_t q, const Target& target, const FrontLocks& locks,
                           std::vector<index_t>& added) {
    if (!target.is_edge() || target.has(p) || target.has(q) || locks.edge(p, q)) return false;
    std::vector<index_t> tets, ring;
    if (!m.edge_ring(p, q, tets, ring)) return false;
    const std::size_t n = ring.size();
    const auto ia = std::find(ring.begin(), ring.end(), target.a), ib = std::find(ring.begin(), ring.end(), target.b);
    if (ia == ring.end() || ib == ring.end()) return false;
    for (index_t r : ring)
        if (locks.face(p, q, r)) return false;
    const auto arc = [&](std::size_t from, std::size_t to) {
        std::vector<index_t> out{ring[from]};
        for (std::size_t i = from; i != to;) {
            i = (i + 1) % n;
            out.push_back(ring[i]);
        }
        return out;
    };
    const std::size_t i = static_cast<std::size_t>(ia - ring.begin()), j = static_cast<std::size_t>(ib - ring.begin());
    const std::vector<index_t> halves[2] = {arc(i, j), arc(j, i)};
    // a and b next to each other in the ring: the tet (p, q, a, b) already has edge ab.
    if (halves[0].size() < 3 || halves[1].size() < 3) return false;
    std::vector<Tet> out;
    std::size_t end[2];
    index_t apex[2];
    std::array<double, 3> at[2];
    for (int h = 0; h < 2; ++h) {
        if (!cone_half_somewhere(m, p, q, halves[h], out, apex[h], at[h])) return false;
        end[h] = out.size();
    }
    // Valid: the new points join the mesh, each in place of its half's placeholder.
    for (int h = 0; h < 2; ++h) {
        if (apex[h] != kNewPoint) continue;
        const index_t s = m.add_point(at[h].data());
        for (std::size_t k = h == 0 ? 0 : end[0]; k < end[h]; ++k)
            std::replace(out[k].begin(), out[k].end(), kNewPoint, s);
        added.push_back(s);
    }
    if (!m.replace(tets, out)) throw Error("boundary recovery: internal error, a shell swap does not fill the shell");
    return true;
}

bool contract_point(RecoveryMesh& m, index_t s) {
    std::vector<index_t> ball;
    m.ball(s, ball);
    if (ball.empty()) return false;
    std::vector<index_t> link;
    for (index_t t : ball)
        for (int i = 0; i < 4; ++i)
            if (m.vertex(t)[i] != s) link.push_back(m.vertex(t)[i]);
    std::sort(link.begin(), link.end());
    link.erase(std::unique(link.begin(), link.end()), link.end());
    double best_q = 0;
    std::vector<Tet> best, out;
    for (index_t v : link) {
        out.clear();
        double q = std::numeric_limits<double>::infinity();
        bool ok = true;
        for (index_t t : ball) {
            Tet n = m.tet(t);
            if (std::find(n.begin(), n.end(), v) != n.end()) continue;
            std::replace(n.begin(), n.end(), s, v);
            if (!positive(m, n)) {
                ok = false;
                break;
            }
            q = std::min(q, collapse(m, n));
            out.push_back(n);
        }
        if (ok && q > best_q) {
            best_q = q;
            best = out;
        }
    }
    if (best.empty()) return false;
    return m.replace(ball, best);
}

}  // namespace tubemesh::tets
