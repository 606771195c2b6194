// `tubemesh mesh [IN] [-o OUT ...] [--economy] [--size S] [--sweep-size St] [--circ N] [--layers L] [--chordal C]
// [--axial-aspect A] [--pyramid-height F] [--gradation G] [--threads T] [--tet-parts P]
// [--tet-relax R] [--move-apexes] [--fixed-surface] [--max-elements N] [--report FILE.json] [--html FILE.html]
// [--quiet] [--solid K | --assembly [--glue-tolerance D]] [--until STAGE] [--msh-ascii]
// [--inp-family stress|heat|coupled|coupled-abaqus] [--inp-pyramid hex|c3d5]
// [--pipe-network [--film-coefficient H] [--reverse-flow K ...]]`: mesh a
// CAD solid (or, without IN, the built-in dam block, preset paper-ex1) through geom::mesh_file,
// show progress, print the phases, Table 1 and where each surface group is, and write the mesh
// to every OUT (format by extension: .msh, .vtu, .vtm, .inp), the report as JSON and as an HTML
// page. The options and their defaults are job::MeshSettings, shared with the Python module.
//
// Safety: arguments, output formats and folders, and that no two outputs are one file (nor inside
// a .vtm's parts folder), are checked before any work; the mesh passes the stage's check
// (engine/pipeline/stage_check.hpp) before any file is written; each file is written to a
// temporary name, and the names are renamed only once every file is complete. Any error: one
// line on stderr, exit 2, no output file, earlier files untouched.
#include <fmt/format.h>

#include <optional>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "engine/io/mesh_io.hpp"
#include "geom/assembly/mesh_assembly.hpp"
#include "geom/sizing/discretize_edges.hpp"
#include "engine/core/usable_memory.hpp"
#include "geom/mesh_file.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/memory_limit.hpp"
#include "tools/cli/option_checks.hpp"
#include "tools/cli/progress_line.hpp"
#include "job/assembly_report.hpp"
#include "job/process_memory.hpp"
#include "job/html_report.hpp"
#include "job/mesh_report.hpp"
#include "job/mesh_settings.hpp"
#include "job/outputs.hpp"

