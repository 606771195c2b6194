// Assemblies: solids glued by the general fuse (one face numbering, shared faces known with
// their two solids, gaps and overlaps refused) and meshed as one conforming hybrid mesh, each
// shared face once. Small solids only: every test runs in CI.
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Trsf.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "engine/check/mesh_check.hpp"
#include "geom/assembly/assembly_occt.hpp"
#include "geom/assembly/mesh_assembly.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/engine_grid.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/import/step_write_occt.hpp"
#include "tests/support/error_of.hpp"

namespace tubemesh::geom {
namespace {

using tubemesh::testing::error_of;
namespace fs = std::filesystem;

TopoDS_Solid box(gp_Pnt lo, gp_Pnt hi) { return BRepPrimAPI_MakeBox(lo, hi).Solid(); }

// A unit box at (x0, y0) with a straight pipe of diameter 0.04 along y through its middle,
// or, with `through_x`, along x (from x0 to x0 + 1: its ends on the x faces).
TopoDS_Solid piped_box(double x0, bool through_x = false, double y0 = 0) {
    BlockSpec spec;
    spec.host.size = {1, 1, 1};
    PipeSpec pipe;
    pipe.kind = PathKind::Line;
    pipe.diameter = 0.04;
    pipe.points = through_x ? std::vector<Vec3>{{0, 0.5, 0.5}, {1, 0.5, 0.5}} : std::vector<Vec3>{{0.5, 0, 0.5}, {0.5, 1, 0.5}};
    spec.pipes.push_back(pipe);
    const BuiltBlock built = build_block(spec);
    gp_Trsf move;
    move.SetTranslation(gp_Vec(x0, y0, 0));
    return TopoDS::Solid(solid_of(built.model).Moved(TopLoc_Location(move)));
}

Assembly glue(const std::vector<TopoDS_Solid>& solids, double tolerance = 1e-6) {
    std::vector<NamedSolid> named;
    for (const TopoDS_Solid& s : solids) named.push_back({s, ""});
    AssemblyReport report;
    report.source = "test";
    report.format = "built";
    report.length_unit = "metre";
    return glue_solids(named, tolerance, report);
}

MeshOptions small_run(int threads = 2) {
    MeshOptions o;
    o.size = 0.25;
    o.threads = threads;
    return o;
}

// The properties every assembly mesh must have: valid and conforming as a whole, each solid's
// cells in its region, the whole volume the sum of the solids'.
void expect_conforming(const AssemblyRun& run, const Assembly& a) {
    const PipelineResult& r = run.run.result;
    EXPECT_TRUE(r.check.ok()) << describe(r.check);
    ASSERT_EQ(r.mesh.region_names.size(), a.solids().size());
    ASSERT_EQ(run.solids.size(), a.solids().size());
    double sum = 0;
    for (std::size_t k = 0; k < run.solids.size(); ++k) {
        EXPECT_EQ(r.mesh.region_names[k], a.solids()[k].name);
        EXPECT_GT(run.solids[k].tets, 0u) << a.solids()[k].name;
        EXPECT_NEAR(run.solids[k].volume, a.solids()[k].model.volume(), 2e-3 * a.solids()[k].model.volume());
        sum += run.solids[k].volume;
    }
    EXPECT_NEAR(r.check.volume, sum, 1e-9 * sum);
}

TEST(GeomAssembly, TwoBoxesTouchingAreGluedIntoOneSharedFace) {
    const Assembly a = glue({box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1})});
    ASSERT_EQ(a.solids().size(), 2u);
    EXPECT_EQ(a.face_count(), 11);  // 6 + 6, the face at x = 1 once
    ASSERT_EQ(a.shared_faces().size(), 1u);
    EXPECT_EQ(a.shared_faces()[0].first, 0);
    EXPECT_EQ(a.shared_faces()[0].second, 1);
    EXPECT_EQ(a.report().glued_faces, 1);
    EXPECT_EQ(a.solids()[0].name, "solid_1");
    // The shared face is one id in both solids' local-to-assembly maps.
    const int shared = a.shared_faces()[0].face;
    EXPECT_NE(std::find(a.solids()[0].face_ids.begin(), a.solids()[0].face_ids.end(), shared), a.solids()[0].face_ids.end());
    EXPECT_NE(std::find(a.solids()[1].face_ids.begin(), a.solids()[1].face_ids.end(), shared), a.solids()[1].face_ids.end());
}

