// Tube recognition (paper §3.1) on solids built with OpenCASCADE: straight, arc and spline
// pipes, the same after splitting every tube face in two and after a STEP round trip, and the
// features that are not tubes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "geom/builders/block_builder.hpp"
#include "geom/builders/serpentine.hpp"
#include "geom/tubes/tubes.hpp"
#include "tests/support/geom_tubes_solids.hpp"

namespace tubemesh {
namespace {

using test::model_of;

constexpr double kR = 0.02;

TopoDS_Solid straight_box() {
    return test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::straight_spine({0.5, 0.5, -0.1}, {0.5, 0.5, 1.1})}, kR);
}
// A quarter circle round the box's z edge at x = y = 0: it meets faces y = 0 and x = 0 at
// right angles, so its end loops are exact circles.
TopoDS_Solid arc_box() {
    return test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::arc_spine({0, 0, 0.5}, 0.5, -15, 105)}, kR);
}
TopoDS_Solid spline_box() {
    return test::box_with_pipes(
        {0, 0, 0}, {1, 1, 1},
        {test::spline_spine({{-0.1, 0.5, 0.3}, {0.3, 0.6, 0.5}, {0.7, 0.4, 0.6}, {1.1, 0.5, 0.4}})}, kR);
}
TopoDS_Solid three_pipes_box() {
    return test::box_with_pipes(
        {0, 0, 0}, {1, 1, 1},
        {test::straight_spine({0.2, 0.2, -0.1}, {0.2, 0.2, 1.1}), test::arc_spine({0, 0, 0.5}, 0.5, -15, 105),
         test::spline_spine({{-0.1, 0.8, 0.3}, {0.3, 0.9, 0.5}, {0.7, 0.7, 0.6}, {1.1, 0.8, 0.4}})},
        kR);
}

std::string rejections(const geom::TubeSearch& s) {
    std::string out;
    for (const auto& r : s.rejected) out += r.reason + "\n";
    return out;
}

TEST(GeomTubes, StraightPipeIsOneTube) {
    const geom::Model model = model_of(straight_box());
    const geom::TubeSearch found = geom::find_tubes(model);
    ASSERT_EQ(found.tubes.size(), 1u) << rejections(found);
    const geom::TubeInfo& t = found.tubes[0];
    EXPECT_EQ(t.faces.size(), 1u);
    EXPECT_NE(t.hosts[0], t.hosts[1]);
    EXPECT_EQ(t.loops[0].size(), 1u);
    EXPECT_EQ(t.loops[1].size(), 1u);
    EXPECT_NEAR(t.radius_min, kR, 1e-9);
    EXPECT_NEAR(t.radius_max, kR, 1e-9);
    EXPECT_NEAR(t.length, 1.0, 1e-9);
    EXPECT_NEAR(t.loop_lengths[0], 2 * std::numbers::pi * kR, 1e-9);
    EXPECT_TRUE(std::isinf(t.min_curvature_radius));
    EXPECT_NEAR(t.max_kink_deg, 0, 1e-9);
}

TEST(GeomTubes, ArcPipeIsOneTubeWithItsBendRadius) {
    const geom::Model model = model_of(arc_box());
    const geom::TubeSearch found = geom::find_tubes(model);
    ASSERT_EQ(found.tubes.size(), 1u) << rejections(found);
    const geom::TubeInfo& t = found.tubes[0];
    EXPECT_NEAR(t.radius_min, kR, 1e-7);
    EXPECT_NEAR(t.radius_max, kR, 1e-7);
    EXPECT_NEAR(t.length, 0.5 * std::numbers::pi / 2, 1e-6);
    EXPECT_NEAR(t.min_curvature_radius, 0.5, 1e-5);
}

TEST(GeomTubes, SplinePipeIsOneTube) {
    const geom::Model model = model_of(spline_box());
    const geom::TubeSearch found = geom::find_tubes(model);
    ASSERT_EQ(found.tubes.size(), 1u) << rejections(found);
    const geom::TubeInfo& t = found.tubes[0];
    // MakePipe's B-spline wall is within ~3e-6 of the true pipe.
    EXPECT_NEAR(t.radius_min, kR, 1e-5);
    EXPECT_NEAR(t.radius_max, kR, 1e-5);
    EXPECT_GT(t.length, 1.0);
    EXPECT_TRUE(std::isfinite(t.min_curvature_radius));
}

