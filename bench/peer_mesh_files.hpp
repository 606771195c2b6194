#pragma once
// The files the peer meshers read and write, for the tet-step benchmark: the closed front as a
// TetGen .smesh and as a Gmsh MSH 2.2 surface, and TetGen's .node/.ele read back. (Gmsh's own
// output is MSH 4.1, which the engine's reader already reads: engine/io/mesh_io.hpp.)
#include <filesystem>
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh::bench {

// A closed triangulated surface on its own points: xyz has 3 coordinates per point, triangles
// 3 point indices (0-based) each.
struct ClosedFront {
    std::vector<double> xyz;
    std::vector<index_t> triangles;
};

// The front's mesh node ids renumbered 0..k-1 in order of first use, as the tet step does.
ClosedFront compact_front(const HybridMesh& mesh, std::span<const index_t> front);

// TetGen's piecewise linear complex: the points, then one 3-corner facet per triangle, no holes
// and no regions (TetGen finds the inside from the closed surface). 1-based, %.17g.
void write_smesh(const ClosedFront& front, const std::filesystem::path& path);

// One discrete surface (elementary tag 1, no physical group) of the triangles, ASCII.
void write_msh22_surface(const ClosedFront& front, const std::filesystem::path& path);

// TetGen's output mesh: its points and tets (region "tets") in a HybridMesh, node numbering
// shifted to 0-based whatever TetGen's first index was. Throws tubemesh::Error when a file is
// missing or malformed.
HybridMesh read_tetgen_mesh(const std::filesystem::path& node_file, const std::filesystem::path& ele_file);

}  // namespace tubemesh::bench
