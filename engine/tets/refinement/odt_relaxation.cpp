#include "engine/tets/refinement/odt_relaxation.hpp"

#include <algorithm>
#include <atomic>
#include <span>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "engine/core/ordered_compact.hpp"
#include "engine/core/timing.hpp"
#include "engine/delaunay/insertion_order.hpp"
#include "engine/delaunay/triangulation.hpp"
#include "engine/tets/domain/point_colouring.hpp"  // build_incidence
#include "engine/tets/domain/star_kernels.hpp"
#include "engine/tets/domain/tet_neighbourhood.hpp"

namespace tubemesh::tets {
namespace {

// Per-thread scratch of one move.
struct MoveScratch {
    StarCorners corners;
    std::vector<double> weight;
};

// Where p goes: towards its weighted ODT position, the whole way, or half, or a quarter,
// whichever first leaves every tet of its star positive (with the other points where they are),
// written to `to`. Returns whether it moved (not when it is at its target already, or no step
// keeps its star positive).
bool move_point(const TetDomain& dom, index_t p, std::span<const index_t> star, std::span<const double> sizes,
                MoveScratch& s, double* to) {
    gather_star_corners(dom, p, star, s.corners, false);
    s.weight.resize(star.size());
    for (std::size_t k = 0; k < star.size(); ++k) {
        const index_t* v = dom.tets.vertex(star[k]);
        const double h = 0.25 * (sizes[v[0]] + sizes[v[1]] + sizes[v[2]] + sizes[v[3]]);
        s.weight[k] = 1.0 / (h * h * h);  // point density of the size field
    }
    const Vec3 here = point_vec(dom, p);
    const Vec3 target = odt_target(s.corners, here, s.weight);
    if (target.x == here.x && target.y == here.y && target.z == here.z) return false;
    for (double step : {1.0, 0.5, 0.25}) {
        const Vec3 x = here + step * (target - here);
        if (!none_inverted(dom, p, star, x)) continue;
        to[0] = x.x;
        to[1] = x.y;
        to[2] = x.z;
        return true;
    }
    return false;
}

// One sweep of moves over the free points (ids >= fixed), all at once from the old positions
// (Jacobi, as in Chen and Holst): each point stays inside its star as the sweep finds it, and
// the tets are built again after the last sweep, so they need not stay positive in between (a
// later sweep moves a point only where its whole star is positive again). As good as moving
// colour by colour (Gauss-Seidel), faster and with no colouring (bench/results/tuning-notes.md).
// A point that still ended outside the region would be refused by the reinsertion's walk.
std::uint64_t move_points(TetDomain& dom, index_t fixed, std::span<const double> sizes) {
    const Incidence inc = build_incidence(dom);
    const index_t n = dom.point_count();
    std::vector<double> moved_xyz(dom.xyz.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, moved_xyz.size(), 1 << 15), [&](const tbb::blocked_range<std::size_t>& r) {
        std::copy(dom.xyz.begin() + r.begin(), dom.xyz.begin() + r.end(), moved_xyz.begin() + r.begin());
    });
    std::vector<std::uint8_t> moved(n, 0);
    tbb::enumerable_thread_specific<MoveScratch> scratch;
    tbb::parallel_for(tbb::blocked_range<index_t>(fixed, n, 64), [&](const tbb::blocked_range<index_t>& r) {
        auto& s = scratch.local();
        for (index_t p = r.begin(); p != r.end(); ++p) {
            const auto star = inc.of(p);
            if (!star.empty()) moved[p] = move_point(dom, p, star, sizes, s, moved_xyz.data() + std::size_t{3} * p);
        }
    });
    dom.xyz.swap(moved_xyz);
    std::uint64_t moves = 0;
    for (std::uint8_t m : moved) moves += m;
    return moves;
}

// Inserts the free points of `dom` again into `recovered` (the recovered mesh or a copy of it)
// and makes the result dom's tets, the far field's points (ids [fixed, fixed + in_place)) first
// and then the others, each group in BRIO rounds (insertion_order.hpp), each along the Hilbert curve,
// each walk from the previous insertion: in curve order alone every point's cavity took in again
// the long tets that the points before it had joined to the far front (about 46 tets made per
// point on the serpentine lift, 38 with rounds). A walk that runs into the front (a
// concave part of it) gets the point blocked; those points get one more walk once the others
// are in, from a tet of the new mesh at one of the point's old neighbours: the two shared a tet,
// so the way between them is short and inside the region. Points that fail that too (none on
// the reference cases) are left without tets. Returns how many needed the second walk.
index_t reinsert(TetDomain& dom, delaunay::TetStore&& recovered, index_t fixed, index_t in_place, unsigned parts,
                 const Pulse& pulse) {
    const index_t n = dom.point_count();
    std::vector<index_t> used;
    {
        // Threads may flag one point at once, always with 1: relaxed stores suffice.
        std::vector<std::uint8_t> in_tet(n, 0);
        const std::span<const index_t> rows = dom.tets.vertices();
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size(), 16384), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t k = r.begin(); k < r.end(); ++k)
                std::atomic_ref<std::uint8_t>(in_tet[rows[k]]).store(1, std::memory_order_relaxed);
        });
        used = kept_indices(n - fixed, [&](std::size_t i) { return in_tet[fixed + i] != 0; });
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, used.size(), 16384), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t k = r.begin(); k < r.end(); ++k) used[k] += fixed;
        });
    }
    // The old tets' vertex rows alone (for the blocked points' second walks): the old store's
    // neighbour rows would only add to the peak while the new mesh is built.
    const std::vector<index_t> old_rows(dom.tets.vertices().begin(), dom.tets.vertices().end());
    dom.tets = delaunay::TetStore();
    // The points kept in place (the far field) go first, in rounds of their own: the others'
    // cavities then stay local, as in the refinement.
    const std::size_t still = static_cast<std::size_t>(
        std::lower_bound(used.begin(), used.end(), fixed + in_place) - used.begin());
    delaunay::InsertionOrder order;
    for (const auto& range : {std::pair<std::size_t, std::size_t>{0, still}, {still, used.size()}}) {
        const std::size_t from = range.first, m = range.second - range.first;
        std::vector<double> x(m), y(m), z(m);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t i = r.begin(); i < r.end(); ++i) {
                const double* q = dom.point(used[from + i]);
                x[i] = q[0];
                y[i] = q[1];
                z[i] = q[2];
            }
        });
        const delaunay::InsertionOrder part = delaunay::brio_hilbert_order(x, y, z);
        const index_t offset = static_cast<index_t>(order.order.size());
        if (order.round_begin.empty()) order.round_begin.push_back(0);
        for (index_t k : part.order) order.order.push_back(static_cast<index_t>(from) + k);
        for (std::size_t r = 1; r < part.round_begin.size(); ++r) order.round_begin.push_back(offset + part.round_begin[r]);
    }
    // The kernel holds every point (kernel id = domain id; the free ones not in a tet yet, the
    // unused ones never inserted) and the recovered tets while it inserts.
    delaunay::Triangulation tri;
    tri.set_pulse(pulse);
    const std::size_t recovered_tets = recovered.size();
    tri.adopt(std::move(dom.xyz), std::move(recovered));
    dom.xyz.clear();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, order.order.size(), 16384), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) order.order[i] = used[order.order[i]];
    });
    tri.reserve_tets(recovered_tets + 8 * used.size() + 1024);
    constexpr index_t kMinPointsPerPart = 64;
    const std::span<const index_t> all(order.order);
    for (std::size_t r = 0; r + 1 < order.round_begin.size(); ++r)
        tri.insert(all.subspan(order.round_begin[r], order.round_begin[r + 1] - order.round_begin[r]), parts, kMinPointsPerPart);
    const std::vector<index_t> blocked = tri.blocked();
    if (!blocked.empty()) {
        std::vector<std::uint8_t> is_blocked(n, 0);
        for (index_t p : blocked) is_blocked[p] = 1;
        std::vector<std::vector<index_t>> near(blocked.size());
        std::vector<index_t> slot(n, kNoIndex);
        for (std::size_t i = 0; i < blocked.size(); ++i) slot[blocked[i]] = static_cast<index_t>(i);
        for (std::size_t t = 0; t < old_rows.size(); t += 4) {
            const index_t* v = old_rows.data() + t;
            for (int i = 0; i < 4; ++i)
                if (is_blocked[v[i]])
                    for (int j = 0; j < 4; ++j)
                        if (!is_blocked[v[j]]) near[slot[v[i]]].push_back(v[j]);
        }
        std::vector<index_t> tet_at(n, kNoIndex);
        const delaunay::TetStore& now = tri.store();
        for (index_t t = 0; t < now.size(); ++t) {
            const index_t* v = now.vertex(t);
            if (v[0] == delaunay::kFreeSlot) continue;
            for (int i = 0; i < 4; ++i) tet_at[v[i]] = t;
        }
        for (std::size_t i = 0; i < blocked.size(); ++i)
            for (index_t q : near[i])
                if (tet_at[q] != kNoIndex) {
                    tri.set_walk_start(blocked[i], tet_at[q]);
                    break;
                }
        tri.insert(blocked, 1, kMinPointsPerPart);
    }
    dom.tets = tri.finish();
    dom.xyz = tri.take_points();
    return static_cast<index_t>(blocked.size());
}

