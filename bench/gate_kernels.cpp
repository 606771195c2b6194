// The kernels behind the performance-regression gate (tools/bench-compare), run by a fixed
// recipe instead of Google Benchmark's adaptive iteration counts: a count or a timing taken
// here must mean the same work on every run.
//
//   bench_gate --list
//   bench_gate --set quick|full --mode count|time [--repeat N]
//
// Mode "count" runs each kernel once with callgrind's instrumentation switched on around
// it alone (run under `valgrind --tool=callgrind --instr-atstart=no`): each kernel becomes
// one callgrind dump named after it, whose instruction total the gate compares. Set-up
// (random points) is not counted, and runs at valgrind's uninstrumented speed.
// Mode "time" runs each kernel N times; before and after every run a fixed scalar loop
// (the calibration) is timed, and the run's seconds are reported with the mean of the two
// calibrations around it, so the gate can divide out what the machine's speed was then.
//
// Output: one JSON object per kernel and line on stdout.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define TUBEMESH_GATE_CALLGRIND 1
#else
#define TUBEMESH_GATE_CALLGRIND 0
#endif

#include "engine/core/types.hpp"
#include "engine/delaunay/delaunay.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Points {
    std::vector<double> x, y, z;
};

Points random_cube(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Points p;
    p.x.resize(n);
    p.y.resize(n);
    p.z.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        p.x[i] = u(rng);
        p.y[i] = u(rng);
        p.z[i] = u(rng);
    }
    return p;
}

// A regular grid: every cell's eight corners are co-spherical, so most insphere tests go to
// the exact predicates and the symbolic tie-break — the path uniform points rarely take.
Points grid(int k) {
    Points p;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j)
            for (int l = 0; l < k; ++l) {
                p.x.push_back(i);
                p.y.push_back(j);
                p.z.push_back(l);
            }
    return p;
}

struct Kernel {
    const char* name;
    const char* set;  // "quick" kernels are also in the full set
    std::function<Points()> input;
    unsigned threads;
    bool box;
};

const std::vector<Kernel>& kernels() {
    static const std::vector<Kernel> all = {
        {"delaunay_cube_100k_1t", "quick", [] { return random_cube(100'000, 7); }, 1, false},
        {"delaunay_grid_24_1t", "quick", [] { return grid(24); }, 1, false},
        {"delaunay_cube_50k_box_1t", "quick", [] { return random_cube(50'000, 11); }, 1, true},
        {"delaunay_cube_1m_1t", "full", [] { return random_cube(1'000'000, 7); }, 1, false},
        {"delaunay_cube_1m_2t", "full", [] { return random_cube(1'000'000, 7); }, 2, false},
        {"delaunay_grid_48_2t", "full", [] { return grid(48); }, 2, false},
    };
    return all;
}

// The calibration: a dependent chain of integer and floating-point work that touches no
// memory, so it measures the core's speed at that moment and nothing else.
double calibration_seconds() {
    const auto t = Clock::now();
    std::uint64_t s = 88172645463325252ULL;
    double acc = 0;
    for (int i = 0; i < 20'000'000; ++i) {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        acc = acc * 0.999999 + double(s >> 40);
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - t).count();
    if (acc == 42.0) std::puts("");  // keeps the loop
    return seconds;
}

std::size_t run(const Kernel& k, const Points& p) {
    tubemesh::delaunay::DelaunayOptions options;
    options.threads = k.threads;
    options.bounding_box = k.box;
    return tubemesh::delaunay::delaunay(p.x, p.y, p.z, options).tet_count();
}

int usage(const char* why) {
    std::fprintf(stderr, "bench_gate: %s\nusage: bench_gate --list | --set quick|full --mode count|time [--repeat N]\n",
                 why);
    return 2;
}

}  // namespace

int main(int argc, char** argv) try {
    std::string set, mode;
    int repeat = 5;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--list") {
            for (const Kernel& k : kernels()) std::printf("%s %s\n", k.set, k.name);
            return 0;
        }
        if (i + 1 >= argc) return usage(("missing value after " + a).c_str());
        if (a == "--set") set = argv[++i];
        else if (a == "--mode") mode = argv[++i];
        else if (a == "--repeat") repeat = std::atoi(argv[++i]);
        else return usage(("unknown argument " + a).c_str());
    }
    if (set != "quick" && set != "full") return usage("--set must be quick or full");
    if (mode != "count" && mode != "time") return usage("--mode must be count or time");
    if (repeat < 1) return usage("--repeat must be at least 1");
    if (mode == "count" && !TUBEMESH_GATE_CALLGRIND)
        return usage("built without <valgrind/callgrind.h>: mode count is not available");

    for (const Kernel& k : kernels()) {
        if (set == "quick" && std::strcmp(k.set, "quick") != 0) continue;
        const Points p = k.input();
        std::size_t tets = 0;
        if (mode == "count") {
#if TUBEMESH_GATE_CALLGRIND
            CALLGRIND_START_INSTRUMENTATION;
            CALLGRIND_ZERO_STATS;
            tets = run(k, p);
            CALLGRIND_DUMP_STATS_AT(k.name);
            CALLGRIND_STOP_INSTRUMENTATION;
#endif
            std::printf("{\"kernel\": \"%s\", \"threads\": %u, \"tets\": %zu}\n", k.name, k.threads, tets);
        } else {
            std::string seconds, calibration;
            for (int r = 0; r < repeat; ++r) {
                const double before = calibration_seconds();
                const auto t = Clock::now();
                tets = run(k, p);
                const double s = std::chrono::duration<double>(Clock::now() - t).count();
                const double after = calibration_seconds();
                seconds += (r ? ", " : "") + std::to_string(s);
                calibration += (r ? ", " : "") + std::to_string(0.5 * (before + after));
            }
            std::printf("{\"kernel\": \"%s\", \"threads\": %u, \"tets\": %zu, \"seconds\": [%s], \"calibration\": [%s]}\n",
                        k.name, k.threads, tets, seconds.c_str(), calibration.c_str());
        }
        std::fflush(stdout);
    }
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "bench_gate: %s\n", e.what());
    return 2;
}
