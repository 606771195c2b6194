// `tubemesh make-dam [--columns C] [--lifts L] [--seed N] -o DIR [--specs] [ranges] [--size S]
// [--sweep-size St] [--formats LIST]`: a parametric dam (geom/builders/dam.hpp) as a batch:
// DIR/manifest.json (batch/manifest.hpp) and one STEP file per block, or with --specs one
// builder spec (JSON) per block. The same arguments give the same files. DIR is new (or empty) and
// appears whole or not at all (io::AtomicFolder).
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "engine/core/types.hpp"
#include "engine/io/atomic_file.hpp"
#include "geom/assembly/dam_section.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/dam.hpp"
#include "geom/builders/spec_json.hpp"
#include "geom/import/step_write.hpp"
#include "tools/cli/commands.hpp"

namespace tubemesh::cli {

namespace {

namespace fs = std::filesystem;

struct MakeDamArgs {
    geom::DamParams dam;
    std::string outdir;
    bool specs = false;
    bool assembled = false;
    double size = 0, sweep_size = 0;
    std::vector<std::string> formats;
    bool quiet = false;
};

// "A:B" or "A" (a fixed value).
void add_range(CLI::App* cmd, const std::string& name, geom::Range& range, const std::string& what) {
    cmd->add_option_function<std::string>(
           name,
           [&range, name](const std::string& text) {
               double lo = 0, hi = 0;
               char colon = 0, extra = 0;
               const int n = std::sscanf(text.c_str(), "%lf%c%lf%c", &lo, &colon, &hi, &extra);
               if (n == 1) hi = lo;
               else if (n != 3 || colon != ':')
                   throw CLI::ValidationError(name, "use MIN:MAX or one value, got " + text);
               range = {lo, hi};
           },
           fmt::format("{} (default {:g}:{:g})", what, range.lo, range.hi))
        ->option_text("MIN:MAX");
}

void write_text(const fs::path& path, const std::string& text) {
    io::AtomicFile file(path);
    file.write(text);
    file.commit();
}

nlohmann::json block_info(const geom::DamBlock& b) {
    nlohmann::json info = {{"column", b.column},
                           {"lift", b.lift},
                           {"role", b.role},
                           {"origin", {b.origin.x, b.origin.y, b.origin.z}},
                           {"size", {b.spec.host.size.x, b.spec.host.size.y, b.spec.host.size.z}}};
    if (!b.spec.pipes.empty()) {
        const geom::PipeSpec& p = b.spec.pipes.front();
        info["pipe_diameter"] = p.diameter;
        info["bend_radius"] = p.bend_radius;
        info["inlet"] = {p.points.front().x, p.points.front().y, p.points.front().z};
    }
    return info;
}

// What the folder got, for the summary lines.
struct DamWritten {
    int pipes = 0;
    std::size_t section_solids = 0, shared_faces = 0;  // 0 solids: no section
};

// The blocks' files, the manifest and the section (if asked for) into `dir`.
DamWritten write_dam(const MakeDamArgs& a, const std::vector<geom::DamBlock>& blocks, const fs::path& dir) {
    DamWritten written;
    // Built and glued first (a section that does not glue fails before the blocks are built),
    // written last: OpenCASCADE numbers the products it writes, so the order shapes the bytes.
    std::optional<geom::Assembly> section;
    if (a.assembled) section = geom::build_dam_section(blocks);
    nlohmann::json defaults = nlohmann::json::object();
    if (a.size > 0) defaults["size"] = a.size;
    if (a.sweep_size > 0) defaults["sweep_size"] = a.sweep_size;
    if (!a.formats.empty()) defaults["formats"] = a.formats;
    nlohmann::json entries = nlohmann::json::array();
    for (const geom::DamBlock& b : blocks) {
        nlohmann::json e = {{"id", b.id}};
        if (a.specs) {
            const std::string name = b.id + ".json";
            write_text(dir / name, geom::block_spec_json(b.spec) + "\n");
            e["spec"] = name;
        } else {
            const std::string name = b.id + ".step";
            geom::write_step(geom::build_block(b.spec).model, dir / name);
            e["cad"] = name;
        }
        e["info"] = block_info(b);
        entries.push_back(std::move(e));
        written.pipes += !b.spec.pipes.empty();
    }
    const nlohmann::json manifest = {
        {"tubemesh_batch", 1},
        {"name", fmt::format("dam seed {} ({} x {})", a.dam.seed, a.dam.columns, a.dam.lifts)},
        {"defaults", defaults},
        {"blocks", entries}};
    write_text(dir / "manifest.json", manifest.dump(2) + "\n");
    if (section) {
        geom::write_assembly_step(*section, dir / "section.step");
        written.section_solids = section->solids().size();
        written.shared_faces = section->shared_faces().size();
    }
    return written;
}

}  // namespace

Command add_make_dam_command(CLI::App& app) {
    auto a = std::make_shared<MakeDamArgs>();
    CLI::App* cmd = app.add_subcommand("make-dam", "Write a parametric dam as a batch: a manifest and one CAD file per block");
    cmd->add_option("--columns", a->dam.columns, "Columns along the dam's axis (default 3)")->check(CLI::Range(1, 1000));
    cmd->add_option("--lifts", a->dam.lifts, "Lifts per column (default 4)")->check(CLI::Range(1, 1000));
    cmd->add_option("--seed", a->dam.seed, "The same seed gives the same dam (default 1)");
    cmd->add_option("-o,--output", a->outdir,
                    "Folder for manifest.json and the blocks' files: new or empty; it appears whole or not at all");
    cmd->add_flag("--specs", a->specs, "Write a builder spec (JSON) per block instead of a STEP file");
    cmd->add_flag("--assembled", a->assembled,
                  "Also write DIR/section.step: the blocks glued into one assembly (solids block_C_L, faces "
                  "shared), every block with a pipe; mesh it with tubemesh mesh --assembly");
    cmd->add_option("--crossing-pipes", a->dam.crossing_pipes,
                    "Straight pipes along the dam's axis, each through every column of one lift a quarter up it, "
                    "crossing the column joints; each block holds its piece (default 0)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--pipe-height", a->dam.pipe_height_radii,
                    "The serpentine pipes' centre this many pipe radii above each lift's bottom, as pipes laid on "
                    "the lift joint (above 1; default: at mid-height)")
        ->check(CLI::Range(1.0, 1e6));
    add_range(cmd, "--width", a->dam.width, "Column width along the dam's axis, drawn per column");
    add_range(cmd, "--depth", a->dam.depth, "Column depth, upstream to downstream, drawn per column");
    add_range(cmd, "--lift-height", a->dam.lift_height, "Lift height, drawn per block");
    add_range(cmd, "--diameter", a->dam.diameter, "Cooling pipe diameter, drawn per block");
    add_range(cmd, "--spacing", a->dam.spacing, "Distance between the pipe's runs, drawn per block");
    cmd->add_option("--size", a->size, "Mesh size S for every block, in the manifest's defaults (default: per block)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--sweep-size", a->sweep_size, "Hex ring thickness St in the manifest's defaults")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--formats", a->formats, "Mesh formats in the manifest's defaults: msh, vtu, inp (default msh)")
        ->delimiter(',')
        ->check(CLI::IsMember({"msh", "vtu", "inp"}));
    cmd->add_flag("--quiet", a->quiet, "Print nothing but errors");
    cmd->footer(
        "Blocks: c<column>-l<lift>, a box with one serpentine cooling pipe (inlet and outlet on the downstream face "
        "y = depth, runs going upstream and back); the foundation block (first column, first lift) and the crest "
        "block (last column, top lift) have none.\nMeshing: tubemesh batch DIR/manifest.json -o OUTDIR");

    return {cmd, [a]() -> int {
        if (a->outdir.empty()) throw Error("make-dam needs -o DIR");
        if (a->assembled) a->dam.pipeless_ends = false;
        const std::vector<geom::DamBlock> blocks = geom::dam_blocks(a->dam);  // Error -> exit 2
        // All or nothing: the files go to a hidden sibling of the folder, renamed at the end, so
        // an error (a section that does not glue, a full disk) or an interrupt leaves no file.
        io::AtomicFolder folder(a->outdir);
        DamWritten written;
        try {
            written = write_dam(*a, blocks, folder.path());
        } catch (const Error& e) {
            throw Error(folder.final_names(e.what()));
        }
        folder.commit();
        const fs::path dir = a->outdir;
        if (!a->quiet)
            fmt::print("wrote {}: {} blocks ({} columns x {} lifts, {} with a cooling pipe), {}\n",
                       (dir / "manifest.json").string(), blocks.size(), a->dam.columns, a->dam.lifts, written.pipes,
                       a->specs ? "one builder spec each" : "one STEP file each");
        if (written.section_solids > 0 && !a->quiet)
            fmt::print("wrote {}: the {} blocks as one assembly, {} shared faces\n", (dir / "section.step").string(),
                       written.section_solids, written.shared_faces);
        return 0;
    }};
}

}  // namespace tubemesh::cli
