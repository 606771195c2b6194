#include "engine/tets/recovery_flips.hpp"

#include <algorithm>
#include <limits>

#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/mesh/topology.hpp"
#include "engine/predicates/predicates.hpp"
#include "engine/quality/quality.hpp"
#include "engine/tets/ring_triangulation.hpp"

namespace tubemesh::tets {

using predicates::orient3d;

namespace {

bool positive(const RecoveryMesh& m, const Tet& t) {
    return orient3d(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.point(t[3])) > 0;
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
