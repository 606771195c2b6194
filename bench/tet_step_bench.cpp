// The tet step (paper §5) against TetGen and Gmsh on the same closed front, and the
// peers' table, on the reference cases (bench/reference_cases.hpp: the paper's three
// examples at the S of their CLI acceptance, the serpentine lift, the large lift), each case's S
// the far size of every program.
//
// Per case, outside any timed region: the case's block through prepare_model and the pipeline
// up to the pyramid layer at the case's S, which gives the closed front of the tet region
// (PipelineResult::tet_front). That front is written as a TetGen .smesh and a Gmsh MSH 2.2
// surface, the solid as STEP. Then, case by case, in this order:
//  * TetGen/<case>: `tetgen -pYq1.414 front.smesh` (1 thread).
//  * GmshFront/<case>: the front as one discrete surface, Surface Loop + Volume, `gmsh -3 -algo
//    hxt -nt 2 -clmax S` (S: the case's far size, the tet step's far_size).
//  * GmshSolid/<case>: Gmsh all-tet on the CAD solid (the STEP file), HXT, 2
//    threads, 8 elements per 2π of curvature (-clcurv 8: 8 segments around each hole), -clmax S.
//    Not run on the large lift (tens of millions of tets): its row says so.
//  * TetStep/<case>/threads:1 and :2: tets::build_tets on a fresh copy of the pyramid-stage
//    mesh, TetStepOptions{far_size = S, threads}.
// Peers run as separate processes (run_program): their time is the wall time of the process
// (input, meshing, output, start-up), and their own timing line is reported beside it (TetGen:
// "Total running seconds", CPU clock, output included; Gmsh: the sum of its "Done meshing" and
// "Done optimizing" wall times). Our time is the wall time of the build_tets call (no I/O).
//
// Quality: tet collapse (engine/quality) on every tet of every program, our measure applied to
// the peers' tets read back (TetGen .node/.ele, Gmsh MSH 4.1 through the engine's reader).
// Memory: ours is the peak resident growth during build_tets (VmHWM reset before it), input
// mesh excluded; a peer's is the peak resident set of its whole process.
//
// Own flags (before Google Benchmark's): --cases=a,b (reference case names; default: all but
// the large lift, which runs only when named), --peer_limit=seconds (per peer run, default
// 1800), --table_out=file (default: the --benchmark_out path with .md instead of .json; none
// without it). The table is printed on stderr, so JSON on stdout stays valid.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "bench/peer_mesh_files.hpp"
#include "bench/process_measure.hpp"
#include "bench/reference_cases.hpp"
#include "engine/core/timing.hpp"
#include "engine/io/mesh_io.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "engine/quality/quality.hpp"
#include "engine/tets/tet_step.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/prepare.hpp"
#include "geom/import/step_write.hpp"
#include "tests/support/process.hpp"

