#pragma once
// Mesh files: Gmsh MSH 4.1 (ASCII and binary, read and write), VTK XML .vtu and Abaqus .inp
// (write). Writers go through a temporary file and rename it, so a failure never leaves a
// partial mesh behind. Readers throw tubemesh::Error naming the line or byte offset.
#include <filesystem>

#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh {

enum class MshEncoding { Ascii, Binary };

void write_msh(const HybridMesh& mesh, const std::filesystem::path& path, MshEncoding encoding = MshEncoding::Binary);
HybridMesh read_msh(const std::filesystem::path& path);

void write_vtu(const HybridMesh& mesh, const std::filesystem::path& path);
void write_inp(const HybridMesh& mesh, const std::filesystem::path& path);

// By extension: .msh (binary), .vtu, .inp. Any other extension is an Error.
void write_mesh(const HybridMesh& mesh, const std::filesystem::path& path);

}  // namespace tubemesh
