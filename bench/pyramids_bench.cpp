// Pyramid layer throughput: 20 parallel straight rings of 500 stations (80,000 front quads)
// in a triangulated box, on 1 and 2 threads. Counter: pyramids per second of build_pyramids
// (the scene is built once; each iteration works on a fresh copy of its mesh).
//
// Second argument: the gap between neighbouring rings' 8-gons in outer quad widths a. At 4 a
// every quad takes its ideal apex except at the host faces; at 2.5 a the quads facing a
// neighbour ring are rejected by the normal pass and served by the relaxed one.
//
// Why this synthetic scene beside Pyramids/<case> in bench_phases (the reference cases through
// geom): 80,000 front quads is about three times the serpentine lift's, and rings 2.5 a apart
// send quads to the relaxed pass, which the reference cases (rings far apart) hardly reach.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "engine/pyramids/build_pyramids.hpp"
#include "tests/support/ring_scene.hpp"

namespace {

using namespace tubemesh;

// Rings of outer radius 1 on a 5 x 4 grid; axial step 1.5 a, as in the pyramid tests.
const testing::RingScene& scene(int gap_tenths) {
    static std::map<int, testing::RingScene> scenes;
    auto it = scenes.find(gap_tenths);
    if (it != scenes.end()) return it->second;
    const double a = 2.0 * std::sin(std::numbers::pi / 8);
    const double block = 1.0 + 0.9 * a, pitch = 2.0 + gap_tenths / 10.0 * a;
    const int nx = 5, ny = 4, segments = 500;
    const double length = segments * 1.5 * a;
    testing::BoxGrid box;
    std::vector<testing::Ring> rings;
    for (int axis = 0; axis < 2; ++axis) {
        const int n = axis == 0 ? nx : ny;
        auto& lines = box.lines[axis];
        lines.push_back(0);
        for (int i = 0; i < n; ++i) {
            const double c = 1.0 + block + i * pitch;
            lines.insert(lines.end(), {c - block, c, c + block});
        }
        lines.push_back(lines.back() + 1.0);
    }
    box.lines[2] = testing::spaced(0, length, segments / 2);
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            rings.push_back(testing::straight_ring(1.0 + block + i * pitch, 1.0 + block + j * pitch, 0, length,
                                                   segments, 1.0, 0.5));
    return scenes.emplace(gap_tenths, testing::build_ring_scene(box, rings)).first->second;
}

void BM_BuildPyramids(benchmark::State& state) {
    const testing::RingScene& s = scene(static_cast<int>(state.range(1)));
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(state.range(0)));
    const PyramidInput in{s.front_quads, s.boundary_triangles, s.obstacle_quads, s.pyramid_region};
    PyramidStats stats;
    for (auto _ : state) {
        state.PauseTiming();
        HybridMesh mesh = s.mesh;
        state.ResumeTiming();
        const PyramidResult r = build_pyramids(mesh, in);
        stats = r.stats;
        benchmark::DoNotOptimize(mesh.x.data());
    }
    state.counters["pyramids"] = stats.pyramids;
    state.counters["ideal"] = stats.ideal;
    state.counters["rejected"] = stats.rejected;
    state.counters["batches"] = stats.batches;
    state.counters["batch_mean"] = stats.batch_mean;
    state.counters["pyramids_per_s"] =
        benchmark::Counter(static_cast<double>(stats.pyramids), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_BuildPyramids)
    ->ArgNames({"threads", "gap_tenths_a"})
    ->Args({1, 40})
    ->Args({2, 40})
    ->Args({1, 25})
    ->Args({2, 25})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

}  // namespace
