// Where a ring stops before a spot (geom/sizing/ring_stop_place.hpp): a diameter before the first
// point without room, seen from each end with a stretch worth a ring; before the wall of another
// pipe (geom/sizing/junction.hpp) and before a blind hole's bottom.
#include <gtest/gtest.h>

#include "geom/sizing/ring_stop_place.hpp"
#include "geom/sizing/junction.hpp"

namespace tubemesh::geom {
namespace {

TubeInfo straight(int points, double r) {
    TubeInfo t;
    t.radius_min = t.radius_max = r;
    for (int i = 0; i < points; ++i) t.centre_line.push_back({double(i), 0, 0});
    t.length = points - 1;
    return t;
}

TEST(RingStopPlace, StopsADiameterBeforeASpotNearTheSecondEnd) {
    const TubeInfo t = straight(21, 0.5);  // x from 0 to 20
    std::vector<double> clearance(21, 5.0);
    clearance[18] = clearance[19] = clearance[20] = 0.1;
    const auto cut = ring_cut(t, clearance, 1.0);
    ASSERT_TRUE(cut.has_value());
    EXPECT_NEAR(cut->centre.x, 17.0, 1e-12);  // the spot at 18, less one diameter
    EXPECT_NEAR(cut->tangent.x, 1.0, 1e-12);
    EXPECT_EQ(cut->keep.x, 0.0);
    EXPECT_NEAR(cut->kept_length, 17.0, 1e-12);
}

TEST(RingStopPlace, KeepsTheLongerStretchOfASpotNearTheFirstEnd) {
    const TubeInfo t = straight(21, 0.5);
    std::vector<double> clearance(21, 5.0);
    clearance[3] = 0.0;
    const auto cut = ring_cut(t, clearance, 1.0);
    ASSERT_TRUE(cut.has_value());
    EXPECT_NEAR(cut->centre.x, 4.0, 1e-12);
    EXPECT_EQ(cut->keep.x, 20.0);
    EXPECT_NEAR(cut->kept_length, 16.0, 1e-12);
}

TEST(RingStopPlace, NoCutWithoutASpotOrWithoutAStretchWorthARing) {
    const TubeInfo t = straight(21, 0.5);
    EXPECT_FALSE(ring_cut(t, std::vector<double>(21, 5.0), 1.0).has_value());
    std::vector<double> middle(21, 5.0);
    for (int i = 2; i <= 18; ++i) middle[static_cast<std::size_t>(i)] = 0.1;  // room only near the ends
    EXPECT_FALSE(ring_cut(t, middle, 1.0).has_value());
}

TEST(RingStopPlace, ASpotInTheMiddleLeavesACutOnEachSide) {
    const TubeInfo t = straight(21, 0.5);
    std::vector<double> clearance(21, 5.0);
    clearance[9] = clearance[10] = 0.1;
    const auto cuts = ring_cuts(t, clearance, 1.0);
    ASSERT_EQ(cuts.size(), 2u);
    // The longer stretch first: from x = 20 to a diameter after the spot's end at 10.
    EXPECT_NEAR(cuts[0].centre.x, 11.0, 1e-12);
    EXPECT_EQ(cuts[0].keep.x, 20.0);
    EXPECT_NEAR(cuts[0].kept_length, 9.0, 1e-12);
    EXPECT_NEAR(cuts[1].centre.x, 8.0, 1e-12);
    EXPECT_EQ(cuts[1].keep.x, 0.0);
    EXPECT_NEAR(cuts[1].kept_length, 8.0, 1e-12);
}

TEST(RingStopPlace, ASideShorterThanTwoDiametersKeepsNoRing) {
    const TubeInfo t = straight(21, 0.5);
    std::vector<double> clearance(21, 5.0);
    clearance[2] = 0.1;  // a diameter before it leaves 1, under two diameters
    const auto cuts = ring_cuts(t, clearance, 1.0);
    ASSERT_EQ(cuts.size(), 1u);
    EXPECT_EQ(cuts[0].keep.x, 20.0);
    EXPECT_TRUE(ring_cuts(t, std::vector<double>(21, 5.0), 1.0).empty());
}

// A pipe along x from 0 to 4 (radius 0.05) meeting another pipe's wall between x = 1.95 and 2.05
// (the crossing curve's points): a cut kJunctionMargin diameters before it on each side, each
// keeping the open end on its side.
TEST(RingStopPlace, WallsThatMeetAreCutBeforeTheJunctionOnEachSideWithAnOpenEnd) {
    JunctionPipe pipe;
    pipe.origin = {0, 0, 0};
    pipe.axis = {1, 0, 0};
    pipe.radius = 0.05;
    pipe.open = {0, 0, 4, 4};
    pipe.junction = {1.95, 2.0, 2.05};
    const std::vector<RingCut> cuts = junction_cuts(pipe, kJunctionMargin);
    ASSERT_EQ(cuts.size(), 2u);
    EXPECT_NEAR(cuts[0].centre.x, 1.75, 1e-12);
    EXPECT_EQ(cuts[0].keep.x, 0.0);
    EXPECT_NEAR(cuts[0].kept_length, 1.75, 1e-12);
    EXPECT_NEAR(cuts[1].centre.x, 2.25, 1e-12);
    EXPECT_EQ(cuts[1].keep.x, 4.0);
    // A blind hole's bottom at x = 2 (no open end beyond): one cut, a diameter before it.
    pipe.open = {0};
    pipe.junction = {2.0};
    const std::vector<RingCut> blind = junction_cuts(pipe, kBlindMargin);
    ASSERT_EQ(blind.size(), 1u);
    EXPECT_NEAR(blind[0].centre.x, 1.9, 1e-12);
    // No stretch of two diameters before the junction: no cut.
    pipe.junction = {0.3};
    EXPECT_TRUE(junction_cuts(pipe, kJunctionMargin).empty());
}

// A branch ending on another pipe's wall stops kJunctionMargin diameters before the first point of
// its end loop, seen from its open end.
TEST(RingStopPlace, ABranchStopsBeforeTheWallItEndsOn) {
    const TubeInfo t = straight(21, 0.5);
    const auto cut = cut_before_end(t, 1, {{19.5, 0.5, 0}, {19.8, 0, 0.5}});
    ASSERT_TRUE(cut.has_value());
    EXPECT_NEAR(cut->centre.x, 17.5, 1e-12);
    EXPECT_EQ(cut->keep.x, 0.0);
    const auto from_e1 = cut_before_end(t, 0, {{0.5, 0.5, 0}});
    ASSERT_TRUE(from_e1.has_value());
    EXPECT_NEAR(from_e1->centre.x, 2.5, 1e-12);
    EXPECT_EQ(from_e1->keep.x, 20.0);
}

}  // namespace
}  // namespace tubemesh::geom
