#include "engine/tets/optimise/optimise.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "engine/core/timing.hpp"
#include "engine/tets/optimise/flip_pass.hpp"
#include "engine/tets/optimise/smoothing.hpp"
#include "engine/tets/optimise/tet_flips.hpp"
#include "engine/tets/domain/tet_neighbourhood.hpp"
#include "engine/tets/optimise/worst_tet_rescue.hpp"

namespace tubemesh::tets {

namespace {

struct Measure {
    double min = 0, mean = 0;
    index_t below = 0;
};

// Every tet's collapse, in parallel. The flips and the smoothing keep this array up to date,
// so it is computed once per optimisation.
void compute_collapses(const TetDomain& dom, std::vector<double>& q) {
    const index_t n = dom.tets.size();
    q.resize(n);
    tbb::parallel_for(tbb::blocked_range<index_t>(0, n, 1024), [&](const tbb::blocked_range<index_t>& r) {
        index_t t = r.begin();
        for (; t + 1 < r.end(); t += 2) collapse_of_pair(dom, dom.tets.vertex(t), dom.tets.vertex(t + 1), &q[t]);
        if (t < r.end()) {
            const index_t* v = dom.tets.vertex(t);
            q[t] = collapse_of(dom, v[0], v[1], v[2], v[3]);
        }
    });
}

// The tets' collapses q summed serially in tet order: the mean does not depend on threads.
// With `poor`, also flags the points of the tets below poor_below.
Measure measure(const TetDomain& dom, double threshold, const std::vector<double>& q,
                std::vector<std::uint8_t>* poor = nullptr, double poor_below = 0) {
    const index_t n = dom.tets.size();
    Measure m;
    if (n == 0) return m;
    m.min = std::numeric_limits<double>::infinity();
    double sum = 0;
    if (poor) std::fill(poor->begin(), poor->end(), 0);
    for (index_t t = 0; t < n; ++t) {
        const double x = q[t];
        if (poor && x < poor_below)
            for (int i = 0; i < 4; ++i) (*poor)[dom.tets.vertex(t)[i]] = 1;
        m.min = std::min(m.min, x);
        sum += x;
        m.below += x < threshold;
    }
    m.mean = sum / n;
    return m;
}

void check(const OptimiseOptions& o) {
    const auto fail = [](const std::string& what) { throw Error("tet optimisation: " + what); };
    if (o.passes < 0) fail("passes must be 0 or more");
    if (o.smoothing_sweeps < 0) fail("smoothing_sweeps must be 0 or more");
    if (o.max_edge_ring < 3 || o.max_edge_ring > EdgeShell::kMaxSize)
        fail("max_edge_ring must lie in 3.." + std::to_string(EdgeShell::kMaxSize));
    if (!(o.min_gain >= 0)) fail("min_gain must be 0 or more");
    if (!(o.flip_threshold <= 1.0 && o.flip_threshold >= 0.0)) fail("flip_threshold must lie in [0, 1]");
    if (!(o.smoothing_threshold >= 0.0)) fail("smoothing_threshold must be 0 or more");
    if (!(o.min_mean_gain >= 0.0)) fail("min_mean_gain must be 0 or more");
    if (!(o.mean_floor >= 0.0 && o.mean_floor <= 1.0)) fail("mean_floor must lie in [0, 1]");
    if (!(o.rescue_below >= 0.0 && o.rescue_below <= 1.0)) fail("rescue_below must lie in [0, 1]");
}

// The points of every tet with a changed point: the points whose star (and so whose flips and
// moves) a change can have touched. Clears `changed`.
void points_near(const TetDomain& dom, std::vector<std::uint8_t>& changed, std::vector<std::uint8_t>& near) {
    near.assign(changed.size(), 0);
    // Threads may flag one point at once, always with the same value: relaxed stores suffice.
    const auto flag = [&](index_t p) { std::atomic_ref<std::uint8_t>(near[p]).store(1, std::memory_order_relaxed); };
    tbb::parallel_for(tbb::blocked_range<index_t>(0, dom.tets.size(), 4096),
                      [&](const tbb::blocked_range<index_t>& r) {
                          for (index_t t = r.begin(); t != r.end(); ++t) {
                              const index_t* v = dom.tets.vertex(t);
                              if (changed[v[0]] || changed[v[1]] || changed[v[2]] || changed[v[3]])
                                  for (int i = 0; i < 4; ++i) flag(v[i]);
                          }
                      });
    std::fill(changed.begin(), changed.end(), 0);
}

// The points of every tet whose collapse q is below `below`: the worklist of the smoothing (the
// star of a point off it has no tet below `below`, so its move would be refused anyway).
void points_of_tets_below(const TetDomain& dom, const std::vector<double>& q, double below,
                          std::vector<std::uint8_t>& flags) {
    flags.assign(dom.point_count(), 0);
    const auto flag = [&](index_t p) { std::atomic_ref<std::uint8_t>(flags[p]).store(1, std::memory_order_relaxed); };
    tbb::parallel_for(tbb::blocked_range<index_t>(0, dom.tets.size(), 4096),
                      [&](const tbb::blocked_range<index_t>& r) {
                          for (index_t t = r.begin(); t != r.end(); ++t)
                              if (q[t] < below)
                                  for (int i = 0; i < 4; ++i) flag(dom.tets.vertex(t)[i]);
                      });
}

// f(p) for every point p, in parallel: element-wise updates of the per-point flags.
template <class F>
void for_points(std::size_t points, F&& f) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points, 16384), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t p = r.begin(); p != r.end(); ++p) f(p);
    });
}

