#include "engine/tets/optimise/worst_tet_rescue.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "engine/tets/optimise/point_insertion.hpp"
#include "engine/tets/domain/star_kernels.hpp"
#include "engine/tets/optimise/tet_flips.hpp"
#include "engine/tets/domain/tet_neighbourhood.hpp"

namespace tubemesh::tets {

namespace {

constexpr int kRescueMoveRounds = 3;
constexpr int kRescueRounds = 2;

// Where an inserted point may go, over each face of the tet, as fractions of the way from
// the face's centroid to the apex that would make the tet on it regular; the rescue's moves
// then place it. Several, because a high site can lie beyond the front or need a cavity larger
// than a plan holds (bench/results/tuning-notes.md has the case that needed it).
constexpr double kInsertionHeights[] = {1.0, 0.75, 0.5, 0.3};

// The old rows of the slots a flip writes (its old tets and their face neighbours), the
// store's size and the point count: writing them back undoes the flip or insertion.
struct Undo {
    index_t size = 0, point_count = 0;
    std::vector<index_t> slots;
    std::vector<std::array<index_t, 8>> rows;
    std::vector<index_t> points;
    std::vector<std::array<double, 3>> xyz;
};

void save(const TetDomain& dom, const FlipPlan& plan, Undo& u) {
    u.size = dom.tets.size();
    u.point_count = dom.point_count();
    u.slots.clear();
    u.rows.clear();
    u.points.clear();
    u.xyz.clear();
    const auto add = [&](index_t t) {
        if (std::find(u.slots.begin(), u.slots.end(), t) != u.slots.end()) return;
        std::array<index_t, 8> row{};
        for (int i = 0; i < 4; ++i) {
            row[i] = dom.tets.vertex(t)[i];
            row[4 + i] = dom.tets.neighbour(4 * t + static_cast<index_t>(i));
        }
        u.slots.push_back(t);
        u.rows.push_back(row);
    };
    for (int i = 0; i < plan.old_count; ++i) {
        const index_t t = plan.old_tets[i];
        add(t);
        for (index_t f = 0; f < 4; ++f)
            if (const index_t n = dom.tets.neighbour(4 * t + f); n != delaunay::kNoAdjacent) add(n >> 2);
    }
}

void restore(TetDomain& dom, const Undo& u) {
    for (std::size_t k = 0; k < u.slots.size(); ++k)
        for (int i = 0; i < 4; ++i) {
            dom.tets.vertex(u.slots[k])[i] = u.rows[k][i];
            dom.tets.neighbour(4 * u.slots[k] + static_cast<index_t>(i)) = u.rows[k][4 + i];
        }
    dom.tets.set_size(u.size);
    for (std::size_t k = u.points.size(); k-- > 0;)  // last move first: a point may have moved twice
        std::copy_n(u.xyz[k].data(), 3, dom.xyz.data() + std::size_t{3} * u.points[k]);
    dom.xyz.resize(std::size_t{3} * u.point_count);
}

// Moves free point p (a vertex of tet seed) to where the worst tet of its star is best, if
// that beats where it is; records its old place in `u`. Appends its star to `touched`.
void lift_point(TetDomain& dom, index_t seed, index_t p, double bound, Undo& u, std::vector<index_t>& star,
                std::vector<index_t>& touched) {
    vertex_star(dom, seed, p, star);
    touched.insert(touched.end(), star.begin(), star.end());
    StarCorners corners;
    gather_star_corners(dom, p, star, corners);
    const Vec3 centroid = star_centroid(corners);
    // Ranked by (min(worst tet, bound), sum of collapses): a star lifted past the bound
    // keeps as much of its sum as it can, which is what the mesh's mean is made of.
    const auto better = [bound](const StarQuality& x, const StarQuality& y) {
        const double a = std::min(x.worst, bound), b = std::min(y.worst, bound);
        return a != b ? a > b + 1e-9 : x.sum > y.sum + 1e-9;
    };
    const Vec3 here = point_vec(dom, p);
    StarQuality best = star_quality(corners, here);
    std::vector<Vec3> targets{centroid};
    for (std::size_t k = 0; k < star.size(); ++k)
        if (tet_collapse(corners.corners[k]) < std::max(bound, best.worst + 0.05))
            targets.push_back(regular_apex(dom, star[k], p));
    Vec3 best_x = here;
    for (const Vec3& target : targets)
        for (double step : {1.0, 0.5, 0.25, 0.125, 0.0625}) {
            const Vec3 x = here + step * (target - here);
            const StarQuality sc = star_quality(corners, x);
            if (better(sc, best)) {
                best = sc;
                best_x = x;
            }
        }
    if (best_x.x == here.x && best_x.y == here.y && best_x.z == here.z) return;
    if (!none_inverted(dom, p, star, best_x)) return;
    u.points.push_back(p);
    u.xyz.push_back({here.x, here.y, here.z});
    double* c = dom.xyz.data() + std::size_t{3} * p;
    c[0] = best_x.x;
    c[1] = best_x.y;
    c[2] = best_x.z;
}

// Applies the plan (appending the point `inserted` first for a PointInsertion) and lifts the
// free points of its new tets. Returns the smallest collapse of the tets changed (new tets and
// the stars of moved points) and, in old_min, the smallest collapse the same places had
// before; `touched` gets the slots changed.
double try_rescue(TetDomain& dom, const FlipPlan& plan, const Vec3* inserted, double bound,
                  const std::vector<double>& q, Undo& u, std::vector<index_t>& touched, double& old_min) {
    save(dom, plan, u);
    if (inserted) dom.xyz.insert(dom.xyz.end(), {inserted->x, inserted->y, inserted->z});
    const index_t first = dom.tets.size();
    apply_flip_appending(dom, plan);
    std::vector<index_t> fresh;
    for (int j = 0; j < plan.new_count; ++j)
        fresh.push_back(j < plan.old_count ? plan.old_tets[j] : first + static_cast<index_t>(j - plan.old_count));
    touched.assign(fresh.begin(), fresh.end());
    std::vector<index_t> star;
    for (int round = 0; round < kRescueMoveRounds; ++round)
        for (int j = 0; j < plan.new_count; ++j)
            for (int i = 0; i < 4; ++i) {
                const index_t p = plan.new_tets[j][i];
                if (p >= dom.front_points) lift_point(dom, fresh[j], p, bound, u, star, touched);
            }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    old_min = plan.old_min;
    double new_min = std::numeric_limits<double>::infinity();
    for (const index_t t : touched) {
        const bool is_new = std::find(fresh.begin(), fresh.end(), t) != fresh.end();
        if (!is_new) old_min = std::min(old_min, q[t]);  // a star tet the flip kept: q is its old value
        const index_t* v = dom.tets.vertex(t);
        new_min = std::min(new_min, collapse_of(dom, v[0], v[1], v[2], v[3]));
    }
    return new_min;
}

// Where rescue_worst_tets tries a new point for tet t: its centroid, and over each face the
// points from the face's centroid towards the regular apex on the tet's side
// (kInsertionHeights). Fixed order, so the choice between equal gains is deterministic.
std::vector<Vec3> insertion_sites(const TetDomain& dom, index_t t) {
    const index_t* v = dom.tets.vertex(t);
    std::vector<Vec3> sites;
    sites.push_back(0.25 * (point_vec(dom, v[0]) + point_vec(dom, v[1]) + point_vec(dom, v[2]) + point_vec(dom, v[3])));
    for (int f = 0; f < 4; ++f) {
        const auto& l = kTetFaceToward[f];
        const Vec3 centroid =
            (1.0 / 3.0) * (point_vec(dom, v[l[0]]) + point_vec(dom, v[l[1]]) + point_vec(dom, v[l[2]]));
        const Vec3 apex = regular_apex(dom, t, v[f]);
        for (const double h : kInsertionHeights) sites.push_back(centroid + h * (apex - centroid));
    }
    return sites;
}

}  // namespace

RescueCounts rescue_worst_tets(TetDomain& dom, double bound, std::vector<double>& q,
                               std::vector<std::uint8_t>& changed) {
    RescueCounts counts;
    Undo u;
    std::vector<index_t> touched;
    bool stuck = false;
    for (int round = 0; round < kRescueRounds; ++round) {
        std::vector<index_t> bad;
        for (index_t t = 0; t < dom.tets.size(); ++t)
            if (q[t] < bound) bad.push_back(t);
        std::sort(bad.begin(), bad.end(), [&](index_t a, index_t b) { return q[a] != q[b] ? q[a] < q[b] : a < b; });
        std::uint64_t lifted_now = 0;
        for (const index_t t : bad) {
            if (dom.tets.vertex(t)[0] == delaunay::kFreeSlot) continue;
            if (!(q[t] < bound)) continue;  // lifted by an earlier rescue (q is kept current)
            // Candidates: faces 0..3 (2-3 flips), then the six edges.
            FlipPlan plan, best_plan;
            double best_gain = 1e-6;
            bool found = false;
            Vec3 best_x{};
            // Tries `plan` (with the new point x for an insertion), undoes it and keeps it if
            // it lifts the changed tets' minimum most so far.
            const auto consider = [&](const Vec3* x) {
                double old_min = 0;
                const double new_min = try_rescue(dom, plan, x, bound, q, u, touched, old_min);
                restore(dom, u);
                if (new_min - old_min > best_gain) {
                    best_gain = new_min - old_min;
                    best_plan = plan;
                    if (x) best_x = *x;
                    found = true;
                }
            };
            for (int c = 0; c < 10; ++c) {
                bool ok;
                if (c < 4) ok = plan_flip23(dom, t, c, plan, q.data());
                else {
                    static constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
                    ok = plan_edge_removal(dom, t, kEdge[c - 4][0], kEdge[c - 4][1], EdgeShell::kMaxSize, plan,
                                           -std::numeric_limits<double>::infinity(),
                                           -std::numeric_limits<double>::infinity(), q.data());
                }
                if (ok) consider(nullptr);
            }
            // No flip: a new point over one of its faces, if one lifts it. Only then, so that
            // meshes whose worst tets flips lift keep their points.
            if (!found)
                for (const Vec3& x : insertion_sites(dom, t))
                    if (plan_point_insertion(dom, t, x, plan, q.data())) consider(&x);
            // The first tet nothing lifts bounds the minimum: lifting the ones above it would
            // only cost the mean.
            if (!found) {
                stuck = true;
                break;
            }
            double old_min = 0;
            const bool insert = best_plan.kind == FlipKind::PointInsertion;
            try_rescue(dom, best_plan, insert ? &best_x : nullptr, bound, q, u, touched, old_min);
            changed.resize(dom.point_count(), 0);
            counts.inserted += insert;
            q.resize(dom.tets.size());
            for (const index_t s : touched) {
                const index_t* v = dom.tets.vertex(s);
                q[s] = collapse_of(dom, v[0], v[1], v[2], v[3]);
                for (int i = 0; i < 4; ++i) changed[v[i]] = 1;
            }
            for (int j = best_plan.new_count; j < best_plan.old_count; ++j) q[best_plan.old_tets[j]] = 1.0;
            ++lifted_now;
        }
        counts.lifted += lifted_now;
        if (stuck || lifted_now == 0) break;
    }
    compact_tets(dom, &q);  // every live slot's q is current: the touched ones were recomputed above
    return counts;
}

}  // namespace tubemesh::tets
