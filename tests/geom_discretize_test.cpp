// Discretisation (paper §3.2): end loops with equal node counts and node 0 at the same angle,
// the centre line on the axis, and B-rep edges cut once by arc length, a curved one into
// segments that turn by at most 0.065 rad (1024 segments at most).
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Elips.hxx>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "geom/sizing/discretize.hpp"
#include "geom/sizing/discretize_edges.hpp"
#include "tests/support/geom_tubes_solids.hpp"
#include "engine/core/vec3_ops.hpp"

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
        EXPECT_NEAR(norm(t.stations[k].centre - t.stations[k - 1].centre), 0.05, 1e-9);
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
        const Vec3 a = ring[0] - s.centre, b = ring[1] - s.centre;
        const Vec3 n{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
        return dot(n, s.tangent);
    };
    EXPECT_GT(turn(t.ring1, t.stations.front()), 0);
    EXPECT_GT(turn(t.ring2, t.stations.back()), 0);
    // Node 0 of each ring is where the station's reference direction points (across the
    // axis: the oblique loops also reach along it).
    const auto across = [](const Vec3& p, const TubeStation& s) {
        const Vec3 d = p - s.centre;
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
        EXPECT_LT(norm(a.stations[k].centre - b.stations[k].centre), 1e-6);
    EXPECT_EQ(b.ring1.size(), 8u);
    EXPECT_EQ(b.loop1_edges.size(), 2u);
}

// Tube stations are evaluated in parallel (each thread on its own copies of the generator
// lines): the same stations, to the bit, for any thread count.
TEST(GeomDiscretize, TubeStationsAreTheSameForOneAndTwoThreads) {
    const TopoDS_Solid solid = test::box_with_pipes(
        {0, 0, 0}, {1, 1, 1},
        {test::spline_spine({{-0.1, 0.5, 0.3}, {0.3, 0.6, 0.5}, {0.7, 0.4, 0.6}, {1.1, 0.5, 0.4}})}, kR);
    const auto stations = [&](int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
        const Case c = run(solid, 0.01);
        return c.geometry.tubes.at(0).stations;
    };
    const std::vector<TubeStation> one = stations(1), two = stations(2);
    ASSERT_GT(one.size(), 100u);  // several parallel tasks' worth
    ASSERT_EQ(one.size(), two.size());
    const auto same = [](const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; };
    for (std::size_t i = 0; i < one.size(); ++i) {
        EXPECT_TRUE(same(one[i].centre, two[i].centre) && same(one[i].tangent, two[i].tangent) &&
                    same(one[i].reference, two[i].reference) && one[i].radius == two[i].radius)
            << "station " << i;
    }
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
            EXPECT_NEAR(norm(e.points[k] - e.points[k - 1]), 0.2, 1e-9);
    }
    const std::set<index_t> loop_edges{c.geometry.tubes[0].loop1_edges[0], c.geometry.tubes[0].loop2_edges[0]};
    for (index_t id : loop_edges) EXPECT_EQ(ids.count(id), 0u);
}

// Curved edges: no segment turns by more than 0.065 rad (at most 1024 segments per edge).
constexpr double kMaxTurn = 0.065;

// A prism of height 0.2 over the ellipse of semi-axes a (along x) and b (along y) about the
// origin: two elliptic edges (z = 0 and 0.2) and a straight seam.
TopoDS_Solid elliptic_prism(double a, double b) {
    const gp_Elips ellipse(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1), gp_Dir(1, 0, 0)), a, b);
    const TopoDS_Face base =
        BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(ellipse).Edge()).Wire()).Face();
    const TopoDS_Shape prism = BRepPrimAPI_MakePrism(base, gp_Vec(0, 0, 0.2)).Shape();
    TopExp_Explorer it(prism, TopAbs_SOLID);
    if (!it.More()) throw std::runtime_error("no solid from the prism");
    return TopoDS::Solid(it.Current());
}

