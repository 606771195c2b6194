// Several faces meshed separately that share their edges' discretisation must close up: a box,
// and a box with a straight pipe whose ring end quads and wall quads stand in for the hex
// ring. Watertight, manifold, consistently oriented, free of self-intersection (exact
// predicates), and the same mesh for 1 and 2 threads.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <tbb/global_control.h>
#include <unordered_map>

#include "engine/surface/mesh_surfaces.hpp"
#include "tests/support/surface_test_support.hpp"

namespace {

using namespace tubemesh;
using namespace tubemesh::testing;
using surface::FaceBoundary;
using surface::SurfaceFace;
constexpr double pi = std::numbers::pi;

// A box's corners, edges cut once by the size field, and its six faces as planes whose
// FaceBoundaries reuse the edges' nodes.
class BoxScene {
public:
    BoxScene(Vec3 lo, Vec3 hi, const SizeField& size, HybridMesh& mesh) : size_(size), mesh_(mesh) {
        for (int k = 0; k < 8; ++k)
            corner_[k] = mesh.add_point(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
        // Faces as corner quadruples counter-clockwise seen from outside, with their outward axis.
        const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (int f = 0; f < 6; ++f) {
            const Vec3 o = mesh.point(corner_[quads[f][0]]);
            const Vec3 e1 = unit(mesh.point(corner_[quads[f][1]]) - o);
            const Vec3 e2 = unit(mesh.point(corner_[quads[f][3]]) - o);
            // Odd faces are parametrised the other way round and marked reversed, so both
            // orientation paths are exercised.
            const bool rev = f % 2 == 1;
            auto plane = std::make_unique<PlaneSurface>(o, rev ? e2 : e1, rev ? e1 : e2, ParamRange{}, ParamRange{}, rev,
                                                        index_t(f + 1));
            SurfaceFace face;
            faces_.emplace_back();
            face.surface = plane.get();
            face.group = mesh.surface_group_id("face_" + std::to_string(f + 1));
            for (int k = 0; k < 4; ++k) {
                const std::vector<index_t> nodes = edge(quads[f][k], quads[f][(k + 1) % 4]);
                for (std::size_t i = 0; i + 1 < nodes.size(); ++i) add_point(f, face.boundary, *plane, nodes[i]);
            }
            face.boundary.close_loop();
            planes_.push_back(std::move(plane));
            faces_.back() = std::move(face);
        }
    }

    std::vector<SurfaceFace>& faces() { return faces_; }
    // Adds a hole loop through existing mesh nodes to face f (0-based).
    void add_hole(int f, const std::vector<index_t>& nodes) {
        for (index_t n : nodes) add_point(f, faces_[f].boundary, *planes_[f], n);
        faces_[f].boundary.close_loop();
    }

private:
    static Vec3 unit(const Vec3& v) { return (1 / norm(v)) * v; }

    void add_point(int f, FaceBoundary& b, const PlaneSurface& plane, index_t global) {
        auto [it, fresh] = local_[f].try_emplace(global, b.node_count());
        if (fresh) b.add_node(global, mesh_.point(global));
        // uv by projection onto the plane's axes: exact for these axis-aligned faces.
        const SurfaceDerivatives d = plane.derivatives({0, 0});
        const Vec3 r = mesh_.point(global) - d.point;
        b.add_loop_point(it->second, {dot(r, d.du), dot(r, d.dv)});
    }

    // The nodes of the edge between corners a and b, from a to b, cut once and reused.
    std::vector<index_t> edge(int a, int b) {
        const auto key = std::make_pair(std::min(a, b), std::max(a, b));
        auto it = edges_.find(key);
        if (it == edges_.end()) {
            const Vec3 p = mesh_.point(corner_[key.first]), q = mesh_.point(corner_[key.second]);
            constexpr int samples = 512;
            std::vector<double> integral(samples + 1, 0.0);
            for (int i = 1; i <= samples; ++i) {
                const Vec3 x = p + (double(i - 0.5) / samples) * (q - p);
                integral[i] = integral[i - 1] + norm(q - p) / samples / size_.at(x);
            }
            const long n = std::max(1L, std::lround(integral[samples]));
            std::vector<index_t> nodes{corner_[key.first]};
            int i = 0;
            for (long k = 1; k < n; ++k) {
                const double target = integral[samples] * double(k) / double(n);
                while (integral[i + 1] < target) ++i;
                const double s = (i + (target - integral[i]) / (integral[i + 1] - integral[i])) / samples;
                const Vec3 x = p + s * (q - p);
                nodes.push_back(mesh_.add_point(x.x, x.y, x.z));
            }
            nodes.push_back(corner_[key.second]);
            it = edges_.emplace(key, std::move(nodes)).first;
        }
        std::vector<index_t> out = it->second;
        if (a > b) std::reverse(out.begin(), out.end());
        return out;
    }

    const SizeField& size_;
    HybridMesh& mesh_;
    index_t corner_[8];
    std::map<std::pair<int, int>, std::vector<index_t>> edges_;
    std::vector<std::unique_ptr<PlaneSurface>> planes_;
    std::vector<SurfaceFace> faces_;
    std::map<int, std::unordered_map<index_t, index_t>> local_;  // per face: mesh node -> boundary node
};

void expect_closed(const ClosedReport& r, long euler, double volume) {
    EXPECT_GT(r.faces, 0u);
    EXPECT_EQ(r.open_edges, 0u);
    EXPECT_EQ(r.nonmanifold_edges, 0u);
    EXPECT_EQ(r.misoriented_edges, 0u);
    EXPECT_EQ(r.nonmanifold_vertices, 0u);
    EXPECT_EQ(r.crossing_pairs, 0u);
    EXPECT_EQ(r.touching_pairs, 0u);
    EXPECT_EQ(r.euler, euler);
    EXPECT_NEAR(r.volume, volume, 1e-9 * volume);
}

TEST(SurfaceClosed, UnitBoxFromSixFaces) {
    const SizeField size({0.15}, {});
    HybridMesh mesh;
    BoxScene box({0, 0, 0}, {1, 1, 1}, size, mesh);
    const auto stats = surface::mesh_surfaces(box.faces(), size, {}, mesh);
    mesh.validate_layout();
    EXPECT_EQ(stats.faces, 6u);
    const ClosedReport r = inspect_closed(mesh);
    expect_closed(r, 2, 1.0);
    std::printf("  unit box: %u triangles, %u points\n", stats.triangles, mesh.point_count());
}

// A straight pipe of radius r along z through a 2 x 1.5 x 1 box. Around it the hex ring's
// outer polygon (radius R, n nodes) is a hole in the top and bottom faces; the ring's end
// quads (between the pipe circle and the polygon) and the pipe wall's quads close the surface.
struct PipeBox {
    HybridMesh mesh;
    surface::SurfaceMeshStats stats;
};

PipeBox mesh_pipe_box() {
    const double r = 0.1, R = 0.16, cx = 1.0, cy = 0.75;
    const int n = 16, layers = 8;
    std::vector<Vec3> top_polygon, bottom_polygon;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * pi * k / n;
        top_polygon.push_back({cx + R * std::cos(a), cy + R * std::sin(a), 1.0});
        bottom_polygon.push_back({cx + R * std::cos(a), cy + R * std::sin(a), 0.0});
    }
    std::vector<SizeSource> sources;
    add_polygon_sources(top_polygon, sources);
    add_polygon_sources(bottom_polygon, sources);
    const SizeField size({0.2}, sources);

