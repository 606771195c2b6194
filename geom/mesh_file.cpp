#include "geom/mesh_file.hpp"

#include <fmt/format.h>

#include <optional>

#include "engine/core/timing.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/describe_groups.hpp"
#include "geom/import/import.hpp"
#include "geom/prepare.hpp"

namespace tubemesh::geom {

namespace {

// The analysis limits DESIGN.md gives: tets the paper reports down to 0.26, hexes 1 <= Cond <= 4.
constexpr double kTetCollapseFloor = 0.2;
constexpr double kHexConditionCeiling = 4;

// Below the analysis limits (a tet under 0.2, a hex condition number over 4) the user hears of
// it, with the likeliest cause: what thinned the ring, or the layers asked for.
void add_quality_warnings(PipelineResult& r, const SizePlan& plan, const MeshOptions& options) {
    const QualitySummary& q = r.quality;
    if (q.tet_collapse.count > 0 && q.tet_collapse.min < kTetCollapseFloor)
        r.warnings.push_back(fmt::format(
            "the worst tetrahedron has collapse {:.3f}, below {}{}", q.tet_collapse.min, kTetCollapseFloor,
            plan.changes.empty() ? std::string(": check the report's histogram before using the mesh")
                                 : "; likely cause: the ring was thinned (" + plan.changes.back().rule + ": " +
                                       plan.changes.back().reason + ")"));
    if (q.hex_condition.count > 0 && q.hex_condition.max > kHexConditionCeiling)
        r.warnings.push_back(fmt::format(
            "the worst hexahedron has condition number {:.3g}, over {}: with {} layers across a ring of "
            "thickness {:.3g}, graded {}, the innermost layer is too thin; use fewer --layers",
            q.hex_condition.max, kHexConditionCeiling, options.sweep.radial_layers, plan.sweep_size,
            options.sweep.grading));
}

PhaseReport model_phase(const char* name, double seconds, const Model& model) {
    return {name, seconds, {{"faces", double(model.face_count())}, {"edges", double(model.edge_count())}}, {}};
}

// The run after the model exists; `first` is the import or build phase, if any.
MeshRun mesh_loaded(const Model& model, const MeshOptions& options, Stage until, std::optional<PhaseReport> first) {
    const PreparedModel prepared = prepare_model(model, prepare_options(options));
    MeshRun run;
    run.result = run_pipeline(prepared.pipeline_input(), options, until);
    PipelineResult& r = run.result;

    std::vector<PhaseReport> phases;
    if (first) phases.push_back(std::move(*first));
    phases.insert(phases.end(), prepared.phases.begin(), prepared.phases.end());
    for (const PhaseReport& p : phases) r.seconds += p.seconds;
    r.phases.insert(r.phases.begin(), phases.begin(), phases.end());
    r.warnings.insert(r.warnings.begin(), prepared.warnings.begin(), prepared.warnings.end());

    add_quality_warnings(r, prepared.plan, options);
    describe_groups(model, prepared.tubes, r.mesh, r.description);

    run.source = model.report().source;
    run.format = model.report().format;
    run.name = model.report().name;
    run.model_lines = prepared.report_lines();
    run.size = prepared.geometry.size;
    run.sweep_size = prepared.geometry.sweep_size;
    run.tubes = prepared.geometry.tubes.size();
    return run;
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
