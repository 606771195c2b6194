// Outside readers as tests: Gmsh's own reader opens our .msh files, meshio our .vtu and .inp
// files, and our reader opens files Gmsh wrote. The Python scripts in tests/scripts print
// JSON; these tests compare it with the mesh.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/io/mesh_io.hpp"
#include "tests/support/mesh_io_samples.hpp"
#include "tests/support/outside_readers.hpp"
#include "tests/support/process.hpp"
#include "tests/support/sample_meshes.hpp"

namespace tubemesh {
namespace {

using nlohmann::json;
using testing::Counts;
using testing::gmsh_counts;
using testing::listed;
using testing::meshio_counts;
using testing::physical_groups;
using testing::run_script;
using testing::TempDir;

// Gmsh lists only physical groups that hold elements.
HybridMesh without_empty_groups(HybridMesh m) {
    m.region_names.resize(3);
    m.surface_group_names.resize(6);
    return m;
}

class GmshReadsOurMsh : public ::testing::TestWithParam<MshEncoding> {};

TEST_P(GmshReadsOurMsh, SameCountsAndPhysicalNames) {
    TempDir dir;
    const HybridMesh patch = testing::conforming_patch();
    const HybridMesh grid = without_empty_groups(testing::mixed_grid(4));
    for (const HybridMesh* mesh : {&patch, &grid}) {
        const auto path = dir / "mesh.msh";
        write_msh(*mesh, path, GetParam());
        const json seen = run_script("gmsh_summary.py", {path.string()});
        EXPECT_EQ(seen["elements"].get<Counts>(), gmsh_counts(*mesh));
        EXPECT_EQ(seen["nodes"], mesh->point_count());
        EXPECT_EQ(seen["physical"], physical_groups(*mesh)) << seen.dump();
        // One entity per group, holding the group's elements.
        json groups = json::object();
        for (const auto& [key, count] : testing::group_sizes(*mesh)) groups[key] = {1, count};
        EXPECT_EQ(seen["groups"], groups);
    }
}

INSTANTIATE_TEST_SUITE_P(Encodings, GmshReadsOurMsh, ::testing::Values(MshEncoding::Ascii, MshEncoding::Binary),
                         [](const auto& info) { return info.param == MshEncoding::Ascii ? "Ascii" : "Binary"; });

TEST(MeshioReads, OurVtu) {
    TempDir dir;
    const HybridMesh mesh = testing::mixed_grid(4);
    write_vtu(mesh, dir / "mesh.vtu");
    const json seen = run_script("meshio_summary.py", {(dir / "mesh.vtu").string()});
    EXPECT_EQ(seen["points"], mesh.point_count());
    EXPECT_EQ(seen["cells"].get<Counts>(), meshio_counts(mesh, false));
    EXPECT_EQ(seen["cell_data"], json({"aspect_ratio", "condition", "group", "kind", "min_dihedral", "quality",
                                       "scaled_jacobian"}));
    // Regions and surface groups each numbered from 0; the empty ones are in the field data too.
    EXPECT_EQ(seen["field_data"], testing::vtu_field_data(mesh)) << seen["field_data"].dump();
    Counts groups;
    for (CellKind k : kAllCellKinds)
        for (index_t r : mesh.block(k).region) ++groups[std::to_string(r)];
    EXPECT_EQ(seen["group_counts"].get<Counts>(), groups);
    EXPECT_EQ(seen["quality_nan"], 0);
    EXPECT_GT(seen["quality_min"].get<double>(), 0.1);  // the grid's cells are all fair
    // No NaN anywhere (ParaView colours it apart, thresholds drop it): a measure a kind does not
    // have is -1, which no defined value of these measures is.
    const index_t tets = mesh.cell_count(CellKind::Tet), hexes = mesh.cell_count(CellKind::Hex);
    ASSERT_GT(tets, 0u);
    ASSERT_GT(hexes, 0u);
    ASSERT_GT(mesh.cell_count(CellKind::Pyramid), 0u);
    for (const char* name : {"quality", "scaled_jacobian", "min_dihedral", "aspect_ratio", "condition"})
        EXPECT_EQ(seen["nan_counts"][name], 0) << name << " " << seen.dump();
    EXPECT_EQ(seen["no_value_counts"]["min_dihedral"], mesh.cell_count() - tets);
    EXPECT_EQ(seen["no_value_counts"]["aspect_ratio"], mesh.cell_count() - tets);
    EXPECT_EQ(seen["no_value_counts"]["condition"], mesh.cell_count() - hexes);
    EXPECT_EQ(seen["no_value_counts"]["quality"], 0);
}

// A name used twice gets "_2" in the field data; names with XML specials survive; in the
// .vtm a face no cell has gets quality -1 (not NaN) and every block reads.
TEST(MeshioReads, OurVtuAndVtmGroupTableEdgeCases) {
    TempDir dir;
    HybridMesh mesh = testing::conforming_patch();
    mesh.surface_group_names[0] = "tets";         // also a region
    mesh.surface_group_names[1] = "a&b <\"c\">";  // XML specials
    const index_t loose = mesh.surface_group_id("loose");
    const index_t nodes[3] = {0, 1, 12};  // two hex corners and the apex: no cell's face
    mesh.add_face(FaceKind::Tri, nodes, loose);
    write_vtu(mesh, dir / "mesh.vtu");
    const json seen = run_script("meshio_summary.py", {(dir / "mesh.vtu").string()});
    EXPECT_EQ(seen["field_data"]["tets"], json({2, 3})) << seen.dump();
    EXPECT_EQ(seen["field_data"]["tets_2"], json({0, 2}));
    EXPECT_EQ(seen["field_data"]["a&b <\"c\">"], json({1, 2}));
    EXPECT_EQ(seen["field_data"]["loose"], json({2, 2}));
    EXPECT_EQ(seen["quality_nan"], 0);

    write_vtm(mesh, dir / "mesh.vtm");
    const json blocks = run_script("meshio_summary.py", {(dir / "mesh.vtm").string()});
    ASSERT_TRUE(blocks.contains("blocks")) << blocks.dump();
    EXPECT_EQ(blocks["blocks"]["boundary/loose"]["quality_nan"], 0) << blocks.dump();
    EXPECT_EQ(blocks["blocks"]["boundary/loose"]["no_value_counts"]["quality"], 1) << blocks.dump();
    EXPECT_EQ(blocks["blocks"]["boundary/loose"]["cells"], json({{"triangle", 1}}));
    EXPECT_EQ(blocks["blocks"]["volume/pyramids"]["cells"], json({{"pyramid", 1}}));
    EXPECT_EQ(blocks["blocks"]["boundary/a&b <\"c\">"]["quality_nan"], 0);
}

TEST(MeshioReads, OurInp) {
    TempDir dir;
    for (const HybridMesh& mesh : {testing::conforming_patch(), testing::mixed_grid(4)}) {
        write_inp(mesh, dir / "mesh.inp");
        const json seen = run_script("meshio_summary.py", {(dir / "mesh.inp").string()});
        EXPECT_EQ(seen["points"], mesh.point_count());
        EXPECT_EQ(seen["cells"].get<Counts>(), meshio_counts(mesh, true));
        EXPECT_EQ(seen["cell_set_sizes"]["EALL"], mesh.cell_count());
        EXPECT_EQ(seen["point_set_sizes"]["NALL"], mesh.point_count());
        for (const std::string& region : mesh.region_names)
            if (region != "unused") {
                EXPECT_TRUE(listed(seen["cell_sets"], region)) << region << seen.dump();
            }
        for (const std::string& group : mesh.surface_group_names)
            if (group != "unused_group") {
                EXPECT_TRUE(listed(seen["point_sets"], group)) << group << seen.dump();
            }
    }
}

// Gmsh's own files: nodes over many entity blocks, physical groups, both encodings.
TEST(OurReaderReads, FilesGmshWrote) {
    TempDir dir;
    const json made = run_script("gmsh_make_meshes.py", {dir.path().string()});
    ASSERT_EQ(made.size(), 3u) << made.dump();
    for (const auto& [file, expected] : made.items()) {
        SCOPED_TRACE(file);
        const HybridMesh mesh = read_msh(dir / file);
        EXPECT_EQ(gmsh_counts(mesh), expected["elements"].get<Counts>());
        EXPECT_EQ(physical_groups(mesh), expected["physical"]);
        // Every node of the box is in use, so Gmsh wrote them all.
        EXPECT_GT(mesh.point_count(), 20u);
    }
    // Without physical groups Gmsh saves its point and line elements too: a clear error.
    try {
        read_msh(dir / "box_saveall.msh");
        ADD_FAILURE() << "box_saveall.msh was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("(1-node point) is not supported"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace tubemesh
