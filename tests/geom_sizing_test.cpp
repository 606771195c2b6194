// Sizing (paper §2): defaults, the three rules in the paper's order on constructed cases, and
// the guards that keep a ring and its pyramids clear of faces, other rings and the bend.
#include <BRepBndLib.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <TopoDS_Compound.hxx>
#include <gtest/gtest.h>

#include "engine/core/types.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/sizing/sizing.hpp"
#include "tests/support/geom_tubes_solids.hpp"

namespace tubemesh {
namespace {

constexpr double kR = 0.02;

// `local_ring`: rules 1 and 2 and the boundary and rings guards are left to each ring's local
// thickness; without (the default), the paper's one St, cut by the rules.
geom::SizePlan plan_for(const TopoDS_Solid& solid, double sweep, bool local_ring = false) {
    const geom::Model model = test::model_of(solid);
    const geom::TubeSearch found = geom::find_tubes(model);
    geom::SizingOptions options;
    options.sweep_size = sweep;
    options.local_ring = local_ring;
    return geom::plan_sizes(model, found.tubes, options);
}

std::string changes(const geom::SizePlan& p) {
    std::string s;
    for (const auto& c : p.changes) s += c.rule + ": " + c.reason + "\n";
    return s;
}

TEST(GeomSizing, DefaultsComeFromTheTubeDiameterAndTheBox) {
    const geom::Model model = test::model_of(
        test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::straight_spine({0.5, 0.5, -0.1}, {0.5, 0.5, 1.1})}, kR));
    const geom::SizePlan p = geom::plan_sizes(model, geom::find_tubes(model).tubes);
    EXPECT_NEAR(p.sweep_size, 2 * kR, 1e-9);
    EXPECT_NEAR(p.size, std::sqrt(3.0) / 25, 1e-6);
    EXPECT_TRUE(p.changes.empty()) << changes(p);
    EXPECT_NEAR(p.dcb, 0.5 - kR, 1e-7);  // to the four side faces
    EXPECT_TRUE(std::isinf(p.dc));
    EXPECT_TRUE(std::isinf(p.rc));
}

// Dcb is measured to the centre line's polyline, which drops the points of straight runs
// before OpenCASCADE sees it: a pipe that comes closest to a face in the middle of a bend
// still gets the true wall-to-face distance, within the centre line's 1%-of-r chord error.
TEST(GeomSizing, DcbFollowsABendTowardsAFace) {
    const geom::Model model = test::model_of(test::box_with_pipes(
        {0, 0, 0}, {1, 1, 1},
        {test::spline_spine({gp_Pnt(0.5, 0.5, -0.1), gp_Pnt(0.5, 0.2, 0.5), gp_Pnt(0.5, 0.5, 1.1)})}, kR));
    const geom::TubeSearch found = geom::find_tubes(model);
    ASSERT_EQ(found.tubes.size(), 1u);
    const geom::SizePlan p = geom::plan_sizes(model, found.tubes);
    // The face y = 0 and the wall, by OpenCASCADE directly.
    int y0 = 0;
    for (int f = 1; f <= model.face_count(); ++f) {
        Bnd_Box b;
        BRepBndLib::Add(geom::face_of(model, f), b);
        double x0, ya, z0, x1, yb, z1;
        b.Get(x0, ya, z0, x1, yb, z1);
        if (yb < 1e-6) y0 = f;
    }
    ASSERT_GT(y0, 0);
    BRep_Builder builder;
    TopoDS_Compound wall;
    builder.MakeCompound(wall);
    for (int f : found.tubes[0].faces) builder.Add(wall, geom::face_of(model, f));
    BRepExtrema_DistShapeShape dist(geom::face_of(model, y0), wall);
    ASSERT_TRUE(dist.IsDone());
    EXPECT_LT(dist.Value(), 0.5 - kR);  // nearer than the straight ends: the bend decides
    EXPECT_NEAR(p.dcb, dist.Value(), 0.01 * kR);
}

TEST(GeomSizing, PipeNearAFaceTriggersRuleOne) {
    // Wall 0.05 from face y = 0.
    const TopoDS_Solid solid =
        test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::straight_spine({0.5, 0.07, -0.1}, {0.5, 0.07, 1.1})}, kR);
    // The local ring: St stays, the ring thins towards the face only.
    const geom::SizePlan local = plan_for(solid, 0.1, true);
    EXPECT_TRUE(local.changes.empty()) << changes(local);
    EXPECT_EQ(local.sweep_size, 0.1);
    EXPECT_TRUE(local.local_ring);
    const geom::SizePlan p = plan_for(solid, 0.1);
    ASSERT_GE(p.changes.size(), 1u);
    EXPECT_EQ(p.changes[0].rule.substr(0, 2), "1:") << changes(p);
    EXPECT_NEAR(p.dcb, 0.05, 1e-7);
    EXPECT_NEAR(p.changes[0].new_sweep_size, 0.07, 1e-7);
    // The rules cut St only; the default S (here 1.3 St) is recomputed from the final St.
    EXPECT_NEAR(p.changes[0].new_size, p.changes[0].old_size, 1e-12);
    // 0.07 + 0.98 x 0.07 still reaches past the face: the boundary guard follows.
    ASSERT_EQ(p.changes.size(), 2u) << changes(p);
    EXPECT_EQ(p.changes[1].rule, "guard: boundary");
    EXPECT_LT(p.sweep_size * (1 + 0.98154), p.dcb);
    EXPECT_NEAR(p.size, std::max(std::sqrt(3.0) / 25, 1.3 * p.sweep_size), 1e-6);
}

