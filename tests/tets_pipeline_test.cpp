// Acceptance of the tet step (paper §5) through the real pipeline: on every builder
// preset and on random blocks (geom/builders/random_block.hpp) at geom's default sizes, every
// front triangle is a face of one tet on its inner side, no tet is inverted, the tets' volume
// is the front's to 1e-9 relative and check_mesh finds nothing; on the paper's three examples
// and the serpentine lift, tet collapse min >= 0.30, mean >= 0.80, none below 0.20
// (tets_pipeline_checks.hpp measures all of it from the mesh).
//
// One source, three executables (one ctest test per block and bar, so `ctest -j` spreads them):
//  * test_tets_pipeline (CI): every preset but the serpentine lift, seeds 1-kCiSeeds; the
//    minimum bars (min >= 0.30, none below 0.20) on the paper's three examples.
// (Determinism of the full mesh is pipeline_test.cpp's.)
//  * test_tets_pipeline_heavy (TUBEMESH_TETS_HEAVY, label heavy): the serpentine lift (about
//    500 k tets), its minimum bars, and the remaining seeds up to 50; seeds 51-150 beyond the
//    acceptance (fill, none below 0.20, any tet below 0.30 one with four front points).
//  * test_tets_pipeline_gaps (TUBEMESH_TETS_GAPS, labels heavy and known_gap): the mean bar,
//    which no block meets yet. Measured at these sizes: paper-ex1 0.679, paper-ex2
//    0.719, paper-ex3 0.766, serpentine lift 0.671 (minima 0.344 / 0.319 / 0.361 / 0.310).
//    12-22 % of the tets have all four nodes on the front, many of them the two tets that
//    fill the pit between four pyramids around a ring node (collapse 0.68 on a flat ring, and
//    only a new point there would do better), and the tets with two or three front nodes
//    average about 0.60; smoothing and flips leave both where they are.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "engine/sizing/tet_size_caps.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "geom/builders/random_block.hpp"
#include "geom/prepare.hpp"
#include "tests/support/tets_pipeline_checks.hpp"