namespace {

using namespace tubemesh;
namespace fs = std::filesystem;

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
constexpr int kPeerThreads = 2;  // Gmsh's -nt: the tet step is compared at 2 threads
constexpr int kCurvatureElements = 8;
constexpr char kStepUnit[] = "metre";  // the STEP files' label; Gmsh's OCCTargetUnit "M"

struct Settings {
    std::vector<std::string> cases;  // reference case names
    double peer_limit_seconds = 1800;
    fs::path table;
};
Settings& settings() {
    static Settings s;
    return s;
}

// ---------------------------------------------------------------------------------------
// One case: the pipeline up to the pyramid layer and the files the peers read.

struct TetCase {
    std::string name;
    std::string error;  // non-empty: the case could not be built; its benchmarks are skipped
    HybridMesh mesh;    // after the pyramid layer
    std::vector<index_t> front;
    double far_size = 0;             // S
    double seconds_before_tets = 0;  // prepare_model + run_pipeline to Pyramids, 2 threads
    index_t hexes = 0, pyramids = 0, front_triangles = 0;
    std::size_t ring_nodes_min = 0, ring_nodes_max = 0;
    Vec3 lo{}, hi{};  // bounding box of the front, to check the peers' units
    fs::path dir, smesh, front_msh, step;
};

testing::TempDir& temp_dir() {
    static testing::TempDir dir;
    return dir;
}

void build_case(TetCase& c, const bench::ReferenceCase& reference) {
    const geom::BuiltBlock& block = bench::built_block(reference);
    MeshOptions options = bench::case_options(reference, kPeerThreads);
    options.check = false;  // the phases alone: the peers' times hold no check either
    const auto t0 = Clock::now();
    // Not bench::prepared_case: preparing is part of the whole pipeline's time here, and the
    // prepared model is freed before the tet step runs.
    const geom::PreparedModel prepared = geom::prepare_model(block.model, geom::prepare_options(options));
    PipelineResult r = run_pipeline(prepared.pipeline_input(), options, Stage::Pyramids);
    c.seconds_before_tets = seconds_since(t0);
    c.far_size = prepared.geometry.size;
    for (const TubeData& t : prepared.geometry.tubes) {
        c.ring_nodes_min = c.ring_nodes_min ? std::min(c.ring_nodes_min, t.ring1.size()) : t.ring1.size();
        c.ring_nodes_max = std::max(c.ring_nodes_max, t.ring1.size());
    }
    if (r.tet_front.empty()) throw Error("the pipeline gave an empty tet front");
    c.front = std::move(r.tet_front);
    c.mesh = std::move(r.mesh);
    c.hexes = c.mesh.cell_count(CellKind::Hex);
    c.pyramids = c.mesh.cell_count(CellKind::Pyramid);
    c.front_triangles = static_cast<index_t>(c.front.size() / 3);

    const bench::ClosedFront front = bench::compact_front(c.mesh, c.front);
    c.lo = c.hi = {front.xyz[0], front.xyz[1], front.xyz[2]};
    for (std::size_t i = 0; i < front.xyz.size(); i += 3) {
        c.lo = {std::min(c.lo.x, front.xyz[i]), std::min(c.lo.y, front.xyz[i + 1]), std::min(c.lo.z, front.xyz[i + 2])};
        c.hi = {std::max(c.hi.x, front.xyz[i]), std::max(c.hi.y, front.xyz[i + 1]), std::max(c.hi.z, front.xyz[i + 2])};
    }
    c.dir = temp_dir() / c.name;
    fs::create_directories(c.dir);
    c.smesh = c.dir / "front.smesh";
    c.front_msh = c.dir / "front.msh";
    c.step = c.dir / "block.step";
    bench::write_smesh(front, c.smesh);
    bench::write_msh22_surface(front, c.front_msh);
    // Gmsh reads the STEP in metres (BM_GmshSolid), so the file must say metre, whatever the
    // preset's unit label (paper-ex3: millimetre; paper-ex2: model units, which the STEP writer
    // calls millimetre): the same block built under that label has the same coordinates as ours.
    if (block.model.report().length_unit == kStepUnit) {
        geom::write_step(block.model, c.step);
    } else {
        geom::BlockSpec spec = geom::preset_spec(reference.preset);
        spec.length_unit = kStepUnit;
        geom::write_step(geom::build_block(spec).model, c.step);
    }
}

// One case in memory at a time: the benchmarks are registered case by case, so each case is
// built once, and the previous one's mesh is freed before the next is built.
const TetCase& tet_case(const std::string& name) {
    static std::unique_ptr<TetCase> current;
    if (current && current->name == name) return *current;
    current.reset();
    auto c = std::make_unique<TetCase>();
    c->name = name;
    try {
        build_case(*c, bench::reference_case(name));
    } catch (const std::exception& e) {
        c->error = "case " + name + ": " + e.what();
    }
    current = std::move(c);
    return *current;
}

// ---------------------------------------------------------------------------------------
// The table: one row per case, program and thread count; the fastest repetition is kept.

struct Row {
    std::string case_name, program;
    int threads = 1;
    double seconds = kNone;      // wall
    double own_seconds = kNone;  // the program's own timing line
    double cpu_seconds = kNone;  // user + system, all threads
    double tets = kNone, cells = kNone;
    double min_collapse = kNone, mean_collapse = kNone;
    double peak_mb = kNone;
    std::string note;
};

std::vector<Row>& rows() {
    static std::vector<Row> r;
    return r;
}

void record(const Row& row) {
    for (Row& r : rows())
        if (r.case_name == row.case_name && r.program == row.program && r.threads == row.threads) {
            if (std::isnan(r.seconds) || row.seconds < r.seconds) r = row;  // a failed repetition never wins
            return;
        }
    rows().push_back(row);
}

const Row* find_row(const std::string& case_name, const std::string& program, int threads) {
    for (const Row& r : rows())
        if (r.case_name == case_name && r.program == program && r.threads == threads && !std::isnan(r.seconds))
            return &r;
    return nullptr;
}

const std::string kTetGen = "TetGen 1.5 -pYq1.414 (front)";
const std::string kGmshFront = "Gmsh 4.8 HXT (front)";
const std::string kGmshSolid = "Gmsh 4.8 HXT all-tet (CAD)";
const std::string kTetStep = "tubemesh tet step";
const std::string kPipeline = "tubemesh whole pipeline";

// ---------------------------------------------------------------------------------------
// Measuring a mesh.

struct TetQuality {
    double count = 0, min = kNone, mean = kNone, inverted = 0;
};

TetQuality tet_quality(const HybridMesh& mesh) {
    const MeasureSummary s = summarize_quality(mesh).tet_collapse;
    TetQuality q{double(s.count), s.min, s.mean, 0};
    for (double v : cell_quality(mesh, CellKind::Tet)) q.inverted += v <= 0;
    return q;
}

// A peer may list its tets with the other handedness (TetGen does): flip all of them when most
// are negative by our convention, so that an inverted tet of the peer still shows as one.
void orient_like_ours(HybridMesh& mesh) {
    const std::vector<double> q = cell_quality(mesh, CellKind::Tet);
    const auto negative = std::count_if(q.begin(), q.end(), [](double v) { return v < 0; });
    if (2 * static_cast<std::size_t>(negative) <= q.size()) return;
    std::vector<index_t>& nodes = mesh.block(CellKind::Tet).nodes;
    for (std::size_t t = 0; t + 3 < nodes.size(); t += 4) std::swap(nodes[t + 1], nodes[t + 2]);
}

// The points' bounding box must match the case's: a STEP unit mix-up would scale it by 1000.
bool same_box(const HybridMesh& mesh, const TetCase& c) {
    if (mesh.point_count() == 0) return false;
    const double lx = *std::min_element(mesh.x.begin(), mesh.x.end()), hx = *std::max_element(mesh.x.begin(), mesh.x.end());
    const double ly = *std::min_element(mesh.y.begin(), mesh.y.end()), hy = *std::max_element(mesh.y.begin(), mesh.y.end());
    const double lz = *std::min_element(mesh.z.begin(), mesh.z.end()), hz = *std::max_element(mesh.z.begin(), mesh.z.end());
    const double tol = 1e-3 * std::max({c.hi.x - c.lo.x, c.hi.y - c.lo.y, c.hi.z - c.lo.z});
    return std::abs(lx - c.lo.x) < tol && std::abs(hx - c.hi.x) < tol && std::abs(ly - c.lo.y) < tol &&
           std::abs(hy - c.hi.y) < tol && std::abs(lz - c.lo.z) < tol && std::abs(hz - c.hi.z) < tol;
}

// The last lines of a peer's output, for an error message.
std::string tail(const std::string& text, std::size_t lines = 4) {
    std::size_t start = text.size();
    for (std::size_t n = 0; n <= lines && start > 0; ++n) {
        const std::size_t newline = text.rfind('\n', start - 1);
        if (newline == std::string::npos) {
            start = 0;
            break;
        }
        start = newline;
    }
    std::string t = text.substr(start == 0 ? 0 : start + 1);
    std::replace(t.begin(), t.end(), '\n', ' ');
    return t;
}

// The number after `key` on the first line holding it; NaN when there is none.
double number_after(const std::string& text, const std::string& key) {
    const std::size_t pos = text.find(key);
    return pos == std::string::npos ? kNone : std::strtod(text.c_str() + pos + key.size(), nullptr);
}

// Gmsh's own time: the wall seconds of every "Done meshing ..." / "Done optimizing ..." line.
double gmsh_own_seconds(const std::string& log) {
    double total = 0;
    bool any = false;
    std::istringstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        if (line.find("Done meshing") == std::string::npos && line.find("Done optimizing") == std::string::npos)
            continue;
        const double wall = number_after(line, "(Wall ");
        if (!std::isnan(wall)) total += wall, any = true;
    }
    return any ? total : kNone;
}

