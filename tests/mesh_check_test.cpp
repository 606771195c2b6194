// The conformity check: hand-made patches with one defect each, single cells with known
// volumes, and randomly jittered structured grids (tets and hexes) whose volume and boundary
// area are those of their box.
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <random>
#include <vector>

#include "engine/core/timing.hpp"
#include "engine/check/mesh_check.hpp"
#include "tests/support/sample_meshes.hpp"

namespace {

using tubemesh::CellKind;
using tubemesh::Clock;
using tubemesh::seconds_since;
using tubemesh::check_mesh;
using tubemesh::CheckReport;
using tubemesh::ElementRef;
using tubemesh::FaceKind;
using tubemesh::HybridMesh;
using tubemesh::index_t;
using tubemesh::Vec3;
using tubemesh::ViolationKind;
using Set = ElementRef::Set;

double orient(const HybridMesh& m, index_t a, index_t b, index_t c, index_t d) {
    const Vec3 pa = m.point(a), pb = m.point(b), pc = m.point(c), pd = m.point(d);
    const double ux = pb.x - pa.x, uy = pb.y - pa.y, uz = pb.z - pa.z;
    const double vx = pc.x - pa.x, vy = pc.y - pa.y, vz = pc.z - pa.z;
    const double wx = pd.x - pa.x, wy = pd.y - pa.y, wz = pd.z - pa.z;
    return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}

void add_positive_tet(HybridMesh& m, std::array<index_t, 4> t) {
    if (orient(m, t[0], t[1], t[2], t[3]) < 0) std::swap(t[0], t[1]);
    m.add_cell(CellKind::Tet, t, 0);
}

// The violation kinds of a report, in report order.
std::vector<ViolationKind> kinds(const CheckReport& r) {
    std::vector<ViolationKind> out;
    for (const auto& v : r.violations) out.push_back(v.kind);
    return out;
}

bool names(const CheckReport& r, ViolationKind kind, ElementRef ref) {
    const auto* v = r.find(kind);
    return v != nullptr && std::find(v->first.begin(), v->first.end(), ref) != v->first.end();
}

HybridMesh single_cell(CellKind kind, const std::vector<Vec3>& pts) {
    HybridMesh m;
    m.region_id("cells");
    std::vector<index_t> nodes;
    for (const Vec3& p : pts) nodes.push_back(m.add_point(p.x, p.y, p.z));
    m.add_cell(kind, nodes, 0);
    return m;
}

const std::vector<Vec3> kUnitHex = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

// ----------------------------------------------------------------------------------------------
// A structured grid over a random box: random grid lines per axis, interior nodes jittered by up
// to 5 % of the smallest spacing (boundary nodes stay on the box, so volume and area are exact).

struct Grid {
    int n;
    std::array<std::vector<double>, 3> lines;
    HybridMesh mesh;
    index_t node(int i, int j, int k) const { return static_cast<index_t>((k * (n + 1) + j) * (n + 1) + i); }
    double volume() const {
        return (lines[0].back() - lines[0][0]) * (lines[1].back() - lines[1][0]) * (lines[2].back() - lines[2][0]);
    }
    double area() const {
        const double a = lines[0].back() - lines[0][0], b = lines[1].back() - lines[1][0],
                     c = lines[2].back() - lines[2][0];
        return 2 * (a * b + b * c + c * a);
    }
    // Node of corner `bits` (bit 0 x, bit 1 y, bit 2 z) of cube (i, j, k).
    index_t corner(int i, int j, int k, int bits) const {
        return node(i + (bits & 1), j + ((bits >> 1) & 1), k + ((bits >> 2) & 1));
    }
};

Grid random_grid_points(int n, unsigned seed) {
    Grid g{n, {}, {}};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> step(0.5, 1.5), unit(-1, 1);
    double h_min = 1e9;
    for (auto& l : g.lines) {
        l.push_back(unit(rng));
        for (int i = 0; i < n; ++i) {
            l.push_back(l.back() + step(rng) / n);
            h_min = std::min(h_min, l.back() - l[l.size() - 2]);
        }
    }
    const double jitter = 0.05 * h_min;
    g.mesh.region_id("cells");
    g.mesh.surface_group_id("box");
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const bool inside = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
                const auto shake = [&] { return inside ? jitter * unit(rng) : 0.0; };
                const double x = g.lines[0][i] + shake(), y = g.lines[1][j] + shake(), z = g.lines[2][k] + shake();
                g.mesh.add_point(x, y, z);
            }
    return g;
}

