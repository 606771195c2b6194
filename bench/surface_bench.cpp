// Surface triangulation throughput: triangles per second on the faces of a serpentine lift
// block (the paper's Example 1 kind: 20 x 15 x 3, pipe diameter 0.032). Gmsh 4.8.4 took 64 s
// for the 2D mesh of that model.
//   BM_LargeFace:      one 20 x 15 face with 40 ring polygons as holes (one face: one thread
//                      is all a face can use).
//   BM_LiftBlockFaces: the block's six faces, 20 ring polygons in each 20 x 15 face, meshed by
//                      mesh_surfaces (faces in parallel).
// Both at 1 and 2 threads (tbb::global_control).
//
// Why these synthetic faces beside Surface/<case> in bench_phases (the reference cases through
// geom): they are planes, so they time the face mesher without OpenCASCADE's surface
// evaluation, and they hold 20 to 40 ring holes per face, where the reference cases have a few
// at most: the mesher's cost per hole shows only here.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <numbers>
#include <optional>
#include <tbb/global_control.h>

#include "engine/surface/mesh_surfaces.hpp"

namespace {

using namespace tubemesh;
using surface::FaceBoundary;

constexpr double kPipeRadius = 0.016;  // diameter 0.032
constexpr double kRingThickness = 0.02;
constexpr double kSize = 0.1;         // S
constexpr int kRingNodes = 16;

// origin + u e1 + v e2 with unit axes.
class Plane : public SurfaceMap {
public:
    Plane(Vec3 o, Vec3 e1, Vec3 e2, index_t id) : o_(o), e1_(e1), e2_(e2), id_(id) {}
    index_t face() const override { return id_; }
    ParamRange u_range() const override { return {}; }
    ParamRange v_range() const override { return {}; }
    bool reversed() const override { return false; }
    Vec3 point(Uv p) const override {
        return {o_.x + p.u * e1_.x + p.v * e2_.x, o_.y + p.u * e1_.y + p.v * e2_.y, o_.z + p.u * e1_.z + p.v * e2_.z};
    }
    SurfaceDerivatives derivatives(Uv p) const override { return {point(p), e1_, e2_}; }
    Projection project(const Vec3&, std::optional<Uv>) const override { return {}; }
    Uv edge_uv(EdgeUse, double) const override { return {}; }
    std::vector<TrimLoop> trimming_loops(double) const override { return {}; }

private:
    Vec3 o_, e1_, e2_;
    index_t id_;
};

// Ring centres on a jittered grid inside [0,w] x [0,h], away from the edges.
std::vector<Uv> ring_centres(int count, double w, double h) {
    std::vector<Uv> c;
    const int cols = count >= 8 ? 8 : count, rows = (count + cols - 1) / cols;
    for (int i = 0; i < count; ++i) {
        const int r = i / cols, k = i % cols;
        const double jitter = 0.15 * std::sin(1.7 * i);
        c.push_back({w * (k + 0.5 + jitter) / cols, h * (r + 0.5 - jitter) / rows});
    }
    return c;
}

// A rectangle [0,w] x [0,h] of plane `p` cut at spacing ~S, with ring polygons as holes.
FaceBoundary rectangle_with_rings(const Plane& p, double w, double h, const std::vector<Uv>& rings,
                                  std::vector<SizeSource>& sources) {
    FaceBoundary b;
    const int nu = int(std::ceil(w / kSize)), nv = int(std::ceil(h / kSize));
    auto add = [&](Uv uv) {
        const index_t n = b.add_node(b.node_count(), p.point(uv));
        b.add_loop_point(n, uv);
    };
    for (int i = 0; i < nu; ++i) add({w * i / nu, 0});
    for (int i = 0; i < nv; ++i) add({w, h * i / nv});
    for (int i = nu; i > 0; --i) add({w * i / nu, h});
    for (int i = nv; i > 0; --i) add({0, h * i / nv});
    b.close_loop();
    const double R = kPipeRadius + kRingThickness;
    for (const Uv& c : rings) {
        std::vector<Vec3> polygon;
        for (int k = 0; k < kRingNodes; ++k) {
            const double a = 2 * std::numbers::pi * k / kRingNodes;
            const Uv uv{c.u + R * std::cos(a), c.v + R * std::sin(a)};
            add(uv);
            polygon.push_back(p.point(uv));
        }
        b.close_loop();
        add_polygon_sources(polygon, sources);
    }
    return b;
}

void set_rate(benchmark::State& state, double triangles) {
    state.counters["triangles"] = triangles;
    state.counters["triangles_per_s"] = benchmark::Counter(triangles, benchmark::Counter::kIsIterationInvariantRate);
}

// Smallest angle (degrees) and share of triangles with all angles >= 40 degrees.
void set_quality(benchmark::State& state, std::span<const Vec3> x, std::span<const index_t> tri) {
    double lo = 180;
    std::size_t good = 0;
    for (std::size_t t = 0; t + 2 < tri.size(); t += 3) {
        double worst = 180;
        for (int i = 0; i < 3; ++i) {
            const Vec3 &a = x[tri[t + i]], &b = x[tri[t + (i + 1) % 3]], &c = x[tri[t + (i + 2) % 3]];
            const Vec3 u{b.x - a.x, b.y - a.y, b.z - a.z}, v{c.x - a.x, c.y - a.y, c.z - a.z};
            const double cosine = (u.x * v.x + u.y * v.y + u.z * v.z) /
                                  std::sqrt((u.x * u.x + u.y * u.y + u.z * u.z) * (v.x * v.x + v.y * v.y + v.z * v.z));
            worst = std::min(worst, std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / std::numbers::pi);
        }
        lo = std::min(lo, worst);
        good += worst >= 40;
    }
    state.counters["min_angle"] = lo;
    state.counters["share_40"] = double(good) / double(tri.size() / 3);
}

void BM_LargeFace(benchmark::State& state) {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, std::size_t(state.range(0)));
    const Plane plane({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1);
    std::vector<SizeSource> sources;
    const FaceBoundary b = rectangle_with_rings(plane, 20, 15, ring_centres(40, 20, 15), sources);
    const SizeField size({kSize}, sources);
    surface::FaceMesher mesher;
    surface::FaceMesh out;
    for (auto _ : state) {
        mesher.mesh(plane, b, size, {}, out);
        benchmark::DoNotOptimize(out.triangles.data());
    }
    set_rate(state, out.triangle_count());
    set_quality(state, out.xyz, out.triangles);
}
BENCHMARK(BM_LargeFace)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_LiftBlockFaces(benchmark::State& state) {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, std::size_t(state.range(0)));
    const double W = 20, H = 15, D = 3;
    // Each face's own nodes (the edges are not shared here: throughput, not conformity).
    const Plane planes[6] = {Plane({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 1), Plane({0, 0, D}, {1, 0, 0}, {0, 1, 0}, 2),
                             Plane({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 3), Plane({0, H, 0}, {0, 0, 1}, {1, 0, 0}, 4),
                             Plane({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 5), Plane({W, 0, 0}, {0, 1, 0}, {0, 0, 1}, 6)};
    const double extent[6][2] = {{H, W}, {W, H}, {W, D}, {D, W}, {D, H}, {H, D}};
    std::vector<SizeSource> sources;
    std::vector<surface::SurfaceFace> faces(6);
    HybridMesh base;
    for (int f = 0; f < 6; ++f) {
        const double w = extent[f][0], h = extent[f][1];
        const std::vector<Uv> rings = f < 2 ? ring_centres(20, w, h) : std::vector<Uv>{};
        faces[f].surface = &planes[f];
        faces[f].boundary = rectangle_with_rings(planes[f], w, h, rings, sources);
        for (index_t& id : faces[f].boundary.node_id) {
            const Vec3& x = faces[f].boundary.xyz[id];
            id = base.add_point(x.x, x.y, x.z);
        }
        faces[f].group = base.surface_group_id("face_" + std::to_string(f + 1));
    }
    const SizeField size({kSize}, sources);
    double triangles = 0;
    for (auto _ : state) {
        HybridMesh mesh = base;
        triangles = surface::mesh_surfaces(faces, size, {}, mesh).triangles;
        benchmark::DoNotOptimize(mesh.x.data());
    }
    set_rate(state, triangles);
}
BENCHMARK(BM_LiftBlockFaces)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
