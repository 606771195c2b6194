// orient3d and insphere calls per second, out of line and inlined, on three kinds of input:
//   random      uniform points: the filter decides;
//   near        points on a plane / sphere moved by a few ulps: the filter mostly fails and the
//               differences are not doubles, so the BigInt path decides;
//   grid        integer points, exactly coplanar / co-spherical: the filter fails, the
//               differences are exact, the expansion path decides.
// Each iteration evaluates a batch of 1024 prepared tuples; items_per_second counts calls.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "engine/predicates/predicates.hpp"
#include "engine/predicates/predicates_inline.hpp"

namespace {

using namespace tubemesh::predicates;
using Point = std::array<double, 3>;
constexpr int kBatch = 1024;

enum Kind { kRandom, kNear, kGrid };

double nudge(double x, std::mt19937_64& rng) {
    for (int s = static_cast<int>(rng() % 5) - 2; s != 0; s += s > 0 ? -1 : 1)
        x = std::nextafter(x, s > 0 ? INFINITY : -INFINITY);
    return x;
}

// kBatch tuples of `n` points each, laid out contiguously.
std::vector<Point> tuples(Kind kind, int n) {
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> u(-1, 1);
    std::normal_distribution<double> g;
    std::vector<Point> pts;
    for (int t = 0; t < kBatch; ++t) {
        const Point o{u(rng) * 10, u(rng) * 10, u(rng) * 10};
        const Point e1{u(rng), u(rng), u(rng)}, e2{u(rng), u(rng), u(rng)};
        const double radius = 0.5 + u(rng) * 0.25;
        int corners[8] = {0, 1, 2, 3, 4, 5, 6, 7};  // distinct, as in a triangulation
        std::shuffle(corners, corners + 8, rng);
        for (int i = 0; i < n; ++i) {
            Point p;
            if (kind == kRandom) {
                p = {u(rng), u(rng), u(rng)};
            } else if (kind == kGrid) {
                // n = 4: distinct points of a 3x3 grid in the z = 1 plane; n = 5: distinct corners
                // of the unit cube (co-spherical)
                const int bits = corners[i];
                p = n == 4 ? Point{double(bits % 3), double(bits / 3), 1.0}
                           : Point{double(bits & 1), double((bits >> 1) & 1), double((bits >> 2) & 1)};
            } else if (n == 4) {  // on a plane
                const double s = u(rng), r = u(rng);
                for (int k = 0; k < 3; ++k) p[k] = nudge(o[k] + s * e1[k] + r * e2[k], rng);
            } else {  // on a sphere
                Point d{g(rng), g(rng), g(rng)};
                const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                for (int k = 0; k < 3; ++k) p[k] = nudge(o[k] + radius * d[k] / len, rng);
            }
            pts.push_back(p);
        }
    }
    return pts;
}

template <int (*Orient)(const double*, const double*, const double*, const double*)>
void BM_Orient3d(benchmark::State& state) {
    const std::vector<Point> p = tuples(static_cast<Kind>(state.range(0)), 4);
    for (auto _ : state) {
        int sum = 0;
        for (int t = 0; t < kBatch; ++t)
            sum += Orient(p[4 * t].data(), p[4 * t + 1].data(), p[4 * t + 2].data(), p[4 * t + 3].data());
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * kBatch);
}

template <int (*Insphere)(const double*, const double*, const double*, const double*, const double*)>
void BM_Insphere(benchmark::State& state) {
    const std::vector<Point> p = tuples(static_cast<Kind>(state.range(0)), 5);
    for (auto _ : state) {
        int sum = 0;
        for (int t = 0; t < kBatch; ++t)
            sum += Insphere(p[5 * t].data(), p[5 * t + 1].data(), p[5 * t + 2].data(), p[5 * t + 3].data(),
                            p[5 * t + 4].data());
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * kBatch);
}

void BM_Orient3dSos(benchmark::State& state) {
    const std::vector<Point> p = tuples(static_cast<Kind>(state.range(0)), 4);
    for (auto _ : state) {
        int sum = 0;
        for (int t = 0; t < kBatch; ++t)
            sum += orient3d_sos(p[4 * t].data(), p[4 * t + 1].data(), p[4 * t + 2].data(), p[4 * t + 3].data(), 1, 2, 3,
                                4);
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * kBatch);
}

void BM_InsphereSos(benchmark::State& state) {
    const std::vector<Point> p = tuples(static_cast<Kind>(state.range(0)), 5);
    for (auto _ : state) {
        int sum = 0;
        for (int t = 0; t < kBatch; ++t)
            sum += insphere_sos(p[5 * t].data(), p[5 * t + 1].data(), p[5 * t + 2].data(), p[5 * t + 3].data(),
                                p[5 * t + 4].data(), 1, 2, 3, 4, 5);
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * kBatch);
}

void kinds(benchmark::internal::Benchmark* b) {
    b->ArgName("random/near/grid")->Arg(kRandom)->Arg(kNear)->Arg(kGrid);
}

BENCHMARK(BM_Orient3d<orient3d>)->Apply(kinds);
BENCHMARK(BM_Orient3d<orient3d_inline>)->Apply(kinds);
BENCHMARK(BM_Insphere<insphere>)->Apply(kinds);
BENCHMARK(BM_Insphere<insphere_inline>)->Apply(kinds);
BENCHMARK(BM_Orient3dSos)->Apply(kinds);
BENCHMARK(BM_InsphereSos)->Apply(kinds);

}  // namespace
