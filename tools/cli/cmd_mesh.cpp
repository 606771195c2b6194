// `tubemesh mesh [IN] [-o OUT ...] [--size S] [--sweep-size St] [--circ N] [--layers L]
// [--axial-aspect A] [--pyramid-height F] [--gradation G] [--threads T] [--tet-parts P]
// [--tet-relax R] [--max-elements N] [--report FILE.json] [--quiet] [--solid K] [--until STAGE]
// [--msh-ascii] [--inp-family stress|heat|coupled] [--inp-pyramid hex|c3d5]`: mesh a CAD solid
// (or, without IN, the built-in dam block, preset paper-ex1) through geom::mesh_file, show
// progress, print the phases, Table 1 and where each surface group is, and write the mesh to
// every OUT (format by extension: .msh, .vtu, .vtm, .inp) and the report as JSON.
//
// Safety: arguments, output formats and output folders are checked before any work; the mesh
// passes the stage's check (engine/pipeline/stage_check.hpp) before any file is written; each
// file is written to a temporary name and renamed, and if a later file fails the earlier ones
// of this run are removed. Any error: one line on stderr, exit 2, no output file.
#include <fmt/format.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/io/atomic_file.hpp"
#include "engine/io/mesh_io.hpp"
#include "geom/mesh_file.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/mesh_report.hpp"
#include "tools/cli/progress_line.hpp"

