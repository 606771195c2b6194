// Each engine phase alone on the reference cases (bench/reference_cases.hpp): the
// sweep, the surface triangulation, the pyramid layer and the tet step, 1 and 2 threads.
//
// Per iteration, run_pipeline runs up to the phase on the case's prepared model (built and
// prepared once, outside the loop); the phases before it run in the same call but are not
// timed: the iteration's time is the phase's own PhaseReport seconds (what `tubemesh mesh`
// reports for it), handed to Google Benchmark as manual time. Its peak memory is measured
// from the end of the phase before it to its own end (bench/phase_measure.hpp): the heap is
// trimmed and VmHWM reset there, so the peak is the phase's own and not an earlier case's.
//
// Counters: elements = what the phase adds (hexes, surface triangles, pyramids, tets),
// elements_per_s, peak_bytes_per_element (peak resident growth during the phase over those
// elements; left out when the peak could not be reset), peak_mb, threads, mesh_cells and
// mesh_nodes after the phase, and the phase report's counts as n_<count> (pyramids: n_ideal_apex,
// n_existing_apex, ...).
//
// The synthetic programs (sweep_bench, surface_bench, pyramids_bench) stay for what these
// cases do not show; each says what in its header.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bench/phase_measure.hpp"
#include "bench/process_measure.hpp"
#include "bench/reference_cases.hpp"

namespace {

using namespace tubemesh;

// The phase run before `stage`; empty for the first.
std::string_view phase_before(Stage stage) {
    for (std::size_t i = 1; i < std::size(kStages); ++i)
        if (kStages[i] == stage) return stage_name(kStages[i - 1]);
    return {};
}

void BM_Phase(benchmark::State& state, const bench::ReferenceCase& c, Stage stage) {
    const int threads = static_cast<int>(state.range(0));
    const std::string_view phase = stage_name(stage), before = phase_before(stage);
    double elements = 0, peak_kb = 0, cells = 0, nodes = 0;
    std::vector<std::pair<std::string, double>> report_counts;
    bool peak_ok = true;
    try {
        const geom::PreparedModel& prepared = bench::prepared_case(c);
        for (auto _ : state) {
            long base_kb = 0, hwm_kb = 0;
            auto start = [&] {
                peak_ok = bench::reset_peak_rss() && peak_ok;
                base_kb = bench::status_kb("VmRSS");
            };
            MeshOptions options = bench::case_options(c, threads);
            options.progress = bench::phase_ends([&](std::string_view p) {
                if (p == before) start();
                if (p == phase) hwm_kb = bench::status_kb("VmHWM");
            });
            if (before.empty()) start();
            const PipelineResult r = run_pipeline(prepared.pipeline_input(), options, stage);
            for (const PhaseReport& p : r.phases)
                if (p.name == phase) {
                    state.SetIterationTime(p.seconds);
                    report_counts = p.counts;
                }
            elements = bench::phase_elements(stage, r.mesh);
            peak_kb = static_cast<double>(hwm_kb - base_kb);
            cells = r.mesh.cell_count();
            nodes = r.mesh.point_count();
        }
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
        return;
    }
    auto& k = state.counters;
    k["elements"] = elements;
    k["elements_per_s"] = benchmark::Counter(elements, benchmark::Counter::kIsIterationInvariantRate);
    if (peak_ok && elements > 0) {
        k["peak_bytes_per_element"] = peak_kb * 1024 / elements;
        k["peak_mb"] = peak_kb * 1024 / 1e6;
    }
    k["threads"] = threads;
    k["mesh_cells"] = cells;
    k["mesh_nodes"] = nodes;
    // The phase's own counts as `tubemesh mesh` reports them ("ideal apex" -> n_ideal_apex).
    for (auto [name, value] : report_counts) {
        std::replace(name.begin(), name.end(), ' ', '_');
        k["n_" + name] = value;
    }
}

// Case by case, so each case is prepared once (reference_cases.hpp keeps only the latest).
// Iterations are Google Benchmark's choice: a sweep of paper-ex3 takes a millisecond.
const bool registered = [] {
    for (const bench::ReferenceCase& c : bench::reference_cases())
        for (Stage stage : kStages) {
            std::string family = stage_name(stage);
            family[0] = static_cast<char>(family[0] - 'a' + 'A');
            benchmark::RegisterBenchmark((family + "/" + c.name).c_str(), BM_Phase, c, stage)
                ->ArgName("threads")
                ->Arg(1)
                ->Arg(2)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
        }
    return true;
}();

}  // namespace