// The angle between the directions of the chords k-1 -> k and k -> k+1 at every inner point.
double max_chord_turn(const EdgePolyline& e) {
    double worst = 0;
    for (std::size_t k = 1; k + 1 < e.points.size(); ++k) {
        const Vec3 u = e.points[k] - e.points[k - 1], v = e.points[k + 1] - e.points[k];
        worst = std::max(worst, std::acos(std::clamp(dot(u, v) / (norm(u) * norm(v)), -1.0, 1.0)));
    }
    return worst;
}

TEST(GeomDiscretize, CircleEdgeSegmentsTurnAtMost0065) {
    // The blind hole's rim (z = 1) and bottom (z = 0.7) circles, at an S far above the box
    // and at one that cuts the straight edges. Their segment count does not depend on the
    // radius or on S here: a whole circle turns by 2 pi, so ceil(2 pi / 0.065) = 97 segments
    // are the fewest that keep each within 0.065 rad.
    for (const double r : {0.1, 1e-3}) {
        SCOPED_TRACE("radius " + std::to_string(r));
        const geom::Model model = test::model_of(test::box_with_blind_hole(r, 0.3));
        for (const double S : {10.0, 0.25}) {
            const std::vector<EdgePolyline> edges = geom::discretize_edges(model, {}, S);
            int circles = 0, straight = 0;
            for (const EdgePolyline& e : edges) {
                const bool circle = e.first_vertex == e.last_vertex &&
                                    std::all_of(e.points.begin(), e.points.end(), [&](const Vec3& p) {
                                        return std::abs(std::hypot(p.x - 0.5, p.y - 0.5) - r) < 1e-6 * r;
                                    });
                if (!circle) {
                    // Straight: the box's edges (length 1) and the hole's seam (0.3), at S alone.
                    const double length = norm(e.points.back() - e.points.front());
                    EXPECT_EQ(e.points.size(), std::size_t(std::ceil(length / S - 1e-9)) + 1) << "edge " << e.edge;
                    ++straight;
                    continue;
                }
                ++circles;
                EXPECT_EQ(e.points.size(), 98u) << "edge " << e.edge;
                // Each segment's arc turns by its central angle, 2 asin(chord / 2r); the
                // polygon's corners turn by the same angles.
                for (std::size_t k = 0; k + 1 < e.points.size(); ++k) {
                    const double chord = norm(e.points[k + 1] - e.points[k]);
                    EXPECT_LE(2 * std::asin(chord / (2 * r)), kMaxTurn) << "edge " << e.edge << " segment " << k;
                }
                EXPECT_LE(max_chord_turn(e), kMaxTurn) << "edge " << e.edge;
            }
            EXPECT_EQ(circles, 2);
            EXPECT_EQ(straight, 13);
        }
    }
}

TEST(GeomDiscretize, ChordalToleranceBoundsEachChordsGapToTheCircle) {
    // r = 0.1 at S = 10: the circles are cut by the tolerance alone. A chord turning by t lies
    // r (1 - cos(t / 2)) from its arc; that gap stays within `chordal` of the chord's length, and
    // the circle is not cut much finer than that asks.
    const double r = 0.1;
    const geom::Model model = test::model_of(test::box_with_blind_hole(r, 0.3));
    for (const double chordal : {0.002, kDefaultChordal, 0.02, 0.05}) {
        SCOPED_TRACE("chordal " + std::to_string(chordal));
        int circles = 0;
        for (const EdgePolyline& e : geom::discretize_edges(model, {}, 10.0, chordal)) {
            if (e.first_vertex != e.last_vertex) continue;
            ++circles;
            double worst = 0;
            for (std::size_t k = 0; k + 1 < e.points.size(); ++k) {
                const double chord = norm(e.points[k + 1] - e.points[k]);
                const double turn = 2 * std::asin(chord / (2 * r));
                worst = std::max(worst, r * (1 - std::cos(turn / 2)) / chord);
            }
            EXPECT_LE(worst, chordal * (1 + 1e-9)) << "edge " << e.edge;
            EXPECT_GT(worst, 0.8 * chordal) << "edge " << e.edge;
        }
        EXPECT_EQ(circles, 2);
    }
    EXPECT_THROW(geom::discretize_edges(model, {}, 10.0, 0.0), Error);
}

