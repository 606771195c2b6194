// The OpenCASCADE SurfaceMap: evaluation, projection with periodic normalisation, trimming
// loops, seams, outward normals, and concurrent use from many threads.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>

#include "engine/core/types.hpp"
#include "geom/model/surface_map_occt.hpp"
#include "geom/tubes/tubes.hpp"
#include "tests/support/geom_tubes_solids.hpp"

namespace tubemesh {
namespace {

constexpr double kR = 0.02;
constexpr double kPi = std::numbers::pi;

geom::Model straight_model() {
    return test::model_of(
        test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::straight_spine({0.5, 0.5, -0.1}, {0.5, 0.5, 1.1})}, kR));
}

double signed_area(const std::vector<Uv>& loop) {
    double a = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Uv& p = loop[i];
        const Uv& q = loop[(i + 1) % loop.size()];
        a += p.u * q.v - q.u * p.v;
    }
    return a / 2;
}

TEST(GeomSurfaceMap, CylinderEvaluatesAndProjectsIntoItsRange) {
    const geom::Model model = straight_model();
    const int wall = geom::find_tubes(model).tubes.at(0).faces.at(0);
    const auto map = geom::make_surface_map(model, wall);
    const ParamRange u = map->u_range(), v = map->v_range();
    // Which direction goes round the axis is the surface's business: find the closed one.
    const bool u_around = u.closed;
    ASSERT_NE(u.closed, v.closed);
    const ParamRange around = u_around ? u : v;
    EXPECT_NEAR(around.period, 2 * kPi, 1e-12);
    EXPECT_NEAR(around.hi - around.lo, 2 * kPi, 1e-9);

    const Uv mid{(u.lo + u.hi) / 2, (v.lo + v.hi) / 2};
    const SurfaceDerivatives d = map->derivatives(mid);
    EXPECT_NEAR(std::hypot(d.point.x - 0.5, d.point.y - 0.5), kR, 1e-12);
    const double h = 1e-6;
    const Vec3 pu = map->point({mid.u + h, mid.v});
    EXPECT_NEAR((pu.x - d.point.x) / h, d.du.x, 1e-6);
    EXPECT_NEAR((pu.y - d.point.y) / h, d.du.y, 1e-6);

    // Points just either side of the seam project into [lo, lo + 2 pi), never one period out.
    for (double angle : {-1e-4, 1e-4, 0.0, kPi, 1.7}) {
        const Vec3 p{0.5 + 0.03 * std::cos(angle), 0.5 + 0.03 * std::sin(angle), 0.4};
        for (const std::optional<Uv>& hint : {std::optional<Uv>{}, std::optional<Uv>{mid}}) {
            const Projection pr = map->project(p, hint);
            ASSERT_TRUE(pr.ok);
            EXPECT_NEAR(pr.distance, 0.01, 1e-9);
            const double c = u_around ? pr.uv.u : pr.uv.v;
            EXPECT_GE(c, around.lo);
            EXPECT_LT(c, around.lo + around.period);
            EXPECT_NEAR(pr.point.z, 0.4, 1e-9);
        }
    }
}

TEST(GeomSurfaceMap, OutwardNormalOfAHoleWallPointsIntoTheHole) {
    const geom::Model model = straight_model();
    const int wall = geom::find_tubes(model).tubes.at(0).faces.at(0);
    const auto map = geom::make_surface_map(model, wall);
    const Uv mid{(map->u_range().lo + map->u_range().hi) / 2, (map->v_range().lo + map->v_range().hi) / 2};
    const Vec3 p = map->point(mid);
    const Vec3 n = map->normal(mid);
    EXPECT_NEAR((p.x - 0.5) * n.x + (p.y - 0.5) * n.y, -kR, 1e-9);  // unit, towards the axis
}

TEST(GeomSurfaceMap, TrimmingLoopsAreOuterFirstWithMaterialOnTheLeft) {
    const geom::Model model = straight_model();
    const geom::TubeInfo tube = geom::find_tubes(model).tubes.at(0);
    int faces_with_holes = 0;
    for (const auto& map : geom::make_surface_maps(model)) {
        const std::vector<TrimLoop> loops = map->trimming_loops(0.05);
        ASSERT_FALSE(loops.empty());
        for (const TrimLoop& loop : loops) {
            ASSERT_EQ(loop.edges.size(), loop.edge_begin.size());
            EXPECT_EQ(loop.edge_begin.front(), 0u);
        }
        if (static_cast<int>(map->face()) == tube.faces[0]) continue;  // the wall's loop wraps in uv
        EXPECT_GT(signed_area(loops[0].uv), 0) << "face " << map->face();
        for (std::size_t k = 1; k < loops.size(); ++k) EXPECT_LT(signed_area(loops[k].uv), 0) << "face " << map->face();
        if (loops.size() == 2) {
            ++faces_with_holes;
            EXPECT_EQ(loops[0].edges.size(), 4u);
            EXPECT_EQ(loops[1].edges.size(), 1u);
        }
    }
    EXPECT_EQ(faces_with_holes, 2);
}

