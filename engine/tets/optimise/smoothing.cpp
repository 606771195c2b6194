#include "engine/tets/optimise/smoothing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "engine/core/ordered_compact.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/core/vec3_pair.hpp"
#include "engine/core/vec3_quad.hpp"
#include "engine/predicates/predicates_inline.hpp"
#include "engine/quality/quality.hpp"
#include "engine/tets/domain/point_colouring.hpp"
#include "engine/tets/domain/star_kernels.hpp"
#include "engine/tets/domain/tet_neighbourhood.hpp"

namespace tubemesh::tets {

namespace {

// Two kinds of move. A star whose worst tet is below `floor` first tries moves that raise that
// tet (towards the neighbours' centroid, the ODT position or the worst tet's regular apex). A
// star at or above the floor, or one no such move helps, tries moves that raise the star's sum
// of collapses (along its gradient, towards the ODT position or the centroid) and keep its
// worst tet at or above min(its value, floor). The sum is what the mean is made of: on the
// paper's examples letting fair stars trade their worst tet for it (they used to try the
// worst-tet moves first, and nearly always found one) raised the mean collapse by 0.007-0.015.
// Points whose worst tet is below this get finer steps and extra sweeps (polish): the few
// worst tets of the mesh decide its minimum, the bulk only the mean.
constexpr double kPolishBelow = 0.35;
// In an ascent-only sweep (SmoothingTargets::AscentForFair) the stars whose worst tet is below
// this (the flips' threshold) still try every target: with only the poor stars (below the
// floor) trying them, a sphere of tets kept a worst tet at 0.257 that no flip, move or new
// point lifted (tests/tets_optimise_test.cpp, RescueInsertsPointsWhereNoFlipLifts, bar 0.275).
constexpr double kAscentOnlyFrom = 0.5;

// Per-thread scratch of try_move: the star (old worst tet first) and its tets' collapses.
struct StarScratch {
    std::vector<index_t> star;
    std::vector<double> collapse;
    StarCorners corners;
};

// `tet_collapse_now`: the collapse of every tet, updated for p's star when p moves. `ascent_only`:
// a fair star tries the ascent of its sum alone (see SmoothingTargets).
bool try_move(TetDomain& dom, index_t p, std::span<const index_t> incident, double threshold, double min_gain,
              double floor, StarScratch& scratch, double& worst_before, bool polish, bool ascent_only,
              std::vector<double>& tet_collapse_now) {
    StarQuality now;
    std::size_t worst_at = 0;
    auto& star = scratch.star;
    auto& collapse = scratch.collapse;
    collapse.resize(incident.size());
    for (std::size_t k = 0; k < incident.size(); ++k) {
        const double q = tet_collapse_now[incident[k]];
        collapse[k] = q;
        now.sum += q;
        if (q < now.worst) {
            now.worst = q;
            worst_at = k;
        }
    }
    worst_before = now.worst;
    if (!(now.worst < threshold)) return false;
    // The old worst tet first: the trial that does not beat it gives up at once. Only the
    // order of summation changes (a sum never decides more than min_gain apart).
    star.assign(incident.begin(), incident.end());
    std::swap(star[0], star[worst_at]);
    std::swap(collapse[0], collapse[worst_at]);
    const index_t worst_tet = star[0];
    StarCorners& corners = scratch.corners;
    gather_star_corners(dom, p, star, corners);

    const Vec3 here = point_vec(dom, p);
    // A sliding surface point aims at its targets' feet in its face's plane.
    const bool slides = dom.slides(p);
    const Vec3 normal = slides ? dom.slide_normal[dom.slide_rank[p]] : Vec3{};
    const auto in_plane = [&](const Vec3& d) { return slides ? d - dot(d, normal) * normal : d; };
    const auto aim = [&](const Vec3& target) { return slides ? here + in_plane(target - here) : target; };
    // The centroid and ODT targets only when a trial reads them (a fair star in an ascent-only
    // sweep does not).
    const bool poor = now.worst < floor;
    const bool other_targets = !ascent_only || now.worst < kAscentOnlyFrom;
    const Vec3 centroid = other_targets ? aim(star_centroid(corners)) : here;
    const Vec3 odt = other_targets ? aim(odt_target(corners, centroid)) : here;
    // Steps of 1/8 and 1/16 rarely win for a fair star and cost more trials; a poor star gets them.
    constexpr double kStepsAll[] = {1.0, 0.5, 0.25, 0.125, 0.0625};
    const std::span<const double> kSteps(kStepsAll, now.worst < kPolishBelow ? 5 : 3);

    double best = now.worst + min_gain;
    double best_worst = 0;  // the collapse of the worst tet at best_x
    Vec3 best_x = here;
    bool improved = false;
    // A pyramid apex keeps every pyramid it tops at apex_floor or better.
    const bool apex = dom.is_apex(p);
    const auto allowed = [&](const Vec3& x) {
        if (!apex) return true;
        const index_t k = dom.apex_rank[p];
        for (index_t b = dom.apex_at[k]; b < dom.apex_at[k + 1]; ++b) {
            const auto& q = dom.apex_bases[b];
            if (pyramid_scaled_jacobian({point_vec(dom, q[0]), point_vec(dom, q[1]), point_vec(dom, q[2]),
                                         point_vec(dom, q[3]), x}) < dom.apex_floor)
                return false;
        }
        return true;
    };
    if (poor) {
        // In a polish sweep a poor star also aims at the regular apices of its other poor tets
        // (up to 4): the worst one's apex alone often only trades it for the next.
        std::array<Vec3, 7> target_store{centroid, odt, aim(regular_apex(dom, worst_tet, p))};
        std::size_t target_count = 3;
        if (polish && now.worst < kPolishBelow)
            for (std::size_t k = 1; k < star.size() && target_count < target_store.size(); ++k) {
                if (collapse[k] < kPolishBelow)
                    target_store[target_count++] = aim(regular_apex(dom, star[k], p));
            }
        const std::span<const Vec3> targets(target_store.data(), target_count);
        for (const Vec3& target : targets)
            for (double step : kSteps) {
                const Vec3 x = here + step * (target - here);
                const double q = star_quality(corners, x, best).worst;
                if (q > best && allowed(x)) {
                    best = best_worst = q;
                    best_x = x;
                    improved = true;
                }
            }
    }
    if (!improved) {
        double best_sum = now.sum + min_gain * static_cast<double>(star.size());
        const double keep_above = std::min(now.worst, floor);
        const double give_up = std::nextafter(keep_above, -1.0);
        // Mean-raising moves of a fair star: the two longer steps (the short one seldom wins).
        const std::span<const double> sum_steps = now.worst < kPolishBelow ? kSteps : kSteps.first(2);
        const auto trial = [&](const Vec3& x) {
            const StarQuality q = star_quality(corners, x, give_up);
            if (!(q.worst >= keep_above && q.sum > best_sum && allowed(x))) return false;
            best_sum = q.sum;
            best_worst = q.worst;
            best_x = x;
            improved = true;
            return true;
        };
        // Along the ascent of the sum: the target lies 0.4 of the star's mean edge from p, and
        // the trials go 1/16, 1/8, 1/4, 1/2 of the way there (0.025 up to 0.2 of the edge) while
        // each beats the one before: the short steps win most often, and on a sum that rises
        // and then falls along the line the first step that does not beat the last ends the
        // search with the same winner as trying all four (bench/results/tuning-notes.md).
        constexpr double kUphillSteps[] = {0.0625, 0.125, 0.25, 0.5};
        const Vec3 g = in_plane(ascent_direction(corners, collapse));
        const double glen = norm(g);
        if (glen > 0) {
            // The star's mean edge at p, only here where it is read (a poor star's move that
            // wins above does not need it).
            double reach = 0;
            for (std::size_t k = 0; k < star.size(); ++k)
                for (int i = 0; i < 4; ++i)
                    if (i != corners.at[k]) reach += norm(corners.corners[k][i] - here);
            reach /= 3.0 * static_cast<double>(star.size());
            const Vec3 uphill = here + (0.4 * reach / glen) * g;
            for (double step : kUphillSteps)
                if (!trial(here + step * (uphill - here))) break;
        }
        if (other_targets)
            for (const Vec3& target : {odt, centroid})
                for (double step : sum_steps) trial(here + step * (target - here));
    }
    // Rounding must not let a sliding point creep off its plane.
    if (improved && slides) best_x = best_x - (dot(normal, best_x) - dom.slide_offset[dom.slide_rank[p]]) * normal;
    // A tet whose computed collapse is this far above 0 is positive beyond any rounding (its
    // volume term is then about 1e-3 of its edges' scale, rounding errors 1e-16 of it): the
    // exact orientation test is left to the stars that come near 0.
    constexpr double kSurelyPositive = 1e-3;
    if (!improved || (best_worst < kSurelyPositive && !none_inverted(dom, p, star, best_x))) return false;
    double* c = dom.xyz.data() + std::size_t{3} * p;
    c[0] = best_x.x;
    c[1] = best_x.y;
    c[2] = best_x.z;
    // No other point of p's colour has a vertex in p's star: these slots are p's alone.
    std::size_t k = 0;
    for (; k + 1 < incident.size(); k += 2) {
        double q[2];
        collapse_of_pair(dom, dom.tets.vertex(incident[k]), dom.tets.vertex(incident[k + 1]), q);
        tet_collapse_now[incident[k]] = q[0];
        tet_collapse_now[incident[k + 1]] = q[1];
    }
    if (k < incident.size()) {
        const index_t* v = dom.tets.vertex(incident[k]);
        tet_collapse_now[incident[k]] = collapse_of(dom, v[0], v[1], v[2], v[3]);
    }
    return true;
}

}  // namespace

namespace {

template <class F>
void for_each_listed(std::vector<index_t>& list, F&& f) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, list.size(), 16384), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) f(list[i]);
    });
}

}  // namespace

