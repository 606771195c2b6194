#include "engine/tets/recovery/boundary_recovery.hpp"

#include <algorithm>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "engine/core/timing.hpp"
#include "engine/delaunay/delaunay.hpp"
#include "engine/predicates/predicates.hpp"
#include "engine/tets/recovery/front_check.hpp"
#include "engine/tets/recovery/recovery_crossings.hpp"
#include "engine/tets/recovery/recovery_flips.hpp"
#include "engine/tets/recovery/recovery_mesh.hpp"

namespace tubemesh::tets {

namespace {

std::string name(const Target& g) {
    std::string s = g.is_edge() ? "front edge " : "front triangle ";
    s += std::to_string(g.a) + "-" + std::to_string(g.b);
    if (!g.is_edge()) s += "-" + std::to_string(g.c);
    return s;
}

// What a reader of the mesh needs for its own ball walks (one per thread when several read).
struct ReaderScratch {
    std::vector<index_t> around;
    SlotMarks marks;
};

// Whether the target is a tet edge / face, given the ball of its first point g.a.
bool present_in(const RecoveryMesh& m, const Target& g, std::span<const index_t> ball_of_a) {
    if (g.is_edge()) return m.edge_in(ball_of_a, g.b) != kNoIndex;
    const RecoveryMesh::FaceSides sides = m.face_in(ball_of_a, g.a, g.b, g.c);
    return sides.tet[0] != kNoIndex || sides.tet[1] != kNoIndex;
}

bool is_present(const RecoveryMesh& m, const Target& g, ReaderScratch& s) {
    m.ball(g.a, s.around, s.marks);
    return present_in(m, g, s.around);
}

// f(i, ball of first[i]) for every i, in parallel, with the mesh only read meanwhile. The
// indices go in order of their first vertex, so a ball is walked once per run of equal first
// vertices in a chunk instead of once per item: a front point starts about three front edges
// and two front triangles.
template <class F>
void with_ball_of_first(const RecoveryMesh& m, const std::vector<index_t>& first, F&& f) {
    std::vector<index_t> order(first.size());
    std::iota(order.begin(), order.end(), index_t{0});
    const auto before = [&](index_t i, index_t j) { return first[i] < first[j] || (first[i] == first[j] && i < j); };
    if (!std::is_sorted(order.begin(), order.end(), before)) tbb::parallel_sort(order.begin(), order.end(), before);
    tbb::enumerable_thread_specific<ReaderScratch> scratch;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, order.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          ReaderScratch& s = scratch.local();
                          index_t walked = kNoIndex;
                          for (std::size_t k = r.begin(); k != r.end(); ++k) {
                              const index_t i = order[k];
                              if (first[i] != walked) {
                                  m.ball(first[i], s.around, s.marks);
                                  walked = first[i];
                              }
                              f(i, std::span<const index_t>(s.around));
                          }
                      });
}

// Whether each target is present now, in parallel. A front edge once present stays so (no flip
// removes a locked edge, and a Steiner point's cavity never holds one inside), and so does a
// front triangle once faces are locked: the serial loops below ask again only about the
// targets missing here and make the same decisions as when they asked about every one (serially,
// one ball walk each).
std::vector<std::uint8_t> present_now(const RecoveryMesh& m, const std::vector<Target>& targets) {
    std::vector<std::uint8_t> out(targets.size(), 0);
    std::vector<index_t> first(targets.size());
    for (std::size_t i = 0; i < targets.size(); ++i) first[i] = targets[i].a;
    with_ball_of_first(m, first, [&](index_t i, std::span<const index_t> ball) { out[i] = present_in(m, targets[i], ball); });
    return out;
}

class Recovery {
public:
    Recovery(RecoveryMesh& m, FrontLocks& locks, const RecoveryOptions& o, index_t input_points)
        : m_(m), locks_(locks), opt_(o), input_points_(input_points) {}

