#include "engine/tets/optimise/tet_flips.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include <tbb/parallel_for.h>

#include "engine/tets/domain/ring_triangulation.hpp"

namespace tubemesh::tets {

using delaunay::kFreeSlot;
using delaunay::kNoAdjacent;

namespace {

bool all_positive(const TetDomain& dom, const FlipPlan& plan) {
    for (int j = 0; j < plan.new_count; ++j)
        if (!positively_oriented(dom, plan.new_tets[j])) return false;
    return true;
}

using FaceKey = std::array<index_t, 3>;

FaceKey face_key(index_t a, index_t b, index_t c) {
    FaceKey k{a, b, c};
    std::sort(k.begin(), k.end());
    return k;
}

FaceKey face_key(const index_t* v, int f) {
    const auto& l = kTetFaceToward[f];
    return face_key(v[l[0]], v[l[1]], v[l[2]]);
}

}  // namespace

double min_collapse_of_tets(const TetDomain& dom, const index_t* tets, int count, double* sum,
                            const double* slot_collapse) {
    double q = std::numeric_limits<double>::infinity(), total = 0;
    for (int i = 0; i < count; ++i) {
        const index_t* v = dom.tets.vertex(tets[i]);
        const double x = slot_collapse ? slot_collapse[tets[i]] : collapse_of(dom, v[0], v[1], v[2], v[3]);
        q = std::min(q, x);
        total += x;
    }
    if (sum) *sum = total;
    return q;
}

bool plan_flip23(const TetDomain& dom, index_t t, int f, FlipPlan& plan, const double* slot_collapse,
                 double must_exceed, double gain) {
    const index_t n = dom.tets.neighbour(4 * t + static_cast<index_t>(f));
    if (n == kNoAdjacent) return false;
    const index_t other = n >> 2;
    const index_t* v = dom.tets.vertex(t);
    const auto& l = kTetFaceToward[f];
    const index_t a = v[l[0]], b = v[l[1]], c = v[l[2]], d = v[f];
    const index_t e = dom.tets.vertex(other)[n & 3];
    plan.kind = FlipKind::Flip23;
    plan.old_count = 2;
    plan.old_tets[0] = t;
    plan.old_tets[1] = other;
    plan.new_count = 3;
    // (a, b, c) is counter-clockwise seen from d and e lies on the other side, so each new
    // tet around the edge d-e is oriented (face edge, e, d).
    plan.new_tets[0] = {a, b, e, d};
    plan.new_tets[1] = {b, c, e, d};
    plan.new_tets[2] = {c, a, e, d};
    plan.old_min = min_collapse_of_tets(dom, plan.old_tets.data(), 2, &plan.old_sum, slot_collapse);
    const double bound = std::max(must_exceed, plan.old_min + gain);
    plan.new_min = std::numeric_limits<double>::infinity();
    plan.new_sum = 0;
    // The first two in one pair evaluation (the same bits as one at a time), then the third.
    double q[3];
    collapse_of_pair(dom, plan.new_tets[0].data(), plan.new_tets[1].data(), q);
    for (int j = 0; j < 3; ++j) {
        if (j == 2) q[2] = collapse_of(dom, plan.new_tets[2]);
        if (!(q[j] > bound)) return false;
        plan.new_min = std::min(plan.new_min, q[j]);
        plan.new_sum += q[j];
    }
    return plan.new_min > 0 && all_positive(dom, plan);
}

bool plan_edge_removal(const TetDomain& dom, index_t t, int la, int lb, int max_ring, FlipPlan& plan,
                       double must_exceed, double gain, const double* slot_collapse) {
    EdgeShell shell;
    if (!edge_shell(dom, t, la, lb, std::min(max_ring, EdgeShell::kMaxSize), shell)) return false;
    return plan_shell_removal(dom, shell, plan, must_exceed, gain, slot_collapse);
}

bool plan_shell_removal(const TetDomain& dom, const EdgeShell& shell, FlipPlan& plan, double must_exceed, double gain,
                        const double* slot_collapse) {
    const int n = shell.size;
    if (n < 3) return false;
    double old_sum = 0;
    const double old_min = min_collapse_of_tets(dom, shell.tets.data(), n, &old_sum, slot_collapse);
    // Triangulations at or below the bound are of no use to the caller: the search skips them
    // (a sub-polygon no better than the bound keeps the bound as its value, which then loses).
    const double bound = std::max(must_exceed, old_min + gain);
    const auto& p = shell.ring;
    // Triangle (p_i, p_k, p_j) makes the tets (p_i, p_k, p_j, b) and (p_k, p_i, p_j, a): the
    // ring runs counter-clockwise seen from b. Both are scored in one pair evaluation; the
    // second is not looked at when the first already cannot beat the search's current best.
    const auto score = [&](int i, int k, int j, double beat) {
        const index_t rows[2][4] = {{p[i], p[k], p[j], shell.b}, {p[k], p[i], p[j], shell.a}};
        double q[2];
        collapse_of_pair(dom, rows[0], rows[1], q);  // both for the price of one
        const double first = q[0];
        if (first <= beat) return RingTriangle{first, first, first};
        const double second = q[1];
        return RingTriangle{std::min(first, second), first, second};
    };
    RingTriangulation<EdgeShell::kMaxSize> ring;
    const bool found = ring.solve(n, bound, score, [](int, int) { return true; });
    plan.kind = n == 3 ? FlipKind::Flip32 : n == 4 ? FlipKind::Flip44 : FlipKind::EdgeRemoval;
    plan.old_count = n;
    std::copy_n(shell.tets.begin(), n, plan.old_tets.begin());
    plan.old_min = old_min;
    plan.old_sum = old_sum;
    plan.new_min = ring.value();
    if (!found) return false;
    plan.new_count = 0;
    plan.new_sum = 0;
    ring.for_each_triangle([&](int i, int k, int j, double first, double second) {
        plan.new_tets[plan.new_count++] = {p[i], p[k], p[j], shell.b};
        plan.new_tets[plan.new_count++] = {p[k], p[i], p[j], shell.a};
        plan.new_sum += first;
        plan.new_sum += second;
    });
    return plan.new_min > 0 && all_positive(dom, plan);
}

int apply_flip(TetDomain& dom, const FlipPlan& plan, std::span<const index_t> spare) {
    auto& store = dom.tets;
    const auto is_old = [&](index_t u) {
        return std::find(plan.old_tets.begin(), plan.old_tets.begin() + plan.old_count, u) !=
               plan.old_tets.begin() + plan.old_count;
    };
    // The cavity's outside, read before any old slot is overwritten.
    struct Outside {
        FaceKey key;
        index_t code;
    };
    std::array<Outside, 4 * FlipPlan::kMaxOld> outside{};
    int outside_count = 0;
    for (int i = 0; i < plan.old_count; ++i) {
        const index_t t = plan.old_tets[i];
        for (int f = 0; f < 4; ++f) {
            const index_t n = store.neighbour(4 * t + static_cast<index_t>(f));
            if (n != kNoAdjacent && is_old(n >> 2)) continue;
            outside[outside_count++] = {face_key(store.vertex(t), f), n};
        }
    }
    const int spare_used = std::max(0, plan.new_count - plan.old_count);
    if (static_cast<std::size_t>(spare_used) > spare.size())
        throw Error("tet optimisation: a flip needs more spare slots than it was given (internal error)");
    std::array<index_t, FlipPlan::kMaxNew> slot{};
    for (int j = 0; j < plan.new_count; ++j)
        slot[j] = j < plan.old_count ? plan.old_tets[j] : spare[static_cast<std::size_t>(j - plan.old_count)];
    for (int j = plan.new_count; j < plan.old_count; ++j) std::fill_n(store.vertex(plan.old_tets[j]), 4, kFreeSlot);
    for (int j = 0; j < plan.new_count; ++j) std::copy_n(plan.new_tets[j].begin(), 4, store.vertex(slot[j]));

    std::array<std::array<FaceKey, 4>, FlipPlan::kMaxNew> keys{};
    for (int j = 0; j < plan.new_count; ++j)
        for (int f = 0; f < 4; ++f) keys[j][f] = face_key(plan.new_tets[j].data(), f);
    for (int j = 0; j < plan.new_count; ++j) {
        for (int f = 0; f < 4; ++f) {
            const index_t code = 4 * slot[j] + static_cast<index_t>(f);
            index_t across = kNoIndex;
            bool found = false;
            for (int j2 = 0; j2 < plan.new_count && !found; ++j2) {
                if (j2 == j) continue;
                for (int f2 = 0; f2 < 4; ++f2) {
                    if (keys[j2][f2] == keys[j][f]) {
                        across = 4 * slot[j2] + static_cast<index_t>(f2);
                        found = true;
                        break;
                    }
                }
            }
            for (int o = 0; o < outside_count && !found; ++o) {
                if (outside[o].key == keys[j][f]) {
                    across = outside[o].code;
                    found = true;
                    if (across != kNoAdjacent) store.neighbour(across) = code;
                }
            }
            if (!found) throw Error("tet optimisation: a flipped tet has a face that matches no neighbour (internal error)");
            store.neighbour(code) = across;
        }
    }
    return spare_used;
}

void apply_flip_appending(TetDomain& dom, const FlipPlan& plan) {
    const int extra = std::max(0, plan.extra_slots());
    std::vector<index_t> spare(static_cast<std::size_t>(extra));
    const index_t first = dom.tets.size();
    dom.tets.reserve(std::size_t{first} + spare.size());
    dom.tets.set_size(first + static_cast<index_t>(extra));
    for (int i = 0; i < extra; ++i) spare[static_cast<std::size_t>(i)] = first + static_cast<index_t>(i);
    apply_flip(dom, plan, spare);
}

void compact_tets(TetDomain& dom, std::vector<double>* per_slot) {
    delaunay::TetStore& store = dom.tets;
    const index_t n = store.size();
    // Fixed chunks count their live tets in parallel; the prefix sums give every tet its new id.
    constexpr index_t kChunk = 16384;
    const index_t chunks = (n + kChunk - 1) / kChunk;
    const auto begin = [&](index_t c) { return std::min(n, c * kChunk); };
    std::vector<index_t> first(std::size_t{chunks} + 1, 0);
    tbb::parallel_for(index_t{0}, chunks, [&](index_t c) {
        index_t live = 0;
        for (index_t t = begin(c); t < begin(c + 1); ++t) live += store.vertex(t)[0] != kFreeSlot;
        first[c + 1] = live;
    });
    for (index_t c = 0; c < chunks; ++c) first[c + 1] += first[c];
    const index_t live = first[chunks];
    if (live == n) return;
    std::vector<index_t> renumber(n, kNoIndex);
    tbb::parallel_for(index_t{0}, chunks, [&](index_t c) {
        index_t to = first[c];
        for (index_t t = begin(c); t < begin(c + 1); ++t)
            if (store.vertex(t)[0] != kFreeSlot) renumber[t] = to++;
    });
    // In place, in increasing order: a tet's new slot is never above its old one, so no row is
    // overwritten before it moves (no second store at the peak of the optimisation).
    for (index_t t = 0; t < n; ++t) {
        const index_t to = renumber[t];
        if (to == kNoIndex) continue;
        for (index_t f = 0; f < 4; ++f) {
            const index_t code = store.neighbour(4 * t + f);
            store.vertex(to)[f] = store.vertex(t)[f];
            store.neighbour(4 * to + f) = code == kNoAdjacent ? kNoAdjacent : 4 * renumber[code >> 2] + (code & 3);
        }
        if (per_slot) (*per_slot)[to] = (*per_slot)[t];
    }
    store.set_size(live);
    if (per_slot) per_slot->resize(live);
}

}  // namespace tubemesh::tets
