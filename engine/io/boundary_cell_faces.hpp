#pragma once
// Which cell face carries each boundary face. Element-based surfaces (Abaqus *SURFACE) name
// boundary faces as "element, face number", so the writer needs the owning cell.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh::io {

struct CellFaceRef {
    CellKind kind;
    index_t cell;              // kNoIndex: no cell has this face
    std::uint8_t local_face;   // index into topology(kind).face
};

// For every boundary face, per face kind in mesh order, the cell face with the same nodes.
// In a conforming mesh exactly one cell has it; if several do, the first in kind and cell
// order is taken. Needs a valid layout (validate_layout()).
std::array<std::vector<CellFaceRef>, kFaceKindCount> boundary_cell_faces(const HybridMesh& mesh);

// The same for the boundary faces of `groups` alone, taken from the cells of `region`: an
// interior face (an assembly's joint) from that region's side. kNoIndex for every other face.
std::array<std::vector<CellFaceRef>, kFaceKindCount> region_cell_faces(const HybridMesh& mesh, index_t region,
                                                                        std::span<const index_t> groups);

}  // namespace tubemesh::io
