#pragma once
// Meshes and file helpers for the mesh file tests (temporary directories and processes:
// tests/support/process.hpp).
#include <filesystem>
#include <string>

#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh::testing {

// n x n x n cubes of a slightly jittered grid, each a hex, six pyramids around its centre or
// six tets (by position), in regions "layer_0..2" by height plus an empty region "unused".
// Every cell face on the outer box is a boundary face in group "xmin" ... "zmax"; an empty
// group "unused_group" too. Not conforming between cubes of different kinds: for file tests.
HybridMesh mixed_grid(int n);

// "" when the two meshes have identical arrays and names, else the first array that differs.
// (HybridMesh's defaulted operator== is unusable while CellBlock and FaceBlock have none.)
std::string first_difference(const HybridMesh& a, const HybridMesh& b);

std::string read_text(const std::filesystem::path& path);
void write_text(const std::filesystem::path& path, const std::string& text);

// Number of entries in a directory.
int entry_count(const std::filesystem::path& dir);

}  // namespace tubemesh::testing