// Once a pass gains little on the mean, later passes only work near the tets below this: the
// ones that can still decide the minimum.
constexpr double kFocusBelow = 0.35;

// How far from the rescued tets the smoothing that wins back the mean reaches (tet rings).
constexpr int kCleanupRings = 6;

OptimiseStats run(TetDomain& dom, const OptimiseOptions& o, const Pulse& pulse) {
    const auto start = Clock::now();
    OptimiseStats s;
    compact_tets(dom);
    std::vector<double> collapses;
    compute_collapses(dom, collapses);
    const Measure before = measure(dom, o.flip_threshold, collapses);
    s.tets_before = dom.tets.size();
    s.min_collapse_before = before.min;
    s.mean_collapse_before = before.mean;
    s.below_threshold_before = before.below;
    // Work lists: after the first pass, flips and moves are only tried near what changed since
    // the same kind of step last ran; elsewhere they would meet the same tets again.
    const std::size_t points = dom.point_count();
    std::vector<std::uint8_t> changed_for_flips(points, 0), changed_for_smoothing(points, 0), changed(points, 0);
    std::vector<std::uint8_t> near, poor(points, 0), poor_ring, bad_points;
    double last_mean = before.mean;
    bool focused = false;
    const auto focus = [&] {
        if (focused) for_points(points, [&](std::size_t p) { near[p] &= poor_ring[p]; });
    };
    for (int pass = 0; pass < o.passes; ++pass) {
        ++s.passes;
        auto t0 = Clock::now();
        if (pass > 0) {
            points_near(dom, changed_for_flips, near);
            focus();
        }
        std::fill(changed.begin(), changed.end(), 0);
        const FlipSweepCounts f =
            flip_sweep(dom, o.flip_threshold, o.min_gain, o.max_edge_ring, last_mean, o.mean_floor,
                       pass > 0 ? &near : nullptr, changed, &collapses, pulse);
        for_points(points, [&](std::size_t p) {
            if (changed[p]) changed_for_flips[p] = changed_for_smoothing[p] = 1;
        });
        s.seconds_flips += seconds_since(t0);
        s.flips23 += f.flips23;
        s.flips32 += f.flips32;
        s.flips44 += f.flips44;
        s.edge_removals += f.edge_removals;
        s.flip_rounds += f.rounds;
        t0 = Clock::now();
        // The smoothing's worklist: the points of the tets below its threshold (near what changed
        // since it last ran, after the first pass).
        points_of_tets_below(dom, collapses, o.smoothing_threshold, bad_points);
        if (pass > 0) {
            points_near(dom, changed_for_smoothing, near);
            focus();
            for_points(points, [&](std::size_t p) { near[p] &= bad_points[p]; });
        }
        std::fill(changed.begin(), changed.end(), 0);
        // After the first pass a star with no tet below 0.5 only follows the ascent of its sum:
        // the ODT and centroid targets won 12 % of the first pass's moves and little after it,
        // for half the trials (bench/results/tuning-notes.md).
        const SmoothingCounts m = smooth_points(dom, o.smoothing_sweeps, o.smoothing_threshold, o.min_gain,
                                                o.mean_floor, pass > 0 ? &near : &bad_points, changed, collapses,
                                                pass > 0 ? SmoothingTargets::AscentForFair : SmoothingTargets::All,
                                                pulse);
        for_points(points, [&](std::size_t p) {
            if (changed[p]) changed_for_flips[p] = changed_for_smoothing[p] = 1;
        });
        s.seconds_smoothing += seconds_since(t0);
        s.moves += m.moves;
        s.colours = std::max(s.colours, m.colours);
        if (f.total() == 0 && m.moves == 0) break;
        // Late passes keep nudging points for ever smaller gains of the mean: when one gains
        // less than min_mean_gain of it, the next ones only work near the poor tets, until one
        // changes nothing or the passes run out (sums are serial, so this is deterministic).
        const Measure now = measure(dom, o.flip_threshold, collapses, &poor, kFocusBelow);
        if (now.mean - last_mean < o.min_mean_gain * last_mean) focused = true;
        // The poor tets' points and their neighbours: moving a neighbour can free a poor tet.
        if (focused) points_near(dom, poor, poor_ring);
        last_mean = now.mean;
    }
    if (o.passes > 0 && o.rescue_below > 0) {
        const auto t0 = Clock::now();
        std::fill(changed.begin(), changed.end(), 0);
        beat(pulse);
        const RescueCounts r = rescue_worst_tets(dom, o.rescue_below, collapses, changed);
        s.rescued = r.lifted;
        s.inserted_points = r.inserted;
        if (s.rescued > 0) {
            // The rescue trades some of the changed tets' sum for their minimum (paper-ex2: a
            // 5-tet shell into 6 tets costs ~1.1 of the sum, 6e-5 of the mean): flips next to
            // them and a smoothing sweep over the free points up to kCleanupRings tets away win
            // it back (one ring did not, six gain 1e-5 to 2e-4 of the mean for ~8 ms on
            // paper-ex1); neither lowers a tet below min(its old worst, mean_floor), so the
            // minimum stays.
            points_near(dom, changed, near);
            const Measure now = measure(dom, o.flip_threshold, collapses);
            const FlipSweepCounts f = flip_sweep(dom, o.flip_threshold, o.min_gain, o.max_edge_ring, now.mean,
                                                 o.mean_floor, &near, changed, &collapses, pulse);
            points_near(dom, changed, poor);
            for_points(near.size(), [&](std::size_t p) { near[p] |= poor[p]; });  // with the inserted points
            for (int ring = 1; ring < kCleanupRings; ++ring) {
                poor = near;
                points_near(dom, poor, near);
            }
            const SmoothingCounts m = smooth_points(dom, o.smoothing_sweeps, o.smoothing_threshold, o.min_gain,
                                                    o.mean_floor, &near, changed, collapses, SmoothingTargets::All,
                                                    pulse);
            s.flips23 += f.flips23;
            s.flips32 += f.flips32;
            s.flips44 += f.flips44;
            s.edge_removals += f.edge_removals;
            s.flip_rounds += f.rounds;
            s.moves += m.moves;
        }
        s.seconds_rescue = seconds_since(t0);
    }
    const Measure after = measure(dom, o.flip_threshold, collapses);
    s.tets_after = dom.tets.size();
    s.min_collapse_after = after.min;
    s.mean_collapse_after = after.mean;
    s.below_threshold_after = after.below;
    s.seconds_total = seconds_since(start);
    return s;
}

}  // namespace

OptimiseStats optimise(TetDomain& domain, const OptimiseOptions& options, const Pulse& pulse) {
    check(options);
    return run(domain, options, pulse);
}

}  // namespace tubemesh::tets
