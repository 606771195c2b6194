// Delaunay kernel: topology, orientation, exact empty-sphere property, convex hull, degenerate
// input, duplicates, bounding box start, determinism across runs and thread counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include "engine/delaunay/delaunay.hpp"
#include "engine/delaunay/insertion_order.hpp"
#include "engine/delaunay/triangulation.hpp"
#include "engine/mesh/topology.hpp"
#include "engine/predicates/predicates.hpp"

namespace {

using namespace tubemesh;
using namespace tubemesh::delaunay;
namespace pred = tubemesh::predicates;

struct Points {
    std::vector<double> x, y, z;
    void add(double a, double b, double c) {
        x.push_back(a);
        y.push_back(b);
        z.push_back(c);
    }
    std::size_t size() const { return x.size(); }
    std::array<double, 3> at(std::size_t i) const { return {x[i], y[i], z[i]}; }
};

Points random_cube(std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Points p;
    for (std::size_t i = 0; i < n; ++i) p.add(u(rng), u(rng), u(rng));
    return p;
}

Points grid(int nx, int ny, int nz) {
    Points p;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) p.add(i, j, k);
    return p;
}

// Adds every point of p to tri under its index; returns the ids 0 .. n-1.
std::vector<index_t> add_all(const Points& p, Triangulation& tri) {
    std::vector<double> xyz;
    std::vector<index_t> ids;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const auto a = p.at(i);
        xyz.insert(xyz.end(), a.begin(), a.end());
        ids.push_back(static_cast<index_t>(i));
    }
    tri.add_points(xyz, ids);
    return ids;
}


// A kernel run with `threads` workers (0: all cores) and `partitions` parts (0: one per thread),
// resolved as a mesh run resolves them.
struct RunOptions {
    int threads = 0;
    unsigned partitions = 0;
    index_t min_points_per_part = DelaunayOptions{}.min_points_per_part;
    bool bounding_box = false;
};

DelaunayResult run(const Points& p, RunOptions o = {}) {
    const Parallelism par = resolve_parallelism(o.threads, o.partitions);
    const auto limit = limit_threads(par);
    DelaunayOptions options;
    options.min_points_per_part = o.min_points_per_part;
    options.bounding_box = o.bounding_box;
    return delaunay::delaunay(p.x, p.y, p.z, par, options);
}

struct Summary {
    std::size_t tets = 0, hull_faces = 0, vertices = 0;
};