    // Makes the target present; returns whether it took no new point (flips, or a shell swap
    // coned from points already there).
    bool recover(const Target& g) {
        int steiner = 0;  // Steiner steps tried, for the limit
        const std::size_t points_before = this->steiner.size();
        for (int step = 0; step < opt_.max_steps_per_element; ++step) {
            if (present(g)) return this->steiner.size() == points_before;
            find_crossings(m_, g, cx_);
            if (cx_.vertex_on_target != kNoIndex) {
                const index_t w = cx_.vertex_on_target;
                throw Error("tet front intersects itself: " +
                            (w < input_points_ ? "front point " + std::to_string(w) : std::string("a Steiner point")) +
                            " lies inside " + name(g));
            }
            for (const auto& [p, q] : cx_.edges)
                if (locks_.edge(p, q))
                    throw Error("tet front intersects itself: front edge " + std::to_string(p) + "-" +
                                std::to_string(q) + " crosses " + name(g));
            if (flip_once(g)) continue;
            if (++steiner > opt_.max_steiner_per_element || !insert_steiner(g))
                throw RecoveryGaveUp("boundary recovery failed: " + name(g) +
                            " could not be recovered by flips and Steiner points");
        }
        throw RecoveryGaveUp("boundary recovery failed: " + name(g) + " still missing after " +
                    std::to_string(opt_.max_steps_per_element) + " steps");
    }

    bool present(const Target& g) {
        return is_present(m_, g, reader_);
    }

    FlipCounters counters;
    std::vector<index_t> steiner;

private:
    bool flip_once(const Target& g) {
        for (const auto& [p, q] : cx_.edges)
            if (remove_edge(m_, p, q, &g, locks_, opt_.max_ring, counters)) return true;
        for (const auto& [t, f] : cx_.faces)
            if (m_.alive(t) && flip23(m_, t, f, &g, locks_, counters)) return true;
        // A crossed face whose 2-3 flip is blocked: the union of its two tets is not convex at
        // one of the face's edges; removing that edge unblocks it.
        for (const auto& [p, q] : face_edges())
            if (remove_edge(m_, p, q, &g, locks_, opt_.max_ring, counters)) return true;
        return false;
    }

    std::vector<std::pair<index_t, index_t>> face_edges() const {
        std::vector<std::pair<index_t, index_t>> out;
        for (const auto& [t, f] : cx_.faces) {
            if (!m_.alive(t)) continue;
            const auto fv = m_.face(t, f);
            for (int k = 0; k < 3; ++k) {
                const index_t a = fv[k], b = fv[(k + 1) % 3];
                if (!locks_.edge(a, b)) out.emplace_back(std::min(a, b), std::max(a, b));
            }
        }
        return out;
    }

