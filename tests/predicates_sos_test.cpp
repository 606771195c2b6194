// Symbolic perturbation: orient3d_sos and insphere_sos against the definition (the lowest-order
// term of the perturbed determinant, expanded by brute force in GMP), their symmetries on
// coplanar and co-spherical grids, and the property it all exists for: the Delaunay
// triangulation of a regular grid, found by brute force with these predicates, is a
// triangulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <span>
#include <vector>

#include "engine/predicates/filters.hpp"
#include "engine/predicates/predicates.hpp"
#include "tests/support/predicates_reference.hpp"

namespace {

using namespace tubemesh::predicates;
using Point = std::array<double, 3>;

// Sign of the permutation that sorts `v` (distinct values).
int permutation_sign(std::vector<int> v) {
    int sign = 1;
    for (std::size_t i = 0; i < v.size(); ++i)
        while (v[i] != static_cast<int>(i)) {
            std::swap(v[i], v[v[i]]);
            sign = -sign;
        }
    return sign;
}

// The definition, independently of sos.cpp: rows [x y z (h) 1] in the given order; entry
// (point i, column x/y/z) perturbed by the parameter with bit (lifted ? n : 0) + 3 rank(i) + axis,
// (point i, h) by bit rank(i), where rank 0 is the largest index. A term's size order is its bit
// mask's numeric order, so the sign is that of the nonzero coefficient with the smallest mask.
// Returns the sign of the perturbed determinant (not yet negated into orient/insphere).
int perturbed_determinant_sign(std::span<const Point> pts, std::span<const std::uint32_t> index, bool lifted) {
    const int n = static_cast<int>(pts.size());
    const int columns = lifted ? 5 : 4;
    std::vector<const double*> raw;
    for (const Point& p : pts) raw.push_back(p.data());
    tubemesh::predicates::test::ScaledPoints s;
    s.set(raw);
    std::vector<std::vector<mpz_class>> m(n, std::vector<mpz_class>(columns));
    std::vector<int> rank(n, 0);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) rank[i] += index[j] > index[i];
        mpz_class h = 0;
        for (int k = 0; k < 3; ++k) {
            m[i][k] = s(i, k);
            h += s(i, k) * s(i, k);
        }
        if (lifted) m[i][3] = h;
        m[i][columns - 1] = 1;
    }
    auto bit = [&](int row, int col) -> int {
        if (col == columns - 1) return -1;  // the constant column is not perturbed
        if (lifted && col == 3) return rank[row];
        return (lifted ? n : 0) + 3 * rank[row] + col;
    };
    std::map<std::uint32_t, mpz_class> poly;
    std::vector<int> sigma(n);
    std::iota(sigma.begin(), sigma.end(), 0);
    do {
        const int sign = permutation_sign(sigma);
        for (unsigned mask = 0; mask < (1u << n); ++mask) {  // rows taking the parameter instead of the value
            mpz_class coefficient = sign;
            std::uint32_t monomial = 0;
            bool possible = true;
            for (int r = 0; r < n && possible; ++r) {
                if (mask & (1u << r)) {
                    const int b = bit(r, sigma[r]);
                    possible = b >= 0;
                    if (possible) monomial |= 1u << b;
                } else {
                    coefficient *= m[r][sigma[r]];
                }
            }
            if (possible && coefficient != 0) poly[monomial] += coefficient;
        }
    } while (std::next_permutation(sigma.begin(), sigma.end()));
    for (const auto& [monomial, coefficient] : poly)
        if (coefficient != 0) return tubemesh::predicates::test::sign_of(coefficient);
    return 0;
}

std::vector<std::uint32_t> distinct_indices(std::mt19937_64& rng, int n) {
    std::set<std::uint32_t> s;
    std::uniform_int_distribution<std::uint32_t> u(0, rng() % 2 ? 20u : 0xFFFFFFFFu);
    while (static_cast<int>(s.size()) < n) s.insert(u(rng));
    std::vector<std::uint32_t> v(s.begin(), s.end());
    std::shuffle(v.begin(), v.end(), rng);
    return v;
}