// Checks everything a Delaunay tetrahedralisation of the convex hull must satisfy:
// valid ids, positive orientation (exact), symmetric adjacency with matching faces, every
// non-duplicate point used, Euler characteristic of a ball, convex hull, and the empty
// sphere property on every interior face (exact insphere <= 0, and < 0 under the symbolic
// perturbation the kernel uses for ties).
Summary check_delaunay(const Points& p, const DelaunayResult& r, std::size_t extra_points = 0) {
    Summary s;
    const std::size_t np = p.size() + extra_points;
    std::vector<std::array<double, 3>> xyz(np);
    for (std::size_t i = 0; i < p.size(); ++i) xyz[i] = p.at(i);
    for (std::size_t k = 0; k < extra_points; ++k) xyz[p.size() + k] = r.box_corners.at(k);
    const auto P = [&](index_t v) { return xyz[v].data(); };

    const auto T = r.tets.size();
    s.tets = T;
    const auto V = r.tets.vertices();
    const auto N = r.tets.neighbours();
    EXPECT_EQ(V.size(), 4 * std::size_t{T});
    std::vector<char> used(np, 0);
    std::atomic<std::size_t> bad_orient = 0, bad_adj = 0, bad_ids = 0, bad_sphere = 0, bad_sos = 0, hull = 0;
    for (index_t v : V)
        if (v < np) used[v] = 1;
    tbb::parallel_for(tbb::blocked_range<index_t>(0, T, 4096), [&](const tbb::blocked_range<index_t>& range) {
        for (index_t t = range.begin(); t < range.end(); ++t) {
            const index_t* v = &V[4 * std::size_t{t}];
            if (!(v[0] < np && v[1] < np && v[2] < np && v[3] < np)) {
                ++bad_ids;
                continue;
            }
            if (pred::orient3d(P(v[0]), P(v[1]), P(v[2]), P(v[3])) <= 0) ++bad_orient;
            for (unsigned f = 0; f < 4; ++f) {
                const index_t code = N[4 * std::size_t{t} + f];
                if (code == kNoAdjacent) {
                    ++hull;
                    continue;
                }
                const index_t u = code >> 2, g = code & 3;
                if (u >= T || N[code] != 4 * t + f) {
                    ++bad_adj;
                    continue;
                }
                // Same face: the three vertices other than the opposite ones agree as sets.
                std::array<index_t, 3> a{}, b{};
                for (unsigned k = 0, m = 0; k < 4; ++k)
                    if (k != f) a[m++] = v[k];
                for (unsigned k = 0, m = 0; k < 4; ++k)
                    if (k != g) b[m++] = V[4 * std::size_t{u} + k];
                std::sort(a.begin(), a.end());
                std::sort(b.begin(), b.end());
                if (a != b) ++bad_adj;
                const index_t w = V[4 * std::size_t{u} + g];
                const int in = pred::insphere(P(v[0]), P(v[1]), P(v[2]), P(v[3]), P(w));
                if (in > 0) ++bad_sphere;
                if (in == 0 && pred::insphere_sos(P(v[0]), P(v[1]), P(v[2]), P(v[3]), P(w), v[0], v[1], v[2], v[3], w) >= 0)
                    ++bad_sos;
            }
        }
    });
    s.hull_faces = hull;
    EXPECT_EQ(bad_ids, 0u);
    EXPECT_EQ(bad_orient, 0u) << "tets with orient3d <= 0";
    EXPECT_EQ(bad_adj, 0u) << "asymmetric or mismatched adjacency";
    EXPECT_EQ(bad_sphere, 0u) << "neighbour vertex strictly inside a circumsphere";
    EXPECT_EQ(bad_sos, 0u) << "local Delaunay violated under the symbolic perturbation";

    // Every point is a vertex except the reported duplicates.
    std::vector<char> dup(np, 0);
    for (auto [d, kept] : r.duplicates) {
        EXPECT_LT(d, np);
        EXPECT_LT(kept, np);
        if (d < np && kept < np) {
            dup[d] = 1;
            EXPECT_EQ(xyz[d], xyz[kept]);
            EXPECT_TRUE(used[kept]);
        }
    }
    std::size_t missing = 0;
    for (std::size_t i = 0; i < np; ++i) {
        if (used[i]) ++s.vertices;
        if (!used[i] && !dup[i]) ++missing;
        if (used[i] && dup[i]) ++missing;
    }
    EXPECT_EQ(missing, 0u) << "points neither used nor reported as duplicates";

    // Euler characteristic of a tetrahedralised ball: V - E + F - T = 1.
    std::vector<std::uint64_t> edges(6 * std::size_t{T});
    for (index_t t = 0; t < T; ++t)
        for (int e = 0; e < 6; ++e) {
            index_t a = V[4 * t + kTetTopology.edge[e].a], b = V[4 * t + kTetTopology.edge[e].b];
            if (a > b) std::swap(a, b);
            edges[6 * std::size_t{t} + e] = std::uint64_t{a} << 32 | b;
        }
    tbb::parallel_sort(edges.begin(), edges.end());
    const auto E = static_cast<std::int64_t>(std::unique(edges.begin(), edges.end()) - edges.begin());
    const auto F = static_cast<std::int64_t>((4 * std::size_t{T} + s.hull_faces) / 2);
    EXPECT_EQ((4 * std::size_t{T} + s.hull_faces) % 2, 0u);
    if (T > 0) {
        EXPECT_EQ(static_cast<std::int64_t>(s.vertices) - E + F - static_cast<std::int64_t>(T), 1);
    }

    // Convex hull: no hull vertex strictly outside any hull face (faces have outward normals).
    std::vector<index_t> hull_vertices;
    std::vector<std::array<index_t, 3>> hull_faces;
    for (index_t t = 0; t < T; ++t)
        for (unsigned f = 0; f < 4; ++f)
            if (N[4 * t + f] == kNoAdjacent) {
                const auto& lf = kTetTopology.face[f];
                hull_faces.push_back({V[4 * t + lf.node[0]], V[4 * t + lf.node[1]], V[4 * t + lf.node[2]]});
                for (int k = 0; k < 3; ++k) hull_vertices.push_back(V[4 * t + lf.node[k]]);
            }
    std::sort(hull_vertices.begin(), hull_vertices.end());
    hull_vertices.erase(std::unique(hull_vertices.begin(), hull_vertices.end()), hull_vertices.end());
    if (hull_faces.size() * hull_vertices.size() < 50'000'000) {
        std::size_t outside = 0;
        for (const auto& hf : hull_faces)
            for (index_t q : hull_vertices)
                if (pred::orient3d(P(hf[0]), P(hf[1]), P(hf[2]), P(q)) > 0) ++outside;
        EXPECT_EQ(outside, 0u) << "hull is not convex";
    }
    return s;
}

