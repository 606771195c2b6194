// The kernels behind the performance-regression gate (bench/bench-compare), run by a fixed
// recipe instead of Google Benchmark's adaptive iteration counts: a count or a timing taken
// here must mean the same work on every run.
//
//   bench_gate --list
//   bench_gate --set quick|full [--repeat N] [--only REGEX]
//
// --only runs the kernels whose --list name REGEX matches (std::regex_search, ECMAScript).
//
// Set "quick" counts instructions: each kernel runs once with callgrind's instrumentation
// switched on around its measured parts alone (run under `valgrind --tool=callgrind
// --instr-atstart=no`); every part ends in one callgrind dump named after it (a part may end
// in several dumps of the same name: the gate sums them), whose instruction total the gate
// compares. Set-up (random points, building and preparing a CAD block) is not counted and
// runs at valgrind's uninstrumented speed. Every quick kernel is single-threaded.
// Set "full" times kernels N times each; before and after every run a fixed scalar loop (the
// calibration) is timed, and the run's seconds are reported with the mean of the two
// calibrations around it, so the gate can divide out what the machine's speed was then.
//
// Kernels: the Delaunay kernel on fixed point sets; and, on the reference cases
// (bench/reference_cases.hpp), the engine's phases each alone (sweep, surface, pyramids on
// paper-ex2 with its four curved holes; the tet step on paper-ex3, the coarsest example) and
// the whole geom::mesh_model (tube recognition, sizing, discretisation, every phase, the
// check) on paper-ex3 — so that a regression anywhere in geom/ or engine/ moves a count.
// A phase is measured inside one run_pipeline call, from the end of the phase before it to
// its own end (bench/phase_measure.hpp), exactly what the pipeline reports as that phase.
//
// Output: one JSON object per measured part and line on stdout; "elements" is what the part
// made (tets, hexes, triangles, pyramids, all cells), so the gate can tell a changed output
// from a slower kernel.
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <random>
#include <regex>
#include <string>
#include <string_view>
#include <vector>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define TUBEMESH_GATE_CALLGRIND 1
#else
#define TUBEMESH_GATE_CALLGRIND 0
#endif

#include "bench/phase_measure.hpp"
#include "bench/reference_cases.hpp"
#include "engine/core/timing.hpp"
#include "engine/core/types.hpp"
#include "engine/delaunay/delaunay.hpp"
#include "geom/mesh_file.hpp"

