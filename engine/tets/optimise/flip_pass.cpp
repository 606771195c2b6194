#include "engine/tets/optimise/flip_pass.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "engine/tets/optimise/tet_flips.hpp"
#include "engine/tets/domain/tet_neighbourhood.hpp"

namespace tubemesh::tets {

using delaunay::kFreeSlot;

namespace {

// A plan as a candidate keeps it between rounds: its kind, old tets and new tets in one block of
// exactly their size. A FlipPlan has room for the largest move (340 bytes) where a 2-3 flip
// needs 14 ids, and a sweep's first round holds a plan for most of its bad tets at once.
class StoredPlan {
public:
    void store(const FlipPlan& p) {
        const std::size_t n = static_cast<std::size_t>(p.old_count) + 4 * static_cast<std::size_t>(p.new_count);
        if (n > capacity_) {
            ids_ = std::make_unique_for_overwrite<index_t[]>(n);
            capacity_ = static_cast<std::uint8_t>(n);
        }
        kind_ = p.kind;
        old_count_ = static_cast<std::uint8_t>(p.old_count);
        new_count_ = static_cast<std::uint8_t>(p.new_count);
        std::copy_n(p.old_tets.begin(), p.old_count, ids_.get());
        for (int j = 0; j < p.new_count; ++j) std::copy_n(p.new_tets[j].begin(), 4, ids_.get() + p.old_count + 4 * j);
    }
    // The plan as apply_flip takes it (its collapse figures are not kept).
    FlipPlan load() const {
        FlipPlan p;
        p.kind = kind_;
        p.old_count = old_count_;
        p.new_count = new_count_;
        std::copy_n(ids_.get(), old_count_, p.old_tets.begin());
        for (int j = 0; j < new_count_; ++j) std::copy_n(ids_.get() + old_count_ + 4 * j, 4, p.new_tets[j].begin());
        return p;
    }
    std::span<const index_t> old_tets() const { return {ids_.get(), old_count_}; }
    // The new tets' point ids, 4 per tet.
    std::span<const index_t> new_points() const { return {ids_.get() + old_count_, 4 * std::size_t{new_count_}}; }
    FlipKind kind() const { return kind_; }

private:
    std::unique_ptr<index_t[]> ids_;
    FlipKind kind_ = FlipKind::Flip23;
    std::uint8_t old_count_ = 0, new_count_ = 0, capacity_ = 0;
};
static_assert(FlipPlan::kMaxOld + 4 * FlipPlan::kMaxNew < 256, "StoredPlan counts ids in a byte");

// A sweep's first round holds one per bad tet: what lives only for a round (the plan's
// claims) is kept beside them, in one array per round.
struct Candidate {
    index_t tet;
    std::array<index_t, 4> vertices;  // to tell whether the slot still holds this tet
    double collapse;
    std::uint32_t planned = 0;  // round whose start the plan describes (0: never)
    bool has_plan = false;
    StoredPlan plan;  // allocated when a plan is first found: most candidates get none
};

// Runs f(0) .. f(n - 1), in parallel unless n is small: late rounds and focused passes have a
// handful of items, and a parallel job for them costs more than it saves (much more when the
// machine is oversubscribed and a worker holding a piece of it is descheduled).
template <class F>
void for_each_index(std::size_t n, F&& f) {
    constexpr std::size_t kSerialBelow = 32;
    if (n < kSerialBelow) {
        for (std::size_t i = 0; i < n; ++i) f(i);
        return;
    }
    tbb::parallel_for(std::size_t{0}, n, f);
}

constexpr std::array<std::array<int, 2>, 6> kTetEdges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

// The shells of a tet's six edges (kTetEdges order), walked once per planning: the walks are
// random memory reads.
struct TetShells {
    std::array<EdgeShell, 6> shell;
    std::array<bool, 6> closed{};
};

void walk_shells(const TetDomain& dom, index_t t, int max_ring, TetShells& s) {
    for (std::size_t i = 0; i < kTetEdges.size(); ++i)
        s.closed[i] =
            edge_shell(dom, t, kTetEdges[i][0], kTetEdges[i][1], std::min(max_ring, EdgeShell::kMaxSize), s.shell[i]);
}

// How much a flip raises the sum of the mesh's collapses beyond keeping its mean: a flip that
// adds a tet must bring more than the mean with it (positive: the mean rises).
double mean_gain(const FlipPlan& p, double mean) {
    return p.new_sum - p.old_sum - mean * static_cast<double>(p.new_count - p.old_count);
}

// A fair tet (collapse at or above the floor) gets the flip that most raises the mesh's mean
// while every tet it makes stays at or above the floor.
bool best_mean_flip(const TetDomain& dom, index_t t, const TetShells& shells, double min_gain, double mean,
                    double floor, const double* slot_collapse, FlipPlan& best) {
    FlipPlan plan;
    bool found = false;
    double best_gain = 0;
    const auto consider = [&](bool planned) {
        if (!planned || plan.new_min < floor) return;
        const double gain = mean_gain(plan, mean);
        if (gain > min_gain * plan.old_count && (!found || gain > best_gain)) {
            best = plan;
            best_gain = gain;
            found = true;
        }
    };
    const double below_floor = std::nextafter(floor, -1.0);
    const double no_gain = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < kTetEdges.size(); ++i)
        if (shells.closed[i])
            consider(plan_shell_removal(dom, shells.shell[i], plan, below_floor, no_gain, slot_collapse));
    for (int f = 0; f < 4; ++f) consider(plan_flip23(dom, t, f, plan, slot_collapse, below_floor));
    return found;
}

// The move that leaves the best smallest collapse among those that beat their own old tets
// by min_gain; false when there is none.
bool best_flip(const TetDomain& dom, index_t t, const TetShells& shells, double min_gain,
               const double* slot_collapse, FlipPlan& best) {
    FlipPlan plan;
    bool found = false;
    const auto consider = [&](bool planned) {
        if (planned && plan.new_min > plan.old_min + min_gain && (!found || plan.new_min > best.new_min)) {
            best = plan;
            found = true;
        }
    };
    // A plan that cannot win is given up as soon as the bound shows it.
    const auto beat = [&] { return found ? best.new_min : -std::numeric_limits<double>::infinity(); };
    for (std::size_t i = 0; i < kTetEdges.size(); ++i)
        if (shells.closed[i])
            consider(plan_shell_removal(dom, shells.shell[i], plan, beat(), min_gain, slot_collapse));
    for (int f = 0; f < 4; ++f) consider(plan_flip23(dom, t, f, plan, slot_collapse, beat(), min_gain));
    return found;
}

bool still_there(const TetDomain& dom, const Candidate& c) {
    if (c.tet >= dom.tets.size()) return false;
    const index_t* v = dom.tets.vertex(c.tet);
    return std::equal(c.vertices.begin(), c.vertices.end(), v);
}

// The old tets and the tets around them whose neighbour codes applying the plan rewrites, as
// they are now (a flip next to a waiting plan changes its neighbours but not the plan), written
// from `out` on: at most kClaimsPerOldTet per old tet. Returns how many.
constexpr std::size_t kClaimsPerOldTet = 5;
static_assert(kClaimsPerOldTet * FlipPlan::kMaxOld < 256, "a plan's claims are counted in a byte");
std::size_t plan_claims(const TetDomain& dom, std::span<const index_t> old_tets, index_t* out) {
    std::size_t n = 0;
    for (const index_t t : old_tets) {
        out[n++] = t;
        for (index_t f = 0; f < 4; ++f) {
            const index_t code = dom.tets.neighbour(4 * t + f);
            if (code != delaunay::kNoAdjacent) out[n++] = code >> 2;
        }
    }
    return n;
}

// `q`: the collapse of every slot (live ones).
std::vector<Candidate> bad_tets(const TetDomain& dom, double threshold, const std::vector<std::uint8_t>* active,
                                const std::vector<double>& q) {
    const index_t n = dom.tets.size();
    // Sorted as (collapse, tet) pairs: a Candidate holds a whole plan, too big to shuffle. Each
    // fixed chunk of slots lists its own, the lists are joined in chunk order, and the pairs
    // are distinct (one per tet), so the parallel sort gives the one sorted order.
    constexpr index_t kChunk = 16384;
    const index_t chunks = (n + kChunk - 1) / kChunk;
    std::vector<std::vector<std::pair<double, index_t>>> listed(chunks);
    tbb::parallel_for(index_t{0}, chunks, [&](index_t c) {
        for (index_t t = c * kChunk; t < std::min(n, (c + 1) * kChunk); ++t) {
            if (!(q[t] < threshold)) continue;
            const index_t* v = dom.tets.vertex(t);
            if (v[0] == kFreeSlot ||
                (active && !(*active)[v[0]] && !(*active)[v[1]] && !(*active)[v[2]] && !(*active)[v[3]]))
                continue;
            listed[c].emplace_back(q[t], t);
        }
    });
    std::vector<std::pair<double, index_t>> order;
    for (const auto& l : listed) order.insert(order.end(), l.begin(), l.end());
    tbb::parallel_sort(order.begin(), order.end());
    std::vector<Candidate> out(order.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, order.size(), 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) {
                              Candidate& c = out[i];
                              const index_t* v = dom.tets.vertex(order[i].second);
                              c.tet = order[i].second;
                              c.vertices = {v[0], v[1], v[2], v[3]};
                              c.collapse = order[i].first;
                          }
                      });
    return out;
}

}  // namespace

