// The topology tables are the base of every face and edge loop: check them geometrically.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <set>

#include "engine/mesh/topology.hpp"

namespace {

using tubemesh::CellKind;
using tubemesh::topology;
using P = std::array<double, 3>;

P sub(P a, P b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P cross(P a, P b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(P a, P b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Reference cells in VTK order.
const std::array<P, 4> kTet = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
const std::array<P, 5> kPyr = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}}};
const std::array<P, 8> kHex = {
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};

template <std::size_t N>
void expect_outward_faces(CellKind kind, const std::array<P, N>& pts) {
    const auto& t = topology(kind);
    ASSERT_EQ(t.node_count, N);
    P centre{0, 0, 0};
    for (const P& p : pts)
        for (int d = 0; d < 3; ++d) centre[d] += p[d] / N;
    for (int f = 0; f < t.face_count; ++f) {
        const auto& face = t.face[f];
        P c{0, 0, 0};
        for (int k = 0; k < face.size; ++k)
            for (int d = 0; d < 3; ++d) c[d] += pts[face.node[k]][d] / face.size;
        const P n = cross(sub(pts[face.node[1]], pts[face.node[0]]), sub(pts[face.node[2]], pts[face.node[0]]));
        EXPECT_GT(dot(n, sub(c, centre)), 0.0) << t.name << " face " << f << " points inwards";
    }
}

// Every edge of the cell lies on exactly two faces, every face edge is a listed edge, and
// each edge appears once in each direction over the faces (closed, consistently oriented).
void expect_closed_surface(CellKind kind) {
    const auto& t = topology(kind);
    std::map<std::pair<int, int>, int> directed;
    for (int f = 0; f < t.face_count; ++f)
        for (int k = 0; k < t.face[f].size; ++k) {
            const int a = t.face[f].node[k], b = t.face[f].node[(k + 1) % t.face[f].size];
            ++directed[{a, b}];
        }
    std::set<std::pair<int, int>> edges;
    for (int e = 0; e < t.edge_count; ++e) {
        const int a = t.edge[e].a, b = t.edge[e].b;
        EXPECT_TRUE(edges.insert({std::min(a, b), std::max(a, b)}).second) << t.name << " edge listed twice";
        EXPECT_EQ((directed[{a, b}]), 1) << t.name;
        EXPECT_EQ((directed[{b, a}]), 1) << t.name;
    }
    EXPECT_EQ(directed.size(), 2u * t.edge_count) << t.name << ": faces use an edge not in the edge table";
    // Euler: V - E + F = 2 for a closed polyhedron.
    EXPECT_EQ(t.node_count - t.edge_count + t.face_count, 2) << t.name;
}

TEST(Topology, TetFacesPointOutward) { expect_outward_faces(CellKind::Tet, kTet); }
TEST(Topology, PyramidFacesPointOutward) { expect_outward_faces(CellKind::Pyramid, kPyr); }
TEST(Topology, HexFacesPointOutward) { expect_outward_faces(CellKind::Hex, kHex); }

TEST(Topology, TablesDescribeClosedOrientedSurfaces) {
    for (CellKind k : tubemesh::kAllCellKinds) expect_closed_surface(k);
}

TEST(Topology, TetFaceIsOppositeItsIndex) {
    const auto& t = tubemesh::kTetTopology;
    for (int f = 0; f < 4; ++f)
        for (int k = 0; k < 3; ++k) EXPECT_NE(t.face[f].node[k], f);
}

TEST(Topology, PyramidBaseIsFaceZero) {
    const auto& t = tubemesh::kPyramidTopology;
    EXPECT_EQ(t.face[0].size, 4);
    for (int f = 1; f < 5; ++f) {
        EXPECT_EQ(t.face[f].size, 3);
        EXPECT_EQ(t.face[f].node[2], 4);
    }
}

}  // namespace
