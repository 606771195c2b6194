// Delaunay throughput against TetGen on the same points: uniform random points in the unit
// cube, 1e6 and 5e6, tubemesh with 1 and 2 threads, the installed `tetgen` program once per
// size. Run with --benchmark_format=json (or --benchmark_out=f.json).
//
// Counters. tets_per_s and points_per_s are per wall second of the whole delaunay() call
// (ordering, insertion, compaction). For TetGen the time is its own "Delaunay seconds" line
// (point sorting and insertion, no file I/O), so the comparison does not favour tubemesh.
// x_tetgen = tubemesh tets/s over TetGen's best tets/s for the same size (when TetGen ran
// first in the same process). store_bytes_per_tet: tet store and point arrays at their
// largest over the final tet count; rss_bytes_per_tet: the process's peak resident growth
// during the call (VmHWM reset before it), input arrays excluded.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "bench/process_measure.hpp"
#include "engine/delaunay/delaunay.hpp"
#include "tests/support/process.hpp"

namespace {

namespace fs = std::filesystem;

struct Points {
    std::vector<double> x, y, z;
};

const Points& cube_points(std::size_t n) {
    static std::map<std::size_t, Points> cache;
    auto [it, fresh] = cache.try_emplace(n);
    if (fresh) {
        std::mt19937_64 rng(12345);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        it->second.x.resize(n);
        it->second.y.resize(n);
        it->second.z.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            it->second.x[i] = u(rng);
            it->second.y[i] = u(rng);
            it->second.z[i] = u(rng);
        }
    }
    return it->second;
}

// tets/s of TetGen per point count, for the x_tetgen ratio.
std::map<std::size_t, double>& tetgen_rate() {
    static std::map<std::size_t, double> rate;
    return rate;
}

using tubemesh::bench::reset_peak_rss;
using tubemesh::bench::status_kb;

void BM_Delaunay(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const auto threads = static_cast<unsigned>(state.range(1));
    const Points& p = cube_points(n);
    tubemesh::delaunay::DelaunayStats stats;
    double rss_growth = 0;
    bool peak_ok = true;
    const tubemesh::Parallelism par{threads, threads};  // one part per thread
    const auto limit = tubemesh::limit_threads(par);
    for (auto _ : state) {
        peak_ok = reset_peak_rss() && peak_ok;
        const long before = status_kb("VmRSS");
        auto r = tubemesh::delaunay::delaunay(p.x, p.y, p.z, par);
        rss_growth = 1024.0 * double(status_kb("VmHWM") - before);
        stats = r.stats;
        benchmark::DoNotOptimize(r.tets.vertices().data());
        state.PauseTiming();  // freeing 250 MB is not part of the work
        r = {};
        state.ResumeTiming();
    }
    const double tets = stats.tets;
    state.counters["tets"] = tets;
    state.counters["points_per_s"] = benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["tets_per_s"] = benchmark::Counter(tets, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["store_bytes_per_tet"] = stats.bytes_per_tet;
    if (peak_ok) state.counters["rss_bytes_per_tet"] = rss_growth / tets;
    state.counters["conflicts"] = double(stats.conflicts);
    state.counters["passes"] = double(stats.passes);
    state.counters["s_order"] = stats.seconds_order;
    state.counters["s_insert"] = stats.seconds_insert;
    state.counters["s_finish"] = stats.seconds_finish;
    if (auto it = tetgen_rate().find(n); it != tetgen_rate().end())
        state.counters["x_tetgen"] = tets / stats.seconds_total / it->second;
}

// Writes the points as a TetGen .node file (%.17g round-trips every double), once per size.
fs::path write_node_file(std::size_t n) {
    static tubemesh::testing::TempDir temp;  // removed at exit
    const fs::path& dir = temp.path();
    const fs::path file = dir / ("cube_" + std::to_string(n) + ".node");
    if (fs::exists(file)) return file;
    const Points& p = cube_points(n);
    std::FILE* f = std::fopen(file.c_str(), "w");
    if (!f) return {};
    std::fprintf(f, "%zu 3 0 0\n", n);
    for (std::size_t i = 0; i < n; ++i) std::fprintf(f, "%zu %.17g %.17g %.17g\n", i, p.x[i], p.y[i], p.z[i]);
    std::fclose(f);
    return file;
}

void BM_TetGen(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    if (!fs::exists("/usr/bin/tetgen")) {
        state.SkipWithError("/usr/bin/tetgen not installed");
        return;
    }
    const fs::path node = write_node_file(n);
    if (node.empty()) {
        state.SkipWithError("cannot write the .node file");
        return;
    }
    double seconds = 0, tets = 0;
    for (auto _ : state) {
        const std::string cmd = "/usr/bin/tetgen -NEFV " + node.string() + " 2>&1";
        std::FILE* out = popen(cmd.c_str(), "r");
        if (!out) {
            state.SkipWithError("cannot run tetgen");
            return;
        }
        char line[512];
        seconds = tets = 0;
        while (std::fgets(line, sizeof line, out)) {
            double v = 0;
            if (std::sscanf(line, "Delaunay seconds: %lf", &v) == 1) seconds = v;
            if (std::sscanf(line, " Mesh tetrahedra: %lf", &v) == 1) tets = v;
        }
        pclose(out);
        if (seconds <= 0 || tets <= 0) {
            state.SkipWithError("tetgen output has no 'Delaunay seconds' or 'Mesh tetrahedra' line");
            return;
        }
        state.SetIterationTime(seconds);
    }
    tetgen_rate()[n] = std::max(tetgen_rate()[n], tets / seconds);  // the best repetition
    state.counters["tets"] = tets;
    state.counters["points_per_s"] = benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["tets_per_s"] = benchmark::Counter(tets, benchmark::Counter::kIsIterationInvariantRate);
}

// On a shared machine the fastest repetition is the one least disturbed by other work:
// with --benchmark_repetitions=N, the "_min" row has the best time, the "_max" row the best
// rates and ratios.
double smallest(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }
double largest(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

BENCHMARK(BM_TetGen)
    ->ArgName("points")
    ->Arg(1'000'000)
    ->Arg(5'000'000)
    ->UseManualTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->ComputeStatistics("min", smallest)
    ->ComputeStatistics("max", largest);
BENCHMARK(BM_Delaunay)
    ->ArgNames({"points", "threads"})
    ->ArgsProduct({{1'000'000, 5'000'000}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->ComputeStatistics("min", smallest)
    ->ComputeStatistics("max", largest);

}  // namespace