namespace tubemesh::tets_acceptance {
namespace {

// Where the tet step's quality bar applies: the paper's examples and the serpentine lift.
const char* const kQualityPresets[] = {"paper-ex1", "paper-ex2", "paper-ex3", "serpentine-lift"};
// The one whose mean bar (0.80) holds at its default size, asserted in CI (at
// S 20.55, 20,106 tets, mean 0.802, min 0.397); the others are the gaps executable's.
const char* const kMeanMetPreset = "paper-ex3";

std::string param_name(std::string n) {
    for (char& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return n;
}

// Seeds 1..kCiSeeds run in CI (about 120 s on 2 cores), the rest up to kLastSeed in the heavy
// suite (about 125 s more): all 50 with the presets would exceed CI's 3 minutes.
constexpr int kCiSeeds = 20, kLastSeed = 50;
// Seeds past the acceptance's 50, heavy only (about 75 s on 2 cores): the minimum bar of 0.30
// is the tet step's for the paper's examples and the lift, and 6 of these 100 blocks fall below it
// (lowest 0.271, seed 60; 12 and 0.263 before the pyramid layer lowered facing apexes together
// and tried a wider wedge apex), always at a tet whose four points the front
// fixes: two rings' apex layers facing each other across a narrow gap, or a ring's end pyramid
// over its host face (an oblique one, or a flat host triangle on the end edge). No move
// reaches such a tet, and the rescue's flips and new points do not lift these; the tet step
// must still fill the front, keep every tet at 0.20 or more, and leave no tet with a free
// point that poor.
constexpr int kWiderFirstSeed = 51, kWiderLastSeed = 150;
// The one preset too big for CI.
const char* const kHeavyPreset = "serpentine-lift";

// Built, prepared and meshed once per process: the tests of one block share one run, and
// only the figures are kept.
const TetFigures& figures(const std::string& name, const geom::BlockSpec& spec) {
    static std::map<std::string, TetFigures> cache;
    auto it = cache.find(name);
    if (it == cache.end()) {
        it = cache.emplace(name, measure_tets(name, spec)).first;
        std::printf("%s", summary(it->second).c_str());
    }
    return it->second;
}

const TetFigures& preset_figures(const std::string& name) { return figures(name, geom::preset_spec(name)); }

std::string preset_test_name(const ::testing::TestParamInfo<std::string>& i) { return param_name(i.param); }

class PresetTets : public ::testing::TestWithParam<std::string> {};
class SeedTets : public ::testing::TestWithParam<int> {};
class PresetTetMinimum : public ::testing::TestWithParam<std::string> {};
class PresetTetMean : public ::testing::TestWithParam<std::string> {};
class WiderSeedTets : public ::testing::TestWithParam<int> {};

// The quality presets of this executable (all but the heavy one in CI, only it in the heavy
// suite, all four in the gaps executable).
std::vector<std::string> quality_presets(bool ci, bool heavy) {
    std::vector<std::string> names;
    for (const char* n : kQualityPresets)
        if ((std::string(n) == kHeavyPreset) ? heavy : ci) names.push_back(n);
    return names;
}

#ifndef TUBEMESH_TETS_GAPS

const TetFigures& seed_figures(int seed) {
    return figures("seed " + std::to_string(seed), geom::random_block_spec(static_cast<std::uint64_t>(seed)));
}

// The presets of this executable: all but the heavy one in CI, only it in the heavy suite.
std::vector<std::string> preset_names(bool heavy) {
    std::vector<std::string> names;
    for (const geom::PresetInfo& p : geom::preset_list())
        if ((p.name == kHeavyPreset) == heavy) names.push_back(p.name);
    return names;
}

std::string seed_test_name(const ::testing::TestParamInfo<int>& i) { return "seed" + std::to_string(i.param); }

TEST_P(PresetTets, FillTheFront) { expect_tets_fill_the_front(preset_figures(GetParam())); }
TEST_P(SeedTets, FillTheFront) { expect_tets_fill_the_front(seed_figures(GetParam())); }
TEST_P(WiderSeedTets, FillTheFrontWithNoTetBelowTheFloor) {
    const TetFigures& f = seed_figures(GetParam());
    expect_tets_fill_the_front(f);
    EXPECT_EQ(f.below_0_2, 0u) << summary(f);
    // Below the bar only where the front fixes all four points: the optimisation and the
    // rescue reach every tet that has a free point.
    if (f.min_collapse < 0.30) {
        EXPECT_EQ(f.worst_front_nodes, 4) << summary(f);
    }
}
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(WiderSeedTets);
// Shares the run of PresetTets' block (figures() meshes each block once per process).
TEST_P(PresetTetMinimum, CollapseMinimum) { expect_tet_minimum(preset_figures(GetParam())); }
TEST_P(PresetTetMean, CollapseMean) { expect_tet_mean(preset_figures(GetParam())); }
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(PresetTetMean);

#ifndef TUBEMESH_TETS_HEAVY
// The serpentine lift with a thin ring (`mesh --sweep-size 0.128 --circ 8 --layers 3`, about
// 260 k tets, a few seconds): where the pipe bends, one pyramid's apex lies 0.01 degrees off
// the plane of the next pyramid's side face, and the tet on that face had the apex as its
// fourth point: four front points, collapse 9e-5, no move or flip to lift it (minimum
// 0.000). The rescue's new point over the face lifts it: minimum 0.312 for this block built in
// memory (0.279 for the CLI on make-block's STEP file, whose tets differ slightly).
TEST(ThinRingTets, NoFlatTetWherePyramidFacesMeet) {
    MeshOptions options;
    options.sweep_size = 0.128;
    options.circumferential = 8;
    options.sweep.radial_layers = 3;
    const TetFigures f = measure_tets("serpentine-lift thin ring", geom::preset_spec("serpentine-lift"), options);
    std::printf("%s", summary(f).c_str());
    expect_tets_fill_the_front(f);
    EXPECT_GE(f.min_collapse, 0.25);
    EXPECT_EQ(f.below_0_2, 0);
}

// A box with straight cooling pipes (diameter 0.032) along x from wall to wall, at height
// z and at each y of `ys`.
geom::BlockSpec straight_pipes(const std::string& name, const Vec3& box, std::initializer_list<double> ys, double z) {
    geom::BlockSpec spec;
    spec.name = name;
    spec.host.size = box;
    for (double y : ys) {
        geom::PipeSpec pipe;
        pipe.kind = geom::PathKind::Line;
        pipe.diameter = 0.032;
        pipe.points = {{0, y, z}, {box.x, y, z}};
        spec.pipes.push_back(pipe);
    }
    return spec;
}

// Pipes 0.5 beside the long side walls of an 8 x 40 x 3 block (default S 1.64, about 47 k tets,
// under a second). The tet step grades from the rings' quads (0.05) and asks for about 0.31 at
// the walls, but the surface field, which grades only from the end walls' ring holes, gave the
// side walls triangles of about 1 there: the tets on them were caps (collapse 0.287). The
// surface is now meshed again with caps where its triangles pass twice the tets' size
// (engine/sizing/tet_size_caps.hpp), and no triangle of the kept pass is left that large.
geom::BlockSpec pipes_beside_walls() { return straight_pipes("two pipes beside the walls", {8, 40, 3}, {0.5, 39.5}, 1.5); }

TEST(PipesBesideWalls, SurfaceTrianglesFitTheTetsBesideThem) {
    const geom::BlockSpec spec = pipes_beside_walls();
    const MeshOptions options;
    const geom::BuiltBlock block = geom::build_block(spec);
    const geom::PreparedModel prepared = geom::prepare_model(block.model, geom::prepare_options(options));
    const PipelineResult r = run_pipeline(prepared.pipeline_input(), options, Stage::Tets);
    EXPECT_FALSE(r.surface_size_caps.empty());
    EXPECT_TRUE(r.warnings.empty());
    // The kept surface: none of its triangles too large for the tets beside them.
    const TetSizeCaps too_large(r.mesh, r.sweep.outer_quads, prepared.geometry.size, options.tets.gradation,
                                options.size_growth);
    EXPECT_TRUE(too_large.caps(r.mesh, 0).empty());
    const TetFigures f = measure_tets(spec.name, r);
    std::printf("%s", summary(f).c_str());
    expect_tets_fill_the_front(f);
    expect_tet_minimum(f);
}

// The passes that add caps give the same surface for 1 and 2 threads (the presets in
// pipeline_test.cpp's determinism tests need no caps).
TEST(PipesBesideWalls, CappedSurfaceIsTheSameForAnyThreadCount) {
    const geom::BuiltBlock block = geom::build_block(pipes_beside_walls());
    std::vector<PipelineResult> runs;
    for (int threads : {1, 2}) {
        MeshOptions options;
        options.threads = threads;
        const geom::PreparedModel prepared = geom::prepare_model(block.model, geom::prepare_options(options));
        runs.push_back(run_pipeline(prepared.pipeline_input(), options, Stage::Surface));
    }
    ASSERT_FALSE(runs[0].surface_size_caps.empty());
    EXPECT_EQ(runs[0].surface_size_caps.size(), runs[1].surface_size_caps.size());
    EXPECT_EQ(runs[0].mesh.x, runs[1].mesh.x);
    EXPECT_EQ(runs[0].mesh.y, runs[1].mesh.y);
    EXPECT_EQ(runs[0].mesh.z, runs[1].mesh.z);
    EXPECT_EQ(runs[0].mesh.block(FaceKind::Tri).nodes, runs[1].mesh.block(FaceKind::Tri).nodes);
}

// Two straight pipes square to both end walls of a 4 x 3 x 3 block, like every cooling pipe of
// a dam lift (about 40 k tets, under a second). The paper's candidates put the end pyramids'
// apexes half an axial step from the host, their lateral faces 34 degrees from it: the tets
// there, with all four points fixed (the wedge tet on the host edge, or the apex with three
// host nodes), were the worst, collapse 0.291 here (0.2895 on the 10-pipe 20 x 15 x 3 lift).
// The end quads' apexes are now lowered and shifted away from the host to open that wedge to
// 48 degrees (engine/pyramids/wedge.hpp): 0.335.
TEST(PipesSquareToEndWalls, NoWedgeTetAtTheHost) {
    const geom::BlockSpec spec = straight_pipes("two pipes square to the end walls", {4, 3, 3}, {0.75, 2.25}, 1.5);
    const TetFigures f = measure_tets(spec.name, spec);
    std::printf("%s", summary(f).c_str());
    expect_tets_fill_the_front(f);
    expect_tet_minimum(f);
}

INSTANTIATE_TEST_SUITE_P(All, PresetTets, ::testing::ValuesIn(preset_names(false)), preset_test_name);
INSTANTIATE_TEST_SUITE_P(Random, SeedTets, ::testing::Range(1, kCiSeeds + 1), seed_test_name);
INSTANTIATE_TEST_SUITE_P(Paper, PresetTetMinimum, ::testing::ValuesIn(quality_presets(true, false)), preset_test_name);
INSTANTIATE_TEST_SUITE_P(Paper, PresetTetMean, ::testing::Values(std::string(kMeanMetPreset)), preset_test_name);
#else
INSTANTIATE_TEST_SUITE_P(Heavy, PresetTets, ::testing::ValuesIn(preset_names(true)), preset_test_name);
INSTANTIATE_TEST_SUITE_P(Random, SeedTets, ::testing::Range(kCiSeeds + 1, kLastSeed + 1), seed_test_name);
INSTANTIATE_TEST_SUITE_P(Wider, WiderSeedTets, ::testing::Range(kWiderFirstSeed, kWiderLastSeed + 1), seed_test_name);
INSTANTIATE_TEST_SUITE_P(Heavy, PresetTetMinimum, ::testing::ValuesIn(quality_presets(false, true)), preset_test_name);
#endif

#else  // TUBEMESH_TETS_GAPS

TEST_P(PresetTetMean, CollapseMean) { expect_tet_mean(preset_figures(GetParam())); }
// The mean bar where it does not hold yet (kMeanMetPreset runs in CI).
std::vector<std::string> mean_gap_presets() {
    std::vector<std::string> names;
    for (const std::string& n : quality_presets(true, true))
        if (n != kMeanMetPreset) names.push_back(n);
    return names;
}
INSTANTIATE_TEST_SUITE_P(Paper, PresetTetMean, ::testing::ValuesIn(mean_gap_presets()), preset_test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(PresetTets);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(SeedTets);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(PresetTetMinimum);

#endif

}  // namespace
}  // namespace tubemesh::tets_acceptance