// Degenerate configurations: a tiny grid (coincident, collinear, coplanar, co-spherical points
// all frequent), at an offset and a scale where differences stay exact or not.
std::vector<Point> grid_points(std::mt19937_64& rng, int n) {
    std::uniform_int_distribution<int> g(0, 2);
    const double scale = rng() % 2 ? 1.0 : 0.1;
    const double offset = rng() % 2 ? 0.0 : 1.0 / 3.0;
    std::vector<Point> p(n);
    for (Point& x : p) x = {offset + scale * g(rng), offset + scale * g(rng), offset + scale * g(rng)};
    return p;
}

TEST(PredicatesSos, Orient3dMatchesDefinition) {
    std::mt19937_64 rng(1);
    int ties = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const std::vector<Point> p = grid_points(rng, 4);
        const std::vector<std::uint32_t> id = distinct_indices(rng, 4);
        const int want = -perturbed_determinant_sign(p, id, false);
        ties += orient3d(p[0].data(), p[1].data(), p[2].data(), p[3].data()) == 0;
        const int got = orient3d_sos(p[0].data(), p[1].data(), p[2].data(), p[3].data(), id[0], id[1], id[2], id[3]);
        ASSERT_NE(got, 0);
        ASSERT_EQ(got, want) << "trial " << trial;
    }
    EXPECT_GT(ties, 5000);
}

TEST(PredicatesSos, InsphereMatchesDefinition) {
    std::mt19937_64 rng(2);
    int ties = 0, coplanar = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const std::vector<Point> p = grid_points(rng, 5);
        const std::vector<std::uint32_t> id = distinct_indices(rng, 5);
        const int want = -perturbed_determinant_sign(p, id, true);
        ties += insphere(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()) == 0;
        coplanar += orient3d(p[0].data(), p[1].data(), p[2].data(), p[3].data()) == 0 &&
                    orient3d(p[0].data(), p[1].data(), p[2].data(), p[4].data()) == 0 &&
                    orient3d(p[0].data(), p[1].data(), p[3].data(), p[4].data()) == 0 &&
                    orient3d(p[0].data(), p[2].data(), p[3].data(), p[4].data()) == 0 &&
                    orient3d(p[1].data(), p[2].data(), p[3].data(), p[4].data()) == 0;
        const int got = insphere_sos(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), id[0], id[1],
                                     id[2], id[3], id[4]);
        ASSERT_NE(got, 0);
        ASSERT_EQ(got, want) << "trial " << trial;
    }
    EXPECT_GT(ties, 1000);
    EXPECT_GT(coplanar, 100);  // the position perturbation is exercised, not only the lifting
}

// The entry point for callers whose filter abstained gives insphere_sos's answer, ties included.
TEST(PredicatesSos, InsphereUnfilteredAgreesWithFiltered) {
    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 4000; ++trial) {
        const std::vector<Point> p = grid_points(rng, 5);
        const std::vector<std::uint32_t> id = distinct_indices(rng, 5);
        ASSERT_EQ(insphere_sos_unfiltered(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), id[0],
                                          id[1], id[2], id[3], id[4]),
                  insphere_sos(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), id[0], id[1], id[2],
                               id[3], id[4]))
            << "trial " << trial;
    }
}

// Ties among coordinates spread over the whole double range: the symbolic terms' minors need
// the wide integer path.
TEST(PredicatesSos, InsphereMatchesDefinitionOverWideRange) {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int> exponent(-1070, 1000), pick(0, 1);
    for (int trial = 0; trial < 300; ++trial) {
        double pool[3][2];
        for (auto& axis : pool)
            for (double& v : axis) v = std::ldexp(1.0 + (rng() % 1024) / 1024.0, exponent(rng));
        std::vector<Point> p(5);
        for (Point& x : p) x = {pool[0][pick(rng)], pool[1][pick(rng)], pool[2][pick(rng)]};
        const std::vector<std::uint32_t> id = distinct_indices(rng, 5);
        const int got = insphere_sos(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), id[0], id[1],
                                     id[2], id[3], id[4]);
        ASSERT_NE(got, 0);
        ASSERT_EQ(got, -perturbed_determinant_sign(p, id, true)) << "trial " << trial;
    }
}