namespace tubemesh::cli {

namespace {

// The flags bind to plain values; those that are automatic when absent become settings only
// when given (job::MeshSettings holds the defaults of the rest).
struct MeshArgs {
    std::string input;
    std::vector<std::string> outputs;
    job::MeshSettings settings;
    double size = 0, sweep_size = 0, max_elements = 0;
    int circumferential = 0, threads = 0, solid = 0;
    std::string report;
    std::string html;
    std::string until_name = stage_name(kLastStage);
    bool quiet = false;
    bool msh_ascii = false;
    bool assembly = false;
    bool economy = false;
    double glue_tolerance = 0;
    std::string inp_family = job::kInpFamilies[0];
    std::string inp_pyramid = job::kInpPyramids[0];
    bool pipe_network = false;
    double film_coefficient = 0;
    std::vector<int> reverse_flow;
    CLI::Option *size_option = nullptr, *sweep_option = nullptr, *circ_option = nullptr, *threads_option = nullptr,
                *max_elements_option = nullptr, *solid_option = nullptr, *layers_option = nullptr,
                *axial_option = nullptr, *chordal_option = nullptr, *film_option = nullptr;
};

template <class T>
void take_if_given(std::optional<T>& setting, const CLI::Option* option, T value) {
    if (option->count() > 0) setting = value;
}

// The ranges as parse-time checks in plain numbers (tools/cli/option_checks.hpp).
CLI::Validator whole_in(job::Range r) {
    return whole_number(static_cast<long long>(r.lo), static_cast<long long>(r.hi));
}
CLI::Validator number_in(job::Range r) { return number_between(r.lo, r.hi); }

void check_outputs(const MeshArgs& a, Stage until) {
    for (const std::string& out : a.outputs) job::check_mesh_output(out, until);
    if (!a.report.empty()) job::check_report_output(a.report, ".json", "the report");
    if (!a.html.empty()) job::check_report_output(a.html, ".html", "the HTML report");
    std::vector<std::string> all = a.outputs;
    for (const std::string* text : {&a.report, &a.html})
        if (!text->empty()) all.push_back(*text);
    job::check_distinct_outputs(all);
}

// All files or none: every file is complete under a temporary name before any target is
// replaced, so a failure (or an interrupt) leaves the targets, old files included, as they were.
void write_all(const geom::MeshRun& meshed, const MeshArgs& a, WriteOptions options,
               const std::optional<geom::AssemblyRun>& assembly) {
    options.description = &meshed.result.description;
    std::vector<std::pair<std::string, std::string>> texts;
    if (!a.report.empty()) {
        nlohmann::json report = job::run_json(meshed, a.outputs);
        if (assembly) report["assembly"] = job::assembly_json(*assembly, meshed);
        texts.emplace_back(a.report, report.dump(2) + "\n");
    }
    if (!a.html.empty()) texts.emplace_back(a.html, job::html_report(meshed));
    job::write_all(meshed.result.mesh, a.outputs, options, texts);
}

MeshOptions mesh_options(MeshArgs& a, ProgressLine& progress) {
    job::MeshSettings& s = a.settings;
    take_if_given(s.size, a.size_option, a.size);
    take_if_given(s.sweep_size, a.sweep_option, a.sweep_size);
    take_if_given(s.circumferential, a.circ_option, a.circumferential);
    take_if_given(s.threads, a.threads_option, a.threads);
    take_if_given(s.max_elements, a.max_elements_option, a.max_elements);
    take_if_given(s.solid, a.solid_option, a.solid);
    s.chordal_given = a.chordal_option->count() > 0;
    if (a.economy)
        job::apply_economy(s, {.layers = a.layers_option->count() > 0,
                               .axial_aspect = a.axial_option->count() > 0,
                               .chordal = a.chordal_option->count() > 0});
    MeshOptions o = job::mesh_options(s, job::Naming::Flags);
    // A phase's end is where its temporaries are gone: hand their pages back before the next.
    o.progress = [line = progress.callback()](const ProgressEvent& e) {
        if (e.total > 0 && e.done >= e.total) job::return_free_memory();
        line(e);
    };
    return o;
}

}  // namespace

Command add_mesh_command(CLI::App& app) {
    auto args = std::make_shared<MeshArgs>();
    const job::MeshSettings& d = args->settings;  // the defaults, shown in the help
    CLI::App* cmd = app.add_subcommand("mesh", "Mesh a CAD solid with tubular holes (hex rings, pyramids, tets)");
    cmd->add_option("IN", args->input,
                    "CAD file (.step .stp .iges .igs .brep); without it, the built-in dam block (paper-ex1)");
    cmd->add_option("-o,--output", args->outputs,
                    "Mesh file to write (.msh Gmsh, .vtu ParaView volume, .vtm ParaView blocks per group, .inp "
                    "Abaqus / CalculiX); repeat for several. Without -o only the reports asked for are written; "
                    "with neither IN, -o, --report nor --html: dam_block.msh and dam_block.vtu")
        ->allow_extra_args(false);  // `-o a.msh IN` must not take IN as a second output
    args->size_option = cmd->add_option("--size", args->size,
                                        "Overall mesh size S (default: bounding-box diagonal / 25, at least 1.3 St)")
                            ->check(positive_number());
    args->sweep_option = cmd->add_option(
        "--sweep-size", args->sweep_size,
        "Hex ring thickness St (default: smallest tube diameter, cut by the paper's rules; a given St the rules "
        "would cut is an error)")
                             ->check(positive_number());
    args->circ_option =
        cmd->add_option("--circ", args->circumferential,
                        "Nodes around each tube, n (default: the multiple of 4 nearest 2 pi (r + St/2) / St, at least 8)")
            ->check(whole_in(job::kCircRange));
    args->chordal_option = cmd->add_option("--chordal", args->settings.chordal,
                    fmt::format("Curved CAD edges: largest gap between a chord and the curve over the chord's length "
                                "(default {}: a segment turns by at most {:.3f} rad)",
                                d.chordal, geom::chordal_turn(d.chordal)))
        ->check(number_in(job::kChordalRange));
    args->layers_option = cmd->add_option("--layers", args->settings.layers,
                    fmt::format("Hex layers across the ring, L (default {}, graded {} towards the wall)", d.layers,
                                job::default_mesh_options().sweep.grading))
        ->check(whole_in(job::kLayersRange));
    args->axial_option = cmd->add_option("--axial-aspect", args->settings.axial_aspect,
                    fmt::format("Axial step of the hex rings over St (default {})", d.axial_aspect))
        ->check(number_in(job::kAxialAspectRange));
    cmd->add_option("--pyramid-height", args->settings.pyramid_height,
                    fmt::format("Pyramid apex height over the quad's mean edge (default {}, the paper's)",
                                d.pyramid_height))
        ->check(number_in(job::kPyramidHeightRange));
    cmd->add_option("--gradation", args->settings.gradation,
                    fmt::format("Largest growth of the tet size from one element to the next (default {})",
                                d.gradation))
        ->check(number_in(job::kGradationRange));
    cmd->add_flag("--economy", args->economy,
                  fmt::format("The paper's economy: {} nodes around each tube in {} hex layers, St = {} S (at most 12.5 "
                              "tube radii, cut by the rules), axial step {} x the ring's outer side, curved edges to --chordal {}; about half "
                              "the default's elements, which keeps quality first. Options given beside it win",
                              job::kEconomy.circumferential, job::kEconomy.layers, job::kEconomy.sweep_share,
                              job::kEconomy.axial_aspect, job::kEconomy.chordal));
    args->threads_option = cmd->add_option("--threads", args->threads, "Worker threads (default: all cores; more than the cores are not used)")
                               ->check(whole_in(job::kThreadsRange));
    cmd->add_option("--tet-parts", args->settings.tet_parts,
                    fmt::format("Spatial parts of the tet step's parallel Delaunay passes (default {}: the mesh is "
                                "the same for any --threads; 0: one per thread, the mesh then depends on it)",
                                d.tet_parts))
        ->check(whole_in(job::kTetPartsRange));
    cmd->add_option("--tet-relax", args->settings.tet_relax,
                    fmt::format("ODT relaxation rounds of the tet step's interior points before the optimisation "
                                "(default {}; 0: none, mean collapse about 0.01 lower, time within about 15 % either way)",
                                d.tet_relax))
        ->check(whole_in(job::kTetRelaxRange));
    cmd->add_flag("--move-apexes", args->settings.move_apexes,
                  "Let the tet optimisation move the pyramid apexes, each pyramid kept at a scaled Jacobian of at "
                  "least 0.5: the tets' minimum and mean rise, the pyramids' fall (default: apexes stay where the "
                  "pyramid layer put them)");
    cmd->add_flag_callback(
        "--global-ring", [args] { args->settings.local_ring = false; },
        "One ring thickness St for every tube, cut by the paper's rules for the closest place of all (default: St "
        "stays and each ring thins, with shorter steps along it, only where a face or another pipe comes near it, "
        "per place and direction; a tube with room everywhere gets the same ring either way)");
    cmd->add_flag_callback(
        "--fixed-surface", [args] { args->settings.slide_surface = false; },
        "Keep every surface node where the surface mesher put it (default: the tet optimisation slides the nodes "
        "inside flat faces of the solid in their plane, which raises the tets' minimum and mean; nodes on CAD "
        "edges, curved faces, rings and pyramids stay, the shape and the surface groups do not change)");
    args->max_elements_option =
        cmd->add_option("--max-elements", args->max_elements,
                        "Refuse sizes that give more elements (cells and boundary faces) than this: before meshing on "
                        "a lower bound from the volume, area, S, St and tube lengths, then after each stage on the "
                        "real counts so far; no mesh over it is written (default: what the memory this process may "
                        "use holds, physical, ulimit -v or cgroup limit, checked on the lower bound only)")
            ->check(positive_number());
    cmd->add_option("--report", args->report, "Also write the report as JSON to this file");
    cmd->add_option("--html", args->html,
                    "Also write the report as one self-contained HTML page (Table 1, histograms, phase times, a 3D "
                    "view of the hybrid layer around the pipes)");
    args->solid_option = cmd->add_option("--solid", args->solid, "Which solid of the file, 1-based (when it holds several)")
                             ->check(whole_in(job::kSolidRange));
    cmd->add_option("--until", args->until_name, "Last stage to run: " + job::stage_names() + " (default: the last)")
        ->option_text("STAGE");
    cmd->add_flag("--assembly", args->assembly,
                  "IN holds several solids that share faces (or touch within --glue-tolerance): mesh them as one "
                  "conforming mesh, a volume group per solid");
    cmd->add_option("--glue-tolerance", args->glue_tolerance,
                    "With --assembly: faces of different solids this close are glued (default: 1e-6 of the "
                    "assembly's bounding-box diagonal); a wider gap or overlap is an error")
        ->check(positive_number());
    cmd->add_flag("--quiet", args->quiet, "Print nothing but errors");
    cmd->add_flag("--msh-ascii", args->msh_ascii, "Write .msh files as text (default: binary)");
    cmd->add_option("--inp-family", args->inp_family,
                    "Element family of .inp files: stress (C3D4/C3D8, default; CalculiX uses them for heat transfer "
                    "too), heat (DC3D4/DC3D8, Abaqus and CalculiX), coupled (coupled temperature-displacement for "
                    "CalculiX: C3D4/C3D8, which its *COUPLED TEMPERATURE-DISPLACEMENT step gives the temperature), "
                    "coupled-abaqus (C3D4T/C3D8T: Abaqus only, CalculiX refuses them)")
        ->check(CLI::IsMember(job::kInpFamilies));
    cmd->add_option("--inp-pyramid", args->inp_pyramid,
                    "Pyramids in .inp files: hex (a C3D8 with the apex repeated, which CalculiX and Abaqus read; "
                    "default) or c3d5 (the 5-node pyramid, stress family only: Abaqus only, CalculiX refuses it)")
        ->check(CLI::IsMember(job::kInpPyramids));
    cmd->add_flag("--pipe-network", args->pipe_network,
                  "Write the water in every pipe into the .inp as a CalculiX fluid network (sets pipe_<k>_water, "
                  "_water_in, _water_out, _water_flow, WATER) and X.films.inp beside X.inp: one *FILM line per wall "
                  "face, forced convection to its water node");
    args->film_option = cmd->add_option("--film-coefficient", args->film_coefficient,
                                        "With --pipe-network: h of the wall faces' films, in the deck's units "
                                        "(default 2000, W/(m2 K) for water in a 25 mm pipe at about 0.5 m/s)")
                            ->option_text("H");
    cmd->add_option("--reverse-flow", args->reverse_flow,
                    "With --pipe-network: the water of pipe_<k> enters at its second end (pipe_<k>_outlet); "
                    "repeatable")
        ->option_text("K")
        ->allow_extra_args(false)  // one number per --reverse-flow: the next word may be IN
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    cmd->footer(
        "Progress: one updating line per phase on a terminal, plain 'progress:' lines otherwise.\n"
        "Partial stages (--until) are checked for what they hold (engine/pipeline/stage_check.hpp); .inp needs "
        "the sweep stage or the full mesh.\n"
        "Exit status: 0 meshed and written, 2 on any error (one line on stderr, no file written).");

    return {cmd, [args]() -> int {
        const Stage until = job::stage_named(args->until_name, job::Naming::Flags);
        args->settings.until = until;
        // A report alone is a run that writes only the report; with nothing asked for, the dam block's
        // default files.
        if (args->outputs.empty() && args->report.empty() && args->html.empty()) {
            if (!args->input.empty())
                throw Error("mesh needs -o OUT.msh|.vtu|.vtm|.inp, --report FILE.json or --html FILE.html for '" +
                            args->input + "'");
            args->outputs = {"dam_block.msh", "dam_block.vtu"};
        }
        check_outputs(*args, until);
        WriteOptions write = job::write_options(args->msh_ascii, args->inp_family, args->inp_pyramid, job::Naming::Flags);
        std::vector<std::string> files = args->outputs;
        std::optional<double> film;
        take_if_given(film, args->film_option, args->film_coefficient);
        write.pipe_network =
            job::pipe_network_options(args->pipe_network, film, args->reverse_flow, files, job::Naming::Flags);
        if (write.pipe_network.write) job::check_distinct_outputs(files);
        ProgressLine progress(ProgressLine::mode_for(args->quiet));
        MeshOptions options = mesh_options(*args, progress);
        auto say = [&](const std::string& s) {
            if (!args->quiet) fmt::print("{}\n", s);
        };

        // 90 % of the physical memory (or the cgroup's limit), or a lower limit already set
        // (ulimit -v): the element budget refuses most runs that would not fit; this stops the
        // rest with a message. The budget reads the memory before this process lowers its own.
        const UsableMemory usable = usable_memory();
        const double cgroup = cgroup_memory_limit_bytes();
        const double memory_limit = limit_memory(0.9 * (cgroup > 0 ? cgroup : physical_memory_bytes()));
        options.memory = usable;
        geom::MeshRun meshed;
        std::optional<geom::AssemblyRun> assembly;
        try {
            if (args->assembly) {
                if (args->input.empty()) throw Error("--assembly needs a CAD file IN");
                if (until != kLastStage) throw Error("--assembly meshes every stage: leave --until out");
                if (args->settings.solid) throw Error("--assembly meshes every solid: leave --solid out");
                assembly = geom::mesh_assembly_file(args->input, options, {.glue_tolerance = args->glue_tolerance});
                meshed = std::move(assembly->run);
            } else if (args->input.empty()) {
                say("no input: meshing the built-in dam block (preset paper-ex1)");
                meshed = geom::mesh_preset("paper-ex1", options, until);
            } else {
                meshed = geom::mesh_file(args->input, options,
                                      {.solid = args->settings.solid.value_or(0), .until = until});
            }
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
        progress.close();

        const PipelineResult& r = meshed.result;
        write_all(meshed, *args, write, assembly);
        if (args->quiet) return 0;

        say(fmt::format("{} ({}): {} tube{}, S = {:.6g}, St = {:.6g}", meshed.source, meshed.format, meshed.tubes,
                        meshed.tubes == 1 ? "" : "s", meshed.size, meshed.sweep_size));
        for (const std::string& line : meshed.model_lines) say("  " + line);
        for (const std::string& w : r.warnings) fmt::print(stderr, "tubemesh: warning: {}\n", w);
        if (write.inp_pyramid == InpPyramid::C3D5 && r.mesh.cell_count(CellKind::Pyramid) > 0)
            for (const std::string& out : args->outputs)
                if (job::lower_extension(out) == ".inp")
                    fmt::print(stderr, "tubemesh: warning: {} holds C3D5 pyramids, which only Abaqus reads (CalculiX "
                               "refuses them: leave --inp-pyramid out for bricks with the apex repeated)\n", out);
        if (r.reached != kLastStage)
            say(fmt::format("note: stopped after the {} stage (--until)", stage_name(r.reached)));
        say("");
        for (const std::string& line : job::phase_lines(meshed)) say(line);
        const HybridMesh& mesh = r.mesh;
        say(fmt::format("\n{} nodes, {} hexahedra, {} pyramids, {} tetrahedra; {} boundary triangles, {} boundary quads",
                        mesh.point_count(), mesh.cell_count(CellKind::Hex), mesh.cell_count(CellKind::Pyramid),
                        mesh.cell_count(CellKind::Tet), mesh.face_count(FaceKind::Tri),
                        mesh.face_count(FaceKind::Quad)));
        fmt::print("\n{}\n", job::run_table(meshed));
        if (assembly)
            for (const std::string& line : job::assembly_lines(*assembly, meshed)) say(line);
        for (const std::string& line : job::group_lines(meshed)) say(line);
        for (const std::string& out : args->outputs) say("wrote " + out);
        if (!args->report.empty()) say("wrote " + args->report);
        if (!args->html.empty()) say("wrote " + args->html);
        return 0;
    }};
}

}  // namespace tubemesh::cli
