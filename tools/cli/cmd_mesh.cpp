// `tubemesh mesh [IN] -o OUT [-o OUT2 ...] [--size S] [--sweep-size St] [--until STAGE]
// [--threads T] [--quiet]`: mesh a CAD solid (or, without IN, the built-in dam block, preset
// paper-ex1) through the pipeline up to STAGE, print one line per phase and the quality table,
// and write the mesh to every OUT (format by extension: .msh, .vtu, .inp). Files are written
// only after every phase succeeded; an error is one line on stderr and exit 2, with no file.
//
// Stages: sweep, surface, pyramids (the default for now; tets come later). Only a sweep-stage
// mesh passes `tubemesh check`: from the surface stage on, the surface triangles are stored as
// boundary faces before any cell has them (engine/pipeline/pipeline.hpp).
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <cctype>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/mesh_io.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "engine/quality/quality.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/import.hpp"
#include "geom/prepare.hpp"
#include "tools/cli/commands.hpp"
#include "tools/cli/quality_table.hpp"

namespace tubemesh::cli {

namespace {

struct MeshArgs {
    std::string input;
    std::vector<std::string> outputs;
    double size = 0;
    double sweep_size = 0;
    std::string until_name = "pyramids";
    Stage until = Stage::Pyramids;
    int threads = 0;
    bool quiet = false;
};

std::string count_text(const std::pair<std::string, double>& c) {
    if (c.second == static_cast<double>(static_cast<long long>(c.second)) && c.second >= 0 && c.second < 1e15)
        return fmt::format("{} {}", static_cast<long long>(c.second), c.first);
    return fmt::format("{} {:.4g}", c.first, c.second);
}

}  // namespace

Command add_mesh_command(CLI::App& app) {
    auto args = std::make_shared<MeshArgs>();
    CLI::App* cmd = app.add_subcommand("mesh", "Mesh a CAD solid with tubular holes (hex rings, pyramids; tets later)");
    cmd->add_option("IN", args->input, "CAD file (STEP, IGES or BREP); without it, the built-in dam block (paper-ex1)");
    cmd->add_option("-o,--output", args->outputs, "Mesh file to write (.msh, .vtu, .inp); repeat for several")
        ->required()
        ->allow_extra_args(false);  // `-o a.msh IN` must not take IN as a second output
    cmd->add_option("--size", args->size, "Overall mesh size S (default: bounding-box diagonal / 25)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--sweep-size", args->sweep_size, "Hex ring thickness St (default: smallest tube diameter)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--until", args->until_name, "Last stage to run: sweep, surface or pyramids (default; tets come later)")
        ->transform(CLI::IsMember({"sweep", "surface", "pyramids"}, CLI::ignore_case))
        ->option_text("STAGE");
    cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::PositiveNumber);
    cmd->add_flag("--quiet", args->quiet, "Print nothing but errors");
    cmd->footer(
        "Only a --until sweep mesh passes `tubemesh check`: later partial meshes store the surface triangles as "
        "boundary faces before the tets make them cell faces (.inp cannot hold them).\n"
        "Exit status: 0 meshed and written, 2 on any error (no file is written then).");

    return {cmd, [args]() -> int {
        auto say = [&](const std::string& s) {
            if (!args->quiet) fmt::print("{}\n", s);
        };
        args->until = args->until_name == "sweep" ? Stage::Sweep
                      : args->until_name == "surface" ? Stage::Surface
                                                      : Stage::Pyramids;
        // Output formats are checked before any work, so a bad name fails fast and writes nothing.
        for (const std::string& out : args->outputs) {
            std::string ext = std::filesystem::path(out).extension().string();
            for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            if (ext != ".msh" && ext != ".vtu" && ext != ".inp")
                throw Error("cannot write '" + out + "': unknown mesh format (use .msh, .vtu or .inp)");
            if (ext == ".inp" && args->until != Stage::Sweep)
                throw Error("cannot write '" + out + "': Abaqus .inp needs every boundary face on a cell, which a " +
                            stage_name(args->until) + "-stage mesh does not have yet (use .msh or .vtu)");
        }
        // The whole command (surface maps, quality summary) on T threads, not only the pipeline.
        std::optional<tbb::global_control> threads;
        if (args->threads > 0)
            threads.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(args->threads));
        const auto t0 = std::chrono::steady_clock::now();
        // The model: a file, or the built-in dam block.
        std::optional<geom::BuiltBlock> built;
        std::optional<geom::Model> imported;
        const geom::Model* model = nullptr;
        if (args->input.empty()) {
            built.emplace(geom::build_block(geom::preset_spec("paper-ex1")));
            model = &built->model;
            say("no input: meshing the built-in dam block (preset paper-ex1)");
        } else {
            imported.emplace(geom::import_model(args->input));  // Error -> exit 2 in main
            model = &*imported;
        }
        say(fmt::format("{} ({}): {} faces, {} edges", model->report().source, model->report().format,
                        model->face_count(), model->edge_count()));

        geom::PrepareOptions prep;
        prep.sizing.size = args->size;
        prep.sizing.sweep_size = args->sweep_size;
        const geom::PreparedModel prepared = geom::prepare_model(*model, prep);
        const double geometry_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();  // import/build + prepare
        for (const std::string& line : prepared.report_lines()) say(line);
        if (args->until == Stage::Pyramids) say("note: tets come later; the last stage available is pyramids");

        MeshOptions options;
        options.threads = args->threads;
        const PipelineResult result = run_pipeline(prepared.pipeline_input(), options, args->until);

        say("");
        say(fmt::format("{:<10} {:8.3f} s  {} tubes, S {:.4g}, St {:.4g}", "geometry", geometry_seconds,
                        prepared.geometry.tubes.size(), prepared.geometry.size, prepared.geometry.sweep_size));
        for (const PhaseReport& p : result.phases) {
            std::string counts;
            for (const auto& c : p.counts) counts += (counts.empty() ? "" : ", ") + count_text(c);
            say(fmt::format("{:<10} {:8.3f} s  {}", p.name, p.seconds, counts));
        }
        const HybridMesh& mesh = result.mesh;
        say(fmt::format("\n{} nodes, {} hexahedra, {} pyramids, {} tetrahedra; {} boundary triangles, {} boundary quads",
                        mesh.point_count(), mesh.cell_count(CellKind::Hex), mesh.cell_count(CellKind::Pyramid),
                        mesh.cell_count(CellKind::Tet), mesh.face_count(FaceKind::Tri),
                        mesh.face_count(FaceKind::Quad)));
        if (!args->quiet) fmt::print("\n{}", format_quality_table(summarize_quality(mesh), mesh.point_count()));
        for (const std::string& out : args->outputs) {
            write_mesh(mesh, out);  // atomic: a failure leaves no file
            say("wrote " + out);
        }
        return 0;
    }};
}

}  // namespace tubemesh::cli