SmoothingCounts smooth_points(TetDomain& dom, int sweeps, double threshold, double min_gain, double floor,
                              const std::vector<std::uint8_t>* active, std::vector<std::uint8_t>& changed,
                              std::vector<double>& collapses, SmoothingTargets targets, const Pulse& pulse) {
    SmoothingCounts counts;
    const index_t points = dom.point_count();
    // No point to try (a late focused pass often has none): the incidence, a pass over every
    // tet, would be built for nothing.
    if (active) {
        const std::size_t first = dom.front_moves() ? 0 : dom.front_points;
        const std::size_t end = std::min<std::size_t>(active->size(), points);
        if (first >= end || std::all_of(active->begin() + first, active->begin() + end, [](auto a) { return a == 0; }))
            return counts;
    }
    const Incidence inc = build_incidence(dom);
    const index_t from = dom.front_moves() ? 0 : dom.front_points;
    // The points from `from` on with ok(p), in order.
    const auto listed = [&](auto&& ok) {
        std::vector<index_t> out = kept_indices(points - from, [&](std::size_t i) { return ok(from + static_cast<index_t>(i)); });
        for_each_listed(out, [&](index_t& p) { p += from; });
        return out;
    };
    std::vector<index_t> todo =
        listed([&](index_t p) { return dom.movable(p) && !inc.of(p).empty() && (!active || (*active)[p]); });
    std::vector<std::uint32_t> colour(points, kNoIndex);
    std::vector<std::uint8_t> moved, again(points, 0);
    std::vector<index_t> moved_points;
    std::vector<double> worst;
    tbb::enumerable_thread_specific<StarScratch> star_scratch;
    // `sweeps` sweeps, then up to kPolishSweeps over the points near a moved poor star.
    constexpr int kPolishSweeps = 3;
    const int total_sweeps = sweeps > 0 ? sweeps + kPolishSweeps : 0;
    for (int sweep = 0; sweep < total_sweeps && !todo.empty(); ++sweep) {
        const bool polish = sweep >= sweeps;
        const double below = polish ? std::min(threshold, kPolishBelow) : threshold;
        const auto classes = colour_points(dom, inc, todo, colour);
        counts.colours = std::max<std::uint64_t>(counts.colours, classes.size());
        moved_points.clear();
        for (const auto& pts : classes) {
            beat(pulse);
            moved.assign(pts.size(), 0);
            worst.assign(pts.size(), 0.0);
            const auto move_range = [&](const tbb::blocked_range<std::size_t>& r) {
                auto& scratch = star_scratch.local();
                for (std::size_t i = r.begin(); i != r.end(); ++i)
                    moved[i] = try_move(dom, pts[i], inc.of(pts[i]), below, min_gain, floor, scratch, worst[i], polish,
                                        targets == SmoothingTargets::AscentForFair, collapses);
            };
            // A small colour (most of the polish sweeps' and focused passes') runs on this
            // thread: a parallel job for a few points costs more than it saves, much more on
            // an oversubscribed machine, where every job waits for its slowest worker.
            constexpr std::size_t kGrain = 16;
            const tbb::blocked_range<std::size_t> all(0, pts.size(), kGrain);
            if (pts.size() < 2 * kGrain)
                move_range(all);
            else
                tbb::parallel_for(all, move_range);
            for (std::size_t i = 0; i < pts.size(); ++i) {
                if (!moved[i]) continue;
                moved_points.push_back(pts[i]);
                changed[pts[i]] = 1;
                // Later sweeps: the free points of the stars of the points that moved (only
                // of poor stars once the polish sweeps come).
                if (sweep + 1 < sweeps || worst[i] < kPolishBelow)
                    for (index_t t : inc.of(pts[i]))
                        for (index_t k = 0; k < 4; ++k) again[dom.tets.vertex(t)[k]] = 1;
            }
        }
        counts.moves += moved_points.size();
        todo = listed([&](index_t p) { return again[p] && dom.movable(p); });
        for_each_listed(todo, [&](index_t p) { again[p] = 0; });
    }
    return counts;
}

}  // namespace tubemesh::tets