// Calls fn(i, j, k, axis, side) for every cube face on the box.
template <class Fn>
void for_each_box_face(int n, Fn fn) {
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::array<int, 3> c{i, j, k};
                for (int axis = 0; axis < 3; ++axis) {
                    if (c[axis] == 0) fn(i, j, k, axis, 0);
                    if (c[axis] == n - 1) fn(i, j, k, axis, 1);
                }
            }
}

// The four corners (bits) of a cube face, in a cycle.
std::array<int, 4> face_corners(int axis, int side) {
    const int a = 1 << ((axis + 1) % 3), b = 1 << ((axis + 2) % 3), s = side << axis;
    return {s, s | a, s | a | b, s | b};
}

// Kuhn split: six tets around the cube diagonal from corner 0 to corner 7, so every cube face is
// cut along the diagonal through corner 0 or corner 7 and neighbouring cubes conform.
Grid kuhn_tet_grid(int n, unsigned seed) {
    Grid g = random_grid_points(n, seed);
    constexpr std::array<std::array<int, 2>, 6> kPaths = {{{0, 1}, {0, 2}, {1, 0}, {1, 2}, {2, 0}, {2, 1}}};
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (const auto& p : kPaths) {
                    const int b1 = 1 << p[0], b2 = b1 | (1 << p[1]);
                    add_positive_tet(g.mesh, {g.corner(i, j, k, 0), g.corner(i, j, k, b1), g.corner(i, j, k, b2),
                                              g.corner(i, j, k, 7)});
                }
    for_each_box_face(n, [&](int i, int j, int k, int axis, int side) {
        const auto q = face_corners(axis, side);
        // Rotate so the face's Kuhn diagonal is q[0]-q[2]: corner 0 or 7, whichever is on it.
        const int start = side == 0 ? 0 : 2;  // face_corners puts corner 0 / corner 7 there
        std::array<index_t, 4> c{};
        for (int t = 0; t < 4; ++t) c[t] = g.corner(i, j, k, q[(start + t) % 4]);
        // face_corners runs counter-clockwise seen from +axis: outward on side 1.
        if (side == 0) std::swap(c[1], c[3]);
        g.mesh.add_face(FaceKind::Tri, std::array<index_t, 3>{c[0], c[1], c[2]}, 0);
        g.mesh.add_face(FaceKind::Tri, std::array<index_t, 3>{c[0], c[2], c[3]}, 0);
    });
    return g;
}

Grid hex_grid(int n, unsigned seed) {
    Grid g = random_grid_points(n, seed);
    constexpr std::array<int, 8> kVtkCorners = {0, 1, 3, 2, 4, 5, 7, 6};
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                std::array<index_t, 8> h{};
                for (int c = 0; c < 8; ++c) h[c] = g.corner(i, j, k, kVtkCorners[c]);
                g.mesh.add_cell(CellKind::Hex, h, 0);
            }
    for_each_box_face(n, [&](int i, int j, int k, int axis, int side) {
        const auto q = face_corners(axis, side);
        std::array<index_t, 4> c{};
        for (int t = 0; t < 4; ++t) c[t] = g.corner(i, j, k, q[t]);
        if (side == 0) std::swap(c[1], c[3]);
        g.mesh.add_face(FaceKind::Quad, c, 0);
    });
    return g;
}

// ----------------------------------------------------------------------------------------------
// The shared fixtures.

TEST(MeshCheck, ConformingPatchPasses) {
    const CheckReport r = check_mesh(tubemesh::testing::conforming_patch());
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_EQ(describe(r), "");
    // Two unit cubes; boundary: 5 faces of the lower one (hex quads), 5 of the upper one (tets).
    EXPECT_NEAR(r.volume, 2.0, 1e-14);
    EXPECT_NEAR(r.boundary_area, 10.0, 1e-14);
    // 51 cell faces (6 + 5 + 40): hex|pyramid 1, pyramid|tet 4, the two tets of each upper face 5,
    // tets across the 8 upper-cube edges off the pyramid 8; 5 quads and 10 triangles free.
    EXPECT_EQ(r.interior_faces, 18u);
    EXPECT_EQ(r.boundary_faces, 15u);
}