    PipeBox out;
    HybridMesh& mesh = out.mesh;
    BoxScene box({0, 0, 0}, {2, 1.5, 1}, size, mesh);
    // circle[l][k]: pipe wall node k at layer l (z = l / layers); polygon nodes at both ends.
    std::vector<std::vector<index_t>> circle(layers + 1);
    for (int l = 0; l <= layers; ++l)
        for (int k = 0; k < n; ++k) {
            const double a = 2 * pi * k / n;
            circle[l].push_back(mesh.add_point(cx + r * std::cos(a), cy + r * std::sin(a), double(l) / layers));
        }
    std::vector<index_t> top, bottom;
    for (int k = 0; k < n; ++k) {
        top.push_back(mesh.add_point(top_polygon[k].x, top_polygon[k].y, top_polygon[k].z));
        bottom.push_back(mesh.add_point(bottom_polygon[k].x, bottom_polygon[k].y, bottom_polygon[k].z));
    }
    box.add_hole(0, bottom);  // face 0 is z = 0
    box.add_hole(1, top);     // face 1 is z = 1
    const index_t ring_ends = mesh.surface_group_id("ring_ends"), wall = mesh.surface_group_id("pipe_wall");
    for (int k = 0; k < n; ++k) {
        const int k1 = (k + 1) % n;
        const index_t up[4] = {circle[layers][k], top[k], top[k1], circle[layers][k1]};
        mesh.add_face(FaceKind::Quad, up, ring_ends);
        const index_t down[4] = {circle[0][k], circle[0][k1], bottom[k1], bottom[k]};
        mesh.add_face(FaceKind::Quad, down, ring_ends);
        for (int l = 0; l < layers; ++l) {
            const index_t q[4] = {circle[l][k], circle[l + 1][k], circle[l + 1][k1], circle[l][k1]};
            mesh.add_face(FaceKind::Quad, q, wall);
        }
    }
    out.stats = surface::mesh_surfaces(box.faces(), size, {}, mesh);
    return out;
}

TEST(SurfaceClosed, BoxWithPipeClosesWithRingQuads) {
    const PipeBox p = mesh_pipe_box();
    p.mesh.validate_layout();
    const ClosedReport r = inspect_closed(p.mesh);
    const double hole = 16 * 0.5 * 0.1 * 0.1 * std::sin(2 * pi / 16);  // the pipe's 16-gon section
    expect_closed(r, 0, 2 * 1.5 * 1 - hole);                            // a torus: V - E + F = 0
    std::printf("  box with pipe: %u triangles, %u quads, %u points\n", p.stats.triangles,
                p.mesh.face_count(FaceKind::Quad), p.mesh.point_count());
}

TEST(SurfaceClosed, SameMeshForOneAndTwoThreads) {
    PipeBox one, two;
    {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
        one = mesh_pipe_box();
    }
    {
        tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
        two = mesh_pipe_box();
    }
    EXPECT_GT(one.stats.triangles, 0u);
    EXPECT_TRUE(one.mesh == two.mesh);
}

TEST(SurfaceClosed, ReusedMesherGivesTheSameMesh) {
    const SizeField size({0.12}, {{{0.5, 0.5, 1.0}, 0.03}});
    HybridMesh mesh;
    BoxScene box({0, 0, 0}, {1, 1, 1}, size, mesh);
    surface::FaceMesher reused, fresh;
    surface::FaceMesh first, again, alone;
    for (int f = 5; f >= 0; --f) reused.mesh(*box.faces()[f].surface, box.faces()[f].boundary, size, {}, first);
    reused.mesh(*box.faces()[1].surface, box.faces()[1].boundary, size, {}, again);
    fresh.mesh(*box.faces()[1].surface, box.faces()[1].boundary, size, {}, alone);
    EXPECT_EQ(again.triangles, alone.triangles);
    ASSERT_EQ(again.xyz.size(), alone.xyz.size());
    for (std::size_t k = 0; k < alone.xyz.size(); ++k) {
        EXPECT_EQ(again.xyz[k].x, alone.xyz[k].x);
        EXPECT_EQ(again.xyz[k].y, alone.xyz[k].y);
        EXPECT_EQ(again.xyz[k].z, alone.xyz[k].z);
    }
}

TEST(SurfaceClosed, ErrorNamesTheFace) {
    const SizeField size({0.2}, {});
    HybridMesh mesh;
    BoxScene box({0, 0, 0}, {1, 1, 1}, size, mesh);
    // A hole loop that crosses the outer loop of face 3.
    const index_t a = mesh.add_point(0.5, 0, -0.5), b = mesh.add_point(0.6, 0, 0.5), c = mesh.add_point(0.4, 0, 0.5);
    box.add_hole(2, {a, b, c});
    try {
        surface::mesh_surfaces(box.faces(), size, {}, mesh);
        FAIL() << "crossing loops were accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("face_3"), std::string::npos) << e.what();
    }
}

}  // namespace
