// k-d tree build and query throughput over the mesh store's point arrays.
#include <benchmark/benchmark.h>

#include <random>

#include "engine/mesh/point_index.hpp"

namespace {

tubemesh::HybridMesh cloud(std::int64_t n) {
    tubemesh::HybridMesh m;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (std::int64_t i = 0; i < n; ++i) m.add_point(u(rng), u(rng), u(rng));
    return m;
}

void BM_PointIndexBuild(benchmark::State& state) {
    const auto m = cloud(state.range(0));
    for (auto _ : state) {
        tubemesh::PointIndex index(m);
        benchmark::DoNotOptimize(index.size());
    }
    state.counters["points_per_s"] = benchmark::Counter(static_cast<double>(state.range(0)),
                                                        benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PointIndexBuild)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void BM_PointIndexNearest8(benchmark::State& state) {
    const auto m = cloud(state.range(0));
    const tubemesh::PointIndex index(m);
    std::vector<tubemesh::Neighbor> out;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (auto _ : state) {
        index.nearest({u(rng), u(rng), u(rng)}, 8, out);
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["queries_per_s"] = benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PointIndexNearest8)->Arg(1'000'000);

}  // namespace