TEST(GeomTubes, PipeWithARoundedCornerIsOneTubeOfThreeFaces) {
    // 0.3 straight, a quarter turn of radius 0.2, 0.3 straight.
    const TopoDS_Solid solid = test::box_with_pipes(
        {0, 0, 0}, {1, 1, 1}, {test::corner_spine({0.5, -0.1, 0.5}, {0.5, 0.5, 0.5}, {1.1, 0.5, 0.5}, 0.2)}, kR);
    for (int split = 0; split < 2; ++split) {
        const geom::TubeSearch found = geom::find_tubes(model_of(split ? test::split_closed_faces(solid) : solid));
        ASSERT_EQ(found.tubes.size(), 1u) << rejections(found);
        const geom::TubeInfo& t = found.tubes[0];
        EXPECT_EQ(t.faces.size(), split ? 6u : 3u);
        EXPECT_NEAR(t.radius_min, kR, 1e-7);
        EXPECT_NEAR(t.radius_max, kR, 1e-7);
        EXPECT_NEAR(t.length, 0.6 + 0.2 * std::numbers::pi / 2, 1e-5);
        EXPECT_NEAR(t.min_curvature_radius, 0.2, 1e-4);
        EXPECT_LT(t.max_kink_deg, 0.01);
    }
}

TEST(GeomTubes, MitredPipeIsOneTubeWithAKink) {
    const TopoDS_Solid solid = test::box_with_pipes(
        {0, 0, 0}, {1, 1, 1}, {test::corner_spine({0.5, -0.1, 0.5}, {0.5, 0.5, 0.5}, {1.1, 0.5, 0.5}, 0)}, kR);
    const geom::TubeSearch found = geom::find_tubes(model_of(solid));
    ASSERT_EQ(found.tubes.size(), 1u) << rejections(found);
    const geom::TubeInfo& t = found.tubes[0];
    EXPECT_EQ(t.faces.size(), 2u);
    // Opposite generator lines gain and lose equally at the mitre: their mean is the axis.
    EXPECT_NEAR(t.length, 1.0, 1e-6);
    EXPECT_NEAR(t.max_kink_deg, 90, 1e-6);
    EXPECT_TRUE(std::isinf(t.min_curvature_radius));
}

TEST(GeomTubes, ThreePipesAreThreeTubes) {
    const geom::TubeSearch found = geom::find_tubes(model_of(three_pipes_box()));
    EXPECT_EQ(found.tubes.size(), 3u) << rejections(found);
}

TEST(GeomTubes, SplitTubeFacesStillGiveOneTubePerPipe) {
    for (const TopoDS_Solid& solid : {straight_box(), arc_box(), spline_box(), three_pipes_box()}) {
        const geom::TubeSearch before = geom::find_tubes(model_of(solid));
        const geom::TubeSearch after = geom::find_tubes(model_of(test::split_closed_faces(solid)));
        ASSERT_EQ(after.tubes.size(), before.tubes.size()) << rejections(after);
        for (std::size_t i = 0; i < after.tubes.size(); ++i) {
            const geom::TubeInfo& t = after.tubes[i];
            EXPECT_EQ(t.faces.size(), 2u);
            EXPECT_EQ(t.loops[0].size(), 2u);
            EXPECT_EQ(t.loops[1].size(), 2u);
            EXPECT_NEAR(t.radius_min, before.tubes[i].radius_min, 1e-5);
            EXPECT_NEAR(t.length, before.tubes[i].length, 1e-5);
        }
    }
}

TEST(GeomTubes, StepRoundTripGivesTheSameTubes) {
    for (const TopoDS_Solid& solid : {straight_box(), arc_box(), spline_box(), three_pipes_box()}) {
        const geom::TubeSearch before = geom::find_tubes(model_of(solid));
        const geom::TubeSearch after = geom::find_tubes(model_of(test::step_round_trip(solid)));
        ASSERT_EQ(after.tubes.size(), before.tubes.size()) << rejections(after);
        for (std::size_t i = 0; i < after.tubes.size(); ++i) {
            EXPECT_EQ(after.tubes[i].faces.size(), before.tubes[i].faces.size());
            EXPECT_NEAR(after.tubes[i].radius_min, before.tubes[i].radius_min, 1e-6);
            EXPECT_NEAR(after.tubes[i].radius_max, before.tubes[i].radius_max, 1e-6);
            EXPECT_NEAR(after.tubes[i].length, before.tubes[i].length, 1e-6);
        }
    }
}

