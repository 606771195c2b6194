// `tubemesh mesh --assembly` end to end on small assemblies written as STEP: each mesh passes
// `tubemesh check`, every interior face is on two cells and no face is free but the outer
// boundary and the pipe walls, the volume is the sum of the solids', Gmsh reopens it with a
// volume group per solid, a joint group per pair of touching solids and one group per pipe (a
// pipe through several solids included), and CalculiX reproduces a linear temperature at every
// node with the joints' nodes left free (a joint whose two sides did not match would leave
// hanging nodes there and break it). A gap or an overlap is exit 2 and no file.
// Built twice: the heavy build meshes the 3 x 3 dam section of the acceptance instead.
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Trsf.hxx>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geom/builders/block_builder.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/import/step_write_occt.hpp"
#include "tests/support/cli_test_names.hpp"
#include "tests/support/outside_readers.hpp"

namespace tubemesh {
namespace {

using testing::run_script;

json read_json(const fs::path& p) {
    std::ifstream in(p);
    return json::parse(in);
}

// What the files of one `mesh --assembly` run say: tubemesh check --json, the run's report, Gmsh.
struct Meshed {
    json check, report, gmsh;
    fs::path inp;
    std::vector<std::string> volumes, surfaces;  // Gmsh's physical names, by dimension
    int exit_code = -1;
};

Meshed mesh_assembly(const TempDir& dir, const fs::path& step, const std::string& options) {
    Meshed m;
    const fs::path msh = dir / "assembly.msh", report = dir / "assembly.json";
    m.inp = dir / "assembly.inp";
    const auto meshed = run_command(cli() + " mesh --assembly --threads 2 --quiet " + options + " " + q(step) + " -o " +
                                    q(msh) + " -o " + q(m.inp) + " --report " + q(report));
    m.exit_code = meshed.exit_code;
    EXPECT_EQ(meshed.exit_code, 0) << meshed.err;
    if (meshed.exit_code != 0) return m;
    const auto checked = run_command(cli() + " check --json " + q(msh));
    EXPECT_EQ(checked.exit_code, 0) << checked.out << checked.err;
    m.check = json::parse(checked.out);
    m.report = read_json(report);
    m.gmsh = run_script("gmsh_summary.py", {msh.string()});
    for (const json& p : m.gmsh["physical"]) (p[0].get<int>() == 3 ? m.volumes : m.surfaces).push_back(p[2]);
    return m;
}

bool has(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

std::vector<std::string> starting_with(const std::vector<std::string>& names, const std::string& prefix) {
    std::vector<std::string> out;
    for (const std::string& n : names)
        if (n.rfind(prefix, 0) == 0) out.push_back(n);
    return out;
}

// The properties every assembly mesh has, whatever its solids.
void expect_assembly(const Meshed& m, const std::vector<std::string>& solids, const std::vector<std::string>& joints) {
    ASSERT_EQ(m.exit_code, 0);
    EXPECT_TRUE(m.check["valid_and_conforming"].get<bool>()) << m.check["violations"].dump();
    EXPECT_EQ(m.check["regions"].get<std::vector<std::string>>(), solids);
    EXPECT_EQ(m.volumes, solids);  // Gmsh: a volume group per solid, by name
    for (const std::string& g : m.check["surface_groups"].get<std::vector<std::string>>())
        EXPECT_TRUE(has(m.surfaces, g)) << g << " is missing in Gmsh";
    EXPECT_EQ(starting_with(m.surfaces, "joint_"), joints);

    // Free faces are exactly the stored faces but the joints': every other cell face is on two
    // cells, and nothing is open inside.
    long joint_faces = 0;
    for (const std::string& j : joints) {
        const long n = m.gmsh["groups"]["2:" + j][1].get<long>();
        EXPECT_GT(n, 0) << j;
        joint_faces += n;
    }
    EXPECT_EQ(m.check["free_faces"].get<long>(),
              m.check["boundary_triangles"].get<long>() + m.check["boundary_quads"].get<long>() - joint_faces);
    EXPECT_GT(m.check["interior_faces"].get<long>(), 0);

    const json& a = m.report["assembly"];
    ASSERT_EQ(a["solids"].size(), solids.size());
    EXPECT_LT(a["volume_mismatch"].get<double>(), 1e-9);
    double cad = 0;
    for (const json& s : a["solids"]) {
        EXPECT_NEAR(s["volume"].get<double>(), s["cad_volume"].get<double>(), 2e-3 * s["cad_volume"].get<double>())
            << s["name"];
        cad += s["cad_volume"].get<double>();
    }
    EXPECT_NEAR(m.check["volume"].get<double>(), cad, 2e-3 * cad);
}

// CalculiX's steady heat patch test on the mesh's .inp: T = x + 2y + 3z on the boundary is
// reproduced at every node, the joints' nodes among the free ones.
void expect_patch_test(const Meshed& m, const TempDir& dir) {
    const fs::path work = dir / "ccx";
    fs::create_directories(work);
    const json patch = run_script("calculix_run.py", {"patch", m.inp.string(), work.string()});
    std::cout << "assembly patch test: " << patch.dump() << "\n";
    ASSERT_TRUE(patch.contains("relative_error")) << patch.dump();
    EXPECT_LT(patch["boundary_nodes"].get<int>(), patch["nodes"].get<int>());
    EXPECT_LT(patch["relative_error"].get<double>(), 1e-6);
}

// `tubemesh make-dam OPTIONS --assembled` into dir, and its section.step meshed.
Meshed dam_section(const TempDir& dir, const std::string& options) {
    const auto made = run_command(cli() + " make-dam " + options + " --assembled --quiet -o " + q(dir.path()));
    EXPECT_EQ(made.exit_code, 0) << made.err;
    return mesh_assembly(dir, dir / "section.step", "");
}

#ifndef TUBEMESH_ASSEMBLY_HEAVY

TopoDS_Solid box(gp_Pnt lo, gp_Pnt hi) { return BRepPrimAPI_MakeBox(lo, hi).Solid(); }

// A unit box at x0 along x with a straight pipe (diameter 0.04) along x through its middle: its
// ends on the box's x faces, so two of them side by side make one pipe through the joint.
TopoDS_Solid piped_box(double x0) {
    geom::BlockSpec spec;
    spec.host.size = {1, 1, 1};
    geom::PipeSpec pipe;
    pipe.kind = geom::PathKind::Line;
    pipe.diameter = 0.04;
    pipe.points = {{0, 0.5, 0.5}, {1, 0.5, 0.5}};
    spec.pipes.push_back(pipe);
    gp_Trsf move;
    move.SetTranslation(gp_Vec(x0, 0, 0));
    return TopoDS::Solid(geom::solid_of(geom::build_block(spec).model).Moved(TopLoc_Location(move)));
}

fs::path write_solids(const TempDir& dir, const std::string& name, const std::vector<TopoDS_Solid>& solids) {
    TopoDS_Compound c;
    BRep_Builder builder;
    builder.MakeCompound(c);
    for (const TopoDS_Solid& s : solids) builder.Add(c, s);
    const fs::path p = dir / (name + ".step");
    geom::write_step_shape(c, p, "metre");
    return p;
}

TEST(CliAssembly, TwoBoxesSharingAFace) {
    TempDir dir;
    const fs::path step = write_solids(dir, "two", {box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1})});
    const Meshed m = mesh_assembly(dir, step, "--size 0.25");
    expect_assembly(m, {"solid_1", "solid_2"}, {"joint_solid_1_solid_2"});
    EXPECT_NEAR(m.check["volume"].get<double>(), 2.0, 1e-9);
    EXPECT_NEAR(m.check["boundary_area"].get<double>(), 10.0, 1e-9);  // the joint is no boundary
    EXPECT_EQ(m.check["hexes"].get<int>(), 0);
}

TEST(CliAssembly, TwoBoxesWithAPipeThroughTheJoint) {
    TempDir dir;
    const fs::path step = write_solids(dir, "piped", {piped_box(0), piped_box(1)});
    const Meshed m = mesh_assembly(dir, step, "--size 0.25");
    expect_assembly(m, {"solid_1", "solid_2"}, {"joint_solid_1_solid_2"});
    // One pipe through both solids: one wall group, its rims only at the two outer ends.
    EXPECT_EQ(starting_with(m.surfaces, "pipe_"), std::vector<std::string>{"pipe_1"});
    EXPECT_EQ(m.report["assembly"]["solids"][0]["hexes"], m.report["assembly"]["solids"][1]["hexes"]);
    EXPECT_GT(m.check["hexes"].get<int>(), 0);
    // The ring's cross-section on the joint is in the joint group: quads there, stored once.
    const json& joint_elements = m.gmsh["groups"]["2:joint_solid_1_solid_2"];
    EXPECT_GT(joint_elements[1].get<int>(), 0);
    std::ifstream inp(m.inp);
    const std::string text((std::istreambuf_iterator<char>(inp)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("NSET=pipe_1_inlet"), std::string::npos);
    EXPECT_NE(text.find("NSET=pipe_1_outlet"), std::string::npos);
    EXPECT_EQ(text.find("NSET=pipe_2"), std::string::npos);
    expect_patch_test(m, dir);
}

TEST(CliAssembly, ThreeSolidsMeetingAtAnEdge) {
    // 1 and 2 share x = 1, 2 and 3 share y = 1; 1 and 3 touch along the edge x = 1, y = 1 only.
    TempDir dir;
    const fs::path step = write_solids(
        dir, "three", {box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1}), box({1, 1, 0}, {2, 2, 1})});
    const Meshed m = mesh_assembly(dir, step, "--size 0.25");
    expect_assembly(m, {"solid_1", "solid_2", "solid_3"}, {"joint_solid_1_solid_2", "joint_solid_2_solid_3"});
    EXPECT_NEAR(m.check["volume"].get<double>(), 3.0, 1e-9);
}