    bool insert_steiner(const Target& g) {
        // First the shell of a crossing edge, or of a crossed face's edge, whose ring holds both
        // ends of a segment target, rebuilt around the segment: on a flat front, where that edge
        // is the target's other diagonal, the points below (joined to that shell only) just
        // move the crossing until the limit (swap_shell_to_segment).
        std::vector<std::pair<index_t, index_t>> edges = cx_.edges;
        const auto more = face_edges();
        edges.insert(edges.end(), more.begin(), more.end());
        if (g.is_edge())
            for (const auto& [p, q] : edges)
                if (swap_shell_to_segment(m_, p, q, g, locks_, steiner)) return true;
        std::vector<index_t> ring_tets, ring;
        for (const auto& [p, q] : edges) {
            if (locks_.edge(p, q) || !m_.edge_ring(p, q, ring_tets, ring)) continue;
            // First the centroid of the ring's points (off the edge: on a flat front the edge's
            // plane is what blocks the flips), then points on the edge.
            std::vector<std::array<double, 3>> cands;
            std::array<double, 3> c = {0, 0, 0};
            for (index_t r : ring)
                for (int k = 0; k < 3; ++k) c[k] += m_.point(r)[k];
            for (int k = 0; k < 3; ++k)
                c[k] = (c[k] + m_.point(p)[k] + m_.point(q)[k]) / static_cast<double>(ring.size() + 2);
            cands.push_back(c);
            for (index_t r : ring) {
                std::array<double, 3> e;
                for (int k = 0; k < 3; ++k) e[k] = 0.5 * (c[k] + m_.point(r)[k]);
                cands.push_back(e);
            }
            // The edge's midpoint moved the fraction t towards each ring point.
            const index_t ep = p, eq = q;  // a lambda may not capture structured bindings (clang 14)
            const auto towards_ring = [&](double t) {
                for (index_t r : ring) {
                    std::array<double, 3> e;
                    for (int k = 0; k < 3; ++k) {
                        const double mid = 0.5 * (m_.point(ep)[k] + m_.point(eq)[k]);
                        e[k] = mid + t * (m_.point(r)[k] - mid);
                    }
                    cands.push_back(e);
                }
            };
            // Near the edge's midpoint: inside the ring's kernel.
            for (double t : {0.1, 0.25}) towards_ring(t);
            for (double w : {0.5, 0.4, 0.6}) {
                std::array<double, 3> e;
                for (int k = 0; k < 3; ++k) e[k] = m_.point(p)[k] + w * (m_.point(q)[k] - m_.point(p)[k]);
                cands.push_back(e);
            }
            // Closer still to the midpoint: when the edge lies in the plane of a flat front (the
            // other diagonal of two front triangles), points on the edge are ruled out above and
            // the ring's far points (a box corner) leave only a thin kernel around the edge.
            for (double t : {0.02, 0.005}) towards_ring(t);
            for (const auto& cand : cands) {
                const double* s = cand.data();
                if (point_on_target(m_, g, s)) continue;
                // In the plane of a segment target and the edge it crosses, a Steiner point only
                // recreates the same blocked crossing.
                if (g.is_edge() && predicates::orient3d(m_.point(g.a), m_.point(g.b), m_.point(p), s) == 0) continue;
                if (!g.is_edge() && predicates::orient3d(m_.point(g.a), m_.point(g.b), m_.point(g.c), s) == 0) continue;
                const index_t v = insert_point(m_, ring_tets, s, locks_);
                if (v != kNoIndex) {
                    steiner.push_back(v);
                    return true;
                }
            }
        }
        for (const auto& [t, f] : cx_.faces) {
            if (!m_.alive(t)) continue;
            const index_t nb = m_.neighbour(4 * t + static_cast<index_t>(f));
            if (nb == kNoIndex) continue;
            const index_t cav[2] = {t, nb >> 2};
            const Tet a = m_.tet(t);
            const index_t apex = m_.vertex(nb >> 2)[nb & 3];
            // Candidates: the 5 points' centroid, then points between the face and each apex.
            const auto fv = m_.face(t, f);
            double c5[3] = {0, 0, 0}, cf[3] = {0, 0, 0};
            for (int k = 0; k < 3; ++k) {
                for (index_t v : a) c5[k] += m_.point(v)[k] / 5;
                c5[k] += m_.point(apex)[k] / 5;
                for (index_t v : fv) cf[k] += m_.point(v)[k] / 3;
            }
            std::vector<std::array<double, 3>> cands = {{c5[0], c5[1], c5[2]}};
            for (index_t ap : {a[f], apex})
                for (double w : {0.25, 0.5})
                    cands.push_back({cf[0] + w * (m_.point(ap)[0] - cf[0]), cf[1] + w * (m_.point(ap)[1] - cf[1]),
                                     cf[2] + w * (m_.point(ap)[2] - cf[2])});
            for (const auto& s : cands) {
                if (point_on_target(m_, g, s.data())) continue;
                const index_t v = insert_point(m_, cav, s.data(), locks_);
                if (v != kNoIndex) {
                    steiner.push_back(v);
                    return true;
                }
            }
        }
        return false;
    }

    RecoveryMesh& m_;
    FrontLocks& locks_;
    const RecoveryOptions& opt_;
    index_t input_points_;
    Crossings cx_;
    ReaderScratch reader_;
};

}  // namespace

