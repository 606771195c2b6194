#pragma once
// What the MSH parser takes from a file, before it becomes a HybridMesh: nodes already in
// node-tag order with element nodes resolved to point indices, elements still carrying their
// tags and entity blocks. assemble_msh() turns entities and physical groups into regions
// and surface groups and restores the element order from the tags.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/msh_format.hpp"
#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh::io {

struct MshPhysicalName {
    int dimension;
    int tag;
    std::string name;
};

struct MshEntity {
    int dimension;
    int tag;
    std::optional<int> physical;  // the first physical tag listed, if any
};

struct MshElementBlock {
    int dimension;
    int entity;
};

// Elements of one supported type, in file order.
struct MshElements {
    std::vector<std::uint64_t> tag;
    std::vector<index_t> block;  // index into MshContents::blocks
    std::vector<index_t> nodes;  // point indices, the type's node count per element
    std::vector<index_t> order;  // element indices by ascending tag (tags are distinct)
};

struct MshContents {
    std::vector<double> x, y, z;  // ascending node tag
    std::vector<MshPhysicalName> physical_names;
    std::vector<MshEntity> entities;  // dimensions 2 and 3 only
    std::vector<MshElementBlock> blocks;
    std::array<MshElements, kMshKindCount> elements;  // by msh_kind_index
};

// Cannot fail: the parser has checked everything assembly relies on.
HybridMesh assemble_msh(MshContents&& contents);

}  // namespace tubemesh::io
