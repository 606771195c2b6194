// `tubemesh mesh [IN] [-o OUT ...] [options]`: the mesh job (job/mesh_job.hpp) on a CAD solid
// (or, without IN, the built-in dam block, preset paper-ex1) with the option table's flags
// (job/option_table.hpp, tools/cli/option_flags.hpp); shows progress, then prints the phases,
// Table 1 and where each surface group is.
//
// Safety (the job's): arguments, output formats and folders, and that no two outputs are one
// file, are checked before any work; the mesh passes its stage's check before any file is
// written; the files are written all or none. Any error: one line on stderr, exit 2, no output
// file, earlier files untouched.
#include <fmt/format.h>

#include <memory>
#include <new>
#include <string>
#include <vector>

#include "engine/core/usable_memory.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/memory_limit.hpp"
#include "tools/cli/option_flags.hpp"
#include "tools/cli/progress_line.hpp"
#include "job/assembly_report.hpp"
#include "job/mesh_job.hpp"
#include "job/mesh_report.hpp"
#include "job/outputs.hpp"
#include "job/process_memory.hpp"

namespace tubemesh::cli {

namespace {

struct MeshArgs {
    std::string input;
    OptionFlags flags;
};

// Runs the job; the memory limit set just before meshing, an out-of-memory stop told in a line.
job::JobResult run_job(const job::JobSource& source, const job::JobSettings& s, ProgressLine& progress,
                       const std::string& announce) {
    double memory_limit = 0;
    job::JobHooks hooks;
    // A phase's end is where its temporaries are gone: hand their pages back before the next.
    hooks.progress = [line = progress.callback()](const ProgressEvent& e) {
        if (e.total > 0 && e.done >= e.total) job::return_free_memory();
        line(e);
    };
    // 90 % of the physical memory (or the cgroup's limit), or a lower limit already set
    // (ulimit -v): the element budget refuses most runs that would not fit; this stops the
    // rest with a message. The budget reads the memory before this process lowers its own.
    hooks.before_mesh = [&](MeshOptions& o) {
        if (!announce.empty()) fmt::print("{}\n", announce);
        const UsableMemory usable = usable_memory();
        const double cgroup = cgroup_memory_limit_bytes();
        memory_limit = limit_memory(0.9 * (cgroup > 0 ? cgroup : physical_memory_bytes()));
        o.memory = usable;
    };
    try {
        job::JobResult r = job::run_mesh_job(source, s, hooks);
        progress.close();
        return r;
    } catch (const std::bad_alloc&) {
        progress.close();
        throw Error(fmt::format("out of memory: the run needed more than the {:.3g} GiB this process may use; give a "
                                "larger --size or --sweep-size, or a smaller --max-elements to be refused before "
                                "meshing",
                                memory_limit / (1024.0 * 1024 * 1024)));
    } catch (...) {
        progress.close();
        throw;
    }
}

void print_summary(const job::JobResult& job, const job::JobSettings& s) {
    const auto say = [](const std::string& line) { fmt::print("{}\n", line); };
    const geom::MeshRun& meshed = job.run;
    const PipelineResult& r = meshed.result;
    say(fmt::format("{} ({}): {} tube{}, S = {:.6g}, St = {:.6g}", meshed.source, meshed.format, meshed.tubes,
                    meshed.tubes == 1 ? "" : "s", meshed.size, meshed.sweep_size));
    for (const std::string& line : meshed.model_lines) say("  " + line);
    for (const std::string& w : r.warnings) fmt::print(stderr, "tubemesh: warning: {}\n", w);
    if (job.write.inp_pyramid == InpPyramid::C3D5 && r.mesh.cell_count(CellKind::Pyramid) > 0)
        for (const std::string& out : s.outputs)
            if (job::lower_extension(out) == ".inp")
                fmt::print(stderr, "tubemesh: warning: {} holds C3D5 pyramids, which only Abaqus reads (CalculiX "
                           "refuses them: leave --inp-pyramid out for bricks with the apex repeated)\n", out);
    if (r.reached != kLastStage) say(fmt::format("note: stopped after the {} stage (--until)", stage_name(r.reached)));
    say("");
    for (const std::string& line : job::phase_lines(meshed)) say(line);
    const HybridMesh& mesh = r.mesh;
    say(fmt::format("\n{} nodes, {} hexahedra, {} pyramids, {} tetrahedra; {} boundary triangles, {} boundary quads",
                    mesh.point_count(), mesh.cell_count(CellKind::Hex), mesh.cell_count(CellKind::Pyramid),
                    mesh.cell_count(CellKind::Tet), mesh.face_count(FaceKind::Tri), mesh.face_count(FaceKind::Quad)));
    fmt::print("\n{}\n", job::run_table(meshed));
    if (job.assembly)
        for (const std::string& line : job::assembly_lines(*job.assembly, meshed)) say(line);
    for (const std::string& line : job::group_lines(meshed)) say(line);
    for (const std::string& out : s.outputs) say("wrote " + out);
    if (!s.report.empty()) say("wrote " + s.report);
    if (!s.html.empty()) say("wrote " + s.html);
}

}  // namespace

Command add_mesh_command(CLI::App& app) {
    auto args = std::make_shared<MeshArgs>();
    CLI::App* cmd = app.add_subcommand("mesh", "Mesh a CAD solid with tubular holes (hex rings, pyramids, tets)");
    cmd->add_option("IN", args->input,
                    "CAD file (.step .stp .iges .igs .brep); without it, the built-in dam block (paper-ex1)");
    args->flags.add_to(cmd);
    cmd->footer(
        "Without IN, -o, --report and --html: dam_block.msh and dam_block.vtu. Output formats by extension: .msh "
        "Gmsh, .vtu ParaView volume, .vtm ParaView blocks per group, .inp Abaqus / CalculiX.\n"
        "Progress: one updating line per phase on a terminal, plain 'progress:' lines otherwise.\n"
        "Partial stages (--until) are checked for what they hold (engine/pipeline/stage_check.hpp); .inp needs "
        "the sweep stage or the full mesh.\n"
        "Exit status: 0 meshed and written, 2 on any error (one line on stderr, no file written).");

    return {cmd, [args]() -> int {
        job::JobSettings s = job::job_settings(args->flags.given(), job::Naming::Flags);
        // A report alone is a run that writes only the report; with nothing asked for, the dam block's
        // default files.
        if (s.outputs.empty() && s.report.empty() && s.html.empty()) {
            if (!args->input.empty())
                throw Error("mesh needs -o OUT.msh|.vtu|.vtm|.inp, --report FILE.json or --html FILE.html for '" +
                            args->input + "'");
            s.outputs = {"dam_block.msh", "dam_block.vtu"};
        }
        job::JobSource source{.cad = args->input};
        std::string announce;
        if (args->input.empty() && !s.assembly) {
            if (!s.quiet) announce = "no input: meshing the built-in dam block (preset paper-ex1)";
            source.preset = "paper-ex1";
        }
        ProgressLine progress(ProgressLine::mode_for(s.quiet));
        const job::JobResult result = run_job(source, s, progress, announce);
        if (!s.quiet) print_summary(result, s);
        return 0;
    }};
}

}  // namespace tubemesh::cli
