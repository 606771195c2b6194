#pragma once
// Abaqus face numbers (S1, S2, ...) of the local faces in topology.hpp.
//
// Abaqus numbers element faces by their corner nodes (Abaqus manual, solid element library;
// 1-based node numbers, and the Abaqus node orders of C3D4, C3D5 and C3D8 are the VTK ones):
//   C3D4  S1 1-2-3    S2 1-4-2    S3 2-4-3    S4 3-4-1
//   C3D5  S1 1-2-3-4  S2 1-5-2    S3 2-5-3    S4 3-5-4    S5 4-5-1
//   C3D8  S1 1-2-3-4  S2 5-8-7-6  S3 1-5-6-2  S4 2-6-7-3  S5 3-7-8-4  S6 4-8-5-1
// A pyramid written as a C3D8 with the apex repeated (1 2 3 4 5 5 5 5) keeps the brick's
// numbers: S1 the base, S2 collapsed to the apex, S3 1-5-2, S4 2-5-3, S5 3-5-4, S6 4-5-1.
// The mapping is derived from these node sets at compile time rather than typed in, so it
// stays right if the topology tables are ever reordered. Result for the current tables:
//   tet      local face 0 1 2 3    -> S3 S4 S2 S1
//   pyramid  local face 0 1 2 3 4  -> S1 S2 S3 S4 S5 (C3D5), S1 S3 S4 S5 S6 (collapsed C3D8)
//   hex      local face 0 ... 5    -> S1 ... S6
#include <array>
#include <cstdint>

#include "engine/mesh/topology.hpp"

namespace tubemesh::io {

struct AbaqusFace {
    std::uint8_t size;
    std::array<std::uint8_t, 4> node;  // 1-based, as in the manual
};

inline constexpr std::array<AbaqusFace, 4> kAbaqusTetFaces = {
    {{3, {1, 2, 3, 0}}, {3, {1, 4, 2, 0}}, {3, {2, 4, 3, 0}}, {3, {3, 4, 1, 0}}}};
inline constexpr std::array<AbaqusFace, 5> kAbaqusPyramidFaces = {
    {{4, {1, 2, 3, 4}}, {3, {1, 5, 2, 0}}, {3, {2, 5, 3, 0}}, {3, {3, 5, 4, 0}}, {3, {4, 5, 1, 0}}}};
// S2 is a single node: no pyramid face matches it.
inline constexpr std::array<AbaqusFace, 6> kAbaqusCollapsedPyramidFaces = {
    {{4, {1, 2, 3, 4}}, {1, {5, 0, 0, 0}}, {3, {1, 5, 2, 0}}, {3, {2, 5, 3, 0}}, {3, {3, 5, 4, 0}}, {3, {4, 5, 1, 0}}}};
inline constexpr std::array<AbaqusFace, 6> kAbaqusHexFaces = {{{4, {1, 2, 3, 4}},
                                                                {4, {5, 8, 7, 6}},
                                                                {4, {1, 5, 6, 2}},
                                                                {4, {2, 6, 7, 3}},
                                                                {4, {3, 7, 8, 4}},
                                                                {4, {4, 8, 5, 1}}}};

namespace detail {

// Local nodes of a face as a bit set, 0-based.
constexpr unsigned node_set(const LocalFace& f) {
    unsigned s = 0;
    for (int k = 0; k < f.size; ++k) s |= 1u << f.node[k];
    return s;
}
constexpr unsigned node_set(const AbaqusFace& f) {
    unsigned s = 0;
    for (int k = 0; k < f.size; ++k) s |= 1u << (f.node[k] - 1);
    return s;
}

template <std::size_t N>
constexpr int find_face(const std::array<AbaqusFace, N>& faces, const LocalFace& f) {
    for (std::size_t i = 0; i < N; ++i)
        if (node_set(faces[i]) == node_set(f)) return static_cast<int>(i) + 1;
    return 0;
}

}  // namespace detail

// Abaqus face number (1 for S1, ...) of local face `local` of a cell of kind k; 0 if none.
// `collapsed_pyramid`: pyramids are written as collapsed C3D8.
constexpr int abaqus_face_number(CellKind k, int local, bool collapsed_pyramid = false) {
    const LocalFace& f = topology(k).face[local];
    switch (k) {
        case CellKind::Tet: return detail::find_face(kAbaqusTetFaces, f);
        case CellKind::Pyramid:
            return collapsed_pyramid ? detail::find_face(kAbaqusCollapsedPyramidFaces, f)
                                     : detail::find_face(kAbaqusPyramidFaces, f);
        case CellKind::Hex: return detail::find_face(kAbaqusHexFaces, f);
    }
    return 0;
}

// Every local face has an Abaqus number, and no two share one.
constexpr bool abaqus_faces_are_a_bijection(CellKind k, bool collapsed_pyramid = false) {
    unsigned seen = 0;
    for (int i = 0; i < topology(k).face_count; ++i) {
        const int s = abaqus_face_number(k, i, collapsed_pyramid);
        if (s == 0 || (seen & (1u << s)) != 0) return false;
        seen |= 1u << s;
    }
    return true;
}
static_assert(abaqus_faces_are_a_bijection(CellKind::Tet));
static_assert(abaqus_faces_are_a_bijection(CellKind::Pyramid));
static_assert(abaqus_faces_are_a_bijection(CellKind::Pyramid, true));
static_assert(abaqus_faces_are_a_bijection(CellKind::Hex));

}  // namespace tubemesh::io
