#pragma once
// The one mesh store of tubemesh: points and cells as struct-of-arrays.
//
// Points: x[] y[] z[]. Cells: one flat uint32 node array per kind (tet 4, pyramid 5, hex 8,
// VTK/Gmsh order, see topology.hpp) with a parallel region-id array. Boundary faces: triangles
// and quads with a group id each. Names of volume regions and surface groups live in two small
// tables; an id is an index into its table (so "physical tag" = id + 1 in Gmsh files).
#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/topology.hpp"
#include "engine/core/vec3.hpp"

namespace tubemesh {

// Cells of one kind: nodes[node_count(kind) * i + k] is local node k of cell i.
struct CellBlock {
    std::vector<index_t> nodes;
    std::vector<index_t> region;  // index into HybridMesh::region_names
    bool operator==(const CellBlock&) const = default;
};

// Surface groups named "joint_..." hold interior faces, where two volume groups meet (an
// assembly's shared faces), for a solver's contact or interface conditions; every other group
// holds boundary faces.
inline bool is_interface_group(std::string_view name) { return name.starts_with("joint_"); }

// Boundary faces of one kind; a face's normal (right-hand rule) points out of the domain (an
// interface group's face: either way).
struct FaceBlock {
    std::vector<index_t> nodes;
    std::vector<index_t> group;  // index into HybridMesh::surface_group_names
    bool operator==(const FaceBlock&) const = default;
};

class HybridMesh {
public:
    std::vector<double> x, y, z;
    std::array<CellBlock, kCellKindCount> cells;
    std::array<FaceBlock, kFaceKindCount> faces;
    std::vector<std::string> region_names;         // volume groups, e.g. "hex_ring", "tets"
    std::vector<std::string> surface_group_names;  // surface groups, e.g. "pipe_1", "face_3"

    index_t point_count() const { return static_cast<index_t>(x.size()); }
    index_t add_point(double px, double py, double pz);
    Vec3 point(index_t i) const { return {x[i], y[i], z[i]}; }

    CellBlock& block(CellKind k) { return cells[static_cast<int>(k)]; }
    const CellBlock& block(CellKind k) const { return cells[static_cast<int>(k)]; }
    FaceBlock& block(FaceKind k) { return faces[static_cast<int>(k)]; }
    const FaceBlock& block(FaceKind k) const { return faces[static_cast<int>(k)]; }

    index_t cell_count(CellKind k) const;
    index_t cell_count() const;
    index_t face_count(FaceKind k) const;
    std::span<const index_t> cell(CellKind k, index_t i) const;
    std::span<const index_t> face(FaceKind k, index_t i) const;

    // Appends a cell / boundary face; node count must match the kind. Returns its index.
    index_t add_cell(CellKind k, std::span<const index_t> nodes, index_t region);
    index_t add_face(FaceKind k, std::span<const index_t> nodes, index_t group);

    // Finds or creates a named group and returns its id.
    index_t region_id(const std::string& name);
    index_t surface_group_id(const std::string& name);

    // Throws tubemesh::Error when array sizes disagree, a node index is out of range or a
    // group id has no name: the invariants every reader and writer relies on.
    void validate_layout() const;

    void clear();
    bool operator==(const HybridMesh&) const = default;
};

}  // namespace tubemesh
