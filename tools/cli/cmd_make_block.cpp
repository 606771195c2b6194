// `tubemesh make-block --preset NAME | --seed N | --spec FILE -o OUT.step`: build a test solid
// with OpenCASCADE (the paper's examples, a dam lift, a random block or a JSON spec) and write it
// as STEP. `--list` prints the presets; `--print-spec` prints the block's JSON spec, which makes
// a random block editable and reproducible without the seed.
#include <fmt/format.h>

#include <cstdint>
#include <memory>
#include <string>

#include "engine/core/types.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/make_block.hpp"
#include "geom/builders/presets.hpp"
#include "geom/builders/spec_json.hpp"
#include "geom/import/step_write.hpp"
#include "tools/cli/commands.hpp"

namespace tubemesh::cli {

namespace {

struct MakeBlockOptions {
    geom::MakeBlockArgs block;
    std::uint64_t seed = 0;
    std::string output;
    bool list = false;
    bool print_spec = false;
};

std::string preset_help() {
    std::string text = "Presets:\n";
    for (const geom::PresetInfo& p : geom::preset_list()) text += fmt::format("  {:<16} {}\n", p.name, p.description);
    return text;
}

std::string diameters(const geom::BlockInfo& info) {
    std::string out;
    for (double d : info.pipe_diameters) out += fmt::format("{}{:g}", out.empty() ? "" : ", ", d);
    return out;
}

}  // namespace

Command add_make_block_command(CLI::App& app) {
    auto opt = std::make_shared<MakeBlockOptions>();
    CLI::App* cmd = app.add_subcommand("make-block", "Build a solid with tubular holes and write it as STEP");
    auto* preset = cmd->add_option("--preset", opt->block.preset, "A named block (see --list)");
    auto* seed = cmd->add_option("--seed", opt->seed, "A random box with 1 to 12 curved pipes, the same for the same N");
    auto* spec = cmd->add_option("--spec", opt->block.spec, "A JSON block spec (format: geom/builders/spec_json.hpp)");
    preset->excludes(seed)->excludes(spec);
    seed->excludes(spec);
    cmd->add_option("-o,--output", opt->output, "The STEP file to write");
    cmd->add_flag("--close", opt->block.close,
                  "With --seed: two straight pipes deliberately close to each other and to a face (or crossing, "
                  "touching, tangent), clearance checks off");
    cmd->add_flag("--list", opt->list, "List the presets and exit");
    cmd->add_flag("--print-spec", opt->print_spec, "Print the block's JSON spec to stdout");
    cmd->footer(preset_help());

    return {cmd, [opt, seed]() -> int {
        if (opt->list) {
            fmt::print("{}", preset_help());
            return 0;
        }
        if (seed->count() > 0) opt->block.seed = opt->seed;
        const geom::BlockSpec spec = geom::block_spec_for(opt->block);  // Error -> exit 2 in main
        if (opt->print_spec) fmt::print("{}\n", geom::block_spec_json(spec));
        if (opt->output.empty()) {
            if (opt->print_spec) return 0;
            throw Error("make-block needs -o OUT.step (or --print-spec to only print the spec)");
        }
        const geom::BuiltBlock block = geom::build_block(spec);
        geom::write_step(block.model, opt->output);
        const geom::BlockInfo& info = block.info;
        std::string volume = fmt::format("volume {:.10g}", info.volume);
        if (info.expected_volume) volume += fmt::format(" (closed form {:.10g})", *info.expected_volume);
        fmt::print("wrote {}: {}, {} pipe{} (diameter {}), {} faces, {}, unit {}\n", opt->output, info.name,
                   info.pipe_count, info.pipe_count == 1 ? "" : "s", diameters(info), block.model.face_count(), volume,
                   info.length_unit);
        return 0;
    }};
}

}  // namespace tubemesh::cli