TEST(MeshCheck, HexFacingTwoTetsIsNonMatching) {
    const CheckReport r = check_mesh(tubemesh::testing::hex_facing_two_tets());
    // The mismatched faces are not boundary, so the rest of the boundary is still closed.
    ASSERT_EQ(kinds(r), std::vector<ViolationKind>{ViolationKind::NonMatchingFace}) << describe(r);
    const auto& v = *r.find(ViolationKind::NonMatchingFace);
    EXPECT_EQ(v.count, 3u);
    EXPECT_EQ(v.first, (std::vector<ElementRef>{{Set::Tet, 0}, {Set::Tet, 1}, {Set::Hex, 0}}));
    EXPECT_NEAR(r.volume, 2.0, 1e-14);
    EXPECT_NEAR(r.boundary_area, 10.0, 1e-14);
}

TEST(MeshCheck, FlippedPyramidIsInvertedAndSameOriented) {
    const CheckReport r = check_mesh(tubemesh::testing::flipped_pyramid_patch());
    EXPECT_TRUE(names(r, ViolationKind::NonPositiveVolume, {Set::Pyramid, 0})) << describe(r);
    EXPECT_EQ(r.find(ViolationKind::NonPositiveVolume)->count, 1u);
    EXPECT_TRUE(names(r, ViolationKind::SameOrientation, {Set::Pyramid, 0}));
    EXPECT_TRUE(names(r, ViolationKind::SameOrientation, {Set::Hex, 0}));
    EXPECT_EQ(describe(r).rfind("NonPositiveVolume: 1 (pyramid 0)\n", 0), 0u) << describe(r);
}

// ----------------------------------------------------------------------------------------------
// One defect each.

TEST(MeshCheck, FaceOnThreeCells) {
    HybridMesh m = tubemesh::testing::conforming_patch();
    // Triangle 4-5-12 lies between the pyramid and a tet; a third cell below it (outside the hex,
    // whose side is at y = 0) makes it a face of three cells.
    const index_t p = m.add_point(0.5, -0.5, 1.2);
    add_positive_tet(m, {4, 5, 12, p});
    const index_t extra = m.cell_count(CellKind::Tet) - 1;
    const CheckReport r = check_mesh(m);
    const auto* v = r.find(ViolationKind::FaceSharedByMany);
    ASSERT_NE(v, nullptr) << describe(r);
    EXPECT_EQ(v->count, 3u);
    EXPECT_TRUE(names(r, ViolationKind::FaceSharedByMany, {Set::Pyramid, 0}));
    EXPECT_TRUE(names(r, ViolationKind::FaceSharedByMany, {Set::Tet, extra}));
}

// Two cubes of six tets side by side whose shared square is cut along different diagonals: the
// four triangles there are all free, and the square's sides carry four free faces each.
TEST(MeshCheck, CrossedDiagonalsLeaveAnOpenBoundary) {
    HybridMesh m;
    m.region_id("tets");
    std::array<index_t, 12> id{};  // x in {0,1,2}, y and z in {0,1}: id[x + 3*(y + 2*z)]
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) id[x + 3 * (y + 2 * z)] = m.add_point(x, y, z);
    const auto at = [&](int x, int y, int z) { return id[x + 3 * (y + 2 * z)]; };
    // Cube [0,1]: tets around its diagonal (0,0,0)-(1,1,1), so x = 1 is cut along (1,0,0)-(1,1,1).
    // Cube [1,2]: around (1,0,1)-(2,1,0), so x = 1 is cut along (1,0,1)-(1,1,0).
    const std::array<std::array<int, 3>, 2> start = {{{0, 0, 0}, {1, 0, 1}}}, dir = {{{1, 1, 1}, {1, 1, -1}}};
    constexpr std::array<std::array<int, 2>, 6> kPaths = {{{0, 1}, {0, 2}, {1, 0}, {1, 2}, {2, 0}, {2, 1}}};
    for (int c = 0; c < 2; ++c)
        for (const auto& p : kPaths) {
            std::array<int, 3> a = start[c];
            a[p[0]] += dir[c][p[0]];
            std::array<int, 3> b = a;
            b[p[1]] += dir[c][p[1]];
            const std::array<int, 3> e{start[c][0] + dir[c][0], start[c][1] + dir[c][1], start[c][2] + dir[c][2]};
            add_positive_tet(m, {at(start[c][0], start[c][1], start[c][2]), at(a[0], a[1], a[2]),
                                 at(b[0], b[1], b[2]), at(e[0], e[1], e[2])});
        }
    const CheckReport r = check_mesh(m);
    ASSERT_EQ(kinds(r), std::vector<ViolationKind>{ViolationKind::OpenBoundary}) << describe(r);
    EXPECT_NEAR(r.volume, 2.0, 1e-14);
}

