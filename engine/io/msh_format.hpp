#pragma once
// Gmsh MSH 4.1 facts shared by the writer and the reader.
//
// How a HybridMesh maps onto the file (the reader relies on it for exact round trips):
// - Volume region r is volume entity r + 1 carrying physical tag r + 1 (dimension 3), named
//   in $PhysicalNames; surface group g is surface entity g + 1 with physical tag g + 1
//   (dimension 2). A mesh without regions still gets volume entity 1, without a physical tag.
// - Node i has tag i + 1. All nodes sit in one block on volume entity 1: Gmsh finds nodes by
//   tag, so their classification does not matter to it.
// - Element tags number tets, then pyramids, hexes, boundary triangles, boundary quads, each
//   kind in mesh order. A kind's elements are spread over one block per region or group, and
//   sorting them by tag restores the mesh order.
// - Node orders of these five types are the same in Gmsh and VTK, so nothing is permuted.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "engine/mesh/topology.hpp"

namespace tubemesh::io {

// Gmsh element type numbers.
inline constexpr int kMshTriangle = 2;
inline constexpr int kMshQuad = 3;
inline constexpr int kMshTet = 4;
inline constexpr int kMshHex = 5;
inline constexpr int kMshPyramid = 7;

constexpr int msh_type(CellKind k) {
    return k == CellKind::Tet ? kMshTet : k == CellKind::Pyramid ? kMshPyramid : kMshHex;
}
constexpr int msh_type(FaceKind k) { return k == FaceKind::Tri ? kMshTriangle : kMshQuad; }

// The five supported types as one index: cell kinds 0-2, then face kinds 3-4 (tag order).
inline constexpr int kMshKindCount = kCellKindCount + kFaceKindCount;
constexpr int msh_kind_index(CellKind k) { return static_cast<int>(k); }
constexpr int msh_kind_index(FaceKind k) { return kCellKindCount + static_cast<int>(k); }

struct MshKind {
    int index;       // msh_kind_index
    int dimension;   // 3 for cells, 2 for boundary faces
    int node_count;
};

constexpr std::optional<MshKind> msh_kind_of_type(int type) {
    switch (type) {
        case kMshTet: return MshKind{msh_kind_index(CellKind::Tet), 3, 4};
        case kMshPyramid: return MshKind{msh_kind_index(CellKind::Pyramid), 3, 5};
        case kMshHex: return MshKind{msh_kind_index(CellKind::Hex), 3, 8};
        case kMshTriangle: return MshKind{msh_kind_index(FaceKind::Tri), 2, 3};
        case kMshQuad: return MshKind{msh_kind_index(FaceKind::Quad), 2, 4};
        default: return std::nullopt;
    }
}

// Names of the common Gmsh types tubemesh does not read, for error messages.
constexpr std::string_view msh_type_name(int type) {
    switch (type) {
        case 1: return "2-node line";
        case 2: return "3-node triangle";
        case 3: return "4-node quadrangle";
        case 4: return "4-node tetrahedron";
        case 5: return "8-node hexahedron";
        case 6: return "6-node prism";
        case 7: return "5-node pyramid";
        case 8: return "3-node second order line";
        case 9: return "6-node second order triangle";
        case 10: return "9-node second order quadrangle";
        case 11: return "10-node second order tetrahedron";
        case 12: return "27-node second order hexahedron";
        case 13: return "18-node second order prism";
        case 14: return "14-node second order pyramid";
        case 15: return "1-node point";
        case 16: return "8-node second order quadrangle";
        case 17: return "20-node second order hexahedron";
        case 18: return "15-node second order prism";
        case 19: return "13-node second order pyramid";
        default: return "element";
    }
}

// Gmsh keeps physical names to this length (MSH 4.1 specification).
inline constexpr std::size_t kMshMaxNameLength = 127;

}  // namespace tubemesh::io