void set_peer_counters(benchmark::State& state, const Row& row, const TetQuality& q) {
    state.counters["tets"] = q.count;
    state.counters["tets_per_s"] = q.count / row.seconds;
    state.counters["min_collapse"] = q.min;
    state.counters["mean_collapse"] = q.mean;
    state.counters["inverted"] = q.inverted;
    state.counters["peak_rss_mb"] = row.peak_mb;
    state.counters["wall_s"] = row.seconds;
    state.counters["cpu_s"] = row.cpu_seconds;
    if (!std::isnan(row.own_seconds)) state.counters["own_s"] = row.own_seconds;
}

// ---------------------------------------------------------------------------------------
// The benchmarks.

void BM_TetGen(benchmark::State& state, const std::string& name) {
    const TetCase& c = tet_case(name);
    if (!c.error.empty()) return state.SkipWithError(c.error.c_str());
    const fs::path node = c.dir / "front.1.node", ele = c.dir / "front.1.ele";
    Row row{name, kTetGen, 1};
    for (auto _ : state) {
        const bench::ProgramRun run =
            bench::run_program({"tetgen", "-pYq1.414", c.smesh.string()}, c.dir / "tetgen.log", settings().peer_limit_seconds);
        if (run.exit_code != 0 || !fs::exists(ele)) {
            row.note = "failed (exit " + std::to_string(run.exit_code) + "): " + tail(run.output);
            state.SkipWithError(("tetgen " + row.note).c_str());
            break;
        }
        state.SetIterationTime(run.wall_seconds);
        row.seconds = run.wall_seconds;
        row.own_seconds = number_after(run.output, "Total running seconds:");
        row.cpu_seconds = run.cpu_seconds;
        row.peak_mb = run.peak_rss_bytes / 1e6;
    }
    if (state.error_occurred()) return record(row);
    HybridMesh mesh = bench::read_tetgen_mesh(node, ele);
    for (const char* ext : {".node", ".ele", ".face", ".edge"}) fs::remove(c.dir / (std::string("front.1") + ext));
    orient_like_ours(mesh);
    const TetQuality q = tet_quality(mesh);
    row.tets = row.cells = q.count;
    row.min_collapse = q.min;
    row.mean_collapse = q.mean;
    record(row);
    set_peer_counters(state, row, q);
    state.counters["points"] = mesh.point_count();
}