// Each solid would be rounded on its own grid, and the faces it shares with it: refused, before
// any meshing.
TEST(GeomAssembly, ScaleFreeGridIsRefused) {
    const Assembly a = glue({box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1})});
    MeshOptions o = small_run();
    o.grid_bits = kScaleFreeGridBits;
    const std::string msg = error_of([&] { (void)mesh_assembly(a, o); });
    EXPECT_NE(msg.find("--scale-free does not apply to an assembly"), std::string::npos) << msg;
}

TEST(GeomAssembly, TwoBoxesMeshIntoOneConformingMesh) {
    const Assembly a = glue({box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1})});
    const AssemblyRun run = mesh_assembly(a, small_run());
    expect_conforming(run, a);
    EXPECT_GT(run.shared_triangles, 0u);
    EXPECT_NEAR(run.run.result.check.volume, 2.0, 1e-9);
    EXPECT_NEAR(run.run.result.check.boundary_area, 10.0, 1e-9);  // the joint is no boundary
}

TEST(GeomAssembly, BoxWithAPipeBesideAPlainBox) {
    const Assembly a = glue({piped_box(0), box({1, 0, 0}, {2, 1, 1})});
    const AssemblyRun run = mesh_assembly(a, small_run());
    expect_conforming(run, a);
    EXPECT_GT(run.solids[0].hexes, 0u);
    EXPECT_GT(run.solids[0].pyramids, 0u);
    EXPECT_EQ(run.solids[1].hexes, 0u);
    EXPECT_EQ(run.run.tubes, 1u);
}

TEST(GeomAssembly, ThreeSolidsMeetingAtAnEdge) {
    // A and B share x = 1, B and C share y = 1; A and C touch along the edge x = 1, y = 1 only.
    const Assembly a = glue({box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1}), box({1, 1, 0}, {2, 2, 1})});
    ASSERT_EQ(a.shared_faces().size(), 2u);
    const AssemblyRun run = mesh_assembly(a, small_run());
    expect_conforming(run, a);
    EXPECT_NEAR(run.run.result.check.volume, 3.0, 1e-9);
}

TEST(GeomAssembly, SameBytesForAnyThreadCount) {
    // A pipe through the joint: the solids and the ring join side by side.
    const Assembly a = glue({piped_box(0, true), piped_box(1, true)});
    const AssemblyRun one = mesh_assembly(a, small_run(1));
    const AssemblyRun two = mesh_assembly(a, small_run(2));
    EXPECT_TRUE(one.run.result.mesh == two.run.result.mesh);
}

TEST(GeomAssembly, GapWiderThanTheToleranceIsAnError) {
    const std::string msg = error_of([] { glue({box({0, 0, 0}, {1, 1, 1}), box({1.001, 0, 0}, {2, 1, 1})}); });
    EXPECT_NE(msg.find("gap of 0.001"), std::string::npos) << msg;
    EXPECT_NE(msg.find("solid_1"), std::string::npos) << msg;
}

TEST(GeomAssembly, GapWithinTheToleranceIsGlued) {
    const Assembly a = glue({box({0, 0, 0}, {1, 1, 1}), box({1 + 1e-7, 0, 0}, {2, 1, 1})});
    EXPECT_EQ(a.shared_faces().size(), 1u);
}

TEST(GeomAssembly, OverlapIsAnError) {
    const std::string msg = error_of([] { glue({box({0, 0, 0}, {1, 1, 1}), box({0.999, 0, 0}, {2, 1, 1})}); });
    EXPECT_NE(msg.find("overlap"), std::string::npos) << msg;
}

