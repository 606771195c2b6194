#pragma once
// Named blocks: the paper's three examples, the serpentine dam lift, and small blocks whose
// volume is known in closed form (for tests).
#include <string>
#include <vector>

#include "geom/builders/block_spec.hpp"

namespace tubemesh::geom {

struct PresetInfo {
    std::string name;
    std::string description;
};

const std::vector<PresetInfo>& preset_list();

// Throws tubemesh::Error listing the preset names when `name` is not one of them.
BlockSpec preset_spec(const std::string& name);

}  // namespace tubemesh::geom
