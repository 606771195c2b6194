// `tubemesh mesh` writes the full hybrid mesh (hex ring, pyramids, tets) of a small block as
// .msh, .vtu, .vtm and .inp; `tubemesh check` passes on it; and outside readers open each
// file and find the same nodes, elements and groups - one surface group per tube wall
// (pipe_k) and per other B-rep face (face_<id>), one volume group per region - Gmsh for
// .msh, meshio for .vtu, the .vtm's blocks and .inp (meshio skips Abaqus *SURFACE; the script
// group_members.py reads those itself).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>

#include "engine/io/mesh_io.hpp"
#include "tests/support/mesh_io_samples.hpp"
#include "tests/support/cli_command.hpp"
#include "tests/support/outside_readers.hpp"
#include "tests/support/process.hpp"

namespace tubemesh {
namespace {

using nlohmann::json;
using testing::Counts;
using testing::run_command;
using testing::run_script;
using testing::cli;
using testing::q;
using testing::TempDir;

// The straight-pipe block (4 x 3 x 2, one pipe of diameter 0.1) at a coarse size: a full
// hybrid mesh of a few thousand elements, meshed once for every test below.
class FullMeshFiles : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new TempDir;
        const auto made = run_command(cli() + " make-block --preset straight-pipe -o " + q(path("x.step")));
        ASSERT_EQ(made.exit_code, 0) << made.out << made.err;
        const auto inspected = run_command(cli() + " inspect --json " + q(path("x.step")));
        ASSERT_EQ(inspected.exit_code, 0) << inspected.err;
        model_ = json::parse(inspected.out);
        const auto meshed = run_command(cli() + " mesh " + q(path("x.step")) + " --size 0.6 --threads 2 --quiet -o " +
                                        q(path("m.msh")) + " -o " + q(path("m.vtu")) + " -o " + q(path("m.inp")) +
                                        " -o " + q(path("m.vtm")));
        ASSERT_EQ(meshed.exit_code, 0) << meshed.out << meshed.err;
        mesh_ = read_msh(path("m.msh"));
    }
    static void TearDownTestSuite() {
        delete dir_;
        dir_ = nullptr;
    }
    static std::filesystem::path path(const std::string& name) { return *dir_ / name; }

    static inline TempDir* dir_ = nullptr;
    static inline json model_;        // `tubemesh inspect --json` of the block
    static inline HybridMesh mesh_;  // the .msh as tubemesh reads it
};

TEST_F(FullMeshFiles, OurCheckPassesAndEveryGroupIsThere) {
    ASSERT_GT(mesh_.point_count(), 0u);
    const auto checked = run_command(cli() + " check " + q(path("m.msh")));
    EXPECT_EQ(checked.exit_code, 0) << checked.out << checked.err;

    const HybridMesh& m = mesh_;
    EXPECT_GT(m.cell_count(CellKind::Hex), 0u);
    EXPECT_GT(m.cell_count(CellKind::Pyramid), 0u);
    EXPECT_GT(m.cell_count(CellKind::Tet), 0u);
    EXPECT_EQ(std::set<std::string>(m.region_names.begin(), m.region_names.end()),
              (std::set<std::string>{"hex_ring", "pyramids", "tets"}));
    // One group per tube wall and one per other B-rep face, each holding faces.
    std::set<std::string> expected;
    for (std::size_t t = 1; t <= model_["tubes"].size(); ++t) expected.insert("pipe_" + std::to_string(t));
    for (const json& f : model_["faces"])
        if (f["role"].get<std::string>().rfind("wall of", 0) != 0) expected.insert("face_" + f["id"].dump());
    EXPECT_EQ(std::set<std::string>(m.surface_group_names.begin(), m.surface_group_names.end()), expected);
    EXPECT_EQ(m.surface_group_names.size(), expected.size());  // no name twice
    const Counts sizes = testing::group_sizes(m);
    for (const std::string& g : m.surface_group_names) EXPECT_GT(sizes.count("2:" + g), 0u) << g;
    for (const std::string& r : m.region_names) EXPECT_GT(sizes.count("3:" + r), 0u) << r;
}

TEST_F(FullMeshFiles, GmshReopensTheMsh) {
    const json seen = run_script("gmsh_summary.py", {path("m.msh").string()});
    EXPECT_EQ(seen["nodes"], mesh_.point_count());
    EXPECT_EQ(seen["elements"].get<Counts>(), testing::gmsh_counts(mesh_));
    EXPECT_EQ(seen["physical"], testing::physical_groups(mesh_)) << seen["physical"].dump();
    json groups = json::object();
    for (const auto& [key, count] : testing::group_sizes(mesh_)) groups[key] = {1, count};
    EXPECT_EQ(seen["groups"], groups);
}

TEST_F(FullMeshFiles, MeshioReadsTheVtuWithItsGroups) {
    const json seen = run_script("meshio_summary.py", {path("m.vtu").string()});
    EXPECT_EQ(seen["points"], mesh_.point_count());
    EXPECT_EQ(seen["cells"].get<Counts>(), testing::meshio_counts(mesh_, false));
    EXPECT_EQ(seen["field_data"], testing::vtu_field_data(mesh_));
    EXPECT_EQ(seen["quality_nan"], 0);
    EXPECT_GT(seen["quality_min"].get<double>(), 0);
    // Every boundary block of the .vtm lies on cells: no face without a quality.
    const json blocks = run_script("meshio_summary.py", {path("m.vtm").string()});
    EXPECT_EQ(blocks["blocks"].size(), mesh_.region_names.size() + mesh_.surface_group_names.size());
    for (const auto& [name, block] : blocks["blocks"].items()) EXPECT_EQ(block["quality_nan"], 0) << name;
}

