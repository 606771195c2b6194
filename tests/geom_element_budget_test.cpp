// The element budget (geom/sizing/element_budget.hpp): its estimate is a lower bound of what the
// phases really make, kind by kind, and a run it refuses is refused before meshing with the
// smallest S that would fit — which then does fit.
#include <gtest/gtest.h>

#include <string>

#include "engine/pipeline/pipeline.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/sizing/element_budget.hpp"
#include "geom/prepare.hpp"
#include "tests/support/error_of.hpp"

namespace {

using namespace tubemesh;

struct Case {
    const char* preset;
    double size;  // 0: the default
};

class ElementBudgetPreset : public ::testing::TestWithParam<Case> {};

TEST_P(ElementBudgetPreset, EstimateIsALowerBoundOfEveryKind) {
    const geom::BuiltBlock block = geom::build_block(geom::preset_spec(GetParam().preset));
    geom::PrepareOptions po;
    po.sizing.size = GetParam().size;
    const geom::PreparedModel p = geom::prepare_model(block.model, po);
    MeshOptions mo;
    mo.size = GetParam().size;
    const PipelineResult r = run_pipeline(p.pipeline_input(), mo);
    const geom::ElementEstimate& e = p.estimate;
    const double tets = r.mesh.cell_count(CellKind::Tet), hexes = r.mesh.cell_count(CellKind::Hex);
    const double pyramids = r.mesh.cell_count(CellKind::Pyramid), triangles = r.mesh.face_count(FaceKind::Tri);
    std::printf("  %s: estimate tets %.0f / %.0f, triangles %.0f / %.0f, hexes %.0f / %.0f, pyramids %.0f / %.0f\n",
                GetParam().preset, e.tets, tets, e.triangles, triangles, e.hexes, hexes, e.pyramids, pyramids);
    EXPECT_GT(e.tets, 0.1 * tets);  // a bound that says something
    EXPECT_LE(e.tets, tets);
    EXPECT_LE(e.triangles, triangles);
    EXPECT_GT(e.hexes, 0);
    EXPECT_LE(e.hexes, hexes);
    EXPECT_LE(e.pyramids, pyramids);
}

INSTANTIATE_TEST_SUITE_P(Presets, ElementBudgetPreset,
                         ::testing::Values(Case{"straight-pipe", 0}, Case{"arc-pipe", 0}, Case{"three-pipes", 0},
                                           Case{"paper-ex3", 40}),
                         [](const auto& info) {
                             std::string n = info.param.preset;
                             for (char& c : n)
                                 if (c == '-') c = '_';
                             return n;
                         });

TEST(ElementBudget, RefusedRunNamesTheSmallestSizeThatFitsAndThatSizeFits) {
    const geom::BuiltBlock block = geom::build_block(geom::preset_spec("straight-pipe"));
    geom::PrepareOptions po;
    po.sizing.size = 0.2;
    po.budget.max_elements = 5000;
    const std::string message = tubemesh::testing::error_of([&] { geom::prepare_model(block.model, po); });
    ASSERT_NE(message.find("the mesh size S = 0.2 (given) is too small"), std::string::npos) << message;
    EXPECT_NE(message.find("--max-elements 5e+03"), std::string::npos) << message;
    const std::size_t at = message.find("give --size ");
    ASSERT_NE(at, std::string::npos) << message;
    const double fitting = std::stod(message.substr(at + 12));
    EXPECT_GT(fitting, 0.2);
    po.sizing.size = fitting;
    const geom::PreparedModel p = geom::prepare_model(block.model, po);
    EXPECT_LE(p.estimate.total(), 5000);
    EXPECT_GT(p.estimate.total(), 0.9 * 5000);  // the smallest that fits, to the bisection's 1 % and rounding
}

TEST(ElementBudget, TinySweepSizeIsBlamedOnTheRings) {
    const geom::BuiltBlock block = geom::build_block(geom::preset_spec("straight-pipe"));
    geom::PrepareOptions po;
    po.sizing.sweep_size = 1e-4;
    po.budget.max_elements = 1e6;
    const std::string message = tubemesh::testing::error_of([&] { geom::prepare_model(block.model, po); });
    EXPECT_NE(message.find("the sweep size St = 0.0001 (given) is too small"), std::string::npos) << message;
    EXPECT_NE(message.find("--sweep-size"), std::string::npos) << message;
}

TEST(ElementBudget, DefaultLimitIsThisMachinesMemory) {
    const double memory = geom::physical_memory_bytes();
    ASSERT_GT(memory, 0);
    EXPECT_DOUBLE_EQ(geom::element_limit({}), memory / geom::kBytesPerElementAtLeast);
    geom::ElementBudget given;
    given.max_elements = 1234;
    EXPECT_DOUBLE_EQ(geom::element_limit(given), 1234);
}

}  // namespace