std::string quoted(const fs::path& p) { return "\"" + p.string() + "\""; }

// The shortest text that reads back as v exactly ("0.6", not "0.59999999999999998"): Gmsh gets
// the same size as we do, and the table stays readable.
std::string number_text(double v) {
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
    return std::string(buf, end);
}

// The first "Error" line of Gmsh's output, empty when there is none.
std::string first_gmsh_error(const std::string& log) {
    const std::size_t pos = log.find("Error   :");
    return pos == std::string::npos ? std::string() : log.substr(pos, log.find('\n', pos) - pos);
}

// Gmsh on a .geo; `extra` are the arguments that differ between the front and the solid.
void run_gmsh(benchmark::State& state, const TetCase& c, const std::string& program, const std::string& stem,
              const std::string& geo_text, const std::vector<std::string>& extra) {
    const fs::path geo = c.dir / (stem + ".geo"), out = c.dir / (stem + "_out.msh");
    std::ofstream(geo) << geo_text;
    Row row{c.name, program, kPeerThreads};
    std::vector<std::string> argv{"gmsh", geo.string(), "-3", "-algo", "hxt", "-nt", std::to_string(kPeerThreads),
                                  "-clmax", number_text(c.far_size)};
    argv.insert(argv.end(), extra.begin(), extra.end());
    argv.insert(argv.end(), {"-format", "msh41", "-bin", "-o", out.string()});
    for (auto _ : state) {
        fs::remove(out);
        const bench::ProgramRun run = bench::run_program(argv, c.dir / (stem + ".log"), settings().peer_limit_seconds);
        if (run.exit_code != 0 || !fs::exists(out)) {
            row.note = "failed (exit " + std::to_string(run.exit_code) + "): " + tail(run.output);
            state.SkipWithError(("gmsh " + row.note).c_str());
            break;
        }
        state.SetIterationTime(run.wall_seconds);
        row.seconds = run.wall_seconds;
        row.own_seconds = gmsh_own_seconds(run.output);
        row.cpu_seconds = run.cpu_seconds;
        row.peak_mb = run.peak_rss_bytes / 1e6;
        row.note = first_gmsh_error(run.output);
    }
    if (state.error_occurred()) return record(row);
    HybridMesh mesh = read_msh(out);
    fs::remove(out);
    if (mesh.cell_count(CellKind::Tet) == 0 || !same_box(mesh, c)) {
        row.note = "no tets, or points outside the case's box (units?) " + row.note;
        record(row);
        return state.SkipWithError(("gmsh: " + row.note).c_str());
    }
    orient_like_ours(mesh);
    const TetQuality q = tet_quality(mesh);
    row.tets = q.count;
    row.cells = double(mesh.cell_count());
    row.min_collapse = q.min;
    row.mean_collapse = q.mean;
    record(row);
    set_peer_counters(state, row, q);
    state.counters["points"] = mesh.point_count();
}

