#pragma once
// Building the solid a BlockSpec describes: host minus swept pipes, checked like an import.
#include "geom/builders/block_spec.hpp"
#include "geom/model/model.hpp"

namespace tubemesh::geom {

struct BuiltBlock {
    Model model;
    BlockInfo info;
};

// Sweeps every pipe, cuts them all from the host in one boolean, and checks the result: one
// valid solid whose faces are the host's plus one wall per pipe. Without pipes: the host. Throws tubemesh::Error, naming
// the pipe, when a path is malformed, does not leave the host at both ends, leaves and re-enters
// it, bends tighter than its radius, or comes too close to another pipe or itself.
BuiltBlock build_block(const BlockSpec& spec);

}  // namespace tubemesh::geom
