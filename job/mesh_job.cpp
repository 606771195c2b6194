#include "job/mesh_job.hpp"

#include "job/assembly_report.hpp"
#include "job/html_report.hpp"
#include "job/mesh_report.hpp"
#include "job/outputs.hpp"

namespace tubemesh::job {

namespace {

void check_files(const JobSettings& s, Stage until, std::vector<std::string>& all) {
    for (const std::string& out : s.outputs) check_mesh_output(out, until);
    if (!s.report.empty()) check_report_output(s.report, ".json", "the report");
    if (!s.html.empty()) check_report_output(s.html, ".html", "the HTML report");
    for (const std::string* text : {&s.report, &s.html})
        if (!text->empty()) all.push_back(*text);
    check_distinct_outputs(all);
}

geom::MeshRun mesh_source(const JobSource& source, const JobSettings& s, const MeshOptions& options,
                          std::optional<geom::AssemblyRun>& assembly, Naming naming) {
    const Stage until = s.mesh.until;
    if (s.assembly) {
        const auto name = [&](const char* k) { return option_name(k, naming); };
        if (source.cad.empty()) throw Error(name("assembly") + " needs a CAD file");
        if (until != kLastStage) throw Error(name("assembly") + " meshes every stage: leave " + name("until") + " out");
        if (s.mesh.solid) throw Error(name("assembly") + " meshes every solid: leave " + name("solid") + " out");
        assembly = geom::mesh_assembly_file(source.cad, options, {.glue_tolerance = s.glue_tolerance});
        return std::move(assembly->run);
    }
    if (source.spec) return geom::mesh_spec(*source.spec, options, until);
    if (!source.preset.empty()) return geom::mesh_preset(source.preset, options, until);
    return geom::mesh_file(source.cad, options,
                           {.solid = s.mesh.solid.value_or(0), .until = until,
                            .keyword_names = naming == Naming::Keywords});
}

}  // namespace

MeshOptions job_mesh_options(const JobSettings& settings, const JobHooks& hooks) {
    MeshOptions o = mesh_options(settings.mesh, hooks.naming);
    if (hooks.progress || hooks.stop)
        o.progress = [progress = hooks.progress, stop = hooks.stop](const ProgressEvent& e) {
            if (stop && stop()) throw Stopped{};
            if (progress) progress(e);
        };
    return o;
}

JobResult run_mesh_job(const JobSource& source, const JobSettings& s, const JobHooks& hooks) {
    std::vector<std::string> files = s.outputs;
    JobResult out;
    out.write = job_write_options(s, files, hooks.naming);
    check_files(s, s.mesh.until, files);
    MeshOptions options = job_mesh_options(s, hooks);
    if (hooks.before_mesh) hooks.before_mesh(options);
    out.run = mesh_source(source, s, options, out.assembly, hooks.naming);

    WriteOptions write = out.write;
    write.description = &out.run.result.description;  // unit, group kinds and rims in the files
    std::vector<std::string> listed = s.outputs;
    if (!s.html.empty()) listed.push_back(s.html);
    std::vector<std::pair<std::string, std::string>> texts;
    if (!s.report.empty()) {
        nlohmann::json report = run_json(out.run, listed);
        if (out.assembly) report["assembly"] = assembly_json(*out.assembly, out.run);
        texts.emplace_back(s.report, report.dump(2) + "\n");
    }
    if (!s.html.empty()) texts.emplace_back(s.html, html_report(out.run));
    write_all(out.run.result.mesh, s.outputs, write, texts);
    return out;
}

}  // namespace tubemesh::job