// `spend` (recovered.tets or nullptr): the last insertion takes it instead of a copy.
RelaxationStats relax(TetDomain& domain, const RecoveredTets& recovered, delaunay::TetStore* spend,
                      std::span<const double> sizes, const Parallelism& par, const RelaxationOptions& options,
                      const Pulse& pulse) {
    const auto t0 = Clock::now();
    if (options.iterations < 0) throw Error("relaxation: iterations must be 0 or more");
    if (sizes.size() != domain.point_count()) throw Error("relaxation: one size per point expected");
    const index_t fixed = recovered.points;
    if (fixed > domain.point_count() || fixed < domain.front_points || recovered.in_place > domain.point_count() - fixed)
        throw Error("relaxation: the recovered mesh is not the start of the domain");
    RelaxationStats stats;
    if (options.iterations == 0) return stats;
    for (int it = 0; it < options.iterations; ++it) {
        ++stats.iterations;
        beat(pulse);
        stats.moves += move_points(domain, fixed + recovered.in_place, sizes);
        beat(pulse);
        if (!options.reinsert_each_iteration && it + 1 < options.iterations) continue;
        const bool last = it + 1 == options.iterations;
        stats.second_walks += reinsert(domain, spend && last ? std::move(*spend) : recovered.tets.clone(),
                                       fixed, recovered.in_place, par.parts, pulse);
        ++stats.reinsertions;
    }
    // A point lost in one iteration stays out of the later ones (it has no tet, so it neither
    // moves nor is inserted again); remove them all.
    const index_t before = domain.point_count();
    drop_unused_points(domain, fixed);
    stats.dropped = before - domain.point_count();
    stats.seconds = seconds_since(t0);
    return stats;
}

}  // namespace

RelaxationStats relax_points(TetDomain& domain, const RecoveredTets& recovered, std::span<const double> sizes,
                             const Parallelism& par, const RelaxationOptions& options, const Pulse& pulse) {
    return relax(domain, recovered, nullptr, sizes, par, options, pulse);
}

RelaxationStats relax_points(TetDomain& domain, RecoveredTets&& recovered, std::span<const double> sizes,
                             const Parallelism& par, const RelaxationOptions& options, const Pulse& pulse) {
    return relax(domain, recovered, &recovered.tets, sizes, par, options, pulse);
}

}  // namespace tubemesh::tets
