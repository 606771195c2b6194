// One face at a time, per analytic surface kind, with and without holes: angle bounds, area,
// nodes on the surface, boundary kept exactly, neighbour size ratio, orientation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include "tests/support/surface_test_support.hpp"

namespace {

using namespace tubemesh;
using namespace tubemesh::testing;
using surface::FaceBoundary;
using surface::FaceMesh;
constexpr double pi = std::numbers::pi;

double polygon_area_uv(const std::vector<Uv>& p) {
    double a = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Uv &x = p[i], &y = p[(i + 1) % p.size()];
        a += x.u * y.v - x.v * y.u;
    }
    return std::abs(a) / 2;
}

// The surface's acceptance bounds, checked on every face.
void expect_good(const FaceReport& r, const char* what) {
    SCOPED_TRACE(what);
    for (const std::string& p : r.problems) ADD_FAILURE() << p;
    EXPECT_GT(r.triangles, 0u);
    EXPECT_GE(r.min_angle, 20.0);
    EXPECT_GE(r.fraction_above_40, 0.95);
    EXPECT_LE(r.max_distance, 1e-7);
    EXPECT_LE(r.max_neighbor_ratio, 1.5);
    std::printf("  %-28s %6u triangles  min angle %5.1f  max %5.1f  >=40: %5.1f%%  neighbour ratio %.2f\n", what,
                r.triangles, r.min_angle, r.max_angle, 100 * r.fraction_above_40, r.max_neighbor_ratio);
}

// Relative area error a mesh of chords may have on a face of curvature k with edges up to h:
// a chord of angle k·h loses 1 - sin(x)/x ≈ x²/6 of the arc's area (twice that is the bound).
double chord_tolerance(double k, double h) { return (k * h) * (k * h) / 3 + 1e-9; }

// TUBEMESH_SURFACE_DUMP=dir writes each face as "V x y z" / "T a b c" lines, for looking at.
void expect_area(const FaceReport& r, double exact, double tolerance) {
    const double error = std::abs(r.area - exact) / exact;
    EXPECT_LE(error, tolerance) << "area " << r.area << " vs " << exact;
    std::printf("  %-28s area relative error %.2e (bound %.2e)\n", "", error, tolerance);
}

struct Case {
    FaceBoundary boundary;
    FaceMesh mesh;
    FaceReport report;
};

// Meshes the uv rectangle [u0,u1] x [v0,v1] of `s` with the given uv holes (n-gons of radius
// rho, which ask for their own edge length as the size nearby).
Case mesh_rectangle(const AnalyticSurface& s, double S, Uv lo, Uv hi, const std::vector<std::vector<Uv>>& holes = {}) {
    std::vector<SizeSource> sources;
    for (const auto& h : holes) add_uv_polygon_sources(s, h, sources);
    const SizeField size({S}, sources);
    BoundaryBuilder b(s, size);
    const Uv corners[4] = {lo, {hi.u, lo.v}, hi, {lo.u, hi.v}};
    b.add_loop(corners);
    for (const auto& h : holes) b.add_polygon(h);
    Case c;
    c.boundary = b.take();
    c.mesh = surface::mesh_face(s, c.boundary, size);
    c.report = inspect_face(s, c.boundary, c.mesh, size);
    dump_face(c.mesh, c.boundary, ::testing::UnitTest::GetInstance()->current_test_info()->name());
    return c;
}

TEST(SurfaceFace, PlaneRectangle) {
    const PlaneSurface s({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 2}, {0, 1});
    const Case c = mesh_rectangle(s, 0.1, {0, 0}, {2, 1});
    expect_good(c.report, "plane");
    expect_area(c.report, 2.0, 1e-3);
}

TEST(SurfaceFace, PlaneWithHoles) {
    const PlaneSurface s({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 2}, {0, 1});
    std::vector<std::vector<Uv>> holes = {uv_polygon({0.5, 0.5}, 0.05, 16), uv_polygon({1.3, 0.4}, 0.08, 16, 0.3),
                                          uv_polygon({1.6, 0.75}, 0.03, 12)};
    const Case c = mesh_rectangle(s, 0.1, {0, 0}, {2, 1}, holes);
    expect_good(c.report, "plane with holes");
    double expected = 2.0;
    for (const auto& h : holes) expected -= polygon_area_uv(h);
    expect_area(c.report, expected, 1e-3);
}

TEST(SurfaceFace, CylinderPatch) {
    const CylinderSurface s(1.0, {0, pi}, {0, 2});
    const Case c = mesh_rectangle(s, 0.15, {0, 0}, {pi, 2});
    expect_good(c.report, "cylinder patch");
    const double exact = s.area(0, pi, 0, 2);
    expect_area(c.report, exact, chord_tolerance(s.max_curvature(), c.report.max_edge));
    EXPECT_LT(c.report.area, exact);  // chords cut inside a convex surface
}