TEST(CliAssembly, DamSectionWithAPipeAcrossTheColumnJoint) {
    TempDir dir;
    const Meshed m = dam_section(dir, "--columns 2 --lifts 1 --width 4 --depth 3 --lift-height 1 --spacing 1 "
                                      "--diameter 0.05 --crossing-pipes 1");
    expect_assembly(m, {"block_1_1", "block_2_1"}, {"joint_block_1_1_block_2_1"});
    // Two serpentines and the crossing pipe, which is one group through both blocks.
    EXPECT_EQ(starting_with(m.surfaces, "pipe_").size(), 3u);
    for (const json& s : m.report["assembly"]["solids"]) EXPECT_GT(s["hexes"].get<int>(), 0);
    expect_patch_test(m, dir);
}

void expect_refused(const std::vector<TopoDS_Solid>& solids, const std::string& says) {
    TempDir dir;
    const fs::path step = write_solids(dir, "bad", solids);
    const fs::path out = dir / "bad.msh";
    const auto r = run_command(cli() + " mesh --assembly " + q(step) + " -o " + q(out));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;  // one line
    EXPECT_FALSE(fs::exists(out));
}

TEST(CliAssembly, GapBetweenSolidsIsExit2AndNoFile) {
    expect_refused({box({0, 0, 0}, {1, 1, 1}), box({1.002, 0, 0}, {2, 1, 1})}, "gap of 0.002");
}