// Points of rings swept along an axis, as a tube's hex rings: full-mantissa coordinates whose
// differences are exact (the integer tier of the exact predicates). A point of one ring and its
// copy on another span rectangles (co-spherical with any fifth point) and right prisms; two
// rings of the same circle lie on one sphere, up to the rounding of their points, so any five
// of their points are a near-tie, and some are moved by a few ulps. Unperturbed signs against
// GMP, perturbed ones against the definition.
TEST(PredicatesSos, InsphereOnSweptRingsMatchesDefinition) {
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(0, 1);
    tubemesh::predicates::test::Reference ref;
    int zeros = 0, near_ties = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const double cx = 20 * u(rng), cy = 15 * u(rng), z0 = 3 * u(rng);
        const double radius = 0.016 * (1 + u(rng)), step = 0.01 * (1 + u(rng)), phase = u(rng);
        const int sides = 6 * (1 + static_cast<int>(rng() % 3));
        std::vector<Point> ring;  // layer l, side k at l * sides + k
        for (int layer = 0; layer < 3; ++layer)
            for (int k = 0; k < sides; ++k) {
                const double a = phase + 2 * M_PI * k / sides;
                ring.push_back({cx + radius * std::cos(a), cy + radius * std::sin(a), z0 + layer * step});
            }
        auto at = [&](int layer, int k) { return ring[layer * sides + k]; };
        auto side = [&] { return static_cast<int>(rng() % sides); };
        auto layer = [&] { return static_cast<int>(rng() % 3); };
        std::vector<Point> p(5);
        switch (trial % 3) {
        case 0: {  // a rectangle and any ring point
            const int i = side(), j = side(), l0 = layer(), l1 = layer();
            p = {at(l0, i), at(l0, j), at(l1, i), at(l1, j), ring[rng() % ring.size()]};
            break;
        }
        case 1: {  // five corners of a right prism over a triangle of one ring
            const int l0 = layer(), l1 = layer();
            const int k[3] = {side(), side(), side()};
            std::vector<Point> prism{at(l0, k[0]), at(l0, k[1]), at(l0, k[2]), at(l1, k[0]), at(l1, k[1]), at(l1, k[2])};
            prism.erase(prism.begin() + static_cast<long>(rng() % 6));
            std::copy(prism.begin(), prism.end(), p.begin());
            break;
        }
        default:
            for (Point& x : p) x = ring[rng() % ring.size()];
        }
        std::shuffle(p.begin(), p.end(), rng);
        if (rng() % 3 == 0) {
            double& c = p[rng() % 5][rng() % 3];
            for (int k = 1 + static_cast<int>(rng() % 2); k > 0; --k) c = std::nextafter(c, rng() % 2 ? 100.0 : -100.0);
        }
        const double* q[5] = {p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()};
        const int exact = insphere(q[0], q[1], q[2], q[3], q[4]);
        ASSERT_EQ(exact, ref.insphere(q[0], q[1], q[2], q[3], q[4])) << "trial " << trial;
        zeros += exact == 0;
        near_ties += exact != 0 && tubemesh::predicates::detail::insphere_filter(q[0], q[1], q[2], q[3], q[4]) == 0;
        const std::vector<std::uint32_t> id = distinct_indices(rng, 5);
        const int got = insphere_sos(q[0], q[1], q[2], q[3], q[4], id[0], id[1], id[2], id[3], id[4]);
        ASSERT_NE(got, 0);
        ASSERT_EQ(got, -perturbed_determinant_sign(p, id, true)) << "trial " << trial;
        ASSERT_EQ(insphere_sos_unfiltered(q[0], q[1], q[2], q[3], q[4], id[0], id[1], id[2], id[3], id[4]), got);
    }
    EXPECT_GT(zeros, 600);
    EXPECT_GT(near_ties, 300);
}