TEST(GeomTubes, BlindHoleIsNoTube) {
    const geom::TubeSearch found = geom::find_tubes(model_of(test::box_with_blind_hole(kR, 0.3)));
    EXPECT_TRUE(found.tubes.empty());
    ASSERT_FALSE(found.rejected.empty());
    EXPECT_NE(found.rejected[0].reason.find("one loop"), std::string::npos) << rejections(found);
}

TEST(GeomTubes, FlatSidedSlotIsNoTube) {
    const geom::TubeSearch found = geom::find_tubes(model_of(test::box_with_slot(0.01, 0.03)));
    EXPECT_TRUE(found.tubes.empty());
    ASSERT_FALSE(found.rejected.empty());
    EXPECT_NE(found.rejected[0].reason.find("planar"), std::string::npos) << rejections(found);
}

TEST(GeomTubes, PocketIsNoTube) {
    const geom::TubeSearch found = geom::find_tubes(model_of(test::box_with_pocket(0.03, 0.2)));
    EXPECT_TRUE(found.tubes.empty());
    ASSERT_FALSE(found.rejected.empty());
    EXPECT_NE(found.rejected[0].reason.find("one loop"), std::string::npos) << rejections(found);
}

TEST(GeomTubes, HoleTooLargeForTheLengthRuleIsNoTube) {
    // 2 pi 0.05 = 0.31 is more than 0.2 x the box's edge length 1.
    const TopoDS_Solid solid =
        test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::straight_spine({0.5, 0.5, -0.1}, {0.5, 0.5, 1.1})}, 0.05);
    const geom::TubeSearch found = geom::find_tubes(model_of(solid));
    EXPECT_TRUE(found.tubes.empty());
    ASSERT_FALSE(found.rejected.empty());
    EXPECT_NE(found.rejected[0].reason.find("too large"), std::string::npos) << rejections(found);
    // A looser rule accepts it.
    geom::TubeOptions loose;
    loose.max_loop_ratio = 0.5;
    EXPECT_EQ(geom::find_tubes(model_of(solid), loose).tubes.size(), 1u);
}

TEST(GeomTubes, PipeSolidsOwnEndCapsAreNoHosts) {
    const TopoDS_Solid solid = test::pipe_solid(test::straight_spine({0, 0, 0}, {0, 0, 1}), kR);
    const geom::TubeSearch found = geom::find_tubes(model_of(solid));
    EXPECT_TRUE(found.tubes.empty());
    EXPECT_TRUE(found.rejected.empty());  // no hole anywhere: nothing was even a candidate
}

// A serpentine whose U-bends are shorter than the first sampling step along its 255 m pipe: a
// section must not jump to the next run across a bend (the radius came out as 0.0146, the
// distances negative and St below zero).
TEST(TubeRecognition, TightUBendsOnALongSerpentineAreFollowed) {
    geom::SerpentineParams params;
    params.size = {20, 3, 1};
    params.spacing = 0.2;
    params.bend_radius = 0.1;
    const geom::BlockSpec spec = geom::serpentine_spec(params);
    const geom::TubeSearch search = geom::find_tubes(geom::build_block(spec).model);
    ASSERT_EQ(search.tubes.size(), 1u);
    const geom::TubeInfo& tube = search.tubes[0];
    EXPECT_NEAR(tube.radius_min, 0.016, 1e-4);
    EXPECT_NEAR(tube.radius_max, 0.016, 1e-4);
    EXPECT_NEAR(tube.min_curvature_radius, params.bend_radius, 0.05 * params.bend_radius);
    // The polyline's length less, at each right-angle corner, the 2R it cuts off plus the
    // quarter circle that replaces it.
    const std::vector<Vec3>& p = spec.pipes[0].points;
    double length = 0;
    for (std::size_t i = 1; i < p.size(); ++i)
        length += std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y, p[i].z - p[i - 1].z);
    length -= static_cast<double>(p.size() - 2) * (2 - std::numbers::pi / 2) * params.bend_radius;
    EXPECT_NEAR(tube.length, length, 1e-3 * length);
}

}  // namespace
}  // namespace tubemesh