TEST(GeomSurfaceMap, SeamUsesGiveBothEndsOfThePeriod) {
    const geom::Model model = straight_model();
    const int wall = geom::find_tubes(model).tubes.at(0).faces.at(0);
    const auto map = geom::make_surface_map(model, wall);
    const std::vector<TrimLoop> loops = map->trimming_loops(0.1);
    ASSERT_EQ(loops.size(), 1u);
    const ParamRange around = map->u_range().closed ? map->u_range() : map->v_range();
    const bool u_around = map->u_range().closed;
    std::vector<double> seam_values;
    for (std::size_t i = 0; i < loops[0].edges.size(); ++i)
        for (std::size_t j = 0; j < loops[0].edges.size(); ++j)
            if (i != j && loops[0].edges[i].edge == loops[0].edges[j].edge) {
                const Uv uv = map->edge_uv(loops[0].edges[i], 0.5);
                seam_values.push_back(u_around ? uv.u : uv.v);
            }
    ASSERT_EQ(seam_values.size(), 2u);
    EXPECT_NEAR(std::abs(seam_values[0] - seam_values[1]), around.period, 1e-9);
    EXPECT_THROW(map->edge_uv({9999, true}, 0.0), Error);
}

TEST(GeomSurfaceMap, ConcurrentProjectionsMatchSerialOnes) {
    const geom::Model model = test::model_of(test::box_with_pipes(
        {0, 0, 0}, {1, 1, 1},
        {test::spline_spine({{-0.1, 0.5, 0.3}, {0.3, 0.6, 0.5}, {0.7, 0.4, 0.6}, {1.1, 0.5, 0.4}})}, kR));
    const int wall = geom::find_tubes(model).tubes.at(0).faces.at(0);
    const auto map = geom::make_surface_map(model, wall);
    const ParamRange u = map->u_range(), v = map->v_range();
    constexpr int kN = 4000;
    std::vector<Vec3> targets;
    for (int i = 0; i < kN; ++i) {
        const double a = (i * 0.618034) - std::floor(i * 0.618034), b = (i * 0.414214) - std::floor(i * 0.414214);
        Vec3 p = map->point({u.lo + a * (u.hi - u.lo), v.lo + (0.05 + 0.9 * b) * (v.hi - v.lo)});
        p.z += 0.001;  // off the surface
        targets.push_back(p);
    }
    std::vector<Projection> serial(kN), parallel(kN);
    for (int i = 0; i < kN; ++i) serial[i] = map->project(targets[i], std::nullopt);
    tbb::parallel_for(0, kN, [&](int i) { parallel[i] = map->project(targets[i], std::nullopt); });
    for (int i = 0; i < kN; ++i) {
        ASSERT_TRUE(parallel[i].ok);
        EXPECT_EQ(parallel[i].uv.u, serial[i].uv.u) << i;
        EXPECT_EQ(parallel[i].uv.v, serial[i].uv.v) << i;
        EXPECT_LT(serial[i].distance, 0.0011);
    }
}

TEST(GeomSurfaceMap, TorusAxisPointDoesNotBreakProjection) {
    const geom::Model model =
        test::model_of(test::box_with_pipes({0, 0, 0}, {1, 1, 1}, {test::arc_spine({0, 0, 0.5}, 0.5, -15, 105)}, kR));
    const int wall = geom::find_tubes(model).tubes.at(0).faces.at(0);
    const auto map = geom::make_surface_map(model, wall);
    const double a = kPi / 4;
    const Projection on_axis = map->project({0.5 * std::cos(a), 0.5 * std::sin(a), 0.5}, std::nullopt);
    if (on_axis.ok) {
        EXPECT_NEAR(on_axis.distance, kR, 1e-7);  // every wall point is a foot point
    }
    const Projection off_axis = map->project({0.51 * std::cos(a), 0.51 * std::sin(a), 0.5}, std::nullopt);
    ASSERT_TRUE(off_axis.ok);
    EXPECT_NEAR(off_axis.distance, kR - 0.01, 1e-9);
    EXPECT_GE(off_axis.uv.u, map->u_range().lo - 1e-9);
    EXPECT_LE(off_axis.uv.u, map->u_range().hi + 1e-9);
    EXPECT_GE(off_axis.uv.v, map->v_range().lo - 1e-9);
    EXPECT_LE(off_axis.uv.v, map->v_range().hi + 1e-9);
}

}  // namespace
}  // namespace tubemesh