// All 24 orders of four coplanar points (some coincident): never 0, sign follows the parity.
TEST(PredicatesSos, Orient3dCoplanarPermutations) {
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<int> g(0, 2);
    for (int trial = 0; trial < 2000; ++trial) {
        std::array<Point, 4> p;
        const int plane = trial % 3;
        for (Point& x : p) {
            x = {double(g(rng)), double(g(rng)), double(g(rng))};
            if (plane == 0) x[2] = 1;                            // axis-aligned
            if (plane == 1) x[2] = x[0] + x[1];                  // slanted, exact
            if (plane == 2) x[2] = 0.1 * x[0] + 0.7 * x[1];       // slanted, rounded: may be off the plane
        }
        const std::vector<std::uint32_t> id = distinct_indices(rng, 4);
        std::vector<int> order{0, 1, 2, 3};
        int reference = 0;
        do {
            const int s = orient3d_sos(p[order[0]].data(), p[order[1]].data(), p[order[2]].data(), p[order[3]].data(),
                                       id[order[0]], id[order[1]], id[order[2]], id[order[3]]);
            ASSERT_NE(s, 0);
            const int normalised = s * permutation_sign(order);
            if (reference == 0) reference = normalised;
            ASSERT_EQ(normalised, reference);
        } while (std::next_permutation(order.begin(), order.end()));
    }
}

// All 120 orders of five co-spherical points (integer points with |v|^2 = 3, 9 or 50 and box
// corners): never 0, sign follows the parity. That covers swapping two tet vertices (the tet's
// orientation flips, so does the answer) and swapping the query point with a tet vertex.
TEST(PredicatesSos, InsphereCosphericalPermutations) {
    std::vector<Point> shell;
    for (int r2 : {3, 9, 50})
        for (int x = -7; x <= 7; ++x)
            for (int y = -7; y <= 7; ++y)
                for (int z = -7; z <= 7; ++z)
                    if (x * x + y * y + z * z == r2) shell.push_back({double(x), double(y), double(z)});
    std::mt19937_64 rng(4);
    for (int trial = 0; trial < 1500; ++trial) {
        std::array<Point, 5> p;
        std::uniform_int_distribution<std::size_t> pick(0, shell.size() - 1);
        const int r2 = trial % 2 == 0 ? 3 : 50;
        for (Point& x : p) {
            do x = shell[pick(rng)];
            while (x[0] * x[0] + x[1] * x[1] + x[2] * x[2] != r2);
            for (double& c : x) c = c * 0.25 + 1.0 / 3.0;  // move off the integers: differences rounded
        }
        const std::vector<std::uint32_t> id = distinct_indices(rng, 5);
        std::vector<int> order{0, 1, 2, 3, 4};
        int reference = 0;
        do {
            const int s = insphere_sos(p[order[0]].data(), p[order[1]].data(), p[order[2]].data(), p[order[3]].data(),
                                       p[order[4]].data(), id[order[0]], id[order[1]], id[order[2]], id[order[3]],
                                       id[order[4]]);
            ASSERT_NE(s, 0);
            const int normalised = s * permutation_sign(order);
            if (reference == 0) reference = normalised;
            ASSERT_EQ(normalised, reference);
        } while (std::next_permutation(order.begin(), order.end()));
    }
}

TEST(PredicatesSos, RepeatedIndexGivesUnperturbedSign) {
    const Point a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{1, 1, 0}, e{0, 0, 1};
    EXPECT_EQ(orient3d_sos(a.data(), b.data(), c.data(), d.data(), 1, 2, 3, 3), 0);
    EXPECT_EQ(orient3d_sos(a.data(), b.data(), c.data(), e.data(), 1, 2, 3, 3), 1);
    const Point f{1, 1, 1};  // the unit cube's corners are co-spherical
    EXPECT_EQ(insphere_sos(a.data(), b.data(), c.data(), e.data(), f.data(), 1, 2, 3, 4, 4), 0);
}