// VTK itself (ParaView's reader): the .vtu's standard measures are Verdict's, as
// vtkMeshQuality computes them, and the .vtm's blocks carry the group names.
TEST_F(FullMeshFiles, VtkReadsTheVtuAndTheVtmBlocks) {
    const json vtu = run_script("vtk_check.py", {path("m.vtu").string()});
    ASSERT_TRUE(vtu.contains("differences")) << vtu.dump();
    EXPECT_EQ(vtu["cells"]["10"], mesh_.cell_count(CellKind::Tet));
    EXPECT_EQ(vtu["cells"]["14"], mesh_.cell_count(CellKind::Pyramid));
    EXPECT_EQ(vtu["cells"]["12"], mesh_.cell_count(CellKind::Hex));
    for (const auto& [measure, difference] : vtu["differences"].items()) {
        ASSERT_FALSE(difference.is_null()) << measure;
        EXPECT_LT(difference.get<double>(), 1e-9) << measure;
    }
    const json vtm = run_script("vtk_check.py", {path("m.vtm").string()});
    const Counts sizes = testing::group_sizes(mesh_);
    Counts blocks;
    for (const auto& [name, cells] : vtm["blocks"].items()) {
        const bool volume = name.rfind("volume/", 0) == 0;
        const std::string group = name.substr(name.find('/') + 1, name.find(" (") - name.find('/') - 1);
        blocks[(volume ? "3:" : "2:") + group] = cells.get<int>();
    }
    EXPECT_EQ(blocks, sizes) << vtm.dump();
}

TEST_F(FullMeshFiles, MeshioReadsTheInpWithItsSets) {
    const json seen = run_script("meshio_summary.py", {path("m.inp").string()});
    EXPECT_EQ(seen["points"], mesh_.point_count());
    EXPECT_EQ(seen["cells"].get<Counts>(), testing::meshio_counts(mesh_, true));
    const Counts sizes = testing::group_sizes(mesh_);
    for (const std::string& r : mesh_.region_names)
        EXPECT_EQ(seen["cell_set_sizes"][r], sizes.at("3:" + r)) << r;
    for (const std::string& g : mesh_.surface_group_names) EXPECT_TRUE(testing::listed(seen["point_sets"], g)) << g;
}

// Element for element: every group holds the same cells or faces in all four files.
TEST_F(FullMeshFiles, TheFourFormatsHoldTheSameGroups) {
    const json seen = run_script("group_members.py", {path("m.msh").string(), path("m.vtu").string(),
                                                      path("m.inp").string(), path("m.vtm").string()});
    ASSERT_TRUE(seen.contains("msh")) << seen.dump();
    Counts msh_sizes;
    for (const auto& [key, v] : seen["msh"].items()) msh_sizes[key] = v[0].get<int>();
    EXPECT_EQ(msh_sizes, testing::group_sizes(mesh_));
    EXPECT_EQ(seen["vtm"], seen["msh"]);
    for (const auto& [key, v] : seen["msh"].items()) {
        EXPECT_EQ(seen["inp"][key], v) << key;
        if (key.rfind("3:", 0) == 0) {
            EXPECT_EQ(seen["vtu"][key], v) << key;  // the .vtu: volume cells only
        }
    }
    const std::regex extra("3:(KIND_TET|KIND_PYRAMID|KIND_HEX|EALL|.*_S[1-6])");
    // The faces' names from the STEP file (make-block writes them): a group's sets once more.
    const std::regex alias("2:(top|bottom|upstream|downstream|left|right)");
    for (const auto& [key, v] : seen["inp"].items()) {  // besides: kinds, every element, face sets
        if (seen["msh"].contains(key) || std::regex_match(key, extra)) continue;
        EXPECT_TRUE(std::regex_match(key, alias)) << key;
        bool a_group = false;
        for (const auto& [group, members] : seen["msh"].items()) a_group = a_group || members == v;
        EXPECT_TRUE(a_group) << key;
    }
    EXPECT_EQ(seen["points"]["vtu"], 0.0);  // binary: the same doubles
    // Text: the shortest form that reads back exactly, round-off below 1e-12 of the model as 0.
    EXPECT_LE(seen["points"]["inp"].get<double>(), 1e-11);
    EXPECT_EQ(seen["nset_mismatch"], json::array());
}

// The file's text without its comments and the sets only the mesh's description gives (the
// pipes' rims, the faces' names), so files written from the .msh compare with the CLI's.
std::string mesh_part(const std::string& text) {
    const std::regex named_face("=(top|bottom|upstream|downstream|left|right)(_S[1-6])?(,.*)?$");
    std::string out;
    bool skipping = false;
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(at, end - at);
        at = end + 1;
        if (line.rfind("*", 0) == 0)
            skipping = line.find("_inlet") != std::string::npos || line.find("_outlet") != std::string::npos ||
                       std::regex_search(line, named_face);
        if (skipping || line.rfind("**", 0) == 0) continue;
        out += line + "\n";
    }
    const std::size_t comment = out.find("<!--");
    if (comment != std::string::npos) out.erase(comment, out.find("-->") + 3 - comment);
    return out;
}

// The .msh holds everything the other writers use, in the same order: writing what tubemesh
// reads back from it gives the CLI's .vtu and .inp but for their notes on the model.
TEST_F(FullMeshFiles, MshHoldsTheWholeMesh) {
    TempDir dir;
    write_vtu(mesh_, dir / "again.vtu");
    write_inp(mesh_, dir / "again.inp");
    EXPECT_TRUE(mesh_part(testing::read_text(dir / "again.vtu")) == mesh_part(testing::read_text(path("m.vtu"))));
    EXPECT_TRUE(mesh_part(testing::read_text(dir / "again.inp")) == mesh_part(testing::read_text(path("m.inp"))));
}

}  // namespace
}  // namespace tubemesh
