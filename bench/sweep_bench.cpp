// Sweep throughput: hex rings along a dam lift's serpentine cooling pipe (20 m legs 1.5 m
// apart, diameter 0.032, St = 2r as geom's default), 1 and 2 threads, hexes per second.
// One lift has one pipe of about 220 m; "4 lifts" sweeps four such pipes at once.
//
// Why this synthetic scene beside Sweep/<case> in bench_phases (the reference cases through
// geom): its walls and hosts are analytic surfaces, so it times the sweep's own work without
// OpenCASCADE's surface evaluation (the difference to Sweep/serpentine-lift is that cost), and
// "4 lifts" is several long tubes at once, which no reference case has (paper-ex2's four
// holes are short): the sweep's scaling over tubes shows only here.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <memory>

#include "engine/sweep/sweep.hpp"
#include "tests/support/sweep_scenes.hpp"

namespace {

using tubemesh::sweep_testing::Scene;
using tubemesh::sweep_testing::TubeSpec;
using tubemesh::sweep_testing::V;

constexpr int kLegs = 10;
constexpr double kLeg = 20.0, kBend = 0.75, kRadius = 0.016;

const Scene& lift(int pipes) {
    static std::unique_ptr<Scene> scenes[5];
    auto& s = scenes[pipes];
    if (!s) {
        s = std::make_unique<Scene>();
        TubeSpec spec{kRadius, 2 * kRadius, 0.2};
        spec.host1 = spec.host2 = s->plane(V(0, 0, 0), V(-1, 0, 0));
        for (int p = 0; p < pipes; ++p)
            s->tube(tubemesh::sweep_testing::serpentine_path(kLegs, kLeg, kBend, spec.lead, V(0, 0, 3.0 * p)), spec);
    }
    return *s;
}

void BM_SerpentineLift(benchmark::State& state) {
    const Scene& scene = lift(static_cast<int>(state.range(0)));
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(state.range(1)));
    double hexes = 0, metres = 0;
    for (const auto& path : scene.paths) metres += path.length() - 2 * 0.2;
    for (auto _ : state) {
        tubemesh::HybridMesh mesh;
        const auto result = tubemesh::sweep_tubes(mesh, scene.tubes, scene.lookup(), scene.options());
        hexes = result.stats.hexes;
        benchmark::DoNotOptimize(mesh.x.data());
    }
    state.counters["hexes"] = hexes;
    state.counters["pipe_m"] = metres;
    state.counters["hexes_per_s"] = benchmark::Counter(hexes, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_SerpentineLift)
    ->ArgNames({"pipes", "threads"})
    ->Args({1, 1})
    ->Args({1, 2})
    ->Args({4, 1})
    ->Args({4, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