FlipSweepCounts flip_sweep(TetDomain& dom, double threshold, double min_gain, int max_edge_ring, double mean,
                           double mean_floor, const std::vector<std::uint8_t>* active,
                           std::vector<std::uint8_t>& changed, std::vector<double>* collapses, const Pulse& pulse) {
    FlipSweepCounts counts;
    // The collapse of every slot, kept up to date as flips write slots: planning reads the old
    // tets' collapses from it (points do not move during the sweep).
    std::vector<double> q;
    if (collapses && collapses->size() == dom.tets.size()) {
        q = std::move(*collapses);  // rebuilt from q at the end
    } else {
        q.resize(dom.tets.size());
        tbb::parallel_for(tbb::blocked_range<index_t>(0, dom.tets.size(), 1024),
                          [&](const tbb::blocked_range<index_t>& r) {
                              for (index_t t = r.begin(); t != r.end(); ++t) {
                                  const index_t* v = dom.tets.vertex(t);
                                  q[t] = v[0] == kFreeSlot ? std::numeric_limits<double>::infinity()
                                                           : collapse_of(dom, v[0], v[1], v[2], v[3]);
                              }
                          });
    }
    std::vector<Candidate> cands = bad_tets(dom, threshold, active, q);
    std::vector<index_t> pending(cands.size());
    for (std::size_t i = 0; i < pending.size(); ++i) pending[i] = static_cast<index_t>(i);
    std::vector<std::uint8_t> alive;
    std::vector<std::uint32_t> claimed;  // round stamp of the round that took the tet
    std::vector<std::uint32_t> written;  // last round whose flips rewrote the slot's vertex row (0: none)
    std::vector<index_t> taken, waiting;
    const index_t spare_per_move = static_cast<index_t>(max_extra_slots(max_edge_ring));
    // Each candidate is applied at most once: room for every slot the sweep can add, reserved
    // now, so that the per-slot arrays never move as they grow (a move holds the old and the
    // new array at once, which set the sweep's memory peak).
    const std::size_t most_slots = std::size_t{dom.tets.size()} + std::size_t{spare_per_move} * cands.size();
    q.reserve(most_slots);
    written.reserve(most_slots);
    claimed.reserve(most_slots);
    // The round's claims: pending[i]'s are claims[claim_at[i] .. claim_at[i] + claim_count[i]).
    std::vector<std::size_t> claim_at;
    std::vector<std::uint8_t> claim_count;
    std::vector<index_t> claims;

    while (!pending.empty()) {
        beat(pulse);
        ++counts.rounds;
        const auto stamp = static_cast<std::uint32_t>(counts.rounds);
        written.resize(dom.tets.size(), 0);
        alive.assign(pending.size(), 0);
        // A plan stays valid while no flip rewrote one of its old tets: it depends on their
        // vertex rows and collapses alone (points do not move in a sweep, and applying reads
        // the cavity's outside as it is then). A flip beside it may have made another plan
        // better; keeping the one it has instead of planning again halved the sweep's
        // plannings and hardly moved the mean (bench/results/tuning-notes.md).
        const double* slot_collapse = q.data();
        for_each_index(pending.size(), [&](std::size_t i) {
            Candidate& c = cands[pending[i]];
            const bool valid =
                c.planned != 0 && c.has_plan &&
                std::none_of(c.plan.old_tets().begin(), c.plan.old_tets().end(),
                             [&](index_t t) { return written[t] >= c.planned; });
            if (!valid) {
                if (!still_there(dom, c)) return;
                c.planned = stamp;
                TetShells shells;
                walk_shells(dom, c.tet, max_edge_ring, shells);
                FlipPlan found;
                c.has_plan = c.collapse < mean_floor || mean <= 0
                                  ? best_flip(dom, c.tet, shells, min_gain, slot_collapse, found)
                                  : best_mean_flip(dom, c.tet, shells, min_gain, mean, mean_floor, slot_collapse,
                                                   found);
                // Only a candidate with a plan stays pending.
                if (c.has_plan) c.plan.store(found);
            }
            alive[i] = c.has_plan;
        });
        // Claims of every plan, a kept one's too: its neighbours may be new tets.
        claim_at.resize(pending.size());
        std::size_t room = 0;
        for (std::size_t i = 0; i < pending.size(); ++i) {
            claim_at[i] = room;
            if (alive[i]) room += kClaimsPerOldTet * cands[pending[i]].plan.old_tets().size();
        }
        claims.resize(room);
        claim_count.assign(pending.size(), 0);
        for_each_index(pending.size(), [&](std::size_t i) {
            if (alive[i])
                claim_count[i] = static_cast<std::uint8_t>(
                    plan_claims(dom, cands[pending[i]].plan.old_tets(), claims.data() + claim_at[i]));
        });

        // Worst first; a candidate whose claims meet a taken one's waits for the next round
        // (two flips that share no claimed tet write disjoint slots and neighbour codes).
        claimed.resize(dom.tets.size(), 0);
        taken.clear();
        waiting.clear();
        for (std::size_t i = 0; i < pending.size(); ++i) {
            if (!alive[i]) continue;
            const std::span<const index_t> fp(claims.data() + claim_at[i], claim_count[i]);
            if (std::any_of(fp.begin(), fp.end(), [&](index_t t) { return claimed[t] == stamp; })) {
                waiting.push_back(pending[i]);
                continue;
            }
            for (index_t t : fp) claimed[t] = stamp;
            taken.push_back(pending[i]);
        }

        const index_t base = dom.tets.size();
        const std::size_t spare_total = std::size_t{spare_per_move} * taken.size();
        dom.tets.reserve(base + spare_total);
        dom.tets.set_size(base + static_cast<index_t>(spare_total));
        for (index_t s = base; s < dom.tets.size(); ++s) std::fill_n(dom.tets.vertex(s), 4, kFreeSlot);
        q.resize(dom.tets.size(), std::numeric_limits<double>::infinity());

        for_each_index(taken.size(), [&](std::size_t k) {
            std::array<index_t, FlipPlan::kMaxNew> spare{};
            for (index_t s = 0; s < spare_per_move; ++s) spare[s] = base + static_cast<index_t>(k) * spare_per_move + s;
            const FlipPlan plan = cands[taken[k]].plan.load();
            apply_flip(dom, plan, {spare.data(), spare_per_move});
            // The slots apply_flip wrote: the old ones first, then the spare ones in order.
            for (int j = 0; j < plan.new_count; ++j) {
                const index_t slot = j < plan.old_count ? plan.old_tets[j] : spare[j - plan.old_count];
                q[slot] = collapse_of(dom, plan.new_tets[j]);
            }
        });
        for (index_t k : taken) {
            const StoredPlan& plan = cands[k].plan;
            for (index_t t : plan.old_tets()) written[t] = stamp;
            for (index_t p : plan.new_points()) changed[p] = 1;
            switch (plan.kind()) {
                case FlipKind::Flip23: ++counts.flips23; break;
                case FlipKind::Flip32: ++counts.flips32; break;
                case FlipKind::Flip44: ++counts.flips44; break;
                case FlipKind::EdgeRemoval: ++counts.edge_removals; break;
                case FlipKind::PointInsertion: break;  // only the rescue plans these
            }
        }
        pending.swap(waiting);
    }
    compact_tets(dom, &q);
    if (collapses) *collapses = std::move(q);
    return counts;
}

}  // namespace tubemesh::tets
