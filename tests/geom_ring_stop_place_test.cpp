// Where a ring stops before a spot (geom/sizing/ring_stop_place.hpp): a diameter before the first
// point without room, seen from the end with the longer stretch of room.
#include <gtest/gtest.h>

#include "geom/sizing/ring_stop_place.hpp"

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

}  // namespace
}  // namespace tubemesh::geom