TEST(SurfaceFace, CylinderPatchWithHoles) {
    const CylinderSurface s(1.0, {0, pi}, {0, 2});
    // Holes are n-gons in uv: u is an angle on a unit radius, so they are near-round in space.
    std::vector<std::vector<Uv>> holes = {round_polygon(s, {1.0, 0.6}, 0.08, 16), round_polygon(s, {2.2, 1.3}, 0.12, 16, 0.2)};
    const Case c = mesh_rectangle(s, 0.15, {0, 0}, {pi, 2}, holes);
    expect_good(c.report, "cylinder patch with holes");
}

// A whole cylinder: the loop runs along the bottom, up the seam at u = 2 pi, back along the
// top and down the seam at u = 0; the seam's nodes appear twice, one period apart.
TEST(SurfaceFace, FullCylinderAcrossTheSeam) {
    const CylinderSurface s(0.5, {0, 2 * pi, true, 2 * pi}, {0, 1.5});
    const Case c = mesh_rectangle(s, 0.12, {0, 0}, {2 * pi, 1.5}, {round_polygon(s, {0.3, 0.7}, 0.08, 16)});
    expect_good(c.report, "full cylinder with a hole");
    // The seam is shared: its nodes were merged, so no node repeats a position.
    EXPECT_LT(c.boundary.node_count(), c.boundary.loop_node.size());
}

TEST(SurfaceFace, ConeFrustum) {
    const ConeSurface s(0.6, 0.4, {0, 2 * pi, true, 2 * pi}, {0, 1.2});
    const Case c = mesh_rectangle(s, 0.12, {0, 0}, {2 * pi, 1.2}, {round_polygon(s, {3.0, 0.6}, 0.08, 16)});
    expect_good(c.report, "cone frustum with a hole");
}

TEST(SurfaceFace, SphereZone) {
    const SphereSurface s(1.0, {0, 2 * pi, true, 2 * pi}, {-1.0, 1.1});
    const Case c = mesh_rectangle(s, 0.12, {0, -1.0}, {2 * pi, 1.1});
    expect_good(c.report, "sphere zone");
    const double exact = s.area(0, 2 * pi, -1.0, 1.1);
    expect_area(c.report, exact, chord_tolerance(s.max_curvature(), c.report.max_edge));
}

TEST(SurfaceFace, SphereZoneWithHoles) {
    const SphereSurface s(1.0, {0, 2 * pi, true, 2 * pi}, {-1.0, 1.1});
    const Case c = mesh_rectangle(s, 0.12, {0, -1.0}, {2 * pi, 1.1},
                                  {round_polygon(s, {1.0, 0.0}, 0.1, 16), round_polygon(s, {4.0, 0.5}, 0.1, 16)});
    expect_good(c.report, "sphere zone with holes");
}

TEST(SurfaceFace, WholeTorus) {
    const TorusSurface s(1.0, 0.3, {0, 2 * pi, true, 2 * pi}, {0, 2 * pi, true, 2 * pi});
    const Case c = mesh_rectangle(s, 0.1, {0, 0}, {2 * pi, 2 * pi});
    expect_good(c.report, "torus");
    const double exact = s.area(0, 2 * pi, 0, 2 * pi);
    expect_area(c.report, exact, chord_tolerance(s.max_curvature(), c.report.max_edge));
}

TEST(SurfaceFace, TorusPatchWithHole) {
    const TorusSurface s(1.0, 0.3, {0, 2 * pi, false, 2 * pi}, {0, 2 * pi, false, 2 * pi});
    const Case c = mesh_rectangle(s, 0.08, {0.2, -1.0}, {2.0, 1.5}, {round_polygon(s, {1.0, 0.2}, 0.06, 16)});
    expect_good(c.report, "torus patch with a hole");
}

BicubicSurface wavy_patch() {
    const double z[4][4] = {{0, 0.3, -0.2, 0.1}, {0.2, 0.6, 0.4, -0.1}, {-0.1, 0.5, 0.7, 0.2}, {0.1, -0.2, 0.3, 0}};
    BicubicSurface s(1.0, z);
    s.set_max_curvature(4.0);  // generous: the checks only need an upper bound
    return s;
}

TEST(SurfaceFace, BicubicPatch) {
    const BicubicSurface s = wavy_patch();
    const Case c = mesh_rectangle(s, 0.1, {0, 0}, {1, 1});
    expect_good(c.report, "bicubic patch");
    const double exact = s.area(0, 1, 0, 1);
    expect_area(c.report, exact, chord_tolerance(s.max_curvature(), c.report.max_edge));
}

TEST(SurfaceFace, BicubicPatchWithHoles) {
    const BicubicSurface s = wavy_patch();
    const Case c = mesh_rectangle(s, 0.1, {0, 0}, {1, 1}, {round_polygon(s, {0.3, 0.3}, 0.05, 16), round_polygon(s, {0.7, 0.6}, 0.04, 12)});
    expect_good(c.report, "bicubic patch with holes");
}

// The face is used reversed in its solid: triangles turn the other way.
TEST(SurfaceFace, ReversedFaceFlipsTriangles) {
    const PlaneSurface s({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1}, {0, 1}, true);
    const Case c = mesh_rectangle(s, 0.1, {0, 0}, {1, 1});
    expect_good(c.report, "reversed plane");  // inspect_face checks normals against -(du x dv)
}

}  // namespace
