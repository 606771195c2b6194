#include "geom/mesh_file.hpp"

#include <fmt/format.h>

#include <optional>

#include "engine/core/timing.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/describe_groups.hpp"
#include "geom/import/import.hpp"
#include "geom/prepare.hpp"
#include "geom/run_retry.hpp"
#include "geom/working_scale.hpp"

namespace tubemesh::geom {

namespace {

// The analysis limits docs/architecture.md gives: tets the paper reports down to 0.26, hexes 1 <= Cond <= 4.
constexpr double kTetCollapseFloor = 0.2;
constexpr double kHexConditionCeiling = 4;

// Below the analysis limits (a tet under 0.2, a hex condition number over 4) the user hears of
// it, with the likeliest cause: a gap too narrow beside a hole meshed with tets, pipe walls that
// meet, what thinned the ring, or the layers asked for.
void add_quality_warnings(PipelineResult& r, const PreparedModel& prepared, const MeshOptions& options) {
    const QualitySummary& q = r.quality;
    const SizePlan& plan = prepared.plan;
    // The thinnest ring where the local ring thinned one (TubeRing::thinnest), and its tube.
    const TubeRing* thin = nullptr;
    for (const TubeRing& ring : r.sweep.rings)
        if (ring.thinnest < ring.sweep_size && (!thin || ring.thinnest < thin->thinnest)) thin = &ring;
    const std::string thinned =
        thin ? fmt::format("the ring of tube {} thinned to {:.3g} where a face or another pipe is near", thin->tube + 1,
                           thin->thinnest)
             : std::string();
    if (q.tet_collapse.count > 0 && q.tet_collapse.min < kTetCollapseFloor)
        r.warnings.push_back(fmt::format(
            "the worst tetrahedron has collapse {:.4f}, below {}{}", q.tet_collapse.min, kTetCollapseFloor,
            !prepared.flat_tets_cause.empty() ? "; likely cause: " + prepared.flat_tets_cause
            : !plan.changes.empty()           ? "; likely cause: the ring was thinned (" + plan.changes.back().rule +
                                          ": " + plan.changes.back().reason + ")"
            : thin ? "; likely cause: " + thinned
                   : std::string(": check the report's histogram before using the mesh")));
    if (q.hex_condition.count > 0 && q.hex_condition.max > kHexConditionCeiling)
        r.warnings.push_back(fmt::format(
            "the worst hexahedron has condition number {:.3g}, over {}: with {} layers across a ring of "
            "thickness {:.3g}{}, graded {}, the innermost layer is too thin; use fewer --layers",
            q.hex_condition.max, kHexConditionCeiling, options.sweep.radial_layers, plan.sweep_size,
            thin ? " (" + thinned + ")" : std::string(), options.sweep.grading));
}

// The report around a meshed attempt: geom's phases first, warnings, groups, sizes; at working
// scale k (the caller scales the run back).
void finish_run(MeshRun& run, const Model& model, const PreparedModel& prepared, const MeshOptions& options,
                std::optional<PhaseReport> first, const RunRetry& retry, int k) {
    PipelineResult& r = run.result;
    std::vector<PhaseReport> phases;
    if (first) phases.push_back(std::move(*first));
    phases.insert(phases.end(), prepared.phases.begin(), prepared.phases.end());
    for (const PhaseReport& p : phases) r.seconds += p.seconds;
    r.phases.insert(r.phases.begin(), phases.begin(), phases.end());
    std::vector<std::string> warnings = prepared.warnings;
    for (const std::string& w : retry.warnings()) warnings.push_back(w);
    r.warnings.insert(r.warnings.begin(), warnings.begin(), warnings.end());

    add_quality_warnings(r, prepared, options);
    describe_groups(model, prepared.tubes, r.mesh, r.description);

    run.source = model.report().source;
    run.format = model.report().format;
    run.name = model.report().name;
    run.model_lines = prepared.report_lines(k);
    for (const std::string& line : retry.report_lines()) run.model_lines.push_back(line);
    run.size = prepared.geometry.size;
    run.sweep_size = prepared.geometry.sweep_size;
    run.tubes = prepared.geometry.tubes.size();
    run.coverage = prepared.coverage;
    for (RingCoverage& c : run.coverage) {
        if (c.tube <= 0) continue;
        const std::size_t t = static_cast<std::size_t>(c.tube - 1);
        for (const TubeRing& ring : r.sweep.rings)
            if (ring.tube == t) {
                c.thinnest = ring.thinnest;
                c.thickest = ring.thickest;
            }
        const std::string thinned = retry.ring_reason(t);
        // A ring that stops keeps saying why it stops.
        if (!thinned.empty()) c.reason = c.length > 0 ? fmt::format("{}; {}", c.reason, thinned) : thinned;
        if (c.thinnest < c.thickest && c.reason.empty()) c.reason = "thinned locally where a face or a tube is near";
    }
}

PhaseReport model_phase(const char* name, double seconds, const Model& model) {
    return {name, seconds, {{"faces", double(model.face_count())}, {"edges", double(model.edge_count())}}, {}};
}

// The run on a model at working scale (working_scale.hpp); `user_options` are the user's. A
// retryable failure is run again with what the user did not give (run_retry.hpp).
MeshRun mesh_working(const Model& model, const MeshOptions& user_options, Stage until,
                     std::optional<PhaseReport> first) {
    const int k = model.scale_exponent();
    const MeshOptions options = working_options(user_options, k);
    RunRetry retry(options);
    for (;;) {
        const PreparedModel prepared = prepare_model(model, retry.prepare_options());
        MeshRun run;
        try {
            run.result = run_pipeline(prepared.pipeline_input(), retry.mesh_options(), until);
        } catch (const RetryableFailure& failure) {
            retry.after(failure, prepared);
            continue;
        }
        retry.accept();
        // Groups and names are the meshed model's: the split one when a ring stops.
        finish_run(run, prepared.meshed(model), prepared, options, std::move(first), retry, k);
        scale_back(run, k);
        for (const std::string& line : coverage_lines(run.coverage)) run.model_lines.push_back(line);
        return run;
    }
}

// The run after the model exists; `first` is the import or build phase, if any. A model not
// yet at working scale is meshed as a scaled copy; an error met at working scale says so, since
// the lengths in its message are that scale's.
MeshRun mesh_loaded(const Model& model, const MeshOptions& options, Stage until, std::optional<PhaseReport> first) {
    const std::optional<Model> copy = working_copy(model);
    const Model& working = copy ? *copy : model;
    if (working.scale_exponent() == 0) return mesh_working(working, options, until, std::move(first));
    try {
        return mesh_working(working, options, until, std::move(first));
    } catch (const Error& e) {
        throw Error(std::string(e.what()) + " [the solid is meshed scaled by 1e" +
                    std::to_string(-working.scale_exponent()) + ": lengths in this message are at that scale]");
    }
}

}  // namespace

MeshRun mesh_file(const std::filesystem::path& path, const MeshOptions& options, const MeshFileOptions& file) {
    const auto limit = limit_threads(run_parallelism(options));
    const auto t0 = Clock::now();
    PhaseProgress progress(options.progress, "import", 1);
    ImportOptions import;
    import.solid = file.solid;
    import.keyword_names = file.keyword_names;
    const Model model = import_model(path, import);
    progress.finish();
    return mesh_loaded(model, options, file.until, model_phase("import", seconds_since(t0), model));
}

MeshRun mesh_model(const Model& model, const MeshOptions& options, Stage until) {
    const auto limit = limit_threads(run_parallelism(options));
    return mesh_loaded(model, options, until, std::nullopt);
}

MeshRun mesh_preset(const std::string& preset, const MeshOptions& options, Stage until) {
    return mesh_spec(preset_spec(preset), options, until);
}

MeshRun mesh_spec(const BlockSpec& spec, const MeshOptions& options, Stage until) {
    const auto limit = limit_threads(run_parallelism(options));
    const auto t0 = Clock::now();
    PhaseProgress progress(options.progress, "build", 1);
    const BuiltBlock block = build_block(spec);
    progress.finish();
    return mesh_loaded(block.model, options, until, model_phase("build", seconds_since(t0), block.model));
}

}  // namespace tubemesh::geom
