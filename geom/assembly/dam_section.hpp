#pragma once
// A dam section as one assembly: the blocks of geom/builders/dam.hpp built, placed at their
// origins and glued, each solid named block_<column>_<lift>. No OpenCASCADE header here.
#include <filesystem>
#include <vector>

#include "geom/assembly/assembly.hpp"
#include "geom/builders/dam.hpp"

namespace tubemesh::geom {

// "block_2_3": the solid's name for column 2, lift 3.
std::string dam_solid_name(const DamBlock& block);

// Throws tubemesh::Error when a block cannot be built or the blocks do not glue.
Assembly build_dam_section(const std::vector<DamBlock>& blocks);

// The glued compound as one STEP file, each solid under its name; written to a temporary name
// and renamed (geom/step_write.hpp).
void write_assembly_step(const Assembly& assembly, const std::filesystem::path& path);

}  // namespace tubemesh::geom