namespace tubemesh::cli {

namespace {

namespace fs = std::filesystem;

struct MeshArgs {
    std::string input;
    std::vector<std::string> outputs;
    double size = 0;
    double sweep_size = 0;
    int circumferential = 0;
    int layers = 2;
    MeshOptions defaults;  // the documented defaults of the options below
    double axial_aspect = defaults.sweep.axial_aspect;
    double pyramid_height = defaults.pyramids.height_factor;
    double gradation = defaults.tets.gradation;
    unsigned tet_parts = defaults.tets.partitions;
    int tet_relax = defaults.tets.relaxation.iterations;
    int threads = 0;
    double max_elements = 0;
    int solid = 0;
    std::string report;
    std::string until_name = stage_name(kLastStage);
    bool quiet = false;
    bool msh_ascii = false;
    std::string inp_family = "stress";
    std::string inp_pyramid = "hex";
    CLI::Option* size_option = nullptr;
    CLI::Option* sweep_option = nullptr;
};

std::string lower_extension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

void require_positive(const CLI::Option* option, double value, const char* name) {
    if (option->count() > 0 && !(value > 0 && std::isfinite(value)))
        throw Error(fmt::format("{} must be a positive number, got {}", name, value));
}

// A file can be created there: its folder exists and is writable, and it is not a folder.
void require_writable(const std::string& path) {
    const fs::path p(path);
    const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw Error("cannot write '" + path + "': the folder '" + dir.string() + "' does not exist");
    if (::access(dir.c_str(), W_OK) != 0)
        throw Error("cannot write '" + path + "': the folder '" + dir.string() + "' is not writable");
    if (fs::is_directory(p, ec)) throw Error("cannot write '" + path + "': it is a folder");
}

void check_outputs(const MeshArgs& a, Stage until) {
    for (const std::string& out : a.outputs) {
        const std::string ext = lower_extension(out);
        if (ext != ".msh" && ext != ".vtu" && ext != ".vtm" && ext != ".inp")
            throw Error("cannot write '" + out + "': unknown mesh format (use .msh, .vtu, .vtm or .inp)");
        if (ext == ".inp" && (until == Stage::Surface || until == Stage::Pyramids))
            throw Error("cannot write '" + out + "': Abaqus .inp needs every boundary face on a cell, which a " +
                        stage_name(until) + "-stage mesh does not have yet (use .msh or .vtu)");
        require_writable(out);
    }
    if (!a.report.empty()) {
        if (lower_extension(a.report) != ".json")
            throw Error("cannot write the report '" + a.report + "': it must end in .json");
        require_writable(a.report);
    }
}

void write_text(const std::string& path, const std::string& text) {
    io::AtomicFile file(path);
    file.write(text);
    file.commit();
}

WriteOptions write_options(const MeshArgs& a) {
    WriteOptions o;
    o.msh_encoding = a.msh_ascii ? MshEncoding::Ascii : MshEncoding::Binary;
    o.inp_family = a.inp_family == "heat" ? InpFamily::HeatTransfer
                   : a.inp_family == "coupled" ? InpFamily::Coupled
                                               : InpFamily::Stress;
    o.inp_pyramid = a.inp_pyramid == "c3d5" ? InpPyramid::C3D5 : InpPyramid::CollapsedHex;
    if (o.inp_pyramid == InpPyramid::C3D5 && o.inp_family != InpFamily::Stress)
        throw Error("--inp-pyramid c3d5 has no heat-transfer or coupled variant: use --inp-pyramid hex with --inp-family " +
                    a.inp_family);
    return o;
}

// All files or none: a failure removes what this run already wrote.
void write_all(const HybridMesh& mesh, const std::vector<std::string>& outputs, const WriteOptions& options,
               const std::string& report, const std::string& report_text) {
    std::vector<std::string> written;
    try {
        for (const std::string& out : outputs) {
            write_mesh(mesh, out, options);
            written.push_back(out);
        }
        if (!report.empty()) write_text(report, report_text);
    } catch (...) {
        std::error_code ec;
        for (const std::string& w : written) fs::remove(w, ec);
        throw;
    }
}

MeshOptions mesh_options(const MeshArgs& a, ProgressLine& progress) {
    require_positive(a.size_option, a.size, "--size");
    require_positive(a.sweep_option, a.sweep_size, "--sweep-size");
    if (a.size_option->count() && a.sweep_option->count() && !(a.sweep_size < a.size))
        throw Error(fmt::format("contradictory sizes: --sweep-size {} must be smaller than --size {}", a.sweep_size,
                                a.size));
    MeshOptions o;
    o.size = a.size;
    o.sweep_size = a.sweep_size;
    o.circumferential = a.circumferential;
    o.sweep.radial_layers = a.layers;
    o.sweep.axial_aspect = a.axial_aspect;
    o.pyramids.height_factor = a.pyramid_height;
    o.tets.gradation = a.gradation;
    o.tets.partitions = a.tet_parts;
    o.tets.relaxation.iterations = a.tet_relax;
    o.threads = a.threads;
    o.max_elements = a.max_elements;
    o.progress = progress.callback();
    return o;
}

}  // namespace

Command add_mesh_command(CLI::App& app) {
    auto args = std::make_shared<MeshArgs>();
    CLI::App* cmd = app.add_subcommand("mesh", "Mesh a CAD solid with tubular holes (hex rings, pyramids, tets)");
    cmd->add_option("IN", args->input,
                    "CAD file (.step .stp .iges .igs .brep); without it, the built-in dam block (paper-ex1)");
    cmd->add_option("-o,--output", args->outputs,
                    "Mesh file to write (.msh Gmsh, .vtu ParaView volume, .vtm ParaView blocks per group, .inp "
                    "Abaqus / CalculiX); repeat for several. Default without IN: dam_block.msh and dam_block.vtu")
        ->allow_extra_args(false);  // `-o a.msh IN` must not take IN as a second output
    args->size_option = cmd->add_option("--size", args->size,
                                        "Overall mesh size S (default: bounding-box diagonal / 25, at least 1.3 St)");
    args->sweep_option = cmd->add_option(
        "--sweep-size", args->sweep_size,
        "Hex ring thickness St (default: smallest tube diameter, cut by the paper's rules; a given St the rules "
        "would cut is an error)");
    cmd->add_option("--circ", args->circumferential,
                    "Nodes around each tube, n (default: the multiple of 4 nearest 2 pi (r + St/2) / St, at least 8)")
        ->check(CLI::Range(3, 4096));
    cmd->add_option("--layers", args->layers, "Hex layers across the ring, L (default 2, graded 1.5 towards the wall)")
        ->check(CLI::Range(1, 64));
    cmd->add_option("--axial-aspect", args->axial_aspect,
                    fmt::format("Axial step of the hex rings over St (default {})", args->axial_aspect))
        ->check(CLI::Range(0.25, 16.0));
    cmd->add_option("--pyramid-height", args->pyramid_height,
                    fmt::format("Pyramid apex height over the quad's mean edge (default {}, the paper's)",
                                args->pyramid_height))
        ->check(CLI::Range(0.2, 3.0));
    cmd->add_option("--gradation", args->gradation,
                    fmt::format("Largest growth of the tet size from one element to the next (default {})",
                                args->gradation))
        ->check(CLI::Range(1.0, 4.0));
    cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 4096));
    cmd->add_option("--tet-parts", args->tet_parts,
                    fmt::format("Spatial parts of the tet step's parallel Delaunay passes (default {}: the mesh is "
                                "the same for any --threads; 0: one per thread, the mesh then depends on it)",
                                args->tet_parts))
        ->check(CLI::Range(0, 4096));
    cmd->add_option("--tet-relax", args->tet_relax,
                    fmt::format("ODT relaxation rounds of the tet step's interior points before the optimisation "
                                "(default {}; 0: none, mean collapse about 0.01 lower, time within about 15 % either way)",
                                args->tet_relax))
        ->check(CLI::Range(0, 16));
    cmd->add_option("--max-elements", args->max_elements,
                    "Refuse, before meshing, sizes that give more elements than this (a lower bound from the "
                    "volume, area, S, St and tube lengths; default: what this machine's memory holds)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--report", args->report, "Also write the report as JSON to this file");
    cmd->add_option("--solid", args->solid, "Which solid of the file, 1-based (when it holds several)")
        ->check(CLI::Range(1, 1 << 30));
    std::string stages;
    for (Stage s : kStages) stages += (stages.empty() ? "" : ", ") + std::string(stage_name(s));
    cmd->add_option("--until", args->until_name, "Last stage to run: " + stages + " (default: the last)")
        ->option_text("STAGE");
    cmd->add_flag("--quiet", args->quiet, "Print nothing but errors");
    cmd->add_flag("--msh-ascii", args->msh_ascii, "Write .msh files as text (default: binary)");
    cmd->add_option("--inp-family", args->inp_family,
                    "Element family of .inp files: stress (C3D4/C3D8, default; CalculiX uses them for heat transfer "
                    "too), heat (Abaqus DC3D4/DC3D8), coupled (C3D4T/C3D8T)")
        ->check(CLI::IsMember({"stress", "heat", "coupled"}));
    cmd->add_option("--inp-pyramid", args->inp_pyramid,
                    "Pyramids in .inp files: hex (a C3D8 with the apex repeated, which CalculiX and Abaqus read; "
                    "default) or c3d5 (the 5-node pyramid, stress family only)")
        ->check(CLI::IsMember({"hex", "c3d5"}));
    cmd->footer(
        "Progress: one updating line per phase on a terminal, plain 'progress:' lines otherwise.\n"
        "Partial stages (--until) are checked for what they hold (engine/pipeline/stage_check.hpp); .inp needs "
        "the sweep stage or the full mesh.\n"
        "Exit status: 0 meshed and written, 2 on any error (one line on stderr, no file written).");

    return {cmd, [args, stages]() -> int {
        const std::optional<Stage> until = stage_from_name(args->until_name);
        if (!until) throw Error("--until " + args->until_name + ": no such stage (use " + stages + ")");
        if (args->outputs.empty()) {
            if (!args->input.empty()) throw Error("mesh needs -o OUT.msh|.vtu|.inp for '" + args->input + "'");
            args->outputs = {"dam_block.msh", "dam_block.vtu"};
        }
        check_outputs(*args, *until);
        WriteOptions write = write_options(*args);
        ProgressLine progress(ProgressLine::mode_for(args->quiet));
        const MeshOptions options = mesh_options(*args, progress);
        auto say = [&](const std::string& s) {
            if (!args->quiet) fmt::print("{}\n", s);
        };

        geom::MeshRun run;
        try {
            if (args->input.empty()) {
                say("no input: meshing the built-in dam block (preset paper-ex1)");
                run = geom::mesh_preset("paper-ex1", options, *until);
            } else {
                run = geom::mesh_file(args->input, options, {.solid = args->solid, .until = *until});
            }
        } catch (...) {
            progress.close();
            throw;
        }
        progress.close();

        const PipelineResult& r = run.result;
        const std::string report_text = args->report.empty() ? "" : run_json(run, args->outputs).dump(2) + "\n";
        write.description = &r.description;
        write_all(r.mesh, args->outputs, write, args->report, report_text);
        if (args->quiet) return 0;

        say(fmt::format("{} ({}): {} tube{}, S = {:.6g}, St = {:.6g}", run.source, run.format, run.tubes,
                        run.tubes == 1 ? "" : "s", run.size, run.sweep_size));
        for (const std::string& line : run.model_lines) say("  " + line);
        for (const std::string& w : r.warnings) fmt::print(stderr, "tubemesh: warning: {}\n", w);
        if (r.reached != kLastStage)
            say(fmt::format("note: stopped after the {} stage (--until)", stage_name(r.reached)));
        say("");
        for (const std::string& line : phase_lines(run)) say(line);
        const HybridMesh& mesh = r.mesh;
        say(fmt::format("\n{} nodes, {} hexahedra, {} pyramids, {} tetrahedra; {} boundary triangles, {} boundary quads",
                        mesh.point_count(), mesh.cell_count(CellKind::Hex), mesh.cell_count(CellKind::Pyramid),
                        mesh.cell_count(CellKind::Tet), mesh.face_count(FaceKind::Tri),
                        mesh.face_count(FaceKind::Quad)));
        fmt::print("\n{}\n", run_table(run));
        for (const std::string& line : group_lines(run)) say(line);
        for (const std::string& out : args->outputs) say("wrote " + out);
        if (!args->report.empty()) say("wrote " + args->report);
        return 0;
    }};
}

}  // namespace tubemesh::cli