TEST(GeomDiscretize, FinerSizeStillWinsOnACircleEdge) {
    // r = 0.1 at S = 0.005: 126 segments by size, more than the 97 the turn asks for.
    const geom::Model model = test::model_of(test::box_with_blind_hole(0.1, 0.3));
    int circles = 0;
    for (const EdgePolyline& e : geom::discretize_edges(model, {}, 0.005)) {
        if (std::abs(std::hypot(e.points[0].x - 0.5, e.points[0].y - 0.5) - 0.1) > 1e-7) continue;
        if (e.first_vertex != e.last_vertex) continue;  // the seam starts on the circle too
        ++circles;
        EXPECT_EQ(e.points.size(), 127u);
    }
    EXPECT_EQ(circles, 2);
}

TEST(GeomDiscretize, EllipseEdgeSegmentsTurnAtMost0065) {
    // Semi-axes 0.5 and 0.25: the curvature runs from b / a^2 = 1 to a / b^2 = 8. The tangent
    // at eccentric angle t is (-a sin t, b cos t); the curve turns between two points by the
    // angle between their tangents (it is convex).
    const double a = 0.5, b = 0.25;
    const std::vector<EdgePolyline> edges = geom::discretize_edges(test::model_of(elliptic_prism(a, b)), {}, 10.0);
    int ellipses = 0;
    for (const EdgePolyline& e : edges) {
        if (e.first_vertex != e.last_vertex) {  // the seam, straight: one segment at S
            EXPECT_EQ(e.points.size(), 2u);
            continue;
        }
        ++ellipses;
        const auto tangent = [&](const Vec3& p) {
            const double t = std::atan2(p.y / b, p.x / a);
            return Vec3{-a * std::sin(t), b * std::cos(t), 0};
        };
        double worst = 0;
        for (std::size_t k = 0; k + 1 < e.points.size(); ++k) {
            const Vec3 u = tangent(e.points[k]), v = tangent(e.points[k + 1]);
            worst = std::max(worst, std::acos(std::clamp(dot(u, v) / (norm(u) * norm(v)), -1.0, 1.0)));
        }
        EXPECT_LE(worst, kMaxTurn) << "edge " << e.edge;
        EXPECT_GT(worst, 0.5 * kMaxTurn) << "edge " << e.edge;  // not cut far finer than asked
        EXPECT_LE(max_chord_turn(e), kMaxTurn) << "edge " << e.edge;
        std::printf("  ellipse %g x %g: %zu segments, largest turn %.4f rad\n", a, b, e.points.size() - 1, worst);
    }
    EXPECT_EQ(ellipses, 2);
}

TEST(GeomDiscretize, CurvatureCutIsCappedAt1024SegmentsPerEdge) {
    // Semi-axes 0.5 and 0.05: curvature up to 200 over a length of about 2, which would ask
    // for about 6200 segments of 0.065 rad.
    const std::vector<EdgePolyline> edges = geom::discretize_edges(test::model_of(elliptic_prism(0.5, 0.05)), {}, 10.0);
    int ellipses = 0;
    for (const EdgePolyline& e : edges) {
        if (e.first_vertex != e.last_vertex) continue;
        ++ellipses;
        EXPECT_EQ(e.points.size(), 1025u) << "edge " << e.edge;
        EXPECT_EQ(e.params.size(), 1025u) << "edge " << e.edge;
    }
    EXPECT_EQ(ellipses, 2);
}

// geom asks the sweep's one rule for n (engine/sweep/sweep.hpp): a thick ring, the paper's
// Example 1 (r = 0.02, St 0.14), gets 8 unless the user asks for the paper's 4.
TEST(GeomDiscretize, TubeRingNodesFollowTheSweepRuleOrTheUser) {
    geom::TubeInfo tube;
    tube.radius_min = 0.0199;
    tube.radius_max = 0.0201;
    EXPECT_EQ(geom::tube_ring_nodes(tube, 0.04, 0), 8);
    EXPECT_EQ(geom::tube_ring_nodes(tube, 0.14, 0), 8);
    EXPECT_EQ(geom::tube_ring_nodes(tube, 0.14, 4), 4);
    EXPECT_EQ(geom::tube_ring_nodes(tube, 0.005, 0), 28);
}

}  // namespace
}  // namespace tubemesh
