#include "tests/support/sample_meshes.hpp"

#include <array>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh::testing {

namespace {

// Sign of the orientation of points a, b, c, d of m (the one tet_volume of vec3_ops).
double orient(const HybridMesh& m, index_t a, index_t b, index_t c, index_t d) {
    return tet_volume(m.point(a), m.point(b), m.point(c), m.point(d));
}

// Adds a tet with positive orientation whatever the order given.
void add_tet(HybridMesh& m, index_t a, index_t b, index_t c, index_t d, index_t region) {
    std::array<index_t, 4> t{a, b, c, d};
    if (orient(m, a, b, c, d) < 0) std::swap(t[0], t[1]);
    m.add_cell(CellKind::Tet, t, region);
}

// Adds a boundary triangle oriented away from `inside`.
void add_outward_tri(HybridMesh& m, index_t a, index_t b, index_t c, index_t inside, index_t group) {
    std::array<index_t, 3> f{a, b, c};
    if (orient(m, a, b, c, inside) > 0) std::swap(f[0], f[1]);
    m.add_face(FaceKind::Tri, f, group);
}

// Points 0-7 unit cube (VTK hex order), 8-11 the top of the upper cube (z = 2), 12 its centre.
HybridMesh two_cubes() {
    HybridMesh m;
    const double base[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (double z : {0.0, 1.0, 2.0})
        for (const auto& xy : base) m.add_point(xy[0], xy[1], z);
    m.add_point(0.5, 0.5, 1.5);
    const std::array<index_t, 8> hex{0, 1, 2, 3, 4, 5, 6, 7};
    m.add_cell(CellKind::Hex, hex, m.region_id("hex_ring"));
    const index_t sides = m.surface_group_id("hex_sides");
    // Hex faces other than the top (face 1 in the topology table), outward.
    for (int f : {0, 2, 3, 4, 5}) {
        std::array<index_t, 4> q{};
        for (int k = 0; k < 4; ++k) q[k] = hex[kHexTopology.face[f].node[k]];
        m.add_face(FaceKind::Quad, q, sides);
    }
    return m;
}

// The five faces of the upper cube other than its bottom, each as two triangles split along
// the diagonal from its first corner. The diagonals are those of the six tets around the
// cube diagonal 4-10, so both upper fillings below share this boundary.
constexpr std::array<std::array<index_t, 4>, 5> kUpperFaces = {
    {{8, 9, 10, 11}, {4, 5, 9, 8}, {5, 6, 10, 9}, {7, 11, 10, 6}, {4, 8, 11, 7}}};

void add_upper_boundary(HybridMesh& m, index_t inside) {
    const index_t g = m.surface_group_id("upper_sides");
    for (const auto& f : kUpperFaces) {
        add_outward_tri(m, f[0], f[1], f[2], inside, g);
        add_outward_tri(m, f[0], f[2], f[3], inside, g);
    }
}

}  // namespace

HybridMesh conforming_patch() {
    HybridMesh m = two_cubes();
    const std::array<index_t, 5> pyr{4, 5, 6, 7, 12};
    m.add_cell(CellKind::Pyramid, pyr, m.region_id("pyramids"));
    const index_t tets = m.region_id("tets");
    for (const auto& f : kUpperFaces) {
        add_tet(m, f[0], f[1], f[2], 12, tets);
        add_tet(m, f[0], f[2], f[3], 12, tets);
    }
    add_upper_boundary(m, 12);
    return m;
}

HybridMesh hex_facing_two_tets() {
    HybridMesh m = two_cubes();
    const index_t tets = m.region_id("tets");
    // Upper cube corners 4-7 (bottom) and 8-11 (top): six tets around the diagonal 4-10,
    // which splits the bottom quad 4-5-6-7 into triangles 4-5-6 and 4-6-7.
    const index_t ring[6] = {5, 6, 7, 11, 8, 9};
    for (int k = 0; k < 6; ++k) add_tet(m, 4, 10, ring[k], ring[(k + 1) % 6], tets);
    add_upper_boundary(m, 12);
    return m;
}

HybridMesh flipped_pyramid_patch() {
    HybridMesh m = conforming_patch();
    auto& pyr = m.block(CellKind::Pyramid).nodes;
    std::swap(pyr[1], pyr[3]);  // base 4-7-6-5: same orientation as the hex's top quad
    return m;
}

}  // namespace tubemesh::testing
