// The ring triangulation search shared by both edge removals (engine/tets/domain/ring_triangulation.hpp)
// against brute force: every triangulation of small polygons with random triangle scores and
// random forbidden chords.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include "engine/tets/domain/ring_triangulation.hpp"

namespace tubemesh::tets {
namespace {

constexpr int kMax = 10;
constexpr double kNone = -std::numeric_limits<double>::infinity();

struct Polygon {
    int n = 0;
    std::array<std::array<std::array<double, kMax>, kMax>, kMax> score{};  // score[i][k][j], i < k < j
    std::array<std::array<bool, kMax>, kMax> chord{};                       // usable chord (i, j)

    bool side_ok(int i, int j) const { return j == i + 1 || (i == 0 && j == n - 1) || chord[i][j]; }
};

// The largest worst-triangle score over the triangulations of p_i .. p_j whose sides are all
// usable, by enumerating every split (no memo: the point is to be independent of the search).
double brute(const Polygon& p, int i, int j) {
    if (j - i < 2) return std::numeric_limits<double>::infinity();
    if (!p.side_ok(i, j)) return kNone;
    double best = kNone;
    for (int k = i + 1; k < j; ++k)
        best = std::max(best, std::min({p.score[i][k][j], brute(p, i, k), brute(p, k, j)}));
    return best;
}

Polygon random_polygon(std::mt19937& rng, int n, double forbid) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Polygon p;
    p.n = n;
    for (int i = 0; i < n; ++i)
        for (int j = i + 2; j < n; ++j) p.chord[i][j] = u(rng) >= forbid;
    // Few distinct values, so ties between triangulations are common.
    for (int i = 0; i < n; ++i)
        for (int k = i + 1; k < n; ++k)
            for (int j = k + 1; j < n; ++j) p.score[i][k][j] = std::round(u(rng) * 8) / 8;
    return p;
}

TEST(RingTriangulation, FindsTheBestWorstTriangleOfEveryTriangulation) {
    std::mt19937 rng(20261203);
    int solved = 0, unsolvable = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const int n = 3 + trial % (kMax - 2);
        const Polygon p = random_polygon(rng, n, trial % 3 == 0 ? 0.0 : 0.3);
        RingTriangulation<kMax> search;
        const auto score = [&](int i, int k, int j, double) {
            const double s = p.score[i][k][j];
            return RingTriangle{s, s, 2 * s};
        };
        const bool found = search.solve(n, kNone, score, [&](int i, int j) { return p.chord[i][j]; });
        const double expected = brute(p, 0, n - 1);
        SCOPED_TRACE(::testing::Message() << "trial " << trial << ", n " << n);
        ASSERT_EQ(found, expected > kNone);
        if (!found) {
            ++unsolvable;
            continue;
        }
        ++solved;
        EXPECT_EQ(search.value(), expected);
        // What it reports is a triangulation: n - 2 distinct triangles over usable sides, each
        // side inside the polygon shared by two of them, each at least the value, one at it,
        // with the parts the score gave.
        std::set<std::array<int, 3>> triangles;
        std::vector<std::vector<int>> side_uses(n, std::vector<int>(n, 0));
        double worst = std::numeric_limits<double>::infinity();
        search.for_each_triangle([&](int i, int k, int j, double first, double second) {
            ASSERT_TRUE(i < k && k < j && j < n);
            EXPECT_TRUE(triangles.insert({i, k, j}).second);
            EXPECT_EQ(first, p.score[i][k][j]);
            EXPECT_EQ(second, 2 * p.score[i][k][j]);
            for (const auto [a, b] : {std::array{i, k}, std::array{k, j}, std::array{i, j}}) {
                EXPECT_TRUE(p.side_ok(a, b));
                ++side_uses[a][b];
            }
            worst = std::min(worst, p.score[i][k][j]);
        });
        EXPECT_EQ(static_cast<int>(triangles.size()), n - 2);
        EXPECT_EQ(worst, expected);
        for (int a = 0; a < n; ++a)
            for (int b = a + 1; b < n; ++b) {
                const bool boundary = b == a + 1 || (a == 0 && b == n - 1);
                if (side_uses[a][b] > 0) {
                    EXPECT_EQ(side_uses[a][b], boundary ? 1 : 2) << a << "-" << b;
                }
            }
        for (int a = 0; a + 1 < n; ++a) EXPECT_EQ(side_uses[a][a + 1], 1);
        EXPECT_EQ(side_uses[0][n - 1], 1);
    }
    // The sample covers both outcomes.
    EXPECT_GT(solved, 100);
    EXPECT_GT(unsolvable, 10);
}

TEST(RingTriangulation, AFloorKeepsOutWhatDoesNotBeatIt) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 100; ++trial) {
        const int n = 4 + trial % (kMax - 3);
        const Polygon p = random_polygon(rng, n, 0.0);
        const double best = brute(p, 0, n - 1);
        const auto score = [&](int i, int k, int j, double) {
            const double s = p.score[i][k][j];
            return RingTriangle{s, s, s};
        };
        const auto all = [](int, int) { return true; };
        RingTriangulation<kMax> search;
        // At the best value nothing beats the floor; just below it the best is found.
        EXPECT_FALSE(search.solve(n, best, score, all));
        EXPECT_EQ(search.value(), best);  // the floor, when there is nothing
        EXPECT_TRUE(search.solve(n, best - 1e-9, score, all));
        EXPECT_EQ(search.value(), best);
    }
}

// A score may give up early (return a min at or below `beat`) without changing the result:
// the optimisation's planner skips the second tet that way.
TEST(RingTriangulation, GivingUpEarlyChangesNothing) {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 200; ++trial) {
        const int n = 3 + trial % (kMax - 2);
        const Polygon p = random_polygon(rng, n, 0.2);
        const auto chord = [&](int i, int j) { return p.chord[i][j]; };
        RingTriangulation<kMax> full, lazy;
        const bool a = full.solve(
            n, kNone, [&](int i, int k, int j, double) { return RingTriangle{p.score[i][k][j], 0, 0}; }, chord);
        const bool b = lazy.solve(
            n, kNone,
            [&](int i, int k, int j, double beat) {
                const double s = p.score[i][k][j];
                return s <= beat ? RingTriangle{beat, 0, 0} : RingTriangle{s, 0, 0};
            },
            chord);
        ASSERT_EQ(a, b);
        if (!a) continue;
        EXPECT_EQ(full.value(), lazy.value());
        std::vector<std::array<int, 3>> ta, tb;
        full.for_each_triangle([&](int i, int k, int j, double, double) { ta.push_back({i, k, j}); });
        lazy.for_each_triangle([&](int i, int k, int j, double, double) { tb.push_back({i, k, j}); });
        EXPECT_EQ(ta, tb) << "trial " << trial;
    }
}

}  // namespace
}  // namespace tubemesh::tets
