// The whole pipeline per reference case (bench/reference_cases.hpp), 1 and 2
// threads. Timed: geom::mesh_model on a block built once outside the timed loop, so tube
// recognition, sizing, discretisation, every engine phase and the final check are in, the
// CAD import is not. Pipeline/large-lift takes minutes: filter it out for quick runs.
//
// Counters: elements (hexes + pyramids + tets), elements_per_s, nodes, per-phase seconds
// (s_sweep, s_surface, s_pyramids, s_tets, s_check), peak resident growth per element
// (heap trimmed and VmHWM reset before the call, so each case's own even after other cases
// in the same process; the built model excluded; left out when the peak could not be reset),
// threads.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "bench/process_measure.hpp"
#include "bench/reference_cases.hpp"
#include "geom/mesh_file.hpp"

namespace {

using namespace tubemesh;

void BM_Pipeline(benchmark::State& state, const bench::ReferenceCase& c) {
    const geom::BuiltBlock& b = bench::built_block(c);
    const MeshOptions options = bench::case_options(c, static_cast<int>(state.range(0)));
    double elements = 0, nodes = 0, peak_kb = 0;
    bool peak_ok = true;
    std::map<std::string, double> phase_seconds;
    for (auto _ : state) {
        peak_ok = bench::reset_peak_rss() && peak_ok;
        const long before_kb = bench::status_kb("VmRSS");
        const geom::MeshRun run = geom::mesh_model(b.model, options);
        peak_kb = static_cast<double>(bench::status_kb("VmHWM") - before_kb);
        const HybridMesh& m = run.result.mesh;
        elements = m.cell_count(CellKind::Hex) + m.cell_count(CellKind::Pyramid) + m.cell_count(CellKind::Tet);
        nodes = m.point_count();
        for (const PhaseReport& p : run.result.phases) phase_seconds["s_" + p.name] = p.seconds;
    }
    state.counters["elements"] = elements;
    state.counters["nodes"] = nodes;
    state.counters["threads"] = static_cast<double>(state.range(0));
    state.counters["elements_per_s"] = benchmark::Counter(elements, benchmark::Counter::kIsIterationInvariantRate);
    if (peak_ok && elements > 0) state.counters["peak_bytes_per_element"] = peak_kb * 1024 / elements;
    for (const char* phase : {"s_sweep", "s_surface", "s_pyramids", "s_tets", "s_check"})
        state.counters[phase] = phase_seconds.count(phase) ? phase_seconds[phase] : 0;
}

const bool registered = [] {
    for (const bench::ReferenceCase& c : bench::reference_cases())
        benchmark::RegisterBenchmark((std::string("Pipeline/") + c.name).c_str(), BM_Pipeline, c)
            ->ArgName("threads")
            ->Arg(1)
            ->Arg(2)
            ->Iterations(1)
            ->Unit(benchmark::kSecond)
            ->UseRealTime();
    return true;
}();

}  // namespace