TEST(CliAssembly, OverlapIsExit2AndNoFile) {
    expect_refused({box({0, 0, 0}, {1, 1, 1}), box({0.998, 0, 0}, {2, 1, 1})}, "overlap");
}

TEST(CliAssembly, PipeEndingOnAJointIsExit2AndNoFile) {
    expect_refused({piped_box(0), box({1, 0, 0}, {2, 1, 1})}, "does not run on");
}

#else

// The acceptance's section: 3 columns x 3 lifts of 20 x 15 x 3 blocks, a serpentine in each
// and two straight pipes, each through the three columns of a lift. 5.9 M cells, 1.6 M nodes:
// CalculiX's direct solver takes about 14 GB for the patch test.
TEST(CliAssemblyHeavy, DamSection3x3) {
    TempDir dir;
    const Meshed m = dam_section(dir, "--columns 3 --lifts 3 --width 20 --depth 15 --lift-height 3 "
                                      "--diameter 0.032 --crossing-pipes 2");
    std::vector<std::string> solids;
    for (int c = 1; c <= 3; ++c)
        for (int l = 1; l <= 3; ++l) solids.push_back("block_" + std::to_string(c) + "_" + std::to_string(l));
    std::vector<std::string> joints = starting_with(m.surfaces, "joint_");
    EXPECT_EQ(joints.size(), 12u);  // 6 between lifts, 6 between columns
    expect_assembly(m, solids, joints);
    EXPECT_EQ(starting_with(m.surfaces, "pipe_").size(), 11u);  // 9 serpentines, 2 crossing pipes
    expect_patch_test(m, dir);
}

#endif

}  // namespace
}  // namespace tubemesh
