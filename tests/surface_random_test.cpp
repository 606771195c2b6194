// Many random faces: planes and cylinder patches with random ring polygons, sizes and aspect
// ratios. Every face must mesh, keep its boundary and pass the minimum angle; the neighbour
// size ratio and the 40 degree share are checked over all faces together (a face of a dozen
// triangles says little about a share).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <numbers>
#include <random>

#include "tests/support/surface_test_support.hpp"

namespace {

using namespace tubemesh;
using namespace tubemesh::testing;
constexpr double pi = std::numbers::pi;

struct Totals {
    index_t faces = 0, triangles = 0, above_40 = 0, pairs = 0, above_1_4 = 0, above_1_5 = 0;
    double min_angle = 180, max_ratio = 0;
    void add(const FaceReport& r) {
        ++faces;
        triangles += r.triangles;
        above_40 += index_t(std::lround(r.fraction_above_40 * r.triangles));
        min_angle = std::min(min_angle, r.min_angle);
        max_ratio = std::max(max_ratio, r.max_neighbor_ratio);
        pairs += r.pairs;
        above_1_4 += r.pairs_above_1_4;
        above_1_5 += r.pairs_above_1_5;
    }
};

// Non-overlapping holes inside [0,w] x [0,h] (in space: the caller maps uv to space isometrically).
std::vector<std::pair<Uv, double>> random_holes(std::mt19937_64& rng, double w, double h, int count, double S) {
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<std::pair<Uv, double>> holes;
    for (int tries = 0; tries < 200 && int(holes.size()) < count; ++tries) {
        const double r = 0.02 + 0.08 * unit(rng);
        const Uv c{r + S + (w - 2 * r - 2 * S) * unit(rng), r + S + (h - 2 * r - 2 * S) * unit(rng)};
        if (c.u < 0 || c.u > w || c.v < 0 || c.v > h) continue;
        bool clear = true;
        for (const auto& [o, ro] : holes) clear = clear && std::hypot(c.u - o.u, c.v - o.v) > r + ro + 2 * S;
        if (clear) holes.push_back({c, r});
    }
    return holes;
}

FaceReport mesh_random(const AnalyticSurface& s, std::mt19937_64& rng, Uv hi, double S, int hole_count,
                       double uv_per_length) {
    std::uniform_int_distribution<int> nodes(8, 24);
    std::vector<std::vector<Uv>> holes;
    for (const auto& [c, r] : random_holes(rng, hi.u / uv_per_length, hi.v, hole_count, S))
        holes.push_back(round_polygon(s, {c.u * uv_per_length, c.v}, r, nodes(rng), 0.7 * r));
    std::vector<SizeSource> sources;
    for (const auto& h : holes) add_uv_polygon_sources(s, h, sources);
    const SizeField size({S}, sources);
    BoundaryBuilder b(s, size);
    const Uv corners[4] = {{0, 0}, {hi.u, 0}, hi, {0, hi.v}};
    b.add_loop(corners);
    for (const auto& h : holes) b.add_polygon(h);
    const surface::FaceBoundary boundary = b.take();
    const surface::FaceMesh m = surface::mesh_face(s, boundary, size);
    FaceReport r = inspect_face(s, boundary, m, size);
    if (r.max_neighbor_ratio > 1.5) {
        static int count = 0;
        dump_face(m, boundary, "random" + std::to_string(count++));
    }
    return r;
}

TEST(SurfaceRandom, PlanesAndCylinderPatches) {
    std::mt19937_64 rng(20240607);
    std::uniform_real_distribution<double> unit(0, 1);
    Totals totals;
    for (int i = 0; i < 60; ++i) {
        SCOPED_TRACE(i);
        const double w = 0.5 + 2.5 * unit(rng), h = 0.3 + 1.5 * unit(rng), S = 0.05 + 0.15 * unit(rng);
        const int holes = int(8 * unit(rng));
        FaceReport r;
        if (i % 2 == 0) {
            const PlaneSurface s({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, w}, {0, h});
            r = mesh_random(s, rng, {w, h}, S, holes, 1.0);
        } else {
            const double radius = 0.3 + unit(rng);  // u is an angle: uv per length is 1 / radius
            const CylinderSurface s(radius, {0, w / radius}, {0, h});
            r = mesh_random(s, rng, {w / radius, h}, S, holes, 1.0 / radius);
        }
        for (const std::string& p : r.problems) ADD_FAILURE() << p;
        EXPECT_GE(r.min_angle, 20.0);
        totals.add(r);
    }
    const double share = double(totals.above_40) / totals.triangles;
    std::printf("  %u faces, %u triangles: min angle %.1f, >=40: %.2f%%, max neighbour ratio %.2f (%u of %u pairs "
                "above 1.4, %u above 1.5)\n",
                totals.faces, totals.triangles, totals.min_angle, 100 * share, totals.max_ratio, totals.above_1_4,
                totals.pairs, totals.above_1_5);
    EXPECT_GE(share, 0.95);
    // The few pairs above 1.5 (7 of ~98,000 with this seed, up to 1.63) all sit on a boundary
    // segment that rounding made longer than the local size (a side of 1.4 sizes gets one
    // segment), which the mesher must keep: bound their share and height, not their existence.
    EXPECT_LE(totals.max_ratio, 1.7);
    EXPECT_LE(totals.above_1_5, totals.pairs / 5000);
}

}  // namespace