// Taking cells away leaves the free faces closed (the hole's walls are free faces), so it is
// the stored boundary faces of the removed cell that no longer lie on a cell.
TEST(MeshCheck, RemovedTetLeavesItsStoredFaceBehind) {
    HybridMesh m = tubemesh::testing::conforming_patch();
    auto& tets = m.block(CellKind::Tet);
    tets.nodes.erase(tets.nodes.begin(), tets.nodes.begin() + 4);  // tet 0: top triangle 8-9-10
    tets.region.erase(tets.region.begin());
    const CheckReport r = check_mesh(m);
    ASSERT_EQ(kinds(r), std::vector<ViolationKind>{ViolationKind::BoundaryFaceNotOnCell}) << describe(r);
    EXPECT_EQ(r.find(ViolationKind::BoundaryFaceNotOnCell)->first, (std::vector<ElementRef>{{Set::BoundaryTri, 0}}));
    EXPECT_NEAR(r.volume, 2.0 - 1.0 / 12, 1e-14);
}

TEST(MeshCheck, StoredFaceInsideOrReversedIsNotOnCell) {
    HybridMesh m = tubemesh::testing::conforming_patch();
    auto& tris = m.block(FaceKind::Tri).nodes;
    std::swap(tris[0], tris[1]);                                            // reversed
    m.add_face(FaceKind::Tri, std::array<index_t, 3>{4, 5, 12}, 0);         // interior
    m.add_face(FaceKind::Quad, std::array<index_t, 4>{4, 5, 6, 7}, 0);      // interior quad
    m.add_face(FaceKind::Tri, std::array<index_t, 3>{0, 0, 1}, 0);          // repeats a node
    const CheckReport r = check_mesh(m);
    ASSERT_EQ(kinds(r), std::vector<ViolationKind>{ViolationKind::BoundaryFaceNotOnCell}) << describe(r);
    EXPECT_EQ(r.find(ViolationKind::BoundaryFaceNotOnCell)->first,
              (std::vector<ElementRef>{{Set::BoundaryTri, 0}, {Set::BoundaryTri, 10}, {Set::BoundaryTri, 11},
                                       {Set::BoundaryQuad, 5}}));
}

TEST(MeshCheck, InterfaceGroupHoldsInteriorFacesOnly) {
    // "joint_..." groups (an assembly's shared faces) hold interior faces, either way round.
    HybridMesh m = tubemesh::testing::conforming_patch();
    const index_t joint = m.surface_group_id("joint_a_b");
    const index_t first_new = m.face_count(FaceKind::Tri);
    m.add_face(FaceKind::Tri, std::array<index_t, 3>{4, 5, 12}, joint);
    m.add_face(FaceKind::Tri, std::array<index_t, 3>{5, 4, 12}, joint);
    m.add_face(FaceKind::Quad, std::array<index_t, 4>{4, 5, 6, 7}, joint);
    EXPECT_TRUE(check_mesh(m).ok()) << describe(check_mesh(m));
    const std::span<const index_t> boundary = m.face(FaceKind::Tri, 0);
    m.add_face(FaceKind::Tri, std::array<index_t, 3>{boundary[0], boundary[1], boundary[2]}, joint);
    const CheckReport r = check_mesh(m);
    ASSERT_EQ(kinds(r), std::vector<ViolationKind>{ViolationKind::BoundaryFaceNotOnCell}) << describe(r);
    EXPECT_EQ(r.find(ViolationKind::BoundaryFaceNotOnCell)->first,
              (std::vector<ElementRef>{{Set::BoundaryTri, first_new + 2}}));
}

TEST(MeshCheck, RemovedStoredFaceIsAllowed) {
    // Stored faces are groups for the solver; they need not cover the whole boundary.
    HybridMesh m = tubemesh::testing::conforming_patch();
    m.block(FaceKind::Tri).nodes.resize(3 * 9);
    m.block(FaceKind::Tri).group.resize(9);
    EXPECT_TRUE(check_mesh(m).ok());
}

