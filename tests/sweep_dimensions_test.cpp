// The ring's dimensions: nodes around, radial grading, axial step.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/core/types.hpp"
#include "engine/sweep/ring_dimensions.hpp"
#include "engine/sweep/sweep.hpp"

namespace tubemesh {
namespace {

TEST(SweepDimensions, CircumferentialCountIsEightForSmallPipes) {
    EXPECT_EQ(circumferential_count(0.02, 0.04), 8);   // geom's default St = 2r
    EXPECT_EQ(circumferential_count(0.016, 0.032), 8);
    EXPECT_EQ(circumferential_count(0.02, 0.14), 8);   // the paper's Example 1 (it had 4)
    EXPECT_EQ(circumferential_count(1.0, 0.92), 8);
    EXPECT_EQ(circumferential_count(1.0, 0.5), 16);
    EXPECT_EQ(circumferential_count(1.0, 0.25), 28);
    EXPECT_EQ(circumferential_count(1.0, 0.1), 64);
    EXPECT_EQ(circumferential_count(0.02, 1.0), 8);    // never fewer than 8
    EXPECT_EQ(circumferential_count(1.0, 0.1) % 4, 0);
    EXPECT_THROW(circumferential_count(0, 1), Error);
    EXPECT_THROW(circumferential_count(1, -1), Error);
    EXPECT_THROW(circumferential_count(1, std::nan("")), Error);
}

TEST(SweepDimensions, RadialLayersAreGradedTowardsTheWall) {
    const auto o = sweep::radial_offsets(1.0, 2, 1.5);
    ASSERT_EQ(o.size(), 3u);
    EXPECT_EQ(o[0], 0.0);
    EXPECT_NEAR(o[1], 0.4, 1e-15);
    EXPECT_EQ(o[2], 1.0);
    const auto u = sweep::radial_offsets(2.0, 4, 1.0);
    for (int j = 0; j <= 4; ++j) EXPECT_NEAR(u[j], 0.5 * j, 1e-15);
    const auto g = sweep::radial_offsets(1.0, 3, 2.0);
    EXPECT_NEAR((g[2] - g[1]) / (g[1] - g[0]), 2.0, 1e-12);
    EXPECT_NEAR((g[3] - g[2]) / (g[2] - g[1]), 2.0, 1e-12);
}

TEST(SweepDimensions, AxialStepFollowsTheAspectUnlessTheConditionCaps) {
    const int n = 8;
    const double r = 1.0;
    // St = 2r: 1.5 times the outer side, condition about 2.5 (< 3): no cap.
    const auto o2 = sweep::radial_offsets(2.0, 2, 1.5);
    const double side2 = 2 * 3.0 * std::sin(std::numbers::pi / n);
    EXPECT_NEAR(sweep::axial_step(r, o2, n, 1.5, 3.0), 1.5 * side2, 1e-12);
    EXPECT_LT(sweep::straight_ring_condition(r, o2, n, 1.5 * side2), 3.0);
    // St = 7r: the wall cells are thin under a long outer quad; the cap shortens the step.
    const auto o7 = sweep::radial_offsets(7.0, 2, 1.5);
    const double side7 = 2 * 8.0 * std::sin(std::numbers::pi / n);
    const double capped = sweep::axial_step(r, o7, n, 1.5, 3.0);
    EXPECT_LT(capped, 1.5 * side7);
    EXPECT_LE(sweep::straight_ring_condition(r, o7, n, capped), 3.0);
    EXPECT_NEAR(sweep::axial_step(r, o7, n, 1.5, 0), 1.5 * side7, 1e-12);  // cap off
}

// Where no step meets the cap (many thin layers) the step stays at kMinAxialAspect outer
// sides, where the pyramids have room; a long wanted step is cut until the cap holds,
// however long.
TEST(SweepDimensions, AxialStepStaysWherePyramidsFit) {
    const double r = 1.0;
    const int n = 8;
    const double side = 2 * 3.0 * std::sin(std::numbers::pi / n);
    const auto thin = sweep::radial_offsets(2.0, 8, 1.5);
    EXPECT_GT(sweep::straight_ring_condition(r, thin, n, kMinAxialAspect * side), 3.0);
    EXPECT_NEAR(sweep::axial_step(r, thin, n, 1.5, 3.0), kMinAxialAspect * side, 1e-12);
    const auto two = sweep::radial_offsets(2.0, 2, 1.5);
    const double cut = sweep::axial_step(r, two, n, 16.0, 3.0);
    EXPECT_LE(sweep::straight_ring_condition(r, two, n, cut), 3.0);
    EXPECT_GE(cut, kMinAxialAspect * side);
}

}  // namespace
}  // namespace tubemesh