// Brute force: no point strictly inside any tet's circumsphere.
void check_empty_spheres_brute_force(const Points& p, const DelaunayResult& r) {
    const auto V = r.tets.vertices();
    std::size_t bad = 0;
    for (index_t t = 0; t < r.tets.size(); ++t) {
        std::array<std::array<double, 3>, 4> c;
        for (int k = 0; k < 4; ++k) c[k] = p.at(V[4 * t + k]);
        for (std::size_t q = 0; q < p.size(); ++q) {
            const auto pq = p.at(q);
            if (pred::insphere(c[0].data(), c[1].data(), c[2].data(), c[3].data(), pq.data()) > 0) ++bad;
        }
    }
    EXPECT_EQ(bad, 0u);
}

bool same_output(const DelaunayResult& a, const DelaunayResult& b) {
    return a.tets.size() == b.tets.size() &&
           std::equal(a.tets.vertices().begin(), a.tets.vertices().end(), b.tets.vertices().begin()) &&
           std::equal(a.tets.neighbours().begin(), a.tets.neighbours().end(), b.tets.neighbours().begin()) &&
           a.duplicates == b.duplicates;
}

TEST(HilbertKey, VisitsEveryCellOfASmallGridOnceWithUnitSteps) {
    const int bits = 3, side = 1 << bits;
    std::vector<std::array<int, 3>> by_key(side * side * side, {-1, -1, -1});
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j)
            for (int k = 0; k < side; ++k) {
                const auto key = hilbert_key(i, j, k, bits);
                ASSERT_LT(key, by_key.size());
                EXPECT_EQ(by_key[key][0], -1);
                by_key[key] = {i, j, k};
            }
    for (std::size_t key = 1; key < by_key.size(); ++key) {
        const int d = std::abs(by_key[key][0] - by_key[key - 1][0]) + std::abs(by_key[key][1] - by_key[key - 1][1]) +
                      std::abs(by_key[key][2] - by_key[key - 1][2]);
        EXPECT_EQ(d, 1) << "curve jumps at key " << key;
    }
}

