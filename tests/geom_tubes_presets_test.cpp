// Tube recognition, sizing and discretisation on every built-in block (geom/builders): each
// pipe is found as one tube of the pipe's radius, and the whole chain runs. The time of the
// tube side (not the build) is recorded as the test property "seconds".
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <optional>

#include "engine/core/timing.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/presets.hpp"
#include "engine/core/types.hpp"
#include "geom/sizing/discretize.hpp"

namespace tubemesh {
namespace {

class GeomTubesPresets : public testing::TestWithParam<std::string> {};

TEST_P(GeomTubesPresets, EveryPipeIsOneTubeAndDiscretises) {
    std::optional<geom::BuiltBlock> built;
    try {
        built.emplace(geom::build_block(geom::preset_spec(GetParam())));
    } catch (const Error& e) {
        GTEST_SKIP() << "the builder cannot build it (its own tests cover that): " << e.what();
    }
    const geom::BuiltBlock& block = *built;
    const auto start = Clock::now();
    const geom::TubeSearch found = geom::find_tubes(block.model);
    std::string why;
    for (const auto& r : found.rejected) why += r.reason + "\n";
    ASSERT_EQ(static_cast<int>(found.tubes.size()), block.info.pipe_count) << why;
    std::vector<double> radii;
    // The builders sweep B-spline paths into walls within 1e-3 of the radius (pipe_sweep.hpp).
    for (const geom::TubeInfo& t : found.tubes) {
        radii.push_back(t.radius_max);
        EXPECT_NEAR(t.radius_min, t.radius_max, 1e-3 * t.radius_max);
    }
    std::sort(radii.begin(), radii.end());
    std::vector<double> expected;
    for (double d : block.info.pipe_diameters) expected.push_back(d / 2);
    std::sort(expected.begin(), expected.end());
    for (std::size_t i = 0; i < radii.size(); ++i) EXPECT_NEAR(radii[i], expected[i], 1e-3 * expected[i]);

    const geom::SizePlan plan = geom::plan_sizes(block.model, found.tubes);
    const DiscreteGeometry geometry = geom::discretize(block.model, found.tubes, plan);
    ASSERT_EQ(geometry.tubes.size(), found.tubes.size());
    for (const TubeData& t : geometry.tubes) {
        EXPECT_EQ(t.ring1.size(), t.ring2.size());
        EXPECT_GE(t.stations.size(), 2u);
    }
    const double seconds = seconds_since(start);
    RecordProperty("seconds", std::to_string(seconds));
}

INSTANTIATE_TEST_SUITE_P(AllPresets, GeomTubesPresets, testing::ValuesIn([] {
                             std::vector<std::string> names;
                             for (const auto& p : geom::preset_list()) names.push_back(p.name);
                             return names;
                         }()),
                         [](const testing::TestParamInfo<std::string>& info) {
                             std::string n = info.param;
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

}  // namespace
}  // namespace tubemesh
