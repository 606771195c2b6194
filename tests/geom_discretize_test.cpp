// Discretisation (paper §3.2): end loops with equal node counts and node 0 at the same angle,
// the centre line on the axis, and B-rep edges cut once by arc length.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "geom/discretize.hpp"
#include "tests/geom_tubes_solids.hpp"

namespace tubemesh {
namespace {

constexpr double kR = 0.02;

struct Case {
    geom::Model model;
    geom::TubeSearch tubes;
    geom::SizePlan plan;
    DiscreteGeometry geometry;
};

Case run(const TopoDS_Solid& solid, double sweep = 0.05, int ring_nodes = 0) {
    Case c{test::model_of(solid), {}, {}, {}};
    c.tubes = geom::find_tubes(c.model);
    geom::SizingOptions sizing;
    sizing.sweep_size = sweep;
    sizing.size = 0.2;
    c.plan = geom::plan_sizes(c.model, c.tubes.tubes, sizing);
    geom::DiscretizeOptions options;
    options.ring_nodes = ring_nodes;
    c.geometry = geom::discretize(c.model, c.tubes.tubes, c.plan, options);
    return c;
}

double norm(const Vec3& a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

TEST(GeomDiscretize, StraightPipeCentreLineIsTheAxisAndRingsAlign) {
    const Case c =
        run(test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::straight_spine({0.5, 0.5, -0.1}, {0.5, 0.5, 1.1})}, kR));
    ASSERT_EQ(c.geometry.tubes.size(), 1u);
    const TubeData& t = c.geometry.tubes[0];
    EXPECT_EQ(t.stations.size(), 21u);  // length 1 at St = 0.05
    for (const TubeStation& s : t.stations) {
        EXPECT_LT(std::hypot(s.centre.x - 0.5, s.centre.y - 0.5), 1e-6 * kR);
        EXPECT_NEAR(std::abs(s.tangent.z), 1.0, 1e-12);
        EXPECT_NEAR(s.radius, kR, 1e-9);
        EXPECT_NEAR(dot(s.reference, s.tangent), 0, 1e-12);
    }
    for (std::size_t k = 1; k < t.stations.size(); ++k)  // equal arc length steps
        EXPECT_NEAR(norm(sub(t.stations[k].centre, t.stations[k - 1].centre)), 0.05, 1e-9);
    ASSERT_EQ(t.ring1.size(), t.ring2.size());
    EXPECT_EQ(t.ring1.size() % 4, 0u);
    for (std::size_t k = 0; k < t.ring1.size(); ++k) {
        const double a1 = std::atan2(t.ring1[k].y - 0.5, t.ring1[k].x - 0.5);
        const double a2 = std::atan2(t.ring2[k].y - 0.5, t.ring2[k].x - 0.5);
        EXPECT_NEAR(std::remainder(a1 - a2, 2 * std::numbers::pi), 0, k == 0 ? 1e-9 : 1e-7) << "node " << k;
    }
}

TEST(GeomDiscretize, ObliqueStraightPipeCentreLineIsTheAxis) {
    const gp_Pnt a(-0.2, 0.3, 0.2), b(1.2, 0.6, 0.9);
    const Case c = run(test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::straight_spine(a, b)}, kR));
    ASSERT_EQ(c.geometry.tubes.size(), 1u);
    const gp_Vec axis = gp_Vec(a, b).Normalized();
    for (const TubeStation& s : c.geometry.tubes[0].stations) {
        const gp_Vec d(a, gp_Pnt(s.centre.x, s.centre.y, s.centre.z));
        EXPECT_LT(d.Crossed(axis).Magnitude(), 1e-6 * kR);
        EXPECT_NEAR(s.radius, kR, 1e-9);
    }
    // The end stations are the centres of the oblique end loops, which lie in faces x = 0, 1
    // (to the intersection curves' tolerance).
    EXPECT_NEAR(c.geometry.tubes[0].stations.front().centre.x, 0.0, 1e-6);
    EXPECT_NEAR(c.geometry.tubes[0].stations.back().centre.x, 1.0, 1e-6);
}

TEST(GeomDiscretize, ArcPipeCentreLineIsTheArcAndRingsAlign) {
    const Case c = run(test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::arc_spine({0, 0, 0.5}, 0.5, -15, 105)}, kR));
    ASSERT_EQ(c.geometry.tubes.size(), 1u);
    const TubeData& t = c.geometry.tubes[0];
    for (const TubeStation& s : t.stations) {
        EXPECT_LT(std::abs(std::hypot(s.centre.x, s.centre.y) - 0.5), 1e-3 * kR);
        EXPECT_LT(std::abs(s.centre.z - 0.5), 1e-3 * kR);
    }
    // Angle around the axis in the torus' own frame: (distance from the z axis - R, z - 0.5).
    ASSERT_EQ(t.ring1.size(), t.ring2.size());
    const auto angle = [](const Vec3& p) { return std::atan2(p.z - 0.5, std::hypot(p.x, p.y) - 0.5); };
    EXPECT_NEAR(std::remainder(angle(t.ring1[0]) - angle(t.ring2[0]), 2 * std::numbers::pi), 0, 1e-9);
    for (std::size_t k = 1; k < t.ring1.size(); ++k)
        EXPECT_NEAR(std::remainder(angle(t.ring1[k]) - angle(t.ring2[k]), 2 * std::numbers::pi), 0, 1e-7);
}

