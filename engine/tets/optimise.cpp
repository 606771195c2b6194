#include "engine/tets/optimise.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "engine/tets/flip_pass.hpp"
#include "engine/tets/smoothing.hpp"
#include "engine/tets/tet_flips.hpp"
#include "engine/tets/tet_neighbourhood.hpp"

namespace tubemesh::tets {

namespace {

struct Measure {
    double min = 0, mean = 0;
    index_t below = 0;
};

// Collapses in parallel, summed serially in tet order: the mean does not depend on threads.
Measure measure(const TetDomain& dom, double threshold) {
    const index_t n = dom.tets.size();
    std::vector<double> q(n);
    tbb::parallel_for(tbb::blocked_range<index_t>(0, n, 1024), [&](const tbb::blocked_range<index_t>& r) {
        for (index_t t = r.begin(); t != r.end(); ++t) {
            const index_t* v = dom.tets.vertex(t);
            q[t] = collapse_of(dom, v[0], v[1], v[2], v[3]);
        }
    });
    Measure m;
    if (n == 0) return m;
    m.min = std::numeric_limits<double>::infinity();
    double sum = 0;
    for (double x : q) {
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
}

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

OptimiseStats run(TetDomain& dom, const OptimiseOptions& o) {
    const auto start = Clock::now();
    OptimiseStats s;
    compact_tets(dom);
    const Measure before = measure(dom, o.flip_threshold);
    s.tets_before = dom.tets.size();
    s.min_collapse_before = before.min;
    s.mean_collapse_before = before.mean;
    s.below_threshold_before = before.below;
    for (int pass = 0; pass < o.passes; ++pass) {
        ++s.passes;
        auto t0 = Clock::now();
        const FlipSweepCounts f = flip_sweep(dom, o.flip_threshold, o.min_gain, o.max_edge_ring);
        s.seconds_flips += since(t0);
        s.flips23 += f.flips23;
        s.flips32 += f.flips32;
        s.flips44 += f.flips44;
        s.edge_removals += f.edge_removals;
        s.flip_rounds += f.rounds;
        t0 = Clock::now();
        const SmoothingCounts m = smooth_points(dom, o.smoothing_sweeps, o.smoothing_threshold, o.min_gain);
        s.seconds_smoothing += since(t0);
        s.moves += m.moves;
        s.colours = std::max(s.colours, m.colours);
        if (f.total() == 0 && m.moves == 0) break;
    }
    const Measure after = measure(dom, o.flip_threshold);
    s.tets_after = dom.tets.size();
    s.min_collapse_after = after.min;
    s.mean_collapse_after = after.mean;
    s.below_threshold_after = after.below;
    s.seconds_total = since(start);
    return s;
}

}  // namespace

OptimiseStats optimise(TetDomain& domain, const OptimiseOptions& options) {
    check(options);
    if (options.threads == 0) return run(domain, options);
    tbb::task_arena arena(static_cast<int>(options.threads));
    return arena.execute([&] { return run(domain, options); });
}

}  // namespace tubemesh::tets
