#include "geom/mesh_file.hpp"

#include <chrono>
#include <optional>

#include "engine/pipeline/stage_check.hpp"
#include "engine/pipeline/thread_limit.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/describe_groups.hpp"
#include "geom/import.hpp"
#include "geom/prepare.hpp"

namespace tubemesh::geom {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

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

    if (options.check) check_result(r, options.progress);
    describe_groups(model, prepared.tubes, r.mesh, r.description);

    run.source = model.report().source;
    run.format = model.report().format;
    run.model_lines = prepared.report_lines();
    run.size = prepared.geometry.size;
    run.sweep_size = prepared.geometry.sweep_size;
    run.tubes = prepared.geometry.tubes.size();
    return run;
}

}  // namespace

MeshRun mesh_file(const std::filesystem::path& path, const MeshOptions& options, const MeshFileOptions& file) {
    const auto limit = limit_threads(options.threads);
    const auto t0 = Clock::now();
    PhaseProgress progress(options.progress, "import", 1);
    ImportOptions import;
    import.solid = file.solid;
    const Model model = import_model(path, import);
    progress.finish();
    return mesh_loaded(model, options, file.until, model_phase("import", seconds_since(t0), model));
}

MeshRun mesh_model(const Model& model, const MeshOptions& options, Stage until) {
    const auto limit = limit_threads(options.threads);
    return mesh_loaded(model, options, until, std::nullopt);
}

MeshRun mesh_preset(const std::string& preset, const MeshOptions& options, Stage until) {
    return mesh_spec(preset_spec(preset), options, until);
}

MeshRun mesh_spec(const BlockSpec& spec, const MeshOptions& options, Stage until) {
    const auto limit = limit_threads(options.threads);
    const auto t0 = Clock::now();
    PhaseProgress progress(options.progress, "build", 1);
    const BuiltBlock block = build_block(spec);
    progress.finish();
    return mesh_loaded(block.model, options, until, model_phase("build", seconds_since(t0), block.model));
}

}  // namespace tubemesh::geom