// Brute-force Delaunay of an n x n x n grid with shuffled indices: every 4-set oriented by
// orient3d_sos whose perturbed sphere (insphere_sos) holds no other point. With consistent
// predicates these tets triangulate the grid's box: their volumes add up to the box, every
// face is shared by two tets except faces on the box, and the Euler characteristic is 1.
TEST(PredicatesSos, DelaunayOfGridIsATriangulation) {
    constexpr int n = 3;
    std::vector<Point> pts;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) pts.push_back({double(i), double(j), double(k)});
    const int count = static_cast<int>(pts.size());
    std::mt19937_64 rng(6);
    for (int shuffle = 0; shuffle < 3; ++shuffle) {
        std::vector<std::uint32_t> id(count);
        std::iota(id.begin(), id.end(), 100u);
        std::shuffle(id.begin(), id.end(), rng);
        std::vector<std::array<int, 4>> tets;
        double volume = 0;
        for (int a = 0; a < count; ++a)
            for (int b = a + 1; b < count; ++b)
                for (int c = b + 1; c < count; ++c)
                    for (int d = c + 1; d < count; ++d) {
                        std::array<int, 4> t{a, b, c, d};
                        auto P = [&](int i) { return pts[t[i]].data(); };
                        if (orient3d_sos(P(0), P(1), P(2), P(3), id[t[0]], id[t[1]], id[t[2]], id[t[3]]) < 0)
                            std::swap(t[0], t[1]);
                        bool empty = true;
                        for (int q = 0; q < count && empty; ++q) {
                            if (q == a || q == b || q == c || q == d) continue;
                            empty = insphere_sos(P(0), P(1), P(2), P(3), pts[q].data(), id[t[0]], id[t[1]], id[t[2]],
                                                 id[t[3]], id[q]) < 0;
                        }
                        if (!empty) continue;
                        tets.push_back(t);
                        const Point &p0 = pts[t[0]], &p1 = pts[t[1]], &p2 = pts[t[2]], &p3 = pts[t[3]];
                        const double ux = p1[0] - p0[0], uy = p1[1] - p0[1], uz = p1[2] - p0[2];
                        const double vx = p2[0] - p0[0], vy = p2[1] - p0[1], vz = p2[2] - p0[2];
                        const double wx = p3[0] - p0[0], wy = p3[1] - p0[1], wz = p3[2] - p0[2];
                        const double det =
                            ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
                        EXPECT_GE(det, 0);  // exact on a small integer grid
                        volume += det;  // six times the volume: integers, summed exactly
                    }
        EXPECT_EQ(volume, 6.0 * (n - 1) * (n - 1) * (n - 1));
        std::map<std::array<int, 3>, int> faces;
        std::set<std::array<int, 2>> edges;
        for (const auto& t : tets)
            for (int skip = 0; skip < 4; ++skip) {
                std::array<int, 3> f;
                for (int i = 0, k = 0; i < 4; ++i)
                    if (i != skip) f[k++] = t[i];
                std::sort(f.begin(), f.end());
                ++faces[f];
                edges.insert({f[0], f[1]});
                edges.insert({f[0], f[2]});
                edges.insert({f[1], f[2]});
            }
        for (const auto& [f, uses] : faces) {
            ASSERT_LE(uses, 2);
            if (uses == 1) {  // a boundary face lies in one of the box's sides
                bool on_side = false;
                for (int axis = 0; axis < 3; ++axis)
                    for (double side : {0.0, double(n - 1)})
                        on_side =
                            on_side || (pts[f[0]][axis] == side && pts[f[1]][axis] == side && pts[f[2]][axis] == side);
                EXPECT_TRUE(on_side);
            }
        }
        const long euler = static_cast<long>(count) - static_cast<long>(edges.size()) +
                           static_cast<long>(faces.size()) - static_cast<long>(tets.size());
        EXPECT_EQ(euler, 1);
    }
}

}  // namespace
