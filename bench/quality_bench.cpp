// Quality measure throughput: cells per second over a mesh of 1e6 jittered tets.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <random>

#include "engine/quality/quality.hpp"

namespace {

// n tets on random 4-tuples of n/5 random points (about the node/tet ratio of a Delaunay
// mesh). The values are meaningless, but the scattered reads of the gather cost what they
// cost in a real mesh, and the measure itself does the same work for any shape.
tubemesh::HybridMesh tet_soup(std::int64_t n) {
    tubemesh::HybridMesh m;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const auto points = static_cast<tubemesh::index_t>(n / 5);
    for (tubemesh::index_t i = 0; i < points; ++i) m.add_point(u(rng), u(rng), u(rng));
    std::uniform_int_distribution<tubemesh::index_t> pick(0, points - 1);
    const tubemesh::index_t region = m.region_id("tets");
    for (std::int64_t i = 0; i < n; ++i) {
        const std::array<tubemesh::index_t, 4> t{pick(rng), pick(rng), pick(rng), pick(rng)};
        m.add_cell(tubemesh::CellKind::Tet, t, region);
    }
    return m;
}

void BM_TetCollapse(benchmark::State& state) {
    const auto m = tet_soup(state.range(0));
    for (auto _ : state) {
        auto q = tubemesh::cell_quality(m, tubemesh::CellKind::Tet);
        benchmark::DoNotOptimize(q.data());
    }
    state.counters["cells_per_s"] = benchmark::Counter(static_cast<double>(state.range(0)),
                                                       benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_TetCollapse)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SummarizeTets(benchmark::State& state) {
    const auto m = tet_soup(state.range(0));
    for (auto _ : state) {
        auto s = tubemesh::summarize_quality(m);
        benchmark::DoNotOptimize(s.tet_collapse.mean);
    }
    state.counters["cells_per_s"] = benchmark::Counter(static_cast<double>(state.range(0)),
                                                       benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_SummarizeTets)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