namespace {

using namespace tubemesh;

// Where a kernel's measured work starts and ends; the set decides what that means.
class Meter {
public:
    virtual ~Meter() = default;
    virtual void begin() = 0;                        // set-up done: measured work starts
    virtual void end(const std::string& part) = 0;  // work since the last mark belongs to `part`
    virtual void skip() = 0;                         // work since the last mark is not measured
};

// Quick set: callgrind's counters. A dump also zeroes them.
class CountMeter final : public Meter {
public:
    void begin() override {
#if TUBEMESH_GATE_CALLGRIND
        CALLGRIND_START_INSTRUMENTATION;
        CALLGRIND_ZERO_STATS;
#endif
    }
    void end(const std::string& part) override {
#if TUBEMESH_GATE_CALLGRIND
        CALLGRIND_DUMP_STATS_AT(part.c_str());
#endif
        (void)part;
    }
    void skip() override {
#if TUBEMESH_GATE_CALLGRIND
        CALLGRIND_ZERO_STATS;
#endif
    }
    ~CountMeter() override {
#if TUBEMESH_GATE_CALLGRIND
        CALLGRIND_STOP_INSTRUMENTATION;
#endif
    }
};

// Full set: wall seconds per part, summed over its marks.
class TimeMeter final : public Meter {
public:
    void begin() override { last_ = Clock::now(); }
    void end(const std::string& part) override { seconds[part] += lap(); }
    void skip() override { lap(); }
    std::map<std::string, double> seconds;

private:
    double lap() {
        const auto now = Clock::now();
        const double s = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        return s;
    }
    Clock::time_point last_ = Clock::now();
};

struct Part {
    std::string name;
    double elements = 0;
};

struct Kernel {
    std::string name;  // a single-part kernel's part; else the group's name (--list)
    bool quick, full;  // counted in the quick set, timed in the full set
    unsigned threads;
    std::function<std::vector<Part>(Meter&)> run;
};

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

Kernel delaunay_kernel(std::string name, bool quick, std::function<Points()> input, unsigned threads, bool box) {
    auto run = [name, input, threads, box](Meter& meter) {
        const Points p = input();
        delaunay::DelaunayOptions options;
        options.bounding_box = box;
        const Parallelism par{threads, threads};  // one part per thread
        const auto limit = limit_threads(par);
        meter.begin();
        const std::size_t tets = delaunay::delaunay(p.x, p.y, p.z, par, options).tet_count();
        meter.end(name);
        return std::vector<Part>{{name, double(tets)}};
    };
    return {name, quick, true, threads, run};
}

std::string part_name(std::string_view phase, const bench::ReferenceCase& c, unsigned threads) {
    return std::string(phase) + "_" + c.name + "_" + std::to_string(threads) + "t";
}

// The given phases of one case in one run_pipeline call, each a part; the phases before and
// between them run unmeasured.
Kernel phases_kernel(const char* case_name, std::vector<Stage> stages, bool quick, bool full, unsigned threads) {
    const bench::ReferenceCase& c = bench::reference_case(case_name);
    auto run = [&c, stages, threads](Meter& meter) {
        const geom::PreparedModel& prepared = bench::prepared_case(c);
        auto wanted = [&](std::string_view phase) {
            for (Stage s : stages)
                if (phase == stage_name(s)) return true;
            return false;
        };
        MeshOptions options = bench::case_options(c, int(threads));
        options.progress = bench::phase_ends([&](std::string_view phase) {
            if (wanted(phase)) meter.end(part_name(phase, c, threads));
            else meter.skip();
        });
        Stage until = stages.front();
        for (Stage s : stages) until = std::max(until, s);
        meter.begin();
        const PipelineResult r = run_pipeline(prepared.pipeline_input(), options, until);
        std::vector<Part> parts;
        for (Stage s : stages) parts.push_back({part_name(stage_name(s), c, threads), bench::phase_elements(s, r.mesh)});
        return parts;
    };
    return {std::string("phases_") + case_name + "_" + std::to_string(threads) + "t", quick, full, threads, run};
}

// geom::mesh_model on the case's built block: everything but the CAD import, one part.
Kernel pipeline_kernel(const char* case_name, bool quick, bool full, unsigned threads) {
    const bench::ReferenceCase& c = bench::reference_case(case_name);
    const std::string name = part_name("pipeline", c, threads);
    auto run = [&c, name, threads](Meter& meter) {
        const geom::BuiltBlock& block = bench::built_block(c);
        meter.begin();
        const geom::MeshRun r = geom::mesh_model(block.model, bench::case_options(c, int(threads)));
        meter.end(name);
        return std::vector<Part>{{name, double(r.result.mesh.cell_count())}};
    };
    return {name, quick, full, threads, run};
}

const std::vector<Kernel>& kernels() {
    static const std::vector<Kernel> all = {
        delaunay_kernel("delaunay_cube_100k_1t", true, [] { return random_cube(100'000, 7); }, 1, false),
        delaunay_kernel("delaunay_grid_24_1t", true, [] { return grid(24); }, 1, false),
        delaunay_kernel("delaunay_cube_50k_box_1t", true, [] { return random_cube(50'000, 11); }, 1, true),
        phases_kernel("paper-ex2", {Stage::Sweep, Stage::Surface, Stage::Pyramids}, true, false, 1),
        phases_kernel("paper-ex3", {Stage::Tets}, true, false, 1),
        pipeline_kernel("paper-ex3", true, false, 1),
        delaunay_kernel("delaunay_cube_1m_1t", false, [] { return random_cube(1'000'000, 7); }, 1, false),
        delaunay_kernel("delaunay_cube_1m_2t", false, [] { return random_cube(1'000'000, 7); }, 2, false),
        delaunay_kernel("delaunay_grid_48_2t", false, [] { return grid(48); }, 2, false),
        pipeline_kernel("paper-ex1", false, true, 1),
        pipeline_kernel("paper-ex1", false, true, 2),
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
    const double seconds = seconds_since(t);
    if (acc == 42.0) std::puts("");  // keeps the loop
    return seconds;
}

std::string json_list(const std::vector<double>& v) {
    std::string s;
    for (double x : v) s += (s.empty() ? "" : ", ") + std::to_string(x);
    return s;
}

void count_kernel(const Kernel& k) {
    std::vector<Part> parts;
    {
        CountMeter meter;
        parts = k.run(meter);
    }
    for (const Part& p : parts)
        std::printf("{\"kernel\": \"%s\", \"threads\": %u, \"elements\": %.0f}\n", p.name.c_str(), k.threads, p.elements);
}

void time_kernel(const Kernel& k, int repeat) {
    std::vector<Part> parts;
    std::map<std::string, std::vector<double>> seconds;
    std::vector<double> calibration;
    for (int r = 0; r < repeat; ++r) {
        const double before = calibration_seconds();
        TimeMeter meter;
        parts = k.run(meter);
        const double after = calibration_seconds();
        for (const Part& p : parts) seconds[p.name].push_back(meter.seconds[p.name]);
        calibration.push_back(0.5 * (before + after));
    }
    for (const Part& p : parts)
        std::printf("{\"kernel\": \"%s\", \"threads\": %u, \"elements\": %.0f, \"seconds\": [%s], \"calibration\": [%s]}\n",
                    p.name.c_str(), k.threads, p.elements, json_list(seconds[p.name]).c_str(),
                    json_list(calibration).c_str());
}

int usage(const char* why) {
    std::fprintf(stderr, "bench_gate: %s\nusage: bench_gate --list | --set quick|full [--repeat N] [--only REGEX]\n",
                 why);
    return 2;
}

}  // namespace

int main(int argc, char** argv) try {
    std::string set;
    int repeat = 5;
    std::regex only(".*");
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--list") {
            for (const Kernel& k : kernels())
                std::printf("%s%s %s\n", k.quick ? "quick(count)" : "", k.full ? (k.quick ? ",full(time)" : "full(time)") : "",
                            k.name.c_str());
            return 0;
        }
        if (i + 1 >= argc) return usage(("missing value after " + a).c_str());
        if (a == "--set") set = argv[++i];
        else if (a == "--repeat") repeat = std::atoi(argv[++i]);
        else if (a == "--only") only = std::regex(argv[++i]);
        else return usage(("unknown argument " + a).c_str());
    }
    if (set != "quick" && set != "full") return usage("--set must be quick or full");
    if (repeat < 1) return usage("--repeat must be at least 1");
    if (set == "quick" && !TUBEMESH_GATE_CALLGRIND)
        return usage("built without <valgrind/callgrind.h>: the quick set (instruction counts) is not available");

    for (const Kernel& k : kernels()) {
        if (!(set == "quick" ? k.quick : k.full) || !std::regex_search(k.name, only)) continue;
        // Set-up (prepare_model) runs under this limit too: one thread is the quick set's rule.
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, k.threads);
        if (set == "quick") count_kernel(k);
        else time_kernel(k, repeat);
        std::fflush(stdout);
    }
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "bench_gate: %s\n", e.what());
    return 2;
}
