#include "engine/tets/flip_pass.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "engine/tets/tet_flips.hpp"
#include "engine/tets/tet_neighbourhood.hpp"

namespace tubemesh::tets {

using delaunay::kFreeSlot;

namespace {

struct Candidate {
    index_t tet;
    std::array<index_t, 4> vertices;  // to tell whether the slot still holds this tet
    double collapse;
};

constexpr std::array<std::array<int, 2>, 6> kTetEdges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

// The move that leaves the best smallest collapse among those that beat their own old tets
// by min_gain; false when there is none.
bool best_flip(const TetDomain& dom, index_t t, double min_gain, int max_ring, FlipPlan& best) {
    FlipPlan plan;
    bool found = false;
    const auto consider = [&](bool planned) {
        if (planned && plan.new_min > plan.old_min + min_gain && (!found || plan.new_min > best.new_min)) {
            best = plan;
            found = true;
        }
    };
    for (const auto& e : kTetEdges) consider(plan_edge_removal(dom, t, e[0], e[1], max_ring, plan));
    for (int f = 0; f < 4; ++f) consider(plan_flip23(dom, t, f, plan));
    return found;
}

bool still_there(const TetDomain& dom, const Candidate& c) {
    if (c.tet >= dom.tets.size()) return false;
    const index_t* v = dom.tets.vertex(c.tet);
    return std::equal(c.vertices.begin(), c.vertices.end(), v);
}

std::vector<Candidate> bad_tets(const TetDomain& dom, double threshold) {
    const index_t n = dom.tets.size();
    std::vector<double> q(n);
    tbb::parallel_for(tbb::blocked_range<index_t>(0, n, 1024), [&](const tbb::blocked_range<index_t>& r) {
        for (index_t t = r.begin(); t != r.end(); ++t) {
            const index_t* v = dom.tets.vertex(t);
            q[t] = v[0] == kFreeSlot ? std::numeric_limits<double>::infinity() : collapse_of(dom, v[0], v[1], v[2], v[3]);
        }
    });
    std::vector<Candidate> out;
    for (index_t t = 0; t < n; ++t) {
        if (!(q[t] < threshold)) continue;
        const index_t* v = dom.tets.vertex(t);
        out.push_back({t, {v[0], v[1], v[2], v[3]}, q[t]});
    }
    std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
        return a.collapse != b.collapse ? a.collapse < b.collapse : a.tet < b.tet;
    });
    return out;
}

}  // namespace

FlipSweepCounts flip_sweep(TetDomain& dom, double threshold, double min_gain, int max_edge_ring) {
    FlipSweepCounts counts;
    std::vector<Candidate> pending = bad_tets(dom, threshold);
    std::vector<std::vector<index_t>> footprint;
    std::vector<std::uint8_t> alive;
    std::vector<std::uint32_t> claimed;  // round stamp of the round that took the tet
    std::vector<std::size_t> taken;
    std::vector<Candidate> waiting;
    std::vector<int> outcome;
    tbb::enumerable_thread_specific<std::vector<index_t>> star_scratch;
    const index_t spare_per_move = static_cast<index_t>(max_extra_slots(max_edge_ring));

    while (!pending.empty()) {
        ++counts.rounds;
        const auto stamp = static_cast<std::uint32_t>(counts.rounds);
        footprint.resize(pending.size());
        alive.assign(pending.size(), 0);
        tbb::parallel_for(std::size_t{0}, pending.size(), [&](std::size_t i) {
            const Candidate& c = pending[i];
            if (!still_there(dom, c)) return;
            alive[i] = 1;
            auto& star = star_scratch.local();
            auto& fp = footprint[i];
            fp.clear();
            for (index_t p : c.vertices) {
                vertex_star(dom, c.tet, p, star);
                fp.insert(fp.end(), star.begin(), star.end());
            }
        });

        // Worst first; a candidate whose stars meet a taken one waits for the next round.
        claimed.resize(dom.tets.size(), 0);
        taken.clear();
        waiting.clear();
        for (std::size_t i = 0; i < pending.size(); ++i) {
            if (!alive[i]) continue;
            const auto& fp = footprint[i];
            if (std::any_of(fp.begin(), fp.end(), [&](index_t t) { return claimed[t] == stamp; })) {
                waiting.push_back(pending[i]);
                continue;
            }
            for (index_t t : fp) claimed[t] = stamp;
            taken.push_back(i);
        }

        const index_t base = dom.tets.size();
        const std::size_t spare_total = std::size_t{spare_per_move} * taken.size();
        dom.tets.reserve(base + spare_total);
        dom.tets.set_size(base + static_cast<index_t>(spare_total));
        for (index_t s = base; s < dom.tets.size(); ++s) std::fill_n(dom.tets.vertex(s), 4, kFreeSlot);

        outcome.assign(taken.size(), -1);
        tbb::parallel_for(std::size_t{0}, taken.size(), [&](std::size_t k) {
            FlipPlan plan;
            if (!best_flip(dom, pending[taken[k]].tet, min_gain, max_edge_ring, plan)) return;
            std::array<index_t, FlipPlan::kMaxNew> spare{};
            for (index_t s = 0; s < spare_per_move; ++s) spare[s] = base + static_cast<index_t>(k) * spare_per_move + s;
            apply_flip(dom, plan, {spare.data(), spare_per_move});
            outcome[k] = static_cast<int>(plan.kind);
        });
        for (int o : outcome) {
            if (o < 0) continue;
            switch (static_cast<FlipKind>(o)) {
                case FlipKind::Flip23: ++counts.flips23; break;
                case FlipKind::Flip32: ++counts.flips32; break;
                case FlipKind::Flip44: ++counts.flips44; break;
                case FlipKind::EdgeRemoval: ++counts.edge_removals; break;
            }
        }
        pending.swap(waiting);
    }
    compact_tets(dom);
    return counts;
}

}  // namespace tubemesh::tets