// curve_order computes its box, keys and sort in parallel: the serial loop's order (keys on a
// 2^16 grid over the bounding cube, sorted as (key, index)) at 1 and 2 threads, with repeated
// points (equal keys) among them.
TEST(InsertionOrder, CurveOrderMatchesTheSerialSort) {
    const Points p = random_cube(50'000, 4);
    std::vector<double> xyz;
    for (std::size_t i = 0; i < p.size(); ++i) xyz.insert(xyz.end(), {p.x[i], p.y[i], p.z[i]});
    xyz.insert(xyz.end(), xyz.begin(), xyz.begin() + 3 * 1000);
    const std::size_t n = xyz.size() / 3;
    double lo[3] = {xyz[0], xyz[1], xyz[2]}, hi[3] = {lo[0], lo[1], lo[2]};
    for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], xyz[3 * i + a]);
            hi[a] = std::max(hi[a], xyz[3 * i + a]);
        }
    const double scale = double((1u << 16) - 1) / std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    std::vector<std::pair<std::uint64_t, index_t>> key(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::uint32_t g[3];
        for (int a = 0; a < 3; ++a) g[a] = static_cast<std::uint32_t>((xyz[3 * i + a] - lo[a]) * scale);
        key[i] = {hilbert_key(g[0], g[1], g[2], 16), static_cast<index_t>(i)};
    }
    std::sort(key.begin(), key.end());
    std::vector<index_t> expected(n);
    for (std::size_t i = 0; i < n; ++i) expected[i] = key[i].second;
    for (int threads : {1, 2}) {
        tbb::task_arena arena(threads);
        arena.execute([&] { EXPECT_EQ(curve_order(xyz), expected) << threads << " threads"; });
    }
}