void BM_GmshFront(benchmark::State& state, const std::string& name) {
    const TetCase& c = tet_case(name);
    if (!c.error.empty()) return state.SkipWithError(c.error.c_str());
    // The merged triangles become discrete surface 1; Gmsh keeps their mesh and fills the volume.
    const std::string geo = "Merge " + quoted(c.front_msh) + ";\nSurface Loop(1) = {1};\nVolume(1) = {1};\n"
                            "Physical Volume(\"tets\", 1) = {1};\n";
    run_gmsh(state, c, kGmshFront, "gmsh_front", geo, {});
}

void BM_GmshSolid(benchmark::State& state, const std::string& name) {
    if (name == bench::kLargeLift) {
        Row row{name, kGmshSolid, kPeerThreads};
        row.note = "not run: tens of millions of tets at this S";
        record(row);
        return state.SkipWithError(row.note.c_str());
    }
    const TetCase& c = tet_case(name);
    if (!c.error.empty()) return state.SkipWithError(c.error.c_str());
    // OpenCASCADE converts STEP lengths to millimetres unless told the target unit; the STEP
    // files say metre (build_case), so their coordinates are kept.
    const std::string geo = "SetFactory(\"OpenCASCADE\");\nGeometry.OCCTargetUnit = \"M\";\nMerge " + quoted(c.step) +
                            ";\nPhysical Volume(\"tets\", 1) = {1};\n";
    run_gmsh(state, c, kGmshSolid, "gmsh_solid", geo, {"-clcurv", std::to_string(kCurvatureElements)});
}

