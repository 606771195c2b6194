#include "engine/sweep/sweep.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <exception>
#include <string>
#include <vector>

#include "engine/sweep/cross_sections.hpp"
#include "engine/sweep/ring_merge.hpp"
#include "engine/sweep/ring_quality.hpp"
#include "engine/sweep/station_chunks.hpp"
#include "engine/sweep/tube_plan.hpp"

namespace tubemesh {
namespace {

using sweep::RingQuality;
using sweep::TubePlan;

std::string tube_name(const std::vector<TubeData>& tubes, std::size_t t) {
    std::string s = "tube " + std::to_string(t + 1) + " (wall face";
    const auto& f = tubes[t].wall_faces;
    if (f.size() > 1) s += "s";
    for (std::size_t i = 0; i < f.size(); ++i) s += (i ? ", " : " ") + std::to_string(f[i]);
    return s + ")";
}

// Runs work(i) for i < count in parallel; failures are kept per item, not thrown across
// threads, so the one reported is the first in item order whatever the timing.
template <class F>
std::vector<std::exception_ptr> for_each_guarded(std::size_t count, F&& work) {
    std::vector<std::exception_ptr> failed(count);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            try {
                work(i);
            } catch (...) {
                failed[i] = std::current_exception();
            }
        }
    });
    return failed;
}

// Rethrows the first failure in item order, naming the tube of item i as tube_of(i).
template <class TubeOf>
void rethrow_first(const std::vector<std::exception_ptr>& failed, TubeOf tube_of, const std::vector<TubeData>& tubes) {
    for (std::size_t i = 0; i < failed.size(); ++i) {
        if (!failed[i]) continue;
        try {
            std::rethrow_exception(failed[i]);
        } catch (const Error& e) {
            throw Error("cannot sweep " + tube_name(tubes, tube_of(i)) + ": " + e.what());
        }
    }
}

// Every ring's thickness range, and each outer quad's share of St (the mean of its four node
// columns') when some ring is thinner than St somewhere.
void local_thickness(const std::vector<TubePlan>& plans, const std::vector<std::vector<double>>& scales,
                     SweepResult& result) {
    const bool any = std::any_of(scales.begin(), scales.end(), [](const auto& v) { return !v.empty(); });
    if (any) {
        result.outer_quad_scale.assign(result.outer_quads.size() / 4, 1.0);
        result.outer_quad_thickness.assign(result.outer_quads.size() / 4, 0.0);
    }
    for (std::size_t t = 0; t < plans.size(); ++t) {
        TubeRing& ring = result.rings[t];
        ring.thinnest = ring.thickest = plans[t].sweep_size;
        const std::vector<double>& s = scales[t];
        if (any)
            for (std::size_t q = 0; q + 1 < ring.stations; ++q)
                for (std::size_t k = 0; k < ring.circumferential; ++k)
                    result.outer_quad_thickness[ring.first_lateral_quad + q * ring.circumferential + k] =
                        plans[t].sweep_size;
        if (s.empty()) continue;
        const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
        ring.thinnest = *lo * plans[t].sweep_size;
        ring.thickest = *hi * plans[t].sweep_size;
        const std::size_t n = ring.circumferential;
        for (std::size_t i = 0; i + 1 < ring.stations; ++i)
            for (std::size_t k = 0; k < n; ++k) {
                const std::size_t k1 = (k + 1) % n;
                const std::size_t q = ring.first_lateral_quad + i * n + k;
                result.outer_quad_scale[q] = 0.25 * (s[i * n + k] + s[i * n + k1] + s[(i + 1) * n + k] + s[(i + 1) * n + k1]);
                result.outer_quad_thickness[q] = result.outer_quad_scale[q] * plans[t].sweep_size;
            }
    }
}

}  // namespace

SweepResult sweep_tubes(HybridMesh& mesh, const std::vector<TubeData>& tubes, const SurfaceLookup& surfaces,
                        const SweepOptions& options) {
    // 1. Plans, tubes in parallel.
    std::vector<TubePlan> plans(tubes.size());
    rethrow_first(for_each_guarded(tubes.size(),
                                   [&](std::size_t t) {
                                       plans[t] = sweep::plan_tube(tubes[t], static_cast<index_t>(t), surfaces, options);
                                   }),
                  [](std::size_t t) { return t; }, tubes);

    // 2. Nodes, in fixed chunks of stations over all tubes in parallel.
    const std::vector<sweep::StationChunk> chunks =
        sweep::station_chunks(plans.size(), [&](std::size_t t) { return plans[t].stations(); });
    const auto tube_of_chunk = [&](std::size_t c) { return chunks[c].tube; };
    std::vector<std::vector<Vec3>> nodes(tubes.size());
    for (std::size_t t = 0; t < tubes.size(); ++t)
        nodes[t].resize(static_cast<std::size_t>(plans[t].stations()) * static_cast<std::size_t>(plans[t].layers + 1) *
                        static_cast<std::size_t>(plans[t].n));
    std::vector<std::vector<sweep::WallStart>> node0(tubes.size());
    rethrow_first(for_each_guarded(tubes.size(), [&](std::size_t t) { node0[t] = sweep::node0_feet(plans[t]); }),
                  [](std::size_t t) { return t; }, tubes);
    // Each node column's share of St, for the tubes whose ring is thinner somewhere.
    std::vector<std::vector<double>> scales(tubes.size());
    for (std::size_t t = 0; t < tubes.size(); ++t)
        if (plans[t].thin) scales[t].assign(static_cast<std::size_t>(plans[t].stations()) * plans[t].n, 1.0);
    std::vector<double> correction(chunks.size(), 0.0);
    rethrow_first(for_each_guarded(chunks.size(),
                                   [&](std::size_t c) {
                                       const sweep::StationChunk& ch = chunks[c];
                                       correction[c] = sweep::place_stations(plans[ch.tube], ch.first, ch.last,
                                                                             node0[ch.tube], nodes[ch.tube],
                                                                             scales[ch.tube]);
                                   }),
                  tube_of_chunk, tubes);

    // 3. Quality over the same chunks (the hex layers starting there), summed per tube in chunk
    // order so the sums do not depend on the thread count; a folded ring stops the sweep.
    std::vector<RingQuality> chunk_quality(chunks.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t c = r.begin(); c != r.end(); ++c) {
            const sweep::StationChunk& ch = chunks[c];
            const TubePlan& p = plans[ch.tube];
            chunk_quality[c] = sweep::measure_layers(p, nodes[ch.tube], ch.first, std::min(ch.last, p.stations() - 1));
        }
    });
    std::vector<RingQuality> quality(tubes.size());
    double max_correction = 0;
    for (std::size_t c = 0; c < chunks.size(); ++c) {
        quality[chunks[c].tube].add(chunk_quality[c]);
        max_correction = std::max(max_correction, correction[c]);
    }
    for (std::size_t t = 0; t < tubes.size(); ++t)
        if (quality[t].folded_layer >= 0)
            throw Error("cannot sweep " + tube_name(tubes, t) + ": its hex ring folds between stations " +
                        std::to_string(quality[t].folded_layer) + " and " + std::to_string(quality[t].folded_layer + 1) +
                        " (of " + std::to_string(plans[t].stations()) + "): the ring of thickness St = " +
                        std::to_string(plans[t].sweep_size) + " does not fit a bend or an end there; lower St");

    // 4. Into the mesh, in tube order.
    SweepResult result = sweep::merge_rings(mesh, tubes, plans, nodes, quality, chunks, options);
    result.stats.max_wall_correction = max_correction;
    local_thickness(plans, scales, result);
    return result;
}

}  // namespace tubemesh
