#include <gtest/gtest.h>

#include <array>

#include "engine/mesh/hybrid_mesh.hpp"

namespace {

using namespace tubemesh;

TEST(HybridMesh, AddsPointsCellsAndFacesAsFlatArrays) {
    HybridMesh m;
    for (int i = 0; i < 5; ++i) m.add_point(i, 2 * i, 3 * i);
    const index_t tets = m.region_id("tets");
    const index_t pyr = m.region_id("pyramids");
    EXPECT_EQ(m.region_id("tets"), tets);
    const std::array<index_t, 4> t{0, 1, 2, 3};
    const std::array<index_t, 5> p{0, 1, 2, 3, 4};
    EXPECT_EQ(m.add_cell(CellKind::Tet, t, tets), 0u);
    EXPECT_EQ(m.add_cell(CellKind::Pyramid, p, pyr), 0u);
    EXPECT_EQ(m.add_cell(CellKind::Tet, t, tets), 1u);
    const index_t wall = m.surface_group_id("pipe_1");
    const std::array<index_t, 3> f{0, 2, 1};
    m.add_face(FaceKind::Tri, f, wall);

    EXPECT_EQ(m.point_count(), 5u);
    EXPECT_EQ(m.cell_count(CellKind::Tet), 2u);
    EXPECT_EQ(m.cell_count(), 3u);
    EXPECT_EQ(m.block(CellKind::Tet).nodes.size(), 8u);
    EXPECT_EQ(m.cell(CellKind::Pyramid, 0)[4], 4u);
    EXPECT_EQ(m.face(FaceKind::Tri, 0)[1], 2u);
    EXPECT_EQ(m.point(3).y, 6.0);
    EXPECT_NO_THROW(m.validate_layout());
    HybridMesh copy = m;
    EXPECT_EQ(copy, m);
    copy.block(CellKind::Tet).region[1] = pyr;
    EXPECT_NE(copy, m);
}

TEST(HybridMesh, RejectsWrongNodeCount) {
    HybridMesh m;
    const std::array<index_t, 3> three{0, 1, 2};
    EXPECT_THROW(m.add_cell(CellKind::Tet, three, 0), Error);
    const std::array<index_t, 4> four{0, 1, 2, 3};
    EXPECT_THROW(m.add_face(FaceKind::Tri, four, 0), Error);
}

TEST(HybridMesh, LayoutValidationNamesTheProblem) {
    HybridMesh m;
    m.add_point(0, 0, 0);
    m.region_id("tets");
    const std::array<index_t, 4> t{0, 0, 0, 7};
    m.add_cell(CellKind::Tet, t, 0);
    try {
        m.validate_layout();
        FAIL() << "out-of-range node accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("refers to node 7"), std::string::npos) << e.what();
    }
    m.block(CellKind::Tet).nodes.assign({0, 0, 0, 0});
    m.block(CellKind::Tet).region[0] = 3;
    EXPECT_THROW(m.validate_layout(), Error);
    m.x.push_back(1);
    EXPECT_THROW(m.validate_layout(), Error);
}

}  // namespace
