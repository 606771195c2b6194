// Names a person can use: `tubemesh mesh` reports and writes where each surface group is
// (alias on a built block, CAD surface, area, centroid, normal), the length unit and the
// pipes' rims, and the standard quality measures beside the paper's; the write options of
// the command line reach the files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_command.hpp"
#include "tests/support/process.hpp"

namespace {

using nlohmann::json;
using tubemesh::testing::cli;
using tubemesh::testing::q;
using tubemesh::testing::run_command;
using tubemesh::testing::TempDir;

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const json* group_named(const json& report, const std::string& name) {
    for (const json& g : report["surface_groups"])
        if (g["name"] == name) return &g;
    return nullptr;
}

// The built-in dam block, 15 x 25 x 4 m: every box face is named, the pipe is a wall.
TEST(CliMeshNames, BuiltBlockSaysWhereEachGroupIs) {
    TempDir dir;
    const auto r = run_command(cli() + " mesh --threads 2 -o " + q(dir / "dam.inp") + " -o " + q(dir / "dam.msh") +
                               " --report " + q(dir / "r.json"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(dir / "r.json");
    const json report = json::parse(in);
    EXPECT_EQ(report["length_unit"], "metre");
    std::map<std::string, json> by_where;
    double area = 0;
    for (const json& g : report["surface_groups"]) {
        by_where[g["where"].get<std::string>()] = g;
        area += g["area"].get<double>();
    }
    for (const char* side : {"top", "bottom", "upstream", "downstream", "left", "right", "pipe wall"})
        EXPECT_EQ(by_where.count(side), 1u) << side << report["surface_groups"].dump();
    const json& top = by_where["top"];
    EXPECT_EQ(top["surface_kind"], "plane");
    EXPECT_NEAR(top["area"].get<double>(), 15.0 * 25.0, 1e-6);
    EXPECT_NEAR(top["centroid"][2].get<double>(), 4.0, 1e-9);
    EXPECT_EQ(top["normal"], json({0.0, 0.0, 1.0}));
    EXPECT_NEAR(by_where["upstream"]["normal"][1].get<double>(), -1.0, 1e-12);
    EXPECT_FALSE(by_where["pipe wall"].contains("normal"));  // not flat
    // The pipe (d 0.04 along y through the 25 m block): about pi d L of wall.
    EXPECT_NEAR(by_where["pipe wall"]["area"].get<double>(), M_PI * 0.04 * 25.0, 0.05 * M_PI * 0.04 * 25.0);
    EXPECT_GT(area, 2 * (15 * 25 + 15 * 4 + 25 * 4) - 0.01);
    EXPECT_EQ(report["node_sets"]["pipe_1_inlet"], report["node_sets"]["pipe_1_outlet"]);
    EXPECT_GE(report["node_sets"]["pipe_1_inlet"].get<int>(), 8);

    // The standard measures beside the paper's, per kind.
    const json& quality = report["quality"];
    EXPECT_EQ(quality["tet_scaled_jacobian"]["count"], report["tets"]);
    EXPECT_GT(quality["tet_scaled_jacobian"]["min"].get<double>(), 0.0);
    EXPECT_GT(quality["tet_min_dihedral_degrees"]["min"].get<double>(), 0.0);
    EXPECT_LE(quality["tet_min_dihedral_degrees"]["max"].get<double>(), 70.5288 + 1e-3);  // the regular tet's
    EXPECT_GE(quality["tet_aspect_ratio"]["min"].get<double>(), 1.0 - 1e-9);
    EXPECT_LE(quality["hex_verdict_scaled_jacobian"]["min"].get<double>(),
              quality["hex_scaled_jacobian"]["min"].get<double>());

    // The same names in the files: the aliases as sets in the .inp, the table in both.
    const std::string inp = read_text(dir / "dam.inp");
    EXPECT_TRUE(contains(inp, "** length unit: metre")) << inp.substr(0, 3000);
    EXPECT_TRUE(contains(inp, "*NSET, NSET=top\n"));
    EXPECT_TRUE(contains(inp, "*SURFACE, NAME=top, TYPE=ELEMENT\n"));
    EXPECT_TRUE(contains(inp, "*NSET, NSET=pipe_1_inlet\n"));
    const std::string msh = read_text(dir / "dam.msh");
    EXPECT_TRUE(contains(msh, "$Comments\nlength unit: metre")) << msh.substr(0, 500);
    EXPECT_TRUE(contains(r.out, "length unit: metre"));
    EXPECT_TRUE(contains(r.out, " top "));
}

// A STEP file keeps its declared unit, and make-block's its face names (paper-ex3 has a flat top
// and bottom).
TEST(CliMeshNames, StepFileKeepsItsUnit) {
    TempDir dir;
    ASSERT_EQ(run_command(cli() + " make-block --preset paper-ex3 -o " + q(dir / "j.step")).exit_code, 0);
    const auto r = run_command(cli() + " mesh " + q(dir / "j.step") + " --quiet -o " + q(dir / "j.vtu") +
                               " --report " + q(dir / "r.json"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(dir / "r.json");
    const json report = json::parse(in);
    EXPECT_EQ(report["length_unit"], "millimetre");
    std::vector<std::string> sides;
    for (const json& g : report["surface_groups"])
        if (g["where"] != "" && g["where"] != "pipe wall") sides.push_back(g["where"]);
    std::sort(sides.begin(), sides.end());
    EXPECT_EQ(sides, (std::vector<std::string>{"bottom", "top"}));
    ASSERT_NE(group_named(report, "pipe_1"), nullptr);
    EXPECT_TRUE(contains(read_text(dir / "j.vtu"), "length unit: millimetre"));
}

TEST(CliMeshNames, WriteOptionsReachTheFiles) {
    TempDir dir;
    ASSERT_EQ(run_command(cli() + " make-block --preset straight-pipe -o " + q(dir / "p.step")).exit_code, 0);
    const std::string mesh = cli() + " mesh " + q(dir / "p.step") + " --size 0.6 --quiet ";
    ASSERT_EQ(run_command(mesh + "--msh-ascii --inp-family heat -o " + q(dir / "a.msh") + " -o " + q(dir / "h.inp"))
                  .exit_code,
              0);
    EXPECT_EQ(read_text(dir / "a.msh").rfind("$MeshFormat\n4.1 0 8\n", 0), 0u);
    const std::string heat = read_text(dir / "h.inp");
    EXPECT_TRUE(contains(heat, "*ELEMENT, TYPE=DC3D4, ELSET=KIND_TET\n"));
    EXPECT_TRUE(contains(heat, "*ELEMENT, TYPE=DC3D8, ELSET=KIND_PYRAMID\n"));
    ASSERT_EQ(run_command(mesh + "--inp-pyramid c3d5 -o " + q(dir / "p.inp")).exit_code, 0);
    EXPECT_TRUE(contains(read_text(dir / "p.inp"), "*ELEMENT, TYPE=C3D5, ELSET=KIND_PYRAMID\n"));

    // No 5-node pyramid in the heat family: refused before meshing, one line, no file.
    const auto refused = run_command(mesh + "--inp-pyramid c3d5 --inp-family heat -o " + q(dir / "x.inp"));
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_TRUE(contains(refused.err, "--inp-pyramid c3d5 has no heat-transfer")) << refused.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.inp"));
    const auto unknown = run_command(mesh + "--inp-family thermal -o " + q(dir / "y.inp"));
    EXPECT_EQ(unknown.exit_code, 2);
    EXPECT_FALSE(std::filesystem::exists(dir / "y.inp"));
}

}  // namespace