TEST(InsertionOrder, IsAPermutationWithGrowingRounds) {
    const Points p = random_cube(100'000, 1);
    const InsertionOrder o = brio_hilbert_order(p.x, p.y, p.z);
    std::vector<index_t> sorted = o.order;
    std::sort(sorted.begin(), sorted.end());
    for (index_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
    ASSERT_GE(o.round_begin.size(), 3u);
    EXPECT_EQ(o.round_begin.front(), 0u);
    EXPECT_EQ(o.round_begin.back(), p.size());
    const std::size_t last = o.round_begin.back() - o.round_begin[o.round_begin.size() - 2];
    EXPECT_GT(last, p.size() * 8 / 10);
}

TEST(Delaunay, SingleTetrahedron) {
    Points p;
    p.add(0, 0, 0);
    p.add(1, 0, 0);
    p.add(0, 1, 0);
    p.add(0, 0, 1);
    const auto r = run(p);
    ASSERT_EQ(r.tets.size(), 1u);
    const auto s = check_delaunay(p, r);
    EXPECT_EQ(s.hull_faces, 4u);
}

TEST(Delaunay, TooFewOrFlatPointsGiveNoTets) {
    Points p;
    EXPECT_EQ(run(p).tets.size(), 0u);
    p.add(0, 0, 0);
    p.add(1, 0, 0);
    p.add(0, 1, 0);
    EXPECT_EQ(run(p).tets.size(), 0u);
    for (int i = 0; i < 50; ++i) p.add(0.1 * i, 0.37 * i * i, 0);  // all in z = 0
    EXPECT_EQ(run(p).tets.size(), 0u);
    Points line;
    for (int i = 0; i < 20; ++i) line.add(i, 2 * i, 3 * i);
    EXPECT_EQ(run(line).tets.size(), 0u);
}

TEST(Delaunay, FlatSetWithOneApex) {
    // The first rounds are all in the plane z = 0: the start falls back to all points, and
    // the apex sees one huge coplanar hull facet.
    std::mt19937_64 rng(37);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Points p;
    for (int i = 0; i < 6000; ++i) p.add(u(rng), u(rng), 0.0);
    p.add(0.5, 0.5, 0.25);
    const auto r = run(p, {.threads = 2, .min_points_per_part = 256});
    const auto s = check_delaunay(p, r);
    EXPECT_EQ(s.vertices, p.size());
}

TEST(Delaunay, RejectsBadInput) {
    std::vector<double> x{0, 1, 0, 0}, y{0, 0, 1, 0}, z{0, 0, 0};
    EXPECT_THROW(delaunay::delaunay(x, y, z, Parallelism{}), Error);
    z.push_back(std::nan(""));
    EXPECT_THROW(delaunay::delaunay(x, y, z, Parallelism{}), Error);
}

TEST(Delaunay, RandomPointsMatchBruteForce) {
    const Points p = random_cube(1500, 7);
    const auto r = run(p, {.threads = 1});
    check_delaunay(p, r);
    check_empty_spheres_brute_force(p, r);
}

TEST(Delaunay, RandomPoints50k) {
    const Points p = random_cube(50'000, 11);
    const auto r = run(p, {.threads = 2});
    const auto s = check_delaunay(p, r);
    EXPECT_EQ(s.vertices, p.size());
    EXPECT_GT(double(s.tets) / double(p.size()), 6.0);
}

TEST(Delaunay, RegularGridIsCospherical) {
    const Points p = grid(9, 8, 7);
    const auto r = run(p, {.threads = 1});
    const auto s = check_delaunay(p, r);
    check_empty_spheres_brute_force(p, r);
    EXPECT_EQ(s.vertices, p.size());
    // Every unit cube is split into tets of total volume 1: 6 * volume sums to 8*7*6 cubes.
    double six_vol = 0;
    const auto V = r.tets.vertices();
    for (index_t t = 0; t < r.tets.size(); ++t) {
        const auto a = p.at(V[4 * t]), b = p.at(V[4 * t + 1]), c = p.at(V[4 * t + 2]), d = p.at(V[4 * t + 3]);
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]},
                     w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        six_vol += u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
    }
    EXPECT_DOUBLE_EQ(six_vol, 6.0 * 8 * 7 * 6);
}

TEST(Delaunay, LargeGridInParallelPasses) {
    const Points p = grid(30, 30, 30);
    const auto r = run(p, {.threads = 2, .min_points_per_part = 64});
    const auto s = check_delaunay(p, r);
    EXPECT_EQ(s.vertices, p.size());
    EXPECT_GT(r.stats.passes, 0u);
}

// The insertion beats its pulse (every Triangulation::kPulseEvery points, in parallel parts and
// serially), and a pulse that throws stops it with that exception: how a caller interrupts it.
TEST(Delaunay, PulseBeatsDuringInsertionAndMayStopIt) {
    const Points p = grid(30, 30, 30);
    const Parallelism par = resolve_parallelism(2, 2);
    const auto limit = limit_threads(par);
    std::atomic<int> beats{0};
    DelaunayOptions counting;
    counting.min_points_per_part = 64;
    counting.pulse = [&beats] { ++beats; };
    const DelaunayResult r = delaunay::delaunay(p.x, p.y, p.z, par, counting);
    check_delaunay(p, r);
    EXPECT_GE(beats.load(), int(p.size() / delaunay::Triangulation::kPulseEvery) - 2);

    struct Stop {};
    for (unsigned parts : {1u, 2u}) {
        DelaunayOptions stopping;
        stopping.min_points_per_part = 64;
        std::atomic<int> left{3};
        stopping.pulse = [&left] {
            if (--left == 0) throw Stop{};
        };
        EXPECT_THROW(delaunay::delaunay(p.x, p.y, p.z, Parallelism{2, parts}, stopping), Stop) << parts << " parts";
    }
}

TEST(Delaunay, ExactlyCosphericalIntegerPoints) {
    // All integer points with x^2 + y^2 + z^2 = 325 (many representations), plus the centre.
    Points p;
    for (int i = -18; i <= 18; ++i)
        for (int j = -18; j <= 18; ++j)
            for (int k = -18; k <= 18; ++k)
                if (i * i + j * j + k * k == 325) p.add(i, j, k);
    ASSERT_GT(p.size(), 100u);
    const auto r_hull = run(p, {.threads = 1});
    check_delaunay(p, r_hull);
    check_empty_spheres_brute_force(p, r_hull);
    p.add(0, 0, 0);
    const auto r = run(p, {.threads = 1});
    const auto s = check_delaunay(p, r);
    check_empty_spheres_brute_force(p, r);
    EXPECT_EQ(s.vertices, p.size());
}

// A grid is co-spherical everywhere: the filter leaves many conflict tests undecided, and a tet
// beside several cavity tets is decided exactly once per cavity, not once per neighbour.
TEST(Triangulation, CosphericalTiesDecidedOncePerCavity) {
    const Points p = grid(8, 7, 6);
    Triangulation tri;
    std::vector<index_t> ids = add_all(p, tri);
    const std::vector<index_t> corners{0, 7, 8 * 6, static_cast<index_t>(p.size() - 1)};
    ASSERT_EQ(tri.start(corners).size(), 4u);
    std::erase_if(ids, [&](index_t v) { return std::find(corners.begin(), corners.end(), v) != corners.end(); });
    tri.insert(ids, 1, 1024);
    const KernelCounters& c = tri.counters();
    EXPECT_GT(c.exact_insphere, 1000u);
    EXPECT_GT(c.exact_insphere_reused, 0u);
    EXPECT_LT(c.exact_insphere_reused, c.exact_insphere);
    DelaunayResult r;
    r.tets = tri.finish();
    r.duplicates = tri.duplicates();
    const auto s = check_delaunay(p, r);
    check_empty_spheres_brute_force(p, r);
    EXPECT_EQ(s.vertices, p.size());
}

TEST(Delaunay, PointsOnASphere) {
    std::mt19937_64 rng(3);
    std::normal_distribution<double> g;
    Points p;
    for (int i = 0; i < 3000; ++i) {
        const double a = g(rng), b = g(rng), c = g(rng), n = std::sqrt(a * a + b * b + c * c);
        p.add(a / n, b / n, c / n);
    }
    const auto r = run(p, {.threads = 2, .min_points_per_part = 256});
    const auto s = check_delaunay(p, r);
    EXPECT_EQ(s.vertices, p.size());
}

TEST(Delaunay, CoplanarSubsets) {
    // Random points on five parallel planes and on three faces of the cube, plus a few inside.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Points p;
    for (int plane = 0; plane < 5; ++plane)
        for (int i = 0; i < 400; ++i) p.add(u(rng), u(rng), 0.25 * plane);
    for (int i = 0; i < 300; ++i) {
        p.add(0.0, u(rng), u(rng));
        p.add(u(rng), 1.0, u(rng));
        p.add(std::round(u(rng) * 8) / 8, std::round(u(rng) * 8) / 8, 0.5);  // grid in a plane
    }
    for (int i = 0; i < 200; ++i) p.add(u(rng), u(rng), u(rng));
    const auto r = run(p, {.threads = 2, .min_points_per_part = 128});
    check_delaunay(p, r);
    check_empty_spheres_brute_force(p, r);
}

TEST(Delaunay, DuplicatesAreReportedNotInserted) {
    Points p = random_cube(5000, 13);
    const auto clean = run(p, {.threads = 1});
    Points q = p;
    for (std::size_t i = 0; i < p.size(); i += 7) {
        const auto a = p.at(i);
        q.add(a[0], a[1], a[2]);
    }
    for (int rep = 0; rep < 3; ++rep) q.add(p.x[10], p.y[10], p.z[10]);
    const auto r = run(q, {.threads = 2, .min_points_per_part = 256});
    check_delaunay(q, r);
    EXPECT_EQ(r.stats.duplicates, (p.size() + 6) / 7 + 3);
    for (auto [d, kept] : r.duplicates) EXPECT_EQ(q.at(d), q.at(kept));
    EXPECT_EQ(r.tets.size(), clean.tets.size());
}

TEST(Delaunay, BoundingBoxCornersMakeTheHull) {
    const Points p = random_cube(3000, 17);
    const auto r = run(p, {.threads = 2, .min_points_per_part = 256, .bounding_box = true});
    ASSERT_EQ(r.box_corners.size(), 8u);
    const auto s = check_delaunay(p, r, 8);
    EXPECT_EQ(s.vertices, p.size() + 8);
    EXPECT_EQ(s.hull_faces, 12u);
    for (index_t v : r.tets.vertices()) ASSERT_LT(v, p.size() + 8);
}

TEST(Triangulation, InsertsIntoAnExistingTriangulationAndHandlesAHugeCavity) {
    // Points on a sphere first, then the centre: its cavity is every tet, its boundary the
    // whole hull (far more vertices than the dense linking matrix takes).
    std::mt19937_64 rng(29);
    std::normal_distribution<double> g;
    Points p;
    for (int i = 0; i < 2000; ++i) {
        const double a = g(rng), b = g(rng), c = g(rng), n = std::sqrt(a * a + b * b + c * c);
        p.add(a / n, b / n, c / n);
    }
    Points q = random_cube(3000, 31);  // a second batch, inserted in parallel passes
    for (std::size_t i = 0; i < q.size(); ++i) p.add(0.5 * q.x[i] - 0.25, 0.5 * q.y[i] - 0.25, 0.5 * q.z[i] - 0.25);
    p.add(0, 0, 0);

    Triangulation tri;
    const std::vector<index_t> ids = add_all(p, tri);
    std::vector<index_t> sphere(ids.begin(), ids.begin() + 2000);
    const std::vector<index_t> used = tri.start(sphere);
    ASSERT_EQ(used.size(), 4u);
    std::erase_if(sphere, [&](index_t v) { return std::find(used.begin(), used.end(), v) != used.end(); });
    tri.insert(sphere, 1, 1024);
    const std::vector<index_t> centre{static_cast<index_t>(p.size() - 1)};
    tri.insert(centre, 1, 1024);
    const std::vector<index_t> inner(ids.begin() + 2000, ids.end() - 1);
    tbb::task_arena arena(2);
    arena.execute([&] { tri.insert(inner, 2, 256); });
    EXPECT_GT(tri.counters().passes, 0u);
    DelaunayResult r;
    r.tets = tri.finish();
    r.duplicates = tri.duplicates();
    const auto s = check_delaunay(p, r);
    EXPECT_EQ(s.vertices, p.size());
}

TEST(Delaunay, DeterministicAcrossRunsAndThreadCounts) {
    const Points p = random_cube(60'000, 19);
    const auto a = run(p, {.threads = 2, .min_points_per_part = 512});
    const auto b = run(p, {.threads = 2, .min_points_per_part = 512});
    EXPECT_TRUE(same_output(a, b));
    EXPECT_GT(a.stats.passes, 0u);
    const auto c = run(p, {.threads = 1, .partitions = 2, .min_points_per_part = 512});
    EXPECT_TRUE(same_output(a, c));
    const auto d = run(p, {.threads = 2, .partitions = 4, .min_points_per_part = 512});
    check_delaunay(p, d);
    const auto e = run(p, {.threads = 1, .partitions = 4, .min_points_per_part = 512});
    EXPECT_TRUE(same_output(d, e));
}

TEST(Delaunay, MillionRandomPointsTwoThreads) {
    const Points p = random_cube(1'000'000, 23);
    const auto r = run(p, {.threads = 2});
    const auto s = check_delaunay(p, r);
    EXPECT_EQ(s.vertices, p.size());
    EXPECT_GT(r.stats.passes, 0u);
    EXPECT_LT(r.stats.bytes_per_tet, 80.0);
    RecordProperty("tets", static_cast<int>(r.tets.size()));
    std::printf("1e6 points: %u tets, %.3f s (order %.3f, insert %.3f, finish %.3f), %llu passes, %llu conflicts, "
                "%.1f B/tet\n",
                r.stats.tets, r.stats.seconds_total, r.stats.seconds_order, r.stats.seconds_insert,
                r.stats.seconds_finish, static_cast<unsigned long long>(r.stats.passes),
                static_cast<unsigned long long>(r.stats.conflicts), r.stats.bytes_per_tet);
}

}  // namespace
