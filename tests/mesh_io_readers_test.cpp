// Outside readers as tests: Gmsh's own reader opens our .msh files, meshio our .vtu and .inp
// files, and our reader opens files Gmsh wrote. The Python scripts in tests/scripts print
// JSON; these tests compare it with the mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/io/mesh_io.hpp"
#include "tests/mesh_io_samples.hpp"
#include "tests/support/process.hpp"
#include "tests/support/sample_meshes.hpp"

namespace tubemesh {
namespace {

using nlohmann::json;
using testing::TempDir;
using Counts = std::map<std::string, int>;

// Runs tests/scripts/<script> with Debian's Python and parses its JSON output.
json run_script(const std::string& script, std::vector<std::string> args) {
    args.insert(args.begin(), std::string(TUBEMESH_TEST_SCRIPTS) + "/" + script);
    std::string command = testing::shell_quote(TUBEMESH_TEST_PYTHON);
    for (const std::string& a : args) {
        command += ' ';
        command += testing::shell_quote(a);
    }
    const testing::ProcessResult r = testing::run_command(command);
    if (r.exit_code != 0) {
        ADD_FAILURE() << script << " failed (exit " << r.exit_code << "):\n" << r.err;
        return json::object();
    }
    return json::parse(r.out);
}

bool listed(const json& array, const std::string& name) {
    return std::find(array.begin(), array.end(), json(name)) != array.end();
}

// Gmsh's element counts per type number, as tubemesh's mesh has them.
std::map<std::string, int> gmsh_counts(const HybridMesh& m) {
    std::map<std::string, int> c;
    auto put = [&](const char* type, index_t n) {
        if (n > 0) c[type] = static_cast<int>(n);
    };
    put("4", m.cell_count(CellKind::Tet));
    put("7", m.cell_count(CellKind::Pyramid));
    put("5", m.cell_count(CellKind::Hex));
    put("2", m.face_count(FaceKind::Tri));
    put("3", m.face_count(FaceKind::Quad));
    return c;
}

// [dim, tag, name] per physical group, as Gmsh lists them (by dimension, then tag).
json physical_groups(const HybridMesh& m) {
    json groups = json::array();
    for (std::size_t g = 0; g < m.surface_group_names.size(); ++g)
        groups.push_back({2, g + 1, m.surface_group_names[g]});
    for (std::size_t r = 0; r < m.region_names.size(); ++r) groups.push_back({3, r + 1, m.region_names[r]});
    return groups;
}

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
    }
}

INSTANTIATE_TEST_SUITE_P(Encodings, GmshReadsOurMsh, ::testing::Values(MshEncoding::Ascii, MshEncoding::Binary),
                         [](const auto& info) { return info.param == MshEncoding::Ascii ? "Ascii" : "Binary"; });

std::map<std::string, int> meshio_counts(const HybridMesh& m) {
    std::map<std::string, int> c;
    auto put = [&](const char* type, index_t n) {
        if (n > 0) c[type] = static_cast<int>(n);
    };
    put("tetra", m.cell_count(CellKind::Tet));
    put("pyramid", m.cell_count(CellKind::Pyramid));
    put("hexahedron", m.cell_count(CellKind::Hex));
    return c;
}

TEST(MeshioReads, OurVtu) {
    TempDir dir;
    const HybridMesh mesh = testing::mixed_grid(4);
    write_vtu(mesh, dir / "mesh.vtu");
    const json seen = run_script("meshio_summary.py", {(dir / "mesh.vtu").string()});
    EXPECT_EQ(seen["points"], mesh.point_count());
    EXPECT_EQ(seen["cells"].get<Counts>(), meshio_counts(mesh));
    EXPECT_EQ(seen["cell_data"], json({"kind", "quality", "region"}));
    std::map<std::string, int> regions;
    for (CellKind k : kAllCellKinds)
        for (index_t r : mesh.block(k).region) ++regions[std::to_string(r)];
    EXPECT_EQ(seen["region_counts"].get<Counts>(), regions);
    EXPECT_GT(seen["quality_min"].get<double>(), 0.1);  // the grid's cells are all fair
}

TEST(MeshioReads, OurInp) {
    TempDir dir;
    for (const HybridMesh& mesh : {testing::conforming_patch(), testing::mixed_grid(4)}) {
        write_inp(mesh, dir / "mesh.inp");
        const json seen = run_script("meshio_summary.py", {(dir / "mesh.inp").string()});
        EXPECT_EQ(seen["points"], mesh.point_count());
        EXPECT_EQ(seen["cells"].get<Counts>(), meshio_counts(mesh));
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
