#pragma once
// `tubemesh make-block`: build a block from a preset, a seed or a JSON spec and write it as STEP.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "geom/builders/block_spec.hpp"

namespace tubemesh::geom {

// Exactly one source: a preset name, a random seed, or a JSON spec file.
struct MakeBlockArgs {
    std::string preset;
    std::optional<std::uint64_t> seed;
    bool close = false;  // with seed: close_block_spec (pipes near each other and a face)
    std::filesystem::path spec;
};

// The spec the arguments describe. Throws tubemesh::Error unless exactly one source is given.
BlockSpec block_spec_for(const MakeBlockArgs& args);

// Builds the block and writes it to `out` (STEP; written to a temporary name and renamed).
// Returns what was built, for the command's summary line.
BlockInfo make_block(const MakeBlockArgs& args, const std::filesystem::path& out);

}  // namespace tubemesh::geom
