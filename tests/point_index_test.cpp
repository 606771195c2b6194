// The k-d tree must agree with brute force, including the documented tie order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "engine/mesh/point_index.hpp"

namespace {

using namespace tubemesh;

std::vector<Neighbor> brute_force(const HybridMesh& m, Vec3 q) {
    std::vector<Neighbor> all;
    for (index_t i = 0; i < m.point_count(); ++i) {
        const double dx = m.x[i] - q.x, dy = m.y[i] - q.y, dz = m.z[i] - q.z;
        all.push_back({i, dx * dx + dy * dy + dz * dz});
    }
    std::sort(all.begin(), all.end(), [](const Neighbor& a, const Neighbor& b) {
        return a.distance_squared < b.distance_squared || (a.distance_squared == b.distance_squared && a.index < b.index);
    });
    return all;
}

HybridMesh random_cloud(int n, unsigned seed) {
    HybridMesh m;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < n; ++i) m.add_point(u(rng), u(rng), u(rng));
    return m;
}

TEST(PointIndex, NearestMatchesBruteForce) {
    const HybridMesh m = random_cloud(5000, 7);
    const PointIndex index(m);
    EXPECT_EQ(index.size(), 5000u);
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    std::vector<Neighbor> got;
    for (int q = 0; q < 200; ++q) {
        const Vec3 p{u(rng), u(rng), u(rng)};
        const auto want = brute_force(m, p);
        for (index_t k : {1u, 5u, 17u}) {
            index.nearest(p, k, got);
            ASSERT_EQ(got.size(), k);
            for (index_t i = 0; i < k; ++i) {
                EXPECT_EQ(got[i].index, want[i].index);
                EXPECT_DOUBLE_EQ(got[i].distance_squared, want[i].distance_squared);
            }
        }
    }
}

TEST(PointIndex, RadiusMatchesBruteForceAndIsStrict) {
    const HybridMesh m = random_cloud(5000, 9);
    const PointIndex index(m);
    std::mt19937 rng(10);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Neighbor> got;
    for (int q = 0; q < 200; ++q) {
        const Vec3 p{u(rng), u(rng), u(rng)};
        const double r = 0.05 + 0.2 * (q % 5);
        auto want = brute_force(m, p);
        want.erase(std::remove_if(want.begin(), want.end(), [&](const Neighbor& n) { return !(n.distance_squared < r * r); }),
                   want.end());
        index.within(p, r, got);
        EXPECT_EQ(got, want);
        EXPECT_EQ(index.any_within(p, r), !want.empty());
    }
}

TEST(PointIndex, GridTiesComeInIndexOrder) {
    // A grid puts many points at exactly the same distance from its nodes.
    HybridMesh m;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            for (int k = 0; k < 6; ++k) m.add_point(i, j, k);
    const PointIndex index(m);
    std::vector<Neighbor> got;
    const Vec3 centre{2, 3, 2};
    index.within(centre, 1.01, got);
    const auto all = brute_force(m, centre);
    EXPECT_EQ(got, std::vector<Neighbor>(all.begin(), all.begin() + 7));
    index.nearest(centre, 7, got);
    ASSERT_EQ(got.size(), 7u);
    EXPECT_EQ(got[0].distance_squared, 0.0);
    for (int i = 2; i < 7; ++i) EXPECT_LT(got[i - 1].index, got[i].index);
}

TEST(PointIndex, EmptyAndSmallInputs) {
    HybridMesh m;
    PointIndex empty(m);
    std::vector<Neighbor> got{{1, 1}};
    empty.nearest({0, 0, 0}, 3, got);
    EXPECT_TRUE(got.empty());
    m.add_point(1, 0, 0);
    PointIndex one(m);
    one.nearest({0, 0, 0}, 3, got);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].distance_squared, 1.0);
    one.within({0, 0, 0}, 1.0, got);  // strict: a point exactly at the radius is outside
    EXPECT_TRUE(got.empty());
    EXPECT_FALSE(one.any_within({0, 0, 0}, 1.0));
    EXPECT_TRUE(one.any_within({0, 0, 0}, std::nextafter(1.0, 2.0)));
    EXPECT_FALSE(one.any_within({1, 0, 0}, 0.0));  // no radius: nothing is strictly inside
    EXPECT_FALSE(one.any_within({1, 0, 0}, -2.0));  // a negative radius is no radius, not 2
    EXPECT_FALSE(empty.any_within({0, 0, 0}, 10.0));
}

}  // namespace