TEST(MeshCheck, InvertedTetInPatch) {
    HybridMesh m = tubemesh::testing::conforming_patch();
    auto& tets = m.block(CellKind::Tet).nodes;
    std::swap(tets[4 * 3], tets[4 * 3 + 1]);
    const CheckReport r = check_mesh(m);
    EXPECT_EQ(r.find(ViolationKind::NonPositiveVolume)->first, (std::vector<ElementRef>{{Set::Tet, 3}}))
        << describe(r);
    EXPECT_TRUE(names(r, ViolationKind::SameOrientation, {Set::Tet, 3}));
}

TEST(MeshCheck, InvertedHexInPatch) {
    HybridMesh m = tubemesh::testing::conforming_patch();
    auto& hex = m.block(CellKind::Hex).nodes;
    std::swap_ranges(hex.begin(), hex.begin() + 4, hex.begin() + 4);  // top and bottom exchanged
    const CheckReport r = check_mesh(m);
    EXPECT_EQ(r.find(ViolationKind::NonPositiveVolume)->first, (std::vector<ElementRef>{{Set::Hex, 0}}))
        << describe(r);
    EXPECT_TRUE(names(r, ViolationKind::BoundaryFaceNotOnCell, {Set::BoundaryQuad, 0}));
    EXPECT_NEAR(r.volume, 0.0, 1e-14);  // -1 (hex) + 1 (pyramid and tets)
}

TEST(MeshCheck, HexWithOneBadCorner) {
    std::vector<Vec3> p = kUnitHex;
    p[6] = {0.3, 0.3, 0.3};  // pulled deep into the cell: the Jacobian at corner 6 turns negative
    const CheckReport r = check_mesh(single_cell(CellKind::Hex, p));
    ASSERT_EQ(kinds(r), std::vector<ViolationKind>{ViolationKind::NonPositiveVolume}) << describe(r);
}

TEST(MeshCheck, FlatAndDegenerateCells) {
    const CheckReport flat = check_mesh(single_cell(CellKind::Tet, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}));
    EXPECT_EQ(kinds(flat), std::vector<ViolationKind>{ViolationKind::NonPositiveVolume}) << describe(flat);
    EXPECT_EQ(flat.volume, 0.0);

    HybridMesh m = single_cell(CellKind::Hex, kUnitHex);
    auto& hex = m.block(CellKind::Hex).nodes;
    hex[6] = hex[7];  // a collapsed edge: a wedge written as a hex
    const CheckReport r = check_mesh(m);
    ASSERT_EQ(kinds(r), std::vector<ViolationKind>{ViolationKind::DegenerateCell}) << describe(r);
    EXPECT_EQ(r.find(ViolationKind::DegenerateCell)->first, (std::vector<ElementRef>{{Set::Hex, 0}}));
    EXPECT_NEAR(r.volume, 0.75, 1e-15);  // still a volume: the trilinear image, det J = 1 - v w
    EXPECT_EQ(r.boundary_faces, 0u);    // and no faces: it takes no part in matching
}

TEST(MeshCheck, BrokenLayoutThrows) {
    HybridMesh m = tubemesh::testing::conforming_patch();
    m.block(CellKind::Tet).nodes[0] = 99;
    EXPECT_THROW(check_mesh(m), tubemesh::Error);
}

// ----------------------------------------------------------------------------------------------
// Volumes of single cells.

TEST(MeshCheck, SingleCellVolumes) {
    EXPECT_NEAR(check_mesh(single_cell(CellKind::Tet, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}})).volume, 1.0 / 6,
                1e-16);
    const CheckReport pyr = check_mesh(single_cell(CellKind::Pyramid, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                                       {0.5, 0.5, 1}}));
    EXPECT_TRUE(pyr.ok()) << describe(pyr);
    EXPECT_NEAR(pyr.volume, 1.0 / 3, 1e-16);
    EXPECT_NEAR(pyr.boundary_area, 1 + 4 * 0.5 * std::sqrt(1.25), 1e-15);
    const CheckReport hex = check_mesh(single_cell(CellKind::Hex, kUnitHex));
    EXPECT_TRUE(hex.ok()) << describe(hex);
    EXPECT_NEAR(hex.volume, 1.0, 1e-15);
    EXPECT_NEAR(hex.boundary_area, 6.0, 1e-15);
}

