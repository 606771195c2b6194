// Acceptance of the hex rings, the surface and the pyramid layer through the real
// pipeline, on every builder preset, on random blocks (geom/builders/random_block.hpp) and on
// pipes close to each other and to a face: pipeline_acceptance_checks.hpp lists what is
// measured and the bars.
//
// Every bar of the three steps on every preset, seeds 1-50 and the close pipes, in CI (the
// 40 seeds 11-50 took 57 s on one core of the loaded machine).
// One ctest test per block and bar, so `ctest -j` spreads them.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "geom/builders/presets.hpp"
#include "geom/builders/random_block.hpp"
#include "tests/support/pipeline_acceptance_checks.hpp"

namespace tubemesh::acceptance {
namespace {

// The paper's three examples and the serpentine lift: where the pyramid bar applies.
bool pyramid_quality_preset(const std::string& name) {
    return name == "paper-ex1" || name == "paper-ex2" || name == "paper-ex3" || name == "serpentine-lift";
}

std::string param_name(std::string n) {
    for (char& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return n;
}

// Measured once per process: the tests of one block share one run of the pipeline.
const CaseFigures& figures(const std::string& name, const geom::BlockSpec& spec, const MeshOptions& options = {}) {
    static std::map<std::string, CaseFigures> cache;
    auto it = cache.find(name);
    if (it == cache.end()) {
        it = cache.emplace(name, measure_case(name, spec, {}, options)).first;
        std::printf("%s", summary(it->second).c_str());
    }
    return it->second;
}

const CaseFigures& preset_figures(const std::string& name) { return figures(name, geom::preset_spec(name)); }
const CaseFigures& seed_figures(int seed) {
    return figures("seed " + std::to_string(seed), geom::random_block_spec(static_cast<std::uint64_t>(seed)));
}

std::vector<std::string> preset_names() {
    std::vector<std::string> names;
    for (const geom::PresetInfo& p : geom::preset_list()) names.push_back(p.name);
    return names;
}

std::vector<int> seeds(int first, int last) {
    std::vector<int> s;
    for (int i = first; i <= last; ++i) s.push_back(i);
    return s;
}

// Two straight pipes of diameter 0.1 along x, `gap` apart (axis to axis), their axes `height`
// over the bottom face of a 3 x 2 x 1.5 box: the sizing guards leave little room between the
// ideal apexes and the other ring's layer or the face, so fronts there are rejected by the
// normal criteria and served by existing nodes, relaxed criteria or try nodes. The layer must
// still close without self-intersection.
const CaseFigures& close_pipes_figures(double gap, double height, double apart_factor = PyramidOptions{}.apart_factor) {
    geom::BlockSpec s;
    s.name = "close-pipes";
    s.length_unit = "metre";
    s.host.kind = geom::HostSpec::Kind::Box;
    s.host.size = {3, 2, 1.5};
    for (double y : {0.9, 0.9 + gap}) {
        geom::PipeSpec p;
        p.kind = geom::PathKind::Line;
        p.diameter = 0.1;
        p.points = {{0, y, height}, {3, y, height}};
        s.pipes.push_back(p);
    }
    MeshOptions options;
    options.pyramids.apart_factor = apart_factor;
    return figures("close pipes " + std::to_string(gap) + " apart at " + std::to_string(height) + ", apart factor " +
                       std::to_string(apart_factor),
                   s, options);
}
// Close enough that with the paper's apexes (apart_factor 0) the normal criteria reject fronts
// between the rings and over the face (38 here). At 0.6 apart and 0.35 high the only fronts
// rejected were the rings' end quads, whose ideal apex was too close to the host; since those
// get an apex placed for the wedge there (engine/pyramids/wedge.hpp), none is.
constexpr double kCloseGap = 0.5, kCloseHeight = 0.3;

std::string preset_test_name(const ::testing::TestParamInfo<std::string>& info) { return param_name(info.param); }
std::string seed_test_name(const ::testing::TestParamInfo<int>& info) { return "seed" + std::to_string(info.param); }

void expect_accepted(const CaseFigures& f) {
    expect_rings_accepted(f);
    // Since the sweep puts the end loops' nodes on the wall too: largest 4.3e-12 r on every
    // preset and seeds 1-50 (was 3.6e-5 r).
    expect_wall_nodes_accepted(f);
    expect_surface_accepted(f);
    // Since B-rep edges follow the size field, curved edges turn by at most 0.065 rad per
    // segment and the grading sweep takes smaller steps: on every preset and seeds 1-50 the
    // smallest angle is 30.0 degrees, 97.8 % >= 40 (was 17.1 and 94.0 %); flat faces 7.0e-4
    // (was 3.1e-3); neighbour ratio 1.498 (was 2.19).
    expect_triangle_angles_accepted(f);
    expect_flat_area_accepted(f);
    expect_neighbor_ratio_accepted(f);
    expect_pyramid_layer_accepted(f);
}

class PresetAcceptance : public ::testing::TestWithParam<std::string> {};
class SeedAcceptance : public ::testing::TestWithParam<int> {};

TEST_P(PresetAcceptance, RingsSurfaceAndPyramids) {
    const CaseFigures& f = preset_figures(GetParam());
    expect_accepted(f);
    if (pyramid_quality_preset(GetParam())) expect_pyramid_quality_accepted(f);
}

TEST_P(SeedAcceptance, RingsSurfaceAndPyramids) { expect_accepted(seed_figures(GetParam())); }

INSTANTIATE_TEST_SUITE_P(All, PresetAcceptance, ::testing::ValuesIn(preset_names()), preset_test_name);
INSTANTIATE_TEST_SUITE_P(Random, SeedAcceptance, ::testing::ValuesIn(seeds(1, 50)), seed_test_name);

TEST(CloseTubes, RejectedFrontsAreServedWithRelaxedCriteria) {
    const CaseFigures& f = close_pipes_figures(kCloseGap, kCloseHeight, 0.0);
    expect_accepted(f);
    const PyramidStats& st = f.pyramids.stats;
    index_t tries = 0;
    for (index_t k : st.try_node) tries += k;
    EXPECT_GT(st.rejected, 0u) << "no front was rejected: the pipes are not close enough to test the relaxed pass";
    EXPECT_GT(st.existing_relaxed + tries, 0u) << "no front needed the relaxed criteria";
}

// The same pipes with the facing apexes lowered together (the default apart_factor): the
// fronts between the rings get their ideal apex, lowered, and none needs the relaxed pass.
TEST(CloseTubes, FacingFrontsAreLoweredTogether) {
    const CaseFigures& f = close_pipes_figures(kCloseGap, kCloseHeight);
    expect_accepted(f);
    const PyramidStats& st = f.pyramids.stats;
    EXPECT_GT(st.lowered, 0u);
    EXPECT_LT(st.rejected, close_pipes_figures(kCloseGap, kCloseHeight, 0.0).pyramids.stats.rejected);
}

// Pipes 0.35 apart, 0.25 over the bottom face: the sizing guards leave the pyramid layer 2.2 St
// of room (geom/sizing/sizing.hpp), which cuts St to about 0.057 here; with the paper's 0.98 St the
// layer could not close (the rings' facing corners 0.73 h apart, the criteria need ~1.2 h).
TEST(CloseTubes, VeryClosePipesGetAClosedPyramidLayer) {
    const CaseFigures& f = close_pipes_figures(0.35, 0.25);
    expect_accepted(f);
}




}  // namespace
}  // namespace tubemesh::acceptance