void BM_TetStep(benchmark::State& state, const std::string& name, unsigned threads) {
    const TetCase& c = tet_case(name);
    if (!c.error.empty()) return state.SkipWithError(c.error.c_str());
    const Parallelism par{threads, MeshOptions{}.tet_parts};
    const auto limit = limit_threads(par);
    tets::TetStepOptions options;
    options.far_size = c.far_size;
    HybridMesh mesh;
    tets::TetStepStats stats;
    double rss_growth = 0, cpu = 0;
    bool peak_ok = true;
    std::string failure;
    for (auto _ : state) {
        state.PauseTiming();
        mesh = HybridMesh(c.mesh);  // a fresh copy: reused capacity would hide the step's memory
        const index_t region = mesh.region_id("tets");
        peak_ok = bench::reset_peak_rss() && peak_ok;
        const long before = bench::status_kb("VmRSS");
        const double cpu_before = bench::process_cpu_seconds();
        state.ResumeTiming();
        try {
            stats = tets::build_tets(mesh, c.front, region, par, options);
            cpu = bench::process_cpu_seconds() - cpu_before;
        } catch (const std::exception& e) {
            failure = e.what();
            state.SkipWithError(("build_tets: " + failure).c_str());
            break;
        }
        rss_growth = 1024.0 * double(bench::status_kb("VmHWM") - before);
    }
    Row row{name, kTetStep, int(threads)};
    if (state.error_occurred()) {
        row.note = "failed: " + failure;
        return record(row);
    }
    const TetQuality q = tet_quality(mesh);
    row.seconds = stats.seconds;
    row.cpu_seconds = cpu;
    row.tets = row.cells = q.count;
    row.min_collapse = q.min;
    row.mean_collapse = q.mean;
    row.peak_mb = peak_ok ? rss_growth / 1e6 : kNone;
    row.note = "S = " + number_text(c.far_size);
    record(row);

    auto& k = state.counters;
    k["tets"] = q.count;
    k["tets_per_s"] = benchmark::Counter(q.count, benchmark::Counter::kIsIterationInvariantRate);
    if (peak_ok) k["rss_bytes_per_tet"] = rss_growth / q.count;
    k["cpu_s"] = cpu;
    if (peak_ok) k["peak_rss_mb"] = row.peak_mb;
    k["min_collapse"] = q.min;
    k["mean_collapse"] = q.mean;
    k["inverted"] = q.inverted;
    k["front_triangles"] = c.front_triangles;
    k["new_points"] = stats.new_points;
    k["steiner_kept"] = stats.recovery.steiner_kept;
    k["s_recovery"] = stats.recovery.seconds_total;
    k["s_refine"] = stats.refine.seconds;
    k["s_optimise"] = stats.optimise.seconds_total;
    k["far_size"] = c.far_size;
    // Ratios > 1: we are faster (peer seconds over ours), by process wall time and by the
    // peer's own timing line.
    const Row* tetgen = find_row(name, kTetGen, 1);
    const Row* gmsh = find_row(name, kGmshFront, kPeerThreads);
    if (tetgen) k["x_tetgen_wall"] = tetgen->seconds / stats.seconds;
    if (gmsh) k["x_gmsh_wall"] = gmsh->seconds / stats.seconds;
    if (tetgen && gmsh) {
        k["x_faster_peer_wall"] = std::min(tetgen->seconds, gmsh->seconds) / stats.seconds;
        k["x_faster_peer_own"] = std::min(tetgen->own_seconds, gmsh->own_seconds) / stats.seconds;
    }
    if (threads == unsigned(kPeerThreads)) {
        // The whole pipeline is the run up to the pyramids (timed once, 2 threads)
        // plus this tet step.
        Row whole{name, kPipeline, kPeerThreads, c.seconds_before_tets + stats.seconds};
        whole.tets = q.count;
        whole.cells = q.count + c.hexes + c.pyramids;
        whole.min_collapse = q.min;
        whole.mean_collapse = q.mean;
        whole.note = std::to_string(c.hexes) + " hexes, " + std::to_string(c.pyramids) + " pyramids, n = " +
                     std::to_string(c.ring_nodes_min) +
                     (c.ring_nodes_max != c.ring_nodes_min ? ".." + std::to_string(c.ring_nodes_max) : "");
        record(whole);
        k["s_whole_pipeline"] = whole.seconds;
        k["hexes"] = c.hexes;
        k["pyramids"] = c.pyramids;
        k["ring_nodes"] = double(c.ring_nodes_min);
    }
}

// ---------------------------------------------------------------------------------------
// The table, after all benchmarks.

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