TEST(GeomSizing, CuttingStKeepsTheUsersSize) {
    // The same pipe near a face, with S given: St is cut, S stays the user's.
    const geom::Model model = test::model_of(
        test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::straight_spine({0.5, 0.07, -0.1}, {0.5, 0.07, 1.1})}, kR));
    geom::SizingOptions options;
    options.sweep_size = 0.1;
    options.size = 0.3;
    options.local_ring = false;
    const geom::SizePlan p = geom::plan_sizes(model, geom::find_tubes(model).tubes, options);
    ASSERT_GE(p.changes.size(), 1u);
    EXPECT_LT(p.sweep_size, 0.07);
    EXPECT_EQ(p.size, 0.3);
}

TEST(GeomSizing, SweepShareTakesStFromSAndTheRulesStillCutIt) {
    // The economy preset's St = share x S: from the given S, from the default S, not over a given
    // St, and cut by the rules like the default St (the pipe 0.05 from a face).
    const geom::Model centred = test::model_of(
        test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::straight_spine({0.5, 0.5, -0.1}, {0.5, 0.5, 1.1})}, kR));
    geom::SizingOptions options;
    options.sweep_share = 0.4;
    options.size = 0.2;
    geom::SizePlan p = geom::plan_sizes(centred, geom::find_tubes(centred).tubes, options);
    EXPECT_NEAR(p.sweep_size, 0.08, 1e-12);
    EXPECT_TRUE(p.changes.empty()) << changes(p);
    EXPECT_EQ(p.sweep_source.substr(0, 8), "economy:");
    options.size = 0;
    p = geom::plan_sizes(centred, geom::find_tubes(centred).tubes, options);
    EXPECT_NEAR(p.size, std::sqrt(3.0) / 25, 1e-6);
    EXPECT_NEAR(p.sweep_size, 0.4 * p.size, 1e-12);
    options.size = 0.8;  // 0.32 would be 16 radii: held at 12.5 (then cut by the boundary guard)
    options.local_ring = false;
    p = geom::plan_sizes(centred, geom::find_tubes(centred).tubes, options);
    EXPECT_NEAR(p.initial_sweep_size, 12.5 * kR, 1e-9);
    EXPECT_EQ(p.sweep_source, "economy: 12.5 tube radii");
    options.sweep_size = 0.03;
    p = geom::plan_sizes(centred, geom::find_tubes(centred).tubes, options);
    EXPECT_EQ(p.sweep_size, 0.03);
    EXPECT_EQ(p.sweep_source, "user");

    const geom::Model near_face = test::model_of(
        test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::straight_spine({0.5, 0.07, -0.1}, {0.5, 0.07, 1.1})}, kR));
    geom::SizingOptions share;
    share.local_ring = false;
    share.sweep_share = 0.4;
    share.size = 0.3;
    p = geom::plan_sizes(near_face, geom::find_tubes(near_face).tubes, share);
    ASSERT_GE(p.changes.size(), 1u);
    EXPECT_NEAR(p.changes.front().old_sweep_size, 0.12, 1e-12);
    EXPECT_LT(p.sweep_size, 0.05);
    EXPECT_EQ(p.size, 0.3);
    share.sweep_share = 1;  // St could never be below S
    EXPECT_THROW(geom::plan_sizes(near_face, geom::find_tubes(near_face).tubes, share), Error);
}

TEST(GeomSizing, TwoClosePipesTriggerRuleTwo) {
    // Walls 0.06 apart, 0.43 from the side faces.
    const geom::SizePlan p = plan_for(test::box_with_pipes({0, 0, 0}, {1, 1, 1},
                                                           {test::straight_spine({0.45, 0.5, -0.1}, {0.45, 0.5, 1.1}),
                                                            test::straight_spine({0.55, 0.5, -0.1}, {0.55, 0.5, 1.1})},
                                                           kR),
                                      0.1, false);
    EXPECT_NEAR(p.dc, 0.06, 1e-7);
    ASSERT_GE(p.changes.size(), 1u);
    EXPECT_EQ(p.changes[0].rule.substr(0, 2), "2:") << changes(p);
    EXPECT_NEAR(p.changes[0].new_sweep_size, 0.036, 1e-7);
    EXPECT_EQ(p.changes.back().rule, "guard: rings") << changes(p);
    EXPECT_LT(p.sweep_size * (2 + 0.98154), p.dc);
}

TEST(GeomSizing, TightBendTriggersRuleThree) {
    // A quarter turn of radius 0.1 round the box's z edge.
    const geom::SizePlan p =
        plan_for(test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::arc_spine({0, 0, 0.5}, 0.1, -30, 120)}, kR), 0.1);
    EXPECT_NEAR(p.rc, 0.1, 1e-5);
    ASSERT_GE(p.changes.size(), 1u);
    EXPECT_EQ(p.changes[0].rule.substr(0, 2), "3:") << changes(p);
    EXPECT_NEAR(p.changes[0].new_sweep_size, 0.08, 1e-5);
    EXPECT_EQ(p.changes.back().rule, "guard: bend") << changes(p);
    EXPECT_LT(kR + p.sweep_size, p.rc);
}

TEST(GeomSizing, BadUserSizesAreErrors) {
    const geom::Model model = test::model_of(test::box_with_blind_hole(kR, 0.2));
    geom::SizingOptions options;
    options.size = -1;
    EXPECT_THROW(geom::plan_sizes(model, {}, options), Error);
}

TEST(GeomSizing, NoTubesPlansOnlyS) {
    const geom::Model model = test::model_of(test::box_with_blind_hole(kR, 0.2));
    const geom::SizePlan p = geom::plan_sizes(model, {});
    EXPECT_EQ(p.sweep_size, 0);
    EXPECT_GT(p.size, 0);
    EXPECT_TRUE(p.changes.empty());
}

}  // namespace
}  // namespace tubemesh
