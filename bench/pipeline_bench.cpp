// The whole pipeline per reference case (issue 10): the paper's three examples at the sizes
// of issue 9's acceptance (S = 0.6, 1.1, 40), the serpentine dam lift at its default size,
// and a large lift (the serpentine lift at S = 0.11: about 6 million elements), 1 and 2
// threads. Timed: geom::mesh_model on a block built once outside the timed loop, so tube
// recognition, sizing, discretisation, every engine phase and the final check are in, the
// CAD import is not. The large lift is registered with its own name (Pipeline/large-lift) so
// quick runs can skip it with --benchmark_filter.
//
// Counters: elements (hexes + pyramids + tets), elements_per_s, nodes, per-phase seconds
// (s_sweep, s_surface, s_pyramids, s_tets, s_check), peak resident growth per element
// (VmHWM reset before the call; the built model excluded), threads.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>

#include "bench/process_measure.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/mesh_file.hpp"

namespace {

using namespace tubemesh;

struct Case {
    const char* name;    // benchmark name
    const char* preset;  // geom builders' preset
    double size;         // S; 0 = the default
};

const Case kCases[] = {
    {"paper-ex1", "paper-ex1", 0.6},       {"paper-ex2", "paper-ex2", 1.1},
    {"paper-ex3", "paper-ex3", 40},        {"serpentine-lift", "serpentine-lift", 0},
    {"large-lift", "serpentine-lift", 0.11},
};

const geom::BuiltBlock& block(const std::string& preset) {
    static std::map<std::string, std::unique_ptr<geom::BuiltBlock>> cache;
    auto& b = cache[preset];
    if (!b) b = std::make_unique<geom::BuiltBlock>(geom::build_block(geom::preset_spec(preset)));
    return *b;
}

void BM_Pipeline(benchmark::State& state, const Case& c) {
    const geom::BuiltBlock& b = block(c.preset);
    MeshOptions options;
    options.size = c.size;
    options.threads = static_cast<int>(state.range(0));
    double elements = 0, nodes = 0, peak_kb = 0;
    std::map<std::string, double> phase_seconds;
    for (auto _ : state) {
        bench::reset_peak_rss();
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
    state.counters["peak_bytes_per_element"] = elements > 0 ? peak_kb * 1024 / elements : 0;
    for (const char* phase : {"s_sweep", "s_surface", "s_pyramids", "s_tets", "s_check"})
        state.counters[phase] = phase_seconds.count(phase) ? phase_seconds[phase] : 0;
}

const bool registered = [] {
    for (const Case& c : kCases)
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
