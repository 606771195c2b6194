// The size field: h(x) = min(S, min_i (h_i + g |x - x_i|)) against brute force, its slope bound,
// and its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/sizing/field/size_field.hpp"

namespace {

using namespace tubemesh;

double brute_force(const std::vector<SizeSource>& sources, double S, double g, const Vec3& p) {
    double h = S;
    for (const SizeSource& s : sources)
        h = std::min(h, s.size + g * std::sqrt((p.x - s.point.x) * (p.x - s.point.x) +
                                               (p.y - s.point.y) * (p.y - s.point.y) +
                                               (p.z - s.point.z) * (p.z - s.point.z)));
    return h;
}

TEST(SizeField, MatchesBruteForceWithMixedSizes) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> pos(0, 10), sz(0.01, 0.5);
    std::vector<SizeSource> sources;
    for (int i = 0; i < 500; ++i) sources.push_back({{pos(rng), pos(rng), pos(rng) * 0.3}, sz(rng)});
    const SizeField field({0.4, 0.25}, sources);
    for (int q = 0; q < 2000; ++q) {
        const Vec3 p{pos(rng), pos(rng), pos(rng) * 0.3};
        ASSERT_DOUBLE_EQ(field.at(p), brute_force(sources, 0.4, 0.25, p)) << q;
    }
    EXPECT_NEAR(field.min_size(), 0.01, 0.005);
}

TEST(SizeField, BelowAgreesWithTheValue) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> pos(0, 10), sz(0.01, 0.5), lim(0, 0.6);
    std::vector<SizeSource> sources;
    for (int i = 0; i < 300; ++i) sources.push_back({{pos(rng), pos(rng), pos(rng) * 0.3}, sz(rng)});
    const SizeField field({0.4, 0.6}, sources);
    int yes = 0;
    for (int q = 0; q < 4000; ++q) {
        const Vec3 p{pos(rng), pos(rng), pos(rng) * 0.3};
        const double limit = lim(rng), h = brute_force(sources, 0.4, 0.6, p);
        ASSERT_EQ(field.below(p, limit), h < limit) << q << ": h " << h << ", limit " << limit;
        yes += h < limit;
    }
    EXPECT_GT(yes, 400);  // both answers are exercised
    EXPECT_LT(yes, 3600);
    const SizeField empty({0.4, 0.6}, {});
    EXPECT_FALSE(empty.below({1, 1, 1}, 0.4));
    EXPECT_TRUE(empty.below({1, 1, 1}, 0.41));
}

TEST(SizeField, SlopeIsBoundedByTheGrowthRate) {
    std::vector<SizeSource> sources;
    add_polygon_sources(std::vector<Vec3>{{0, 0, 0}, {0.1, 0, 0}, {0.1, 0.1, 0}, {0, 0.1, 0}}, sources);
    ASSERT_EQ(sources.size(), 4u);
    EXPECT_DOUBLE_EQ(sources[0].size, 0.1);
    const SizeField field({1.0, 0.3}, sources);
    for (int i = 0; i < 400; ++i) {
        const Vec3 a{0.01 * i, 0.003 * i, 0}, b{0.01 * (i + 1), 0.003 * i, 0.002};
        const double d = std::sqrt(0.01 * 0.01 + 0.002 * 0.002);
        EXPECT_LE(std::abs(field.at(a) - field.at(b)), 0.3 * d + 1e-15);
    }
    EXPECT_DOUBLE_EQ(field.at({100, 100, 100}), 1.0);  // far away: S
    EXPECT_DOUBLE_EQ(field.at({0, 0, 0}), 0.1);         // at a source: its size
}

TEST(SizeField, WithoutSourcesIsConstant) {
    const SizeField field({0.7}, {});
    EXPECT_DOUBLE_EQ(field.at({1, 2, 3}), 0.7);
    EXPECT_DOUBLE_EQ(field.growth(), 0.25);
}

TEST(SizeField, RejectsBadInput) {
    EXPECT_THROW(SizeField({0.0}, {}), Error);
    EXPECT_THROW(SizeField({1.0, -0.1}, {}), Error);
    EXPECT_THROW(SizeField({1.0}, {{{0, 0, 0}, 0.0}}), Error);
    std::vector<SizeSource> out;
    EXPECT_THROW(add_polygon_sources(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}}, out), Error);
}

}  // namespace