TetDomain recover_boundary(std::span<const double> xyz, std::span<const index_t> front, const Parallelism& par,
                           const RecoveryOptions& options, RecoveryStats* stats_out, const Pulse& pulse) {
    // Elements checked or recovered between two pulses: a missing one costs flips and
    // Steiner tries, a present one a ball lookup.
    constexpr std::size_t kPulseEvery = 256;
    const auto t_start = Clock::now();
    RecoveryStats st;
    if (options.max_ring < 3 || options.max_ring > kMaxRecoveryRing)
        throw Error("boundary recovery: max_ring must lie in 3.." + std::to_string(kMaxRecoveryRing) + ", got " +
                    std::to_string(options.max_ring));
    if (xyz.size() % 3 != 0) throw Error("tet front: the coordinate array's length is not a multiple of 3");
    const index_t n = static_cast<index_t>(xyz.size() / 3);
    const FrontElements elements = check_front(front, n);
    const auto& edges = elements.edges;
    st.front_triangles = static_cast<index_t>(front.size() / 3);
    st.front_edges = static_cast<index_t>(edges.size());

    // 1. Delaunay of the used points in a box.
    auto t0 = Clock::now();
    std::vector<std::uint8_t> used(n, 0);
    for (index_t v : front) used[v] = 1;
    std::vector<index_t> ids;
    std::vector<double> x, y, z;
    for (index_t i = 0; i < n; ++i) {
        if (!used[i]) continue;
        ids.push_back(i);
        x.push_back(xyz[3 * i]);
        y.push_back(xyz[3 * i + 1]);
        z.push_back(xyz[3 * i + 2]);
    }
    st.front_points = static_cast<index_t>(ids.size());
    st.unused_points = n - st.front_points;
    delaunay::DelaunayOptions dopt;
    dopt.bounding_box = true;
    dopt.box_margin = options.box_margin;
    dopt.pulse = pulse;
    delaunay::DelaunayResult del = delaunay::delaunay(x, y, z, par, dopt);
    if (!del.duplicates.empty())
        throw Error("tet front: points " + std::to_string(ids[del.duplicates[0].first]) + " and " +
                    std::to_string(ids[del.duplicates[0].second]) + " have the same coordinates");
    const index_t m_used = static_cast<index_t>(ids.size());
    std::vector<double> all(xyz.begin(), xyz.end());
    for (const auto& c : del.box_corners) all.insert(all.end(), c.begin(), c.end());
    {
        index_t* v = del.tets.vertex(0);
        for (std::size_t i = 0; i < std::size_t{4} * del.tets.size(); ++i)
            v[i] = v[i] < m_used ? ids[v[i]] : n + (v[i] - m_used);
    }
    st.delaunay_tets = del.tets.size();
    RecoveryMesh mesh(std::move(all), std::move(del.tets));
    st.seconds_delaunay = seconds_since(t0);

    // 2. Edges, then faces.
    FrontLocks locks(elements);
    Recovery rec(mesh, locks, options, n);
    t0 = Clock::now();
    std::vector<Target> targets;
    targets.reserve(edges.size());
    for (const auto& [u, v] : edges) targets.push_back({u, v, kNoIndex});
    // Recovers every target not already there; counts the missing and those flips alone gave.
    const auto recover_targets = [&](index_t& missing, index_t& by_flips) {
        beat(pulse);
        const std::vector<std::uint8_t> there = present_now(mesh, targets);
        for (std::size_t i = 0; i < targets.size(); ++i) {
            if (i % kPulseEvery == kPulseEvery - 1) beat(pulse);
            if (there[i] || rec.present(targets[i])) continue;
            ++missing;
            by_flips += rec.recover(targets[i]);
        }
    };
    recover_targets(st.missing_edges, st.edges_by_flips);
    st.seconds_edges = seconds_since(t0);
    t0 = Clock::now();
    locks.lock_faces = true;
    targets.clear();
    for (std::size_t i = 0; i < front.size(); i += 3) targets.push_back({front[i], front[i + 1], front[i + 2]});
    recover_targets(st.missing_faces, st.faces_by_flips);
    st.seconds_faces = seconds_since(t0);
    st.steiner_inserted = static_cast<index_t>(rec.steiner.size());
    t0 = Clock::now();
    beat(pulse);
    if (options.remove_steiner)
        for (std::size_t i = 0; i < rec.steiner.size(); ++i) {
            if (i % kPulseEvery == kPulseEvery - 1) beat(pulse);
            const index_t s = rec.steiner[i];
            if (mesh.incident_tet(s) != kNoIndex && contract_point(mesh, s)) ++st.steiner_removed;
        }
    st.seconds_steiner_removal = seconds_since(t0);

    // 3. Inside / outside by flood fill, seeded on both sides of every front triangle.
    beat(pulse);
    t0 = Clock::now();
    const index_t slots = mesh.slot_count();
    constexpr std::uint8_t kInside = 1, kOutside = 2;
    std::vector<std::uint8_t> label(slots, 0), is_front(std::size_t{4} * slots, 0);
    std::vector<index_t> queue;
    auto set_label = [&](index_t t, std::uint8_t l) {
        if (label[t] == l) return;
        if (label[t] != 0)
            throw Error("tet front does not bound a region consistently: a tetrahedron lies both inside and "
                        "outside (front triangles touching or oriented inconsistently)");
        label[t] = l;
        queue.push_back(t);
    };
    // The tets on both sides of every front triangle, found in parallel; seeded in order.
    std::vector<RecoveryMesh::FaceSides> sides(front.size() / 3);
    {
        std::vector<index_t> first(sides.size());
        for (std::size_t i = 0; i < sides.size(); ++i) first[i] = front[3 * i];
        with_ball_of_first(mesh, first, [&](index_t i, std::span<const index_t> ball) {
            const std::size_t k = 3 * std::size_t{i};
            sides[i] = mesh.face_in(ball, front[k], front[k + 1], front[k + 2]);
        });
    }
    for (std::size_t i = 0; i < sides.size(); ++i) {
        const auto [tin, tout] = sides[i].tet;
        if (tin == kNoIndex || tout == kNoIndex)
            throw Error("boundary recovery: internal error, front triangle " + std::to_string(i) + " lost");
        is_front[4 * std::size_t{tin} + sides[i].local[0]] = 1;
        is_front[4 * std::size_t{tout} + sides[i].local[1]] = 1;
        set_label(tin, kInside);
        set_label(tout, kOutside);
    }
    for (std::size_t k = 0; k < queue.size(); ++k) {
        const index_t t = queue[k];
        for (int f = 0; f < 4; ++f) {
            if (is_front[4 * std::size_t{t} + f]) continue;
            const index_t nb = mesh.neighbour(4 * t + static_cast<index_t>(f));
            if (nb != kNoIndex) set_label(nb >> 2, label[t]);
        }
    }
    beat(pulse);
    std::vector<std::uint8_t> keep(slots, 0);
    for (index_t t = 0; t < slots; ++t) {
        if (!mesh.alive(t) || label[t] != kInside) continue;
        keep[t] = 1;
        for (int i = 0; i < 4; ++i)
            if (mesh.vertex(t)[i] >= n && mesh.vertex(t)[i] < n + 8)
                throw Error("tet front is oriented inwards: its triangles' normals must point out of the region");
    }
    TetDomain out;
    out.front_points = n;
    out.front.assign(front.begin(), front.end());
    out.tets = mesh.release(keep);
    // Points: the input ones, then the Steiner points still in a tet, in creation order.
    std::vector<index_t> new_id(mesh.point_count(), kNoIndex);
    for (index_t i = 0; i < n; ++i) new_id[i] = i;
    out.xyz.assign(xyz.begin(), xyz.end());
    std::vector<std::uint8_t> in_tet(mesh.point_count(), 0);
    for (index_t v : out.tets.vertices()) in_tet[v] = 1;
    for (index_t s : rec.steiner)
        if (in_tet[s]) {
            new_id[s] = out.point_count();
            out.xyz.insert(out.xyz.end(), mesh.point(s), mesh.point(s) + 3);
            ++st.steiner_kept;
        }
    for (index_t t = 0; t < out.tets.size(); ++t)
        for (int i = 0; i < 4; ++i) out.tets.vertex(t)[i] = new_id[out.tets.vertex(t)[i]];
    std::size_t open = 0;
    for (index_t nb : out.tets.neighbours()) open += nb == kNoIndex;
    if (open != front.size() / 3)
        throw Error("boundary recovery: internal error, the region's boundary has " + std::to_string(open) +
                    " faces, the front " + std::to_string(front.size() / 3));
    st.seconds_classify = seconds_since(t0);
    st.tets = out.tets.size();
    st.flips23 = rec.counters.flips23;
    st.edge_removals = rec.counters.edge_removals;
    st.flips32 = rec.counters.flips32;
    st.flips44 = rec.counters.flips44;
    st.seconds_total = seconds_since(t_start);
    if (stats_out) *stats_out = st;
    return out;
}

}  // namespace tubemesh::tets