TEST(MeshCheck, NonPlanarCellsUseBilinearFaces) {
    // Trilinear hex with z = w (1 + t u v): det J = 1 + t u v, volume 1 + t / 4.
    const double t = 0.3;
    std::vector<Vec3> h = kUnitHex;
    h[6].z += t;
    EXPECT_NEAR(check_mesh(single_cell(CellKind::Hex, h)).volume, 1 + t / 4, 1e-15);
    // Pyramid over a twisted base: the cone over the bilinear base, the mean of both splits.
    const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.4}, {0, 1, 0}, {0.5, 0.5, 1}};
    const HybridMesh m = single_cell(CellKind::Pyramid, p);
    const double split02 = orient(m, 0, 1, 2, 4) + orient(m, 0, 2, 3, 4);
    const double split13 = orient(m, 0, 1, 3, 4) + orient(m, 1, 2, 3, 4);
    EXPECT_NEAR(check_mesh(m).volume, (split02 + split13) / 12, 1e-15);
}

// ----------------------------------------------------------------------------------------------
// Random grids.

TEST(MeshCheck, RandomKuhnTetGridPasses) {
    const Grid g = kuhn_tet_grid(20, 7);
    ASSERT_EQ(g.mesh.cell_count(CellKind::Tet), 48000u);
    const CheckReport r = check_mesh(g.mesh);
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_NEAR(r.volume, g.volume(), 1e-12 * g.volume());
    EXPECT_NEAR(r.boundary_area, g.area(), 1e-12 * g.area());
    EXPECT_EQ(r.boundary_faces, 6u * 20 * 20 * 2);
    EXPECT_EQ(r.interior_faces, (4u * 48000 - r.boundary_faces) / 2);
}

TEST(MeshCheck, RandomHexGridWithWarpedFacesPasses) {
    // Jittered interior nodes make every interior quad non-planar; shared bilinear faces cancel,
    // so the cells still add up to the box.
    const Grid g = hex_grid(12, 11);
    const CheckReport r = check_mesh(g.mesh);
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_NEAR(r.volume, g.volume(), 1e-12 * g.volume());
    EXPECT_NEAR(r.boundary_area, g.area(), 1e-12 * g.area());
}

TEST(MeshCheck, ReportDoesNotDependOnThreadCount) {
    Grid g = kuhn_tet_grid(20, 3);
    // Scatter defects over the whole mesh so that every phase reports from many chunks.
    auto& tets = g.mesh.block(CellKind::Tet).nodes;
    for (std::size_t t = 5; t < 48000; t += 997) std::swap(tets[4 * t], tets[4 * t + 1]);
    for (std::size_t t = 11; t < 48000; t += 1999) tets[4 * t + 3] = tets[4 * t];
    auto& tris = g.mesh.block(FaceKind::Tri).nodes;
    for (std::size_t f = 3; f < tris.size() / 3; f += 101) std::swap(tris[3 * f], tris[3 * f + 1]);
    CheckReport one, two;
    {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
        one = check_mesh(g.mesh);
    }
    {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
        two = check_mesh(g.mesh);
    }
    EXPECT_FALSE(one.ok());
    for (ViolationKind k : {ViolationKind::NonPositiveVolume, ViolationKind::DegenerateCell,
                            ViolationKind::SameOrientation, ViolationKind::BoundaryFaceNotOnCell}) {
        ASSERT_NE(one.find(k), nullptr) << tubemesh::violation_name(k) << "\n" << describe(one);
        EXPECT_EQ(one.find(k)->first.size(), 10u);
    }
    EXPECT_TRUE(one == two) << describe(one) << "\n---\n" << describe(two);
    EXPECT_EQ(std::memcmp(&one.volume, &two.volume, sizeof(double)), 0);
}

// Timing on 5 M cells, with one thread and with all; run with --gtest_also_run_disabled_tests.
void time_check(const HybridMesh& mesh) {
    for (int threads : {1, 0}) {
        std::optional<tbb::global_control> limit;
        if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, threads);
        const auto start = Clock::now();
        const CheckReport r = check_mesh(mesh);
        const double took = seconds_since(start);
        EXPECT_TRUE(r.ok()) << describe(r);
        std::printf("%u cells, %s: checked in %.2f s\n", mesh.cell_count(), threads ? "1 thread" : "all threads",
                    took);
    }
}

TEST(MeshCheck, DISABLED_FiveMillionTets) { time_check(kuhn_tet_grid(94, 5).mesh); }

TEST(MeshCheck, DISABLED_FiveMillionHexes) { time_check(hex_grid(171, 5).mesh); }

}  // namespace
