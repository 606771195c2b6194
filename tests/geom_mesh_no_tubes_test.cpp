// A solid without tubular holes gets an all-tetrahedral mesh and a warning: the whole pipeline through geom::mesh_model gives only tetrahedra, passes
// the check, fills the solid's volume and says why there are no hexes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/quality/quality.hpp"
#include "geom/mesh_file.hpp"
#include "tests/support/geom_tubes_solids.hpp"

namespace {

using namespace tubemesh;

void expect_all_tets(const TopoDS_Solid& solid, double volume, double size) {
    MeshOptions options;
    options.size = size;
    const geom::MeshRun run = geom::mesh_model(test::model_of(solid), options);
    const PipelineResult& r = run.result;
    EXPECT_EQ(run.tubes, 0u);
    EXPECT_EQ(r.reached, Stage::Tets);
    EXPECT_EQ(r.mesh.cell_count(CellKind::Hex), 0u);
    EXPECT_EQ(r.mesh.cell_count(CellKind::Pyramid), 0u);
    EXPECT_GT(r.mesh.cell_count(CellKind::Tet), 100u);
    EXPECT_TRUE(std::any_of(r.warnings.begin(), r.warnings.end(),
                            [](const std::string& w) { return w.find("no tubular hole") != std::string::npos; }));
    // mesh_model ran the full check (it throws otherwise): no violation, the volume it summed.
    EXPECT_TRUE(r.check.ok());
    EXPECT_NEAR(r.check.volume, volume, 2e-3 * volume);  // curved faces are chords
    EXPECT_GT(r.quality.tet_collapse.min, 0.1);  // no sliver (the tet step bars 0.2 on its own cases)
}

TEST(MeshWithoutTubes, BoxIsAllTets) {
    expect_all_tets(test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {}, 0.05), 1.0, 0.2);
}

TEST(MeshWithoutTubes, BlindHoleIsNotATubeAndIsMeshedWithTets) {
    const double r = 0.1, depth = 0.4;
    expect_all_tets(test::box_with_blind_hole(r, depth), 1.0 - M_PI * r * r * depth, 0.15);
}

}  // namespace