std::string fixed(double v, int digits) {
    if (std::isnan(v)) return "—";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string table_text(const std::string& load_before, const std::string& load_after) {
    std::ostringstream t;
    t << "Tet step and peers (bench/tet_step_bench.cpp); load average before " << load_before << ", after "
      << load_after << "\n\n"
      << "| case | program | threads | wall s | own s | CPU s | tets | tets/s | all cells | min collapse | "
         "mean collapse | peak MB | note |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows())
        t << "| " << r.case_name << " | " << r.program << " | " << r.threads << " | " << fixed(r.seconds, 3) << " | "
          << fixed(r.own_seconds, 3) << " | " << fixed(r.cpu_seconds, 2) << " | " << fixed(r.tets, 0) << " | " << fixed(r.tets / r.seconds, 0) << " | "
          << fixed(r.cells, 0) << " | " << fixed(r.min_collapse, 4) << " | " << fixed(r.mean_collapse, 4) << " | "
          << fixed(r.peak_mb, 1) << " | " << r.note << " |\n";
    t << "\nwall s: the program's wall time (peers: the whole process, I/O included; tet step: the build_tets "
         "call). own s: TetGen's \"Total running seconds\" (CPU clock), Gmsh's \"Done meshing/optimizing\" wall "
         "times summed. CPU s: user + system of all threads (peers: the process), which shows how much of the "
         "shared machine a run got. peak MB: tet step = peak resident growth during the call; peers = peak resident set of "
         "the process. Whole pipeline = prepare_model + pipeline to the pyramids (2 threads) + the 2-thread tet "
         "step.\n\nGoal: tet step at 2 threads at least 3x faster than the faster peer, with better "
         "minimum and mean collapse.\n";
    for (const std::string& name : settings().cases) {
        const Row* ours = find_row(name, kTetStep, kPeerThreads);
        const Row* tetgen = find_row(name, kTetGen, 1);
        const Row* gmsh = find_row(name, kGmshFront, kPeerThreads);
        if (!ours || (!tetgen && !gmsh)) {
            t << "- " << name << ": not all programs ran\n";
            continue;
        }
        const Row* faster = !gmsh || (tetgen && tetgen->seconds < gmsh->seconds) ? tetgen : gmsh;
        const double best_min = std::max(tetgen ? tetgen->min_collapse : -1e300, gmsh ? gmsh->min_collapse : -1e300);
        const double best_mean = std::max(tetgen ? tetgen->mean_collapse : -1e300, gmsh ? gmsh->mean_collapse : -1e300);
        const double x = faster->seconds / ours->seconds;
        t << "- " << name << ": faster peer " << faster->program << " " << fixed(faster->seconds, 3) << " s, ours "
          << fixed(ours->seconds, 3) << " s: x" << fixed(x, 2) << (x >= 3 ? " (meets 3x)" : " (misses 3x)")
          << "; by the peer's own time x" << fixed(faster->own_seconds / ours->seconds, 2) << "; by tets/s x"
          << fixed((ours->tets / ours->seconds) / (faster->tets / faster->seconds), 2) << "; min collapse "
          << fixed(ours->min_collapse, 4) << " vs best peer " << fixed(best_min, 4)
          << (ours->min_collapse > best_min ? " (better)" : " (not better)") << "; mean "
          << fixed(ours->mean_collapse, 4) << " vs " << fixed(best_mean, 4)
          << (ours->mean_collapse > best_mean ? " (better)" : " (not better)") << "\n";
    }
    return t.str();
}

// Takes our own flags out of argv; notes --benchmark_out for the table's default path. Throws
// tubemesh::Error for a case name that is no reference case.
void parse_own_flags(int& argc, char** argv) {
    int kept = 1;
    fs::path json;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&](const char* flag) {
            const std::string f = std::string(flag) + "=";
            return a.rfind(f, 0) == 0 ? std::optional<std::string>(a.substr(f.size())) : std::nullopt;
        };
        if (auto v = value("--cases")) {
            settings().cases.clear();
            std::istringstream in(*v);
            for (std::string name; std::getline(in, name, ',');)
                if (!name.empty()) settings().cases.emplace_back(bench::reference_case(name).name);
        } else if (auto v = value("--peer_limit")) {
            settings().peer_limit_seconds = std::atof(v->c_str());
        } else if (auto v = value("--table_out")) {
            settings().table = *v;
        } else {
            if (auto v = value("--benchmark_out")) json = *v;
            argv[kept++] = argv[i];
        }
    }
    argc = kept;
    if (settings().cases.empty())
        for (const bench::ReferenceCase& c : bench::reference_cases())
            if (std::string_view(c.name) != bench::kLargeLift) settings().cases.emplace_back(c.name);
    if (settings().table.empty() && !json.empty()) settings().table = fs::path(json).replace_extension(".md");
}

void register_benchmarks() {
    for (const std::string& name : settings().cases) {
        auto peer = [](benchmark::internal::Benchmark* b) {
            b->UseManualTime()->Unit(benchmark::kSecond)->Iterations(1);
        };
        peer(benchmark::RegisterBenchmark(("TetGen/" + name).c_str(), [name](benchmark::State& s) { BM_TetGen(s, name); }));
        peer(benchmark::RegisterBenchmark(("GmshFront/" + name).c_str(),
                                          [name](benchmark::State& s) { BM_GmshFront(s, name); }));
        peer(benchmark::RegisterBenchmark(("GmshSolid/" + name).c_str(),
                                          [name](benchmark::State& s) { BM_GmshSolid(s, name); }));
        for (unsigned threads : {1u, 2u})
            benchmark::RegisterBenchmark(("TetStep/" + name + "/threads:" + std::to_string(threads)).c_str(),
                                         [name, threads](benchmark::State& s) { BM_TetStep(s, name, threads); })
                ->UseRealTime()
                ->Unit(benchmark::kSecond)
                ->Iterations(1);
    }
}

}  // namespace

int main(int argc, char** argv) {
    try {
        parse_own_flags(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    register_benchmarks();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    const std::string load_before = load_average();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    const std::string table = table_text(load_before, load_average());
    std::fputs(table.c_str(), stderr);
    if (!settings().table.empty()) std::ofstream(settings().table) << table;
    return 0;
}
