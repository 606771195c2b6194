// From geometry to face boundaries: edges cut once and shared, seams used twice, a cone's apex
// (a degenerate edge), a tube's end loop replaced by its ring's outer polygon.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <functional>
#include <map>
#include <numbers>

#include "engine/surface/face_boundaries.hpp"
#include "engine/surface/mesh_surfaces.hpp"
#include "tests/surface_test_support.hpp"

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

// TUBEMESH_SURFACE_DUMP=dir: "V x y z" / "U u v" / "T a b c" lines for looking at a face.
void dump_face(const surface::FaceMesh& m, const FaceBoundary& b, const char* name) {
    const char* dir = std::getenv("TUBEMESH_SURFACE_DUMP");
    if (dir == nullptr) return;
    FILE* f = std::fopen((std::string(dir) + "/" + name + ".txt").c_str(), "w");
    for (const Vec3& x : m.xyz) std::fprintf(f, "V %.17g %.17g %.17g\n", x.x, x.y, x.z);
    std::vector<Uv> uv(m.xyz.size());
    for (std::size_t k = b.loop_node.size(); k-- > 0;) uv[b.loop_node[k]] = b.loop_uv[k];
    for (std::size_t k = 0; k < m.interior_uv.size(); ++k) uv[m.boundary_count + k] = m.interior_uv[k];
    for (const Uv& p : uv) std::fprintf(f, "U %.17g %.17g\n", p.u, p.v);
    for (index_t t = 0; t < m.triangle_count(); ++t)
        std::fprintf(f, "T %u %u %u\n", m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]);
    std::fclose(f);
}

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

}  // namespace
