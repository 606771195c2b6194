#include "geom/builders/make_block.hpp"

#include "engine/core/types.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/close_block.hpp"
#include "geom/builders/presets.hpp"
#include "geom/builders/random_block.hpp"
#include "geom/builders/spec_json.hpp"
#include "geom/import/step_write.hpp"

namespace tubemesh::geom {

BlockSpec block_spec_for(const MakeBlockArgs& args) {
    const int sources = (args.preset.empty() ? 0 : 1) + (args.seed ? 1 : 0) + (args.spec.empty() ? 0 : 1);
    if (sources != 1) throw Error("make-block needs exactly one of --preset NAME, --seed N or --spec FILE");
    if (!args.preset.empty()) return preset_spec(args.preset);
    if (args.seed) return args.close ? close_block_spec(*args.seed) : random_block_spec(*args.seed);
    if (args.close) throw Error("make-block --close needs --seed N");
    return read_block_spec(args.spec);
}

BlockInfo make_block(const MakeBlockArgs& args, const std::filesystem::path& out) {
    BuiltBlock block = build_block(block_spec_for(args));
    write_step(block.model, out);
    return block.info;
}

}  // namespace tubemesh::geom