std::vector<std::string> surface_groups_of(const AssemblyRun& run) { return run.run.result.mesh.surface_group_names; }

bool has(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(GeomAssembly, PipeThroughTheJointIsOnePipe) {
    const Assembly a = glue({piped_box(0, true), piped_box(1, true)});
    const AssemblyRun run = mesh_assembly(a, small_run());
    expect_conforming(run, a);
    const HybridMesh& mesh = run.run.result.mesh;
    const std::vector<std::string> groups = surface_groups_of(run);
    EXPECT_TRUE(has(groups, "pipe_1"));
    EXPECT_FALSE(has(groups, "pipe_2"));  // the second piece is the same pipe
    EXPECT_TRUE(has(groups, "joint_solid_1_solid_2"));
    EXPECT_GT(run.solids[0].hexes, 0u);
    EXPECT_EQ(run.solids[0].hexes, run.solids[1].hexes);
    // The joint's quads (the ring's cross-section) and triangles are interior faces, stored once.
    index_t joint_quads = 0;
    const FaceBlock& quads = mesh.block(FaceKind::Quad);
    for (index_t g : quads.group) joint_quads += mesh.surface_group_names[g] == "joint_solid_1_solid_2";
    EXPECT_GT(joint_quads, 0u);
    // Two rims (inlet and outlet), none at the joint.
    EXPECT_EQ(run.run.result.description.node_sets.size(), 2u);
}

// Tubes 1 and 2 are one pipe through the joint, tube 3 a pipe of its own: pipe_1 and pipe_2, no
// gap where the second piece's number was.
TEST(GeomAssembly, PipesAreNumberedWithoutGaps) {
    const Assembly a = glue({piped_box(0, true), piped_box(1, true), piped_box(0, true, 1)});
    const AssemblyRun run = mesh_assembly(a, small_run());
    expect_conforming(run, a);
    std::vector<std::string> pipes;
    for (const std::string& g : surface_groups_of(run))
        if (g.rfind("pipe_", 0) == 0) pipes.push_back(g);
    EXPECT_EQ(pipes, (std::vector<std::string>{"pipe_1", "pipe_2"}));
    // Each pipe's rims carry its name, and each pipe group is described by its CAD surface.
    std::vector<std::string> rims;
    for (const NamedNodeSet& set : run.run.result.description.node_sets) rims.push_back(set.name);
    std::sort(rims.begin(), rims.end());
    EXPECT_EQ(rims, (std::vector<std::string>{"pipe_1_inlet", "pipe_1_outlet", "pipe_2_inlet", "pipe_2_outlet"}));
    const HybridMesh& mesh = run.run.result.mesh;
    for (std::size_t g = 0; g < mesh.surface_group_names.size(); ++g)
        if (mesh.surface_group_names[g].rfind("pipe_", 0) == 0) {
            EXPECT_EQ(run.run.result.description.surface_groups[g].surface_kind, "cylinder") << mesh.surface_group_names[g];
        }
}

TEST(GeomAssembly, StepKeepsTheSolidsNames) {
    const fs::path dir = fs::path(::testing::TempDir()) / "tubemesh_geom_assembly";
    fs::create_directories(dir);
    const Assembly a = glue({box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1})});
    std::vector<NamedShape> names{{solid_of(a.solids()[0].model), "left"}, {solid_of(a.solids()[1].model), "right"}};
    write_step_shape(compound_of(a), dir / "two.step", "metre", names);
    const Assembly read = import_assembly((dir / "two.step").string());
    ASSERT_EQ(read.solids().size(), 2u);
    EXPECT_EQ(read.solids()[0].name, "left");
    EXPECT_EQ(read.solids()[1].name, "right");
    EXPECT_EQ(read.shared_faces().size(), 1u);
}

}  // namespace
}  // namespace tubemesh::geom