TEST(GeomDiscretize, RoundedCornerCentreLineFollowsLineArcLine) {
    // Along y at x = 0.5 to y = 0.3, a quarter turn of radius 0.2 about (0.7, 0.3), along x.
    const Case c = run(test::box_with_pipes(
        {0, 0, 0}, {1, 1, 1}, {test::corner_spine({0.5, -0.1, 0.5}, {0.5, 0.5, 0.5}, {1.1, 0.5, 0.5}, 0.2)}, kR));
    ASSERT_EQ(c.geometry.tubes.size(), 1u);
    const TubeData& t = c.geometry.tubes[0];
    EXPECT_EQ(t.wall_faces.size(), 3u);
    const auto off_axis = [](const Vec3& p) {
        if (p.y <= 0.3) return std::hypot(p.x - 0.5, p.z - 0.5);
        if (p.x >= 0.7) return std::hypot(p.y - 0.5, p.z - 0.5);
        return std::hypot(std::hypot(p.x - 0.7, p.y - 0.3) - 0.2, p.z - 0.5);
    };
    for (const TubeStation& s : t.stations) {
        EXPECT_LT(off_axis(s.centre), 1e-6 * kR);
        EXPECT_NEAR(s.radius, kR, 1e-9);
    }
    ASSERT_EQ(t.ring1.size(), t.ring2.size());
}

TEST(GeomDiscretize, RingsTurnRightHandedAboutTheTangent) {
    const Case c = run(test::box_with_pipes(
        {0, 0, 0}, {1, 1, 1},
        {test::spline_spine({{-0.1, 0.5, 0.3}, {0.3, 0.6, 0.5}, {0.7, 0.4, 0.6}, {1.1, 0.5, 0.4}})}, kR));
    ASSERT_EQ(c.geometry.tubes.size(), 1u);
    const TubeData& t = c.geometry.tubes[0];
    const auto turn = [](const std::vector<Vec3>& ring, const TubeStation& s) {
        const Vec3 a = sub(ring[0], s.centre), b = sub(ring[1], s.centre);
        const Vec3 n{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
        return dot(n, s.tangent);
    };
    EXPECT_GT(turn(t.ring1, t.stations.front()), 0);
    EXPECT_GT(turn(t.ring2, t.stations.back()), 0);
    // Node 0 of each ring is where the station's reference direction points (across the
    // axis: the oblique loops also reach along it).
    const auto across = [](const Vec3& p, const TubeStation& s) {
        const Vec3 d = sub(p, s.centre);
        const double along = dot(d, s.tangent);
        const Vec3 q{d.x - along * s.tangent.x, d.y - along * s.tangent.y, d.z - along * s.tangent.z};
        return dot(q, s.reference) / norm(q);
    };
    EXPECT_NEAR(across(t.ring1[0], t.stations.front()), 1.0, 1e-12);
    EXPECT_NEAR(across(t.ring2[0], t.stations.back()), 1.0, 1e-12);
}

TEST(GeomDiscretize, SplitWallsDiscretiseLikeWholeOnes) {
    const TopoDS_Solid solid =
        test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::arc_spine({0, 0, 0.5}, 0.5, -15, 105)}, kR);
    const Case whole = run(solid, 0.05, 8);
    const Case split = run(test::split_closed_faces(solid), 0.05, 8);
    ASSERT_EQ(split.geometry.tubes.size(), 1u);
    const TubeData& a = whole.geometry.tubes[0];
    const TubeData& b = split.geometry.tubes[0];
    ASSERT_EQ(a.stations.size(), b.stations.size());
    for (std::size_t k = 0; k < a.stations.size(); ++k)
        EXPECT_LT(norm(sub(a.stations[k].centre, b.stations[k].centre)), 1e-6);
    EXPECT_EQ(b.ring1.size(), 8u);
    EXPECT_EQ(b.loop1_edges.size(), 2u);
}

TEST(GeomDiscretize, EdgesAreCutOnceAtSizeS) {
    const Case c =
        run(test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::straight_spine({0.5, 0.5, -0.1}, {0.5, 0.5, 1.1})}, kR));
    // The box's 12 edges; the tube's loops and seam belong to the ring.
    ASSERT_EQ(c.geometry.edges.size(), 12u);
    std::set<index_t> ids;
    for (const EdgePolyline& e : c.geometry.edges) {
        EXPECT_TRUE(ids.insert(e.edge).second);
        EXPECT_EQ(e.points.size(), 6u);  // length 1 at S = 0.2
        EXPECT_EQ(e.points.size(), e.params.size());
        EXPECT_NE(e.first_vertex, e.last_vertex);
        for (std::size_t k = 1; k < e.points.size(); ++k)
            EXPECT_NEAR(norm(sub(e.points[k], e.points[k - 1])), 0.2, 1e-9);
    }
    const std::set<index_t> loop_edges{c.geometry.tubes[0].loop1_edges[0], c.geometry.tubes[0].loop2_edges[0]};
    for (index_t id : loop_edges) EXPECT_EQ(ids.count(id), 0u);
}

TEST(GeomDiscretize, RingNodeCountMakesSquareQuads) {
    EXPECT_EQ(geom::ring_node_count(0.02, 0.14), 4);  // the paper's Example 1
    EXPECT_EQ(geom::ring_node_count(0.02, 0.04), 8);  // the default St = diameter
    EXPECT_EQ(geom::ring_node_count(1.0, 0.1), 64);
}

}  // namespace
}  // namespace tubemesh
