#pragma once
// One constexpr table per cell kind: local faces (outward orientation) and local edges, in
// VTK/Gmsh node order. Every algorithm that needs faces or edges reads these tables.
//
// Orientation conventions (right-hand rule):
//   tet      0-1-2 counter-clockwise seen from 3       => orient3d(p0,p1,p2,p3) > 0
//   pyramid  base 0-1-2-3 counter-clockwise seen from apex 4
//   hex      bottom 0-1-2-3 counter-clockwise seen from the top face 4-5-6-7 (4 above 0)
// Every face listed below has its normal (right-hand rule) pointing out of the cell.
#include <array>
#include <cstdint>

namespace tubemesh {

enum class CellKind : std::uint8_t { Tet = 0, Pyramid = 1, Hex = 2 };
inline constexpr int kCellKindCount = 3;
inline constexpr std::array<CellKind, kCellKindCount> kAllCellKinds = {CellKind::Tet, CellKind::Pyramid,
                                                                      CellKind::Hex};

// Boundary faces are triangles or quads.
enum class FaceKind : std::uint8_t { Tri = 0, Quad = 1 };
inline constexpr int kFaceKindCount = 2;
constexpr int face_size(FaceKind k) { return k == FaceKind::Tri ? 3 : 4; }

struct LocalFace {
    std::uint8_t size;                 // 3 or 4
    std::array<std::uint8_t, 4> node;  // local node ids; node[3] unused for triangles
};

struct LocalEdge {
    std::uint8_t a, b;
};

struct CellTopology {
    const char* name;
    std::uint8_t node_count;
    std::uint8_t face_count;
    std::uint8_t edge_count;
    std::array<LocalFace, 6> face;  // first face_count entries used
    std::array<LocalEdge, 12> edge;  // first edge_count entries used
};

// Tet: face i is opposite node i, so "4*tet + i" names the face across from node i.
inline constexpr CellTopology kTetTopology{
    "tetrahedron", 4, 4, 6,
    {{{3, {1, 2, 3, 0}}, {3, {0, 3, 2, 0}}, {3, {0, 1, 3, 0}}, {3, {0, 2, 1, 0}}, {}, {}}},
    {{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}, {}, {}, {}, {}, {}, {}}}};

// Pyramid: face 0 is the quad base, faces 1-4 the triangles from base edge k to the apex.
inline constexpr CellTopology kPyramidTopology{
    "pyramid", 5, 5, 8,
    {{{4, {0, 3, 2, 1}}, {3, {0, 1, 4, 0}}, {3, {1, 2, 4, 0}}, {3, {2, 3, 4, 0}}, {3, {3, 0, 4, 0}}, {}}},
    {{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}, {}, {}, {}, {}}}};

// Hex: bottom, top, then the four sides starting at edge 0-1.
inline constexpr CellTopology kHexTopology{
    "hexahedron", 8, 6, 12,
    {{{4, {0, 3, 2, 1}},
      {4, {4, 5, 6, 7}},
      {4, {0, 1, 5, 4}},
      {4, {1, 2, 6, 5}},
      {4, {2, 3, 7, 6}},
      {4, {3, 0, 4, 7}}}},
    {{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}}};

constexpr const CellTopology& topology(CellKind k) {
    return k == CellKind::Tet ? kTetTopology : k == CellKind::Pyramid ? kPyramidTopology : kHexTopology;
}

constexpr int node_count(CellKind k) { return topology(k).node_count; }

}  // namespace tubemesh
