// From geometry to face boundaries: edges cut once and shared, seams used twice, a cone's apex
// (a degenerate edge), a tube's end loop replaced by its ring's outer polygon; edges cut again
// to the size field, short edge segments as size sources.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <string>
#include <functional>
#include <map>
#include <numbers>
#include <unordered_map>

#include "engine/surface/face_boundaries.hpp"
#include "engine/surface/mesh_surfaces.hpp"
#include "tests/support/surface_test_support.hpp"

namespace {

using namespace tubemesh;
using namespace tubemesh::testing;
using surface::EdgeNodes;
using surface::FaceBoundary;
constexpr double pi = std::numbers::pi;

// An analytic face with B-rep style trimming: each edge use has its uv curve t -> uv over the
// edge's parameter range, as geom's SurfaceMap gives them.
template <class Base>
class TrimmedSurface : public Base {
public:
    using Curve = std::function<Uv(double)>;
    struct Use {
        EdgeUse use;
        double t0, t1;  // the edge's parameter range (increasing)
        Curve uv;
    };
    using Base::Base;

    void add_loop(std::vector<Use> uses) { loops_.push_back(std::move(uses)); }

    Uv edge_uv(EdgeUse use, double t) const override {
        for (const auto& loop : loops_)
            for (const Use& u : loop)
                if (u.use.edge == use.edge && u.use.forward == use.forward) return u.uv(t);
        throw Error("edge not on this face");
    }
    std::vector<TrimLoop> trimming_loops(double max_step) const override {
        std::vector<TrimLoop> out;
        for (const auto& loop : loops_) {
            TrimLoop l;
            for (const Use& u : loop) {
                l.edges.push_back(u.use);
                l.edge_begin.push_back(l.uv.size());
                const int n = std::max(4, int(std::ceil((u.t1 - u.t0) / max_step)));
                for (int k = 0; k < n; ++k) {
                    const double s = double(k) / n;
                    l.uv.push_back(u.uv(u.use.forward ? u.t0 + s * (u.t1 - u.t0) : u.t1 - s * (u.t1 - u.t0)));
                }
            }
            out.push_back(std::move(l));
        }
        return out;
    }

private:
    std::vector<std::vector<Use>> loops_;
};

EdgePolyline cut(index_t edge, index_t v0, index_t v1, double t0, double t1, int n,
                 const std::function<Vec3(double)>& curve) {
    EdgePolyline e{edge, v0, v1, {}, {}};
    for (int k = 0; k <= n; ++k) {
        const double t = t0 + (t1 - t0) * k / n;
        e.params.push_back(t);
        e.points.push_back(curve(t));
    }
    return e;
}

TEST(SurfaceBoundaries, CylinderWithSeamAndRing) {
    const double r = 0.5, H = 1.2;
    TrimmedSurface<CylinderSurface> s(r, ParamRange{0, 2 * pi, true, 2 * pi}, ParamRange{0, H});
    // Edges: 1 bottom circle (vertex 1), 2 top circle (vertex 2), 3 seam from 1 to 2.
    const auto circle = [&](double z) { return [=](double t) { return Vec3{r * std::cos(t), r * std::sin(t), z}; }; };
    std::vector<EdgePolyline> edges = {cut(1, 1, 1, 0, 2 * pi, 32, circle(0)), cut(2, 2, 2, 0, 2 * pi, 32, circle(H)),
                                       cut(3, 1, 2, 0, H, 8, [&](double t) { return Vec3{r, 0, t}; })};
    s.add_loop({{{1, true}, 0, 2 * pi, [](double t) { return Uv{t, 0}; }},
                {{3, true}, 0, H, [](double t) { return Uv{2 * pi, t}; }},
                {{2, false}, 0, 2 * pi, [=](double t) { return Uv{t, H}; }},
                {{3, false}, 0, H, [](double t) { return Uv{0, t}; }}});
    HybridMesh mesh;
    const EdgeNodes nodes = surface::add_edge_nodes(edges, mesh);
    EXPECT_EQ(mesh.point_count(), 32u + 32u + 7u);  // vertices shared, closed edges' ends once
    // A ring's outer polygon around uv (2, 0.6), round in space.
    std::vector<index_t> ring_nodes;
    const std::vector<Uv> ring_uv = round_polygon(s, {2.0, 0.6}, 0.12, 16);
    for (const Uv& p : ring_uv) {
        const Vec3 x = s.point(p);
        ring_nodes.push_back(mesh.add_point(x.x, x.y, x.z));
    }
    const surface::HolePolygon ring{ring_nodes, ring_uv};
    surface::SurfaceFace face{&s, surface::face_boundary(s, edges, nodes, {}, {&ring, 1}, mesh, 0.1), 0};
    EXPECT_EQ(face.boundary.loop_count(), 2u);
    EXPECT_EQ(face.boundary.loop_begin[1], 32u + 8u + 32u + 8u);  // the seam's nodes twice

    std::vector<SizeSource> sources;
    add_uv_polygon_sources(s, ring_uv, sources);
    const SizeField size({2 * pi * r / 32}, sources);
    const surface::FaceMesh m = surface::mesh_face(s, face.boundary, size);
    const FaceReport rep = inspect_face(s, face.boundary, m, size);
    for (const std::string& p : rep.problems) ADD_FAILURE() << p;
    EXPECT_GE(rep.min_angle, 20.0);
    EXPECT_GE(rep.fraction_above_40, 0.95);
}

// The bottom circle is where a ring stops (TubeData::stops): its polyline takes the ring's
// nodes, and the seam, which ends at that circle's vertex, starts at the ring's node there.
TEST(SurfaceBoundaries, FixedEdgeNodesAreTheRingsAndShareTheirVertex) {
    const double r = 0.5, H = 1.2;
    const auto circle = [&](double z) { return [=](double t) { return Vec3{r * std::cos(t), r * std::sin(t), z}; }; };
    std::vector<EdgePolyline> edges = {cut(1, 1, 1, 0, 2 * pi, 16, circle(0)), cut(2, 2, 2, 0, 2 * pi, 32, circle(H)),
                                       cut(3, 1, 2, 0, H, 8, [&](double t) { return Vec3{r, 0, t}; })};
    HybridMesh mesh;
    surface::FixedEdgeNodes ring{1, {}};
    for (int k = 0; k < 16; ++k) {
        const Vec3 p = circle(0)(2 * pi * k / 16);
        ring.ids.push_back(mesh.add_point(p.x, p.y, p.z));
    }
    ring.ids.push_back(ring.ids.front());
    const index_t before = mesh.point_count();
    const EdgeNodes nodes = surface::add_edge_nodes(edges, mesh, {&ring, 1});
    EXPECT_EQ(mesh.point_count(), before + 32u + 7u);  // the top circle and the seam's inner nodes only
    EXPECT_EQ(nodes.nodes[nodes.polyline_of.at(1)], ring.ids);
    EXPECT_EQ(nodes.nodes[nodes.polyline_of.at(3)].front(), ring.ids.front());
    EXPECT_EQ(nodes.vertex_node.at(1), ring.ids.front());
    ring.ids.pop_back();
    EXPECT_THROW(surface::add_edge_nodes(edges, mesh, {&ring, 1}), Error);
}

TEST(SurfaceBoundaries, ConeApexIsADegenerateEdge) {
    const double alpha = 0.5, H = 1.0;
    TrimmedSurface<ConeSurface> s(0.0, alpha, ParamRange{0, 2 * pi, true, 2 * pi}, ParamRange{0, H});
    const double R = H * std::sin(alpha), Z = H * std::cos(alpha);
    // Edges: 1 the apex (degenerate, no polyline), 2 the seam from the apex (vertex 1) to the
    // rim (vertex 2), 3 the rim circle.
    std::vector<EdgePolyline> edges = {
        cut(2, 1, 2, 0, H, 10, [&](double t) { return Vec3{t * std::sin(alpha), 0, t * std::cos(alpha)}; }),
        cut(3, 2, 2, 0, 2 * pi, 40, [&](double t) { return Vec3{R * std::cos(t), R * std::sin(t), Z}; })};
    s.add_loop({{{1, true}, 0, 2 * pi, [](double t) { return Uv{t, 0}; }},
                {{2, true}, 0, H, [](double t) { return Uv{2 * pi, t}; }},
                {{3, false}, 0, 2 * pi, [=](double t) { return Uv{t, H}; }},
                {{2, false}, 0, H, [](double t) { return Uv{0, t}; }}});
    HybridMesh mesh;
    const EdgeNodes nodes = surface::add_edge_nodes(edges, mesh);
    const FaceBoundary b = surface::face_boundary(s, edges, nodes, {}, {}, mesh, 0.1);
    const SizeField size({0.1}, {});
    const surface::FaceMesh m = surface::mesh_face(s, b, size);
    dump_face(m, b, "cone_apex");
    const FaceReport rep = inspect_face(s, b, m, size);
    for (const std::string& p : rep.problems) ADD_FAILURE() << p;
    EXPECT_GE(rep.min_angle, 20.0);
    EXPECT_GE(rep.fraction_above_40, 0.95);
    // The apex is one node with a closed fan: every edge at it is used twice (checked above),
    // and the area is the cone's up to the chord error.
    const double exact = pi * R * H;
    EXPECT_NEAR(rep.area, exact, 0.02 * exact);
    std::printf("  cone with apex: %u triangles, min angle %.1f, >=40: %.1f%%\n", rep.triangles, rep.min_angle,
                100 * rep.fraction_above_40);
}

TEST(SurfaceBoundaries, WholeSphereWithTwoPoles) {
    const double R = 1.0;
    TrimmedSurface<SphereSurface> s(R, ParamRange{0, 2 * pi, true, 2 * pi}, ParamRange{-pi / 2, pi / 2});
    // Edges: 1 the south pole and 3 the north pole (degenerate), 2 the seam meridian from the
    // south pole (vertex 1) to the north pole (vertex 2).
    std::vector<EdgePolyline> edges = {cut(2, 1, 2, -pi / 2, pi / 2, 24, [&](double t) {
        return Vec3{R * std::cos(t), 0, R * std::sin(t)};
    })};
    s.add_loop({{{1, true}, 0, 2 * pi, [](double t) { return Uv{t, -pi / 2}; }},
                {{2, true}, -pi / 2, pi / 2, [](double t) { return Uv{2 * pi, t}; }},
                {{3, false}, 0, 2 * pi, [](double t) { return Uv{t, pi / 2}; }},
                {{2, false}, -pi / 2, pi / 2, [](double t) { return Uv{0, t}; }}});
    HybridMesh mesh;
    const EdgeNodes nodes = surface::add_edge_nodes(edges, mesh);
    const FaceBoundary b = surface::face_boundary(s, edges, nodes, {}, {}, mesh, 0.2);
    const SizeField size({0.15}, {});
    const surface::FaceMesh m = surface::mesh_face(s, b, size);
    dump_face(m, b, "sphere");
    const FaceReport rep = inspect_face(s, b, m, size);
    for (const std::string& p : rep.problems) ADD_FAILURE() << p;
    EXPECT_GE(rep.min_angle, 20.0);
    EXPECT_GE(rep.fraction_above_40, 0.95);
    const double exact = 4 * pi * R * R;
    EXPECT_NEAR(rep.area, exact, 0.02 * exact);
    std::printf("  whole sphere: %u triangles, min angle %.1f, >=40: %.1f%%, area error %.2e\n", rep.triangles,
                rep.min_angle, 100 * rep.fraction_above_40, std::abs(rep.area - exact) / exact);
}

TEST(SurfaceBoundaries, TubeEndLoopIsReplacedByTheRing) {
    PlaneSurface base({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1}, {0, 1});
    TrimmedSurface<PlaneSurface> s({0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, ParamRange{0, 1}, ParamRange{0, 1});
    // Outer square: edges 1-4 between vertices 1-4; the tube's end circle: edge 9 (no polyline).
    const Vec3 c[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    std::vector<EdgePolyline> edges;
    for (int k = 0; k < 4; ++k) {
        const Vec3 a = c[k], d = c[(k + 1) % 4];
        edges.push_back(cut(index_t(k + 1), index_t(k + 1), index_t((k + 1) % 4 + 1), 0, 1, 10,
                            [=](double t) { return a + t * (d - a); }));
    }
    std::vector<TrimmedSurface<PlaneSurface>::Use> outer;
    for (int k = 0; k < 4; ++k) {
        const Vec3 a = c[k], d = c[(k + 1) % 4];
        outer.push_back({{index_t(k + 1), true}, 0, 1, [=](double t) { return Uv{a.x + t * (d.x - a.x), a.y + t * (d.y - a.y)}; }});
    }
    s.add_loop(outer);
    s.add_loop({{{9, false}, 0, 2 * pi, [](double t) { return Uv{0.5 + 0.05 * std::cos(t), 0.5 + 0.05 * std::sin(t)}; }}});
    HybridMesh mesh;
    const EdgeNodes nodes = surface::add_edge_nodes(edges, mesh);
    std::vector<index_t> ring_nodes;
    std::vector<Uv> ring_uv = uv_polygon({0.5, 0.5}, 0.1, 16);
    std::reverse(ring_uv.begin(), ring_uv.end());  // clockwise, as engine/sweep gives a hole
    for (const Uv& p : ring_uv) ring_nodes.push_back(mesh.add_point(p.u, p.v, 0));
    const surface::HolePolygon ring{ring_nodes, ring_uv};
    const index_t tube_edges[] = {9};
    const FaceBoundary b = surface::face_boundary(s, edges, nodes, tube_edges, {&ring, 1}, mesh, 0.05);
    ASSERT_EQ(b.loop_count(), 2u);
    EXPECT_EQ(b.loop_begin[2] - b.loop_begin[1], 16u);
    EXPECT_EQ(b.node_id[b.loop_node[b.loop_begin[1]]], ring_nodes[0]);
    std::vector<SizeSource> sources;
    add_uv_polygon_sources(s, ring_uv, sources);
    const SizeField size({0.1}, sources);
    const surface::FaceMesh m = surface::mesh_face(s, b, size);
    const FaceReport rep = inspect_face(s, b, m, size);
    for (const std::string& p : rep.problems) ADD_FAILURE() << p;
    const double hole = 16 * 0.5 * 0.01 * std::sin(2 * pi / 16);
    EXPECT_NEAR(rep.area, 1 - hole, 1e-12);
    // Without the tube edge list the loop has no polyline to stand on.
    EXPECT_THROW(surface::face_boundary(s, edges, nodes, {}, {}, mesh, 0.05), Error);
}

// follow_size_field and add_short_edge_sources: B-rep edge polylines against the size field.

// A straight edge on the plane z = 0 (the face's uv is x, y) from a to b, parameter 0 to 1.
struct PlaneEdge {
    Vec3 a, b;
    Vec3 at(double t) const { return a + t * (b - a); }
    Uv uv(double t) const { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }
};

using PlaneFace = TrimmedSurface<PlaneSurface>;
PlaneFace unit_plane() { return PlaneFace({0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, ParamRange{0, 1}, ParamRange{0, 1}); }

// Every byte of the two polylines equal (points as stored, not up to a tolerance).
bool same_bytes(const EdgePolyline& a, const EdgePolyline& b) {
    return a.edge == b.edge && a.first_vertex == b.first_vertex && a.last_vertex == b.last_vertex &&
           a.points.size() == b.points.size() && a.params.size() == b.params.size() &&
           std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(Vec3)) == 0 &&
           std::memcmp(a.params.data(), b.params.data(), a.params.size() * sizeof(double)) == 0;
}
bool same_bytes(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

// The contract's t(s) = min(h(x(s)), length of the input segment at s), integrated by the
// midpoint rule along the input polyline from position p0 to p1 (segment index + fraction).
double integral_over_t(const EdgePolyline& in, const SizeField& size, double p0, double p1) {
    const int steps = 2000;
    double sum = 0;
    for (int k = 0; k < steps; ++k) {
        const double p = p0 + (p1 - p0) * (k + 0.5) / steps;
        const std::size_t i = std::min(std::size_t(p), in.points.size() - 2);
        const Vec3 a = in.points[i], d = in.points[i + 1] - a;
        const double len = norm(d);
        sum += len * (p1 - p0) / steps / std::min(size.at(a + (p - double(i)) * d), len);
    }
    return sum;
}

// Position along the input polyline (segment index + fraction) of curve parameter t.
double position_of(const EdgePolyline& in, double t) {
    const auto it = std::upper_bound(in.params.begin(), in.params.end(), t);
    const std::size_t i = std::min<std::size_t>(std::max<std::ptrdiff_t>(it - in.params.begin(), 1) - 1, in.params.size() - 2);
    return double(i) + (t - in.params[i]) / (in.params[i + 1] - in.params[i]);
}

// The largest segment length over h at the segment's midpoint. (Against h at the segment's
// small end it can reach about 1.12 where h grows at the full rate g: N = ceil(I) bounds each
// segment's integral of ds / h, not its length over the smallest h along it.)
double worst_length_over_midpoint_size(const EdgePolyline& e, const SizeField& size) {
    double worst = 0;
    for (std::size_t k = 0; k + 1 < e.points.size(); ++k) {
        const Vec3 a = e.points[k], d = e.points[k + 1] - a;
        worst = std::max(worst, norm(d) / size.at(a + 0.5 * d));
    }
    return worst;
}

// The contract's cut of `in` into `out`: N = ceil(I) segments, each an equal share I / N of
// I = integral of ds / t(s), to 1 % (the function integrates by coarser trapezoids).
void expect_equal_shares(const EdgePolyline& in, const EdgePolyline& out, const SizeField& size) {
    const double total = integral_over_t(in, size, 0, double(in.points.size() - 1));
    const std::size_t n = out.points.size() - 1;
    EXPECT_EQ(n, std::size_t(std::ceil(total)));
    for (std::size_t k = 0; k < n; ++k)
        EXPECT_NEAR(integral_over_t(in, size, position_of(in, out.params[k]), position_of(in, out.params[k + 1])),
                    total / double(n), 0.01 * total / double(n))
            << "segment " << k;
}

TEST(SurfaceEdgeSizes, StraightEdgeIsCutAgainNearAPointSource) {
    PlaneFace s = unit_plane();
    const PlaneEdge line{{0, 0, 0}, {1, 0, 0}};
    s.add_loop({{{1, true}, 0, 1, [&](double t) { return line.uv(t); }}});
    std::vector<EdgePolyline> in = {cut(1, 1, 2, 0, 1, 5, [&](double t) { return line.at(t); })};  // at S
    // The B-rep vertices' own points, a little off the curve (within a vertex's tolerance).
    in[0].points.front() = {0, 1e-9, 0};
    in[0].points.back() = {1, -1e-9, 0};
    const std::unordered_map<index_t, surface::EdgeOnFace> on_face = {{1, {&s, {1, true}}}};
    // h = 0.015 where the edge passes the source, S = 0.2 from x = 0.8 on.
    const SizeField size({0.2}, {{{0.05, 0.02, 0}, 0.01}});
    const std::vector<EdgePolyline> out = surface::follow_size_field(in, on_face, size);
    ASSERT_EQ(out.size(), 1u);
    const EdgePolyline& e = out[0];
    EXPECT_EQ(e.edge, 1u);
    EXPECT_EQ(e.first_vertex, 1u);
    EXPECT_EQ(e.last_vertex, 2u);
    ASSERT_EQ(e.points.size(), e.params.size());
    ASSERT_GE(e.points.size(), 2u);
    // The end points are the input's, bit for bit (B-rep vertices shared with other edges).
    EXPECT_TRUE(same_bytes(e.points.front(), in[0].points.front()));
    EXPECT_TRUE(same_bytes(e.points.back(), in[0].points.back()));
    EXPECT_EQ(e.params.front(), 0.0);
    EXPECT_EQ(e.params.back(), 1.0);
    // New points are the face's points at their parameters: on the line, at x = t.
    for (std::size_t k = 1; k < e.points.size(); ++k) {
        EXPECT_GT(e.params[k], e.params[k - 1]) << "point " << k;
        if (k + 1 == e.points.size()) break;
        EXPECT_EQ(e.points[k].x, e.params[k]) << "point " << k;
        EXPECT_EQ(e.points[k].y, 0.0);
        EXPECT_EQ(e.points[k].z, 0.0);
    }
    expect_equal_shares(in[0], e, size);
    // So it follows h: the segment by the source is about h there, none is longer than 1.1 h.
    EXPECT_LT(norm(e.points[1] - e.points[0]), 1.1 * size.at(e.points[0]));
    const double worst = worst_length_over_midpoint_size(e, size);
    EXPECT_LE(worst, 1.1);
    std::printf("  straight edge: %zu -> %zu segments, worst length / h(midpoint) %.3f\n", in[0].points.size() - 1,
                e.points.size() - 1, worst);
}

TEST(SurfaceEdgeSizes, EdgeWithinTheSizeFieldIsKeptAsItIs) {
    // Segments of 0.21 = 1.05 h (h = S = 0.2 along the edge; the source is 3 away), without a
    // face to evaluate on: kept as given, so no face is needed.
    const PlaneEdge line{{0, 0, 0}, {1.05, 0, 0}};
    const std::vector<EdgePolyline> in = {cut(4, 1, 2, 0, 1, 5, [&](double t) { return line.at(t); })};
    const SizeField size({0.2}, {{{0.5, 3, 0}, 0.05}});
    std::vector<EdgePolyline> out;
    ASSERT_NO_THROW(out = surface::follow_size_field(in, {}, size));
    ASSERT_EQ(out.size(), 1u);
    EXPECT_TRUE(same_bytes(out[0], in[0]));
}

TEST(SurfaceEdgeSizes, CurvedEdgeKeepsGeomsFinerCutAwayFromTheSource) {
    // A circle of radius 0.1 cut as geom cuts it for its curvature (97 segments of 0.0065,
    // far below S = 0.2), with a source by the circle's point at t = 0 asking for 0.001.
    const double r = 0.1;
    const int n0 = 97;
    PlaneFace s = unit_plane();
    const auto uv = [&](double t) { return Uv{0.5 + r * std::cos(t), 0.5 + r * std::sin(t)}; };
    s.add_loop({{{7, true}, 0, 2 * pi, uv}});
    const std::vector<EdgePolyline> in = {cut(7, 3, 3, 0, 2 * pi, n0, [&](double t) { return s.point(uv(t)); })};
    const std::unordered_map<index_t, surface::EdgeOnFace> on_face = {{7, {&s, {7, true}}}};
    const SizeField size({0.2}, {{{0.5 + r + 0.005, 0.5, 0}, 0.001}});
    const std::vector<EdgePolyline> out = surface::follow_size_field(in, on_face, size);
    ASSERT_EQ(out.size(), 1u);
    const EdgePolyline& e = out[0];
    EXPECT_EQ(e.first_vertex, 3u);
    EXPECT_EQ(e.last_vertex, 3u);
    EXPECT_TRUE(same_bytes(e.points.front(), in[0].points.front()));
    EXPECT_TRUE(same_bytes(e.points.back(), in[0].points.back()));
    EXPECT_GT(e.points.size(), in[0].points.size());  // cut again by the source
    // New points on the circle itself (evaluated on the face, not on geom's chords: those
    // are up to 5e-5 inside it).
    for (const Vec3& p : e.points) EXPECT_NEAR(std::hypot(p.x - 0.5, p.y - 0.5), r, 1e-12);
    // Nowhere coarser than geom's cut (the chord of a fraction of a segment of the 97-gon is
    // at most 1 + 2e-4 times that fraction of its length), and fine by the source.
    const double geom_segment = 2 * r * std::sin(pi / n0);
    double longest = 0;
    for (std::size_t k = 0; k + 1 < e.points.size(); ++k) longest = std::max(longest, norm(e.points[k + 1] - e.points[k]));
    EXPECT_LE(longest, (1 + 2e-4) * geom_segment);
    expect_equal_shares(in[0], e, size);
    EXPECT_LE(worst_length_over_midpoint_size(e, size), 1.1);
    std::printf("  circle: %zu -> %zu segments, longest %.3g (geom's %.3g)\n", in[0].points.size() - 1,
                e.points.size() - 1, longest, geom_segment);
}

TEST(SurfaceEdgeSizes, OutputIsDeterministicAndInTheInputOrder) {
    PlaneFace s = unit_plane();
    const PlaneEdge l1{{0, 0, 0}, {1, 0, 0}}, l2{{1, 0, 0}, {1, 1, 0}}, l3{{0, 1, 0}, {0, 0, 0}};
    s.add_loop({{{1, true}, 0, 1, [&](double t) { return l1.uv(t); }},
                {{2, true}, 0, 1, [&](double t) { return l2.uv(t); }},
                {{3, true}, 0, 1, [&](double t) { return l3.uv(t); }}});
    // Edges 3 and 1 pass the source and are cut again; edge 2 is fine as it is.
    const std::vector<EdgePolyline> in = {cut(3, 4, 1, 0, 1, 5, [&](double t) { return l3.at(t); }),
                                          cut(1, 1, 2, 0, 1, 5, [&](double t) { return l1.at(t); }),
                                          cut(2, 2, 3, 0, 1, 5, [&](double t) { return l2.at(t); })};
    const SizeField size({0.2}, {{{0.03, 0.03, 0}, 0.01}});
    // The same map built in two insertion orders, one with other edges making it rehash.
    std::unordered_map<index_t, surface::EdgeOnFace> a, b;
    for (index_t id : {1u, 2u, 3u}) a.emplace(id, surface::EdgeOnFace{&s, {id, true}});
    for (index_t id = 1000; id > 10; --id) b.emplace(id, surface::EdgeOnFace{nullptr, {id, true}});
    for (index_t id : {3u, 2u, 1u}) b.emplace(id, surface::EdgeOnFace{&s, {id, true}});
    const std::vector<EdgePolyline> one = surface::follow_size_field(in, a, size);
    const std::vector<EdgePolyline> two = surface::follow_size_field(in, b, size);
    ASSERT_EQ(one.size(), 3u);
    ASSERT_EQ(two.size(), 3u);
    EXPECT_EQ(one[0].edge, 3u);
    EXPECT_EQ(one[1].edge, 1u);
    EXPECT_EQ(one[2].edge, 2u);
    EXPECT_GT(one[0].points.size(), 6u);
    EXPECT_GT(one[1].points.size(), 6u);
    EXPECT_TRUE(same_bytes(one[2], in[2]));
    for (std::size_t k = 0; k < 3; ++k) EXPECT_TRUE(same_bytes(one[k], two[k])) << "edge " << one[k].edge;
}

TEST(SurfaceEdgeSizes, EdgeToCutAgainWithoutAFaceThrows) {
    const PlaneEdge line{{0, 0, 0}, {1, 0, 0}};
    const std::vector<EdgePolyline> in = {cut(5, 1, 2, 0, 1, 5, [&](double t) { return line.at(t); })};
    const SizeField size({0.2}, {{{0.5, 0, 0}, 0.01}});
    EXPECT_THROW(surface::follow_size_field(in, {}, size), Error);
    const std::unordered_map<index_t, surface::EdgeOnFace> no_surface = {{5, {nullptr, {5, true}}}};
    EXPECT_THROW(surface::follow_size_field(in, no_surface, size), Error);
}

TEST(SurfaceEdgeSizes, ShortSegmentsBecomeSizeSources) {
    // h = S = 0.2: a node becomes a source when the mean of its segments is under 0.16.
    const SizeField size({0.2}, {});
    // Segments 0.02, 0.02, 0.2, 0.2, 0.15, 0.18: nodes 0-2 (0.02, 0.02, 0.11) are sources,
    // nodes 3-6 (0.2, 0.175, 0.165, 0.18) are not.
    EdgePolyline curved{1, 1, 2, {}, {}};
    for (double x : {0.0, 0.02, 0.04, 0.24, 0.44, 0.59, 0.77}) curved.points.push_back({x, 0, 0});
    curved.params = {0, 1, 2, 3, 4, 5, 6};
    // A short edge between two vertices: both ends, its one segment's length.
    const EdgePolyline short_edge{2, 2, 3, {{0.77, 0, 0}, {0.77, 0.15, 0}}, {0, 1}};
    const std::vector<EdgePolyline> edges = {curved, short_edge};
    std::vector<SizeSource> out = {{{9, 9, 9}, 1.0}};  // appended to, not replaced
    surface::add_short_edge_sources(edges, size, out);
    ASSERT_EQ(out.size(), 6u);
    EXPECT_EQ(out[0].size, 1.0);
    const Vec3 at[5] = {curved.points[0], curved.points[1], curved.points[2], short_edge.points[0], short_edge.points[1]};
    const double want[5] = {0.02, 0.02, 0.11, 0.15, 0.15};
    for (int k = 0; k < 5; ++k) {
        EXPECT_TRUE(same_bytes(out[k + 1].point, at[k])) << "source " << k;
        EXPECT_NEAR(out[k + 1].size, want[k], 1e-12) << "source " << k;
    }
}

TEST(SurfaceEdgeSizes, ShortSegmentsAreMeasuredAgainstHAtTheNode) {
    // Even segments of 0.1 along x; h = 0.06 + 0.25 x (to S = 0.2): 0.1 < 0.8 h from x = 0.3.
    const SizeField size({0.2}, {{{0, 0, 0}, 0.06}});
    const EdgePolyline e = cut(1, 1, 2, 0, 1, 10, [](double t) { return Vec3{t, 0, 0}; });
    std::vector<SizeSource> out;
    surface::add_short_edge_sources({&e, 1}, size, out);
    ASSERT_EQ(out.size(), 8u);
    for (std::size_t k = 0; k < out.size(); ++k) {
        EXPECT_TRUE(same_bytes(out[k].point, e.points[k + 3])) << "source " << k;
        EXPECT_NEAR(out[k].size, 0.1, 1e-12);
    }
}

}  // namespace
