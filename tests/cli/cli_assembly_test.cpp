// `tubemesh make-dam --assembled` and `tubemesh mesh --assembly` end to end: a small dam section
// written as one STEP (named solids, shared faces), meshed as one mesh that `tubemesh check`
// passes, Gmsh reopens with a volume group per solid and a surface group per pipe, and on which
// CalculiX reproduces a linear temperature at every node (a joint whose two sides did not match
// would leave hanging nodes there and break it); a gap between solids is exit 2 and no file.
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "geom/step_write_occt.hpp"
#include "tests/support/cli_command.hpp"
#include "tests/support/outside_readers.hpp"
#include "tests/support/process.hpp"

namespace tubemesh {
namespace {

using nlohmann::json;
using testing::cli;
using testing::q;
using testing::run_command;
using testing::run_script;
using testing::TempDir;

json read_json(const std::filesystem::path& p) {
    std::ifstream in(p);
    return json::parse(in);
}

TEST(CliAssembly, DamSectionMeshesChecksReopensAndSolves) {
    TempDir dir;
    const auto made = run_command(cli() + " make-dam --columns 2 --lifts 2 --width 4 --depth 3 --lift-height 1 "
                                          "--spacing 1 --diameter 0.05 --assembled --quiet -o " + q(dir.path()));
    ASSERT_EQ(made.exit_code, 0) << made.err;
    ASSERT_TRUE(std::filesystem::exists(dir / "section.step"));

    const auto msh = dir / "section.msh", inp = dir / "section.inp", report = dir / "report.json";
    const auto meshed = run_command(cli() + " mesh --assembly --threads 2 " + q(dir / "section.step") + " -o " + q(msh) +
                                    " -o " + q(inp) + " --report " + q(report));
    ASSERT_EQ(meshed.exit_code, 0) << meshed.out << meshed.err;
    EXPECT_NE(meshed.out.find("block_2_2"), std::string::npos) << meshed.out;

    const auto checked = run_command(cli() + " check " + q(msh));
    EXPECT_EQ(checked.exit_code, 0) << checked.out << checked.err;

    const json r = read_json(report);
    ASSERT_TRUE(r.contains("assembly")) << r.dump();
    const json& a = r["assembly"];
    ASSERT_EQ(a["solids"].size(), 4u);
    EXPECT_EQ(a["shared_faces"].get<int>(), 4);
    EXPECT_GT(a["shared_triangles"].get<int>(), 0);
    EXPECT_LT(a["volume_mismatch"].get<double>(), 1e-9);
    for (const json& s : a["solids"]) {
        EXPECT_GT(s["hexes"].get<int>(), 0) << s.dump();
        EXPECT_NEAR(s["volume"].get<double>(), s["cad_volume"].get<double>(), 2e-3 * s["cad_volume"].get<double>());
    }

    const json g = run_script("gmsh_summary.py", {msh.string()});
    std::vector<std::string> volumes, surfaces;
    for (const json& p : g["physical"]) (p[0].get<int>() == 3 ? volumes : surfaces).push_back(p[2]);
    EXPECT_EQ(volumes, (std::vector<std::string>{"block_1_1", "block_1_2", "block_2_1", "block_2_2"}));
    for (const char* pipe : {"pipe_1", "pipe_2", "pipe_3", "pipe_4"})
        EXPECT_NE(std::find(surfaces.begin(), surfaces.end(), pipe), surfaces.end()) << pipe;

    const json patch = run_script("calculix_run.py", {"patch", inp.string(), dir.path().string()});
    std::cout << "assembly patch test: " << patch.dump() << "\n";
    ASSERT_TRUE(patch.contains("relative_error")) << patch.dump();
    EXPECT_LT(patch["boundary_nodes"].get<int>(), patch["nodes"].get<int>());
    EXPECT_LT(patch["relative_error"].get<double>(), 1e-6);
}

TEST(CliAssembly, GapBetweenSolidsIsExit2AndNoFile) {
    TempDir dir;
    TopoDS_Compound two;
    BRep_Builder builder;
    builder.MakeCompound(two);
    builder.Add(two, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(1, 1, 1)).Solid());
    builder.Add(two, BRepPrimAPI_MakeBox(gp_Pnt(1.002, 0, 0), gp_Pnt(2, 1, 1)).Solid());
    tubemesh::geom::write_step_shape(two, dir / "gap.step", "metre");
    const auto out = dir / "gap.msh";
    const auto r = run_command(cli() + " mesh --assembly " + q(dir / "gap.step") + " -o " + q(out));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("gap of 0.002"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace tubemesh
