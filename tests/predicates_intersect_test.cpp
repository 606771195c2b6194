// segment_triangle and triangle_triangle: hand cases for every kind of contact, then random
// cases on small grids (where touching, coplanar and degenerate configurations are common)
// against an exact rational reference that works on a different principle: the contact set is
// a system of linear equations and inequalities in barycentric parameters, solved by Gaussian
// elimination and Fourier-Motzkin elimination in mpq. Crossing = the parameters can be strictly
// inside with a non-coplanar, non-degenerate pair; Touching = only on the closed boundary.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <array>
#include <random>
#include <vector>

#include "engine/predicates/predicates.hpp"

namespace {

using namespace tubemesh::predicates;
using Point = std::array<double, 3>;
using Q = mpq_class;

// ---------------------------------------------------------------------------------------
// Exact feasibility of { A x = b, C x <= d (some strict) }.

struct Inequality {
    std::vector<Q> a;  // a . x <= b, or < when strict
    Q b;
    bool strict = false;
};

bool feasible(std::vector<std::vector<Q>> A, std::vector<Q> b, std::vector<Inequality> ineq) {
    const int n = static_cast<int>(A[0].size());
    // Gaussian elimination: each pivot variable becomes an affine function of the free ones.
    std::vector<int> pivot_row(n, -1);
    int row = 0;
    for (int col = 0; col < n && row < static_cast<int>(A.size()); ++col) {
        int p = row;
        while (p < static_cast<int>(A.size()) && A[p][col] == 0) ++p;
        if (p == static_cast<int>(A.size())) continue;
        std::swap(A[p], A[row]);
        std::swap(b[p], b[row]);
        const Q inv = 1 / A[row][col];
        for (Q& v : A[row]) v *= inv;
        b[row] *= inv;
        for (int r = 0; r < static_cast<int>(A.size()); ++r) {
            if (r == row || A[r][col] == 0) continue;
            const Q f = A[r][col];
            for (int c = 0; c < n; ++c) A[r][c] -= f * A[row][c];
            b[r] -= f * b[row];
        }
        pivot_row[col] = row++;
    }
    for (int r = row; r < static_cast<int>(A.size()); ++r)
        if (b[r] != 0) return false;  // 0 = nonzero
    // Substitute x_pivot = b_row - sum over free j of A[row][j] x_j.
    for (Inequality& q : ineq)
        for (int col = 0; col < n; ++col) {
            if (pivot_row[col] < 0 || q.a[col] == 0) continue;
            const Q f = q.a[col];
            const int r = pivot_row[col];
            for (int c = 0; c < n; ++c) q.a[c] -= f * A[r][c];
            q.b -= f * b[r];
            q.a[col] = 0;
        }
    // Fourier-Motzkin on the free variables.
    for (int col = 0; col < n; ++col) {
        if (pivot_row[col] >= 0) continue;
        std::vector<Inequality> pos, neg, next;
        for (Inequality& q : ineq) (q.a[col] > 0 ? pos : (q.a[col] < 0 ? neg : next)).push_back(q);
        for (const Inequality& p : pos)
            for (const Inequality& m : neg) {
                const Q fp = -m.a[col], fm = p.a[col];  // both > 0
                Inequality c;
                c.a.resize(n);
                for (int k = 0; k < n; ++k) c.a[k] = fp * p.a[k] + fm * m.a[k];
                c.b = fp * p.b + fm * m.b;
                c.strict = p.strict || m.strict;
                next.push_back(c);
            }
        ineq = std::move(next);
    }
    for (const Inequality& q : ineq)
        if (q.strict ? !(0 < q.b) : !(0 <= q.b)) return false;
    return true;
}

std::array<Q, 3> sub(const Point& a, const Point& b) {
    return {Q(a[0]) - Q(b[0]), Q(a[1]) - Q(b[1]), Q(a[2]) - Q(b[2])};
}
std::array<Q, 3> cross(const std::array<Q, 3>& u, const std::array<Q, 3>& v) {
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
Q dot(const std::array<Q, 3>& u, const std::array<Q, 3>& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
bool is_zero(const std::array<Q, 3>& u) { return u[0] == 0 && u[1] == 0 && u[2] == 0; }

// Constraints "barycentric pair (x[i], x[i+1]) in the standard triangle", open or closed.
void triangle_constraints(std::vector<Inequality>& ineq, int n, int i, bool strict) {
    auto add = [&](std::vector<std::pair<int, int>> terms, int b) {
        Inequality q;
        q.a.assign(n, 0);
        for (auto [var, coef] : terms) q.a[var] = coef;
        q.b = b;
        q.strict = strict;
        ineq.push_back(q);
    };
    add({{i, -1}}, 0);
    add({{i + 1, -1}}, 0);
    add({{i, 1}, {i + 1, 1}}, 1);
}

// p + t (q - p) = a + u (b - a) + v (c - a), unknowns (t, u, v).
Contact reference_segment_triangle(const Point& p, const Point& q, const Point& a, const Point& b, const Point& c) {
    const auto pq = sub(q, p), ab = sub(b, a), ac = sub(c, a), pa = sub(a, p);
    std::vector<std::vector<Q>> A(3, std::vector<Q>(3));
    std::vector<Q> rhs(3);
    for (int k = 0; k < 3; ++k) {
        A[k] = {pq[k], -ab[k], -ac[k]};
        rhs[k] = pa[k];
    }
    auto constraints = [&](bool strict) {
        std::vector<Inequality> ineq;
        Inequality lo{{-1, 0, 0}, 0, strict}, hi{{1, 0, 0}, 1, strict};
        ineq.push_back(lo);
        ineq.push_back(hi);
        triangle_constraints(ineq, 3, 1, strict);
        return ineq;
    };
    const bool transversal = dot(pq, cross(ab, ac)) != 0;  // also false for a degenerate segment or triangle
    if (transversal && feasible(A, rhs, constraints(true))) return Contact::Crossing;
    return feasible(A, rhs, constraints(false)) ? Contact::Touching : Contact::None;
}

// a + u1 (b - a) + v1 (c - a) = d + u2 (e - d) + v2 (f - d), unknowns (u1, v1, u2, v2).
Contact reference_triangle_triangle(const Point& a, const Point& b, const Point& c, const Point& d, const Point& e,
                                    const Point& f) {
    const auto ab = sub(b, a), ac = sub(c, a), de = sub(e, d), df = sub(f, d), ad = sub(d, a);
    std::vector<std::vector<Q>> A(3);
    std::vector<Q> rhs(3);
    for (int k = 0; k < 3; ++k) {
        A[k] = {ab[k], ac[k], -de[k], -df[k]};
        rhs[k] = ad[k];
    }
    auto constraints = [&](bool strict) {
        std::vector<Inequality> ineq;
        triangle_constraints(ineq, 4, 0, strict);
        triangle_constraints(ineq, 4, 2, strict);
        return ineq;
    };
    const auto n1 = cross(ab, ac), n2 = cross(de, df);
    const bool proper = !is_zero(n1) && !is_zero(n2) && !(is_zero(cross(n1, n2)) && dot(n1, ad) == 0);
    if (proper && feasible(A, rhs, constraints(true))) return Contact::Crossing;
    return feasible(A, rhs, constraints(false)) ? Contact::Touching : Contact::None;
}

const char* name(Contact c) { return c == Contact::None ? "None" : (c == Contact::Touching ? "Touching" : "Crossing"); }

// ---------------------------------------------------------------------------------------

Contact seg_tri(const Point& p, const Point& q, const Point& a, const Point& b, const Point& c) {
    return segment_triangle(p.data(), q.data(), a.data(), b.data(), c.data());
}
Contact tri_tri(const Point& a, const Point& b, const Point& c, const Point& d, const Point& e, const Point& f) {
    return triangle_triangle(a.data(), b.data(), c.data(), d.data(), e.data(), f.data());
}

TEST(PredicatesIntersect, SegmentTriangleHandCases) {
    const Point a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    struct Case {
        Point p, q;
        Contact want;
        const char* what;
    };
    const Case cases[] = {
        {{0.2, 0.2, -1}, {0.2, 0.2, 1}, Contact::Crossing, "through the interior"},
        {{0, 0, -1}, {0, 0, 1}, Contact::Touching, "through a vertex"},
        {{0.5, 0, -1}, {0.5, 0, 1}, Contact::Touching, "through an edge"},
        {{0.2, 0.2, 0}, {0.2, 0.2, 1}, Contact::Touching, "endpoint inside"},
        {{0, 0, 0}, {1, 1, 1}, Contact::Touching, "shared vertex"},
        {{0.5, 0.5, 0}, {0.5, 0.5, 1}, Contact::Touching, "endpoint on the hypotenuse"},
        {{2, 2, -1}, {2, 2, 1}, Contact::None, "misses the triangle"},
        {{0.2, 0.2, 1}, {0.3, 0.3, 2}, Contact::None, "same side"},
        {{0.2, 0.2, 0.5}, {0.2, 0.2, 1}, Contact::None, "stops short of the plane"},
        {{0, 0, 1}, {1, 0, 1}, Contact::None, "parallel"},
        {{-1, 0.2, 0}, {2, 0.2, 0}, Contact::Touching, "coplanar, across"},
        {{0.1, 0.1, 0}, {0.2, 0.2, 0}, Contact::Touching, "coplanar, inside"},
        {{0, 0, 0}, {1, 0, 0}, Contact::Touching, "coplanar, along an edge"},
        {{2, 2, 0}, {3, 3, 0}, Contact::None, "coplanar, apart"},
        {{-1, 0, 0}, {-0.5, 0, 0}, Contact::None, "collinear with an edge, apart"},
        {{0.3, 0.3, 0}, {0.3, 0.3, 0}, Contact::Touching, "a point inside"},
    };
    for (const Case& k : cases) {
        EXPECT_EQ(seg_tri(k.p, k.q, a, b, c), k.want) << k.what;
        EXPECT_EQ(seg_tri(k.q, k.p, c, a, b), k.want) << k.what << " (reordered)";
        EXPECT_EQ(reference_segment_triangle(k.p, k.q, a, b, c), k.want) << k.what << " (reference)";
    }
    // A degenerate triangle is a segment: contact with it is at most Touching.
    const Point l0{0, 0, 0}, l1{1, 0, 0}, l2{2, 0, 0};
    EXPECT_EQ(seg_tri({1, -1, 0}, {1, 1, 0}, l0, l1, l2), Contact::Touching);
    EXPECT_EQ(seg_tri({1, -1, 1}, {1, 1, 1}, l0, l1, l2), Contact::None);
    EXPECT_EQ(seg_tri({3, -1, 0}, {3, 1, 0}, l0, l2, l1), Contact::None);
    EXPECT_EQ(seg_tri({1, -1, 0}, {1, 1, 0}, l0, l0, l0), Contact::None);
    EXPECT_EQ(seg_tri({0, -1, 0}, {0, 1, 0}, l0, l0, l0), Contact::Touching);
    EXPECT_EQ(seg_tri(l0, l0, l0, l0, l0), Contact::Touching);  // everything at one point
    EXPECT_EQ(seg_tri(l1, l1, l0, l0, l0), Contact::None);
}

TEST(PredicatesIntersect, TriangleTriangleHandCases) {
    const Point a{0, 0, 0}, b{2, 0, 0}, c{0, 2, 0};
    struct Case {
        Point d, e, f;
        Contact want;
        const char* what;
    };
    const Case cases[] = {
        {{0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0}, Contact::Crossing, "edge through the interior"},
        {{0.5, 0, -1}, {0.5, 0, 1}, {0.5, 1.5, 0}, Contact::Crossing, "intervals share both ends"},
        {{0, 0, 0}, {-1, 0, 1}, {0, -1, 1}, Contact::Touching, "shared vertex"},
        {{0, 0, 0}, {2, 0, 0}, {1, 0, 1}, Contact::Touching, "shared edge"},
        {{1, 0, -1}, {1, 0, 1}, {1, -2, 0}, Contact::Touching, "edge crosses edge"},
        {{0.5, 0.5, 0}, {1, 0.5, 1}, {0.5, 1, 1}, Contact::Touching, "vertex on the interior"},
        {{-1, 0.5, 0}, {3, 0.5, 0}, {1, 0.5, 1}, Contact::Touching, "edge lies across the interior"},
        {{0.5, 0.5, 0}, {3, 0.5, 0}, {0.5, 3, 0}, Contact::Touching, "coplanar overlap"},
        {{0, 0, 0}, {2, 0, 0}, {1, -1, 0}, Contact::Touching, "coplanar, shared edge"},
        {{3, 3, 0}, {4, 3, 0}, {3, 4, 0}, Contact::None, "coplanar, apart"},
        {{0, 0, 1}, {2, 0, 1}, {0, 2, 1}, Contact::None, "parallel planes"},
        {{5, 5, -1}, {5, 5, 1}, {6, 5, 0}, Contact::None, "apart"},
        {{1.5, 1.5, -1}, {1.5, 1.5, 1}, {3, 3, 0}, Contact::None, "plane crossed outside"},
        {{0.5, 0.5, -1}, {0.5, 0.5, 0}, {0.5, 0.5, 1}, Contact::Touching, "degenerate, piercing"},
    };
    for (const Case& k : cases) {
        EXPECT_EQ(tri_tri(a, b, c, k.d, k.e, k.f), k.want) << k.what;
        EXPECT_EQ(tri_tri(k.e, k.f, k.d, c, b, a), k.want) << k.what << " (reordered)";
        EXPECT_EQ(reference_triangle_triangle(a, b, c, k.d, k.e, k.f), k.want) << k.what << " (reference)";
    }
}

// Random configurations: grid points {0..3}^3 (many ties), or random doubles (generic).
Point random_point(std::mt19937_64& rng, bool grid) {
    if (grid) {
        std::uniform_int_distribution<int> g(0, 3);
        return {double(g(rng)), double(g(rng)), double(g(rng))};
    }
    std::uniform_real_distribution<double> u(-1, 1);
    return {u(rng), u(rng), u(rng)};
}

TEST(PredicatesIntersect, SegmentTriangleMatchesRationalReference) {
    std::mt19937_64 rng(11);
    int counts[3] = {0, 0, 0};
    for (int trial = 0; trial < 60000; ++trial) {
        const bool grid = trial % 6 != 0;
        std::array<Point, 5> p;
        for (Point& x : p) x = random_point(rng, grid);
        const Contact want = reference_segment_triangle(p[0], p[1], p[2], p[3], p[4]);
        const Contact got = seg_tri(p[0], p[1], p[2], p[3], p[4]);
        ++counts[static_cast<int>(want)];
        ASSERT_EQ(name(got), name(want)) << "trial " << trial;
        ASSERT_EQ(got, seg_tri(p[1], p[0], p[3], p[4], p[2])) << "trial " << trial;
    }
    for (int k = 0; k < 3; ++k) EXPECT_GT(counts[k], 3000) << name(static_cast<Contact>(k));
}

TEST(PredicatesIntersect, TriangleTriangleMatchesRationalReference) {
    std::mt19937_64 rng(12);
    int counts[3] = {0, 0, 0};
    for (int trial = 0; trial < 40000; ++trial) {
        const bool grid = trial % 6 != 0;
        std::array<Point, 6> p;
        for (Point& x : p) x = random_point(rng, grid);
        if (trial % 5 == 0) p[3] = p[0];  // shared vertices are the common case in a mesh
        if (trial % 10 == 0) p[4] = p[1];
        const Contact want = reference_triangle_triangle(p[0], p[1], p[2], p[3], p[4], p[5]);
        const Contact got = tri_tri(p[0], p[1], p[2], p[3], p[4], p[5]);
        ++counts[static_cast<int>(want)];
        ASSERT_EQ(name(got), name(want)) << "trial " << trial;
        ASSERT_EQ(got, tri_tri(p[4], p[5], p[3], p[1], p[0], p[2])) << "trial " << trial;
    }
    for (int k = 0; k < 3; ++k) EXPECT_GT(counts[k], 2000) << name(static_cast<Contact>(k));
}

}  // namespace
