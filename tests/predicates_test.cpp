// orient3d, insphere and orient2d against exact GMP evaluation on near-degenerate input:
// 10^6 cases each for orient3d and insphere, spread over generators that hit the filter's
// boundary (points on planes and spheres moved by a few ulps), exact ties (points snapped to
// small grids, box corners, integer points on spheres), and the range limits (tiny, huge,
// subnormal and mixed magnitudes).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <sstream>
#include <vector>

#include "engine/predicates/exact.hpp"
#include "engine/predicates/expansion.hpp"
#include "engine/predicates/predicates.hpp"
#include "engine/predicates/predicates_inline.hpp"
#include "tests/support/predicates_reference.hpp"

namespace {

using namespace tubemesh::predicates;
using Point = std::array<double, 3>;

class Random {
public:
    explicit Random(std::uint64_t seed) : rng_(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    double gaussian() { return std::normal_distribution<double>()(rng_); }
    Point vector(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    Point unit() {
        Point v{gaussian(), gaussian(), gaussian()};
        const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return {v[0] / n, v[1] / n, v[2] / n};
    }
    // x moved by up to `k` ulps either way.
    double nudge(double x, int k) {
        for (int s = integer(-k, k); s != 0; s += s > 0 ? -1 : 1) x = std::nextafter(x, s > 0 ? INFINITY : -INFINITY);
        return x;
    }
    Point nudge(const Point& p, int k) { return {nudge(p[0], k), nudge(p[1], k), nudge(p[2], k)}; }
    // A double anywhere in the finite range, subnormals included.
    double wild() {
        const double m = uniform(1.0, 2.0) * (integer(0, 1) ? 1 : -1);
        return std::ldexp(m, integer(-1074, 1020));
    }
    std::mt19937_64& engine() { return rng_; }

private:
    std::mt19937_64 rng_;
};

Point scaled(const Point& p, int k) { return {std::ldexp(p[0], k), std::ldexp(p[1], k), std::ldexp(p[2], k)}; }
Point add(const Point& a, const Point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point mul(const Point& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

// Counts what the generated input was like, so a pass means something.
struct Tally {
    long cases = 0, zeros = 0, naive_wrong = 0, mismatches = 0;
    void print(const char* name) const {
        std::cout << "  " << name << ": " << cases << " cases, " << zeros << " exact zeros, " << naive_wrong
                  << " where plain doubles get the sign wrong\n";
    }
};

int sign(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

double naive_orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    const double px = b[0] - a[0], py = b[1] - a[1], pz = b[2] - a[2];
    const double qx = c[0] - a[0], qy = c[1] - a[1], qz = c[2] - a[2];
    const double rx = d[0] - a[0], ry = d[1] - a[1], rz = d[2] - a[2];
    return px * (qy * rz - qz * ry) - py * (qx * rz - qz * rx) + pz * (qx * ry - qy * rx);
}

double naive_insphere(const std::array<Point, 5>& p) {
    double m[4][4];
    for (int r = 0; r < 4; ++r) {
        m[r][3] = 0;
        for (int k = 0; k < 3; ++k) {
            m[r][k] = p[r][k] - p[4][k];
            m[r][3] += m[r][k] * m[r][k];
        }
    }
    auto det3 = [](double a[3][3]) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    double det = 0;
    for (int j = 0; j < 4; ++j) {
        double minor[3][3];
        for (int r = 1; r < 4; ++r)
            for (int c = 0, cc = 0; c < 4; ++c)
                if (c != j) minor[r - 1][cc++] = m[r][c];
        det += (j % 2 == 0 ? 1 : -1) * m[0][j] * det3(minor);
    }
    return -det;
}

// ---------------------------------------------------------------------------------------
// orient3d generators: four points.

using Quad = std::array<Point, 4>;

Quad plane_nudged(Random& r) {
    const Point o = r.integer(0, 3) == 0 ? r.vector(-1e6, 1e6) : r.vector(-10, 10);
    const Point u = r.vector(-1, 1), v = r.vector(-1, 1);
    const double size = std::ldexp(1.0, r.integer(-10, 10));
    Quad q;
    for (Point& p : q) p = r.nudge(add(o, add(mul(u, r.uniform(-size, size)), mul(v, r.uniform(-size, size)))), 2);
    return q;
}

Quad line_nudged(Random& r) {
    const Point a = r.vector(-10, 10), b = r.vector(-10, 10);
    Quad q;
    for (int i = 0; i < 3; ++i) q[i] = r.nudge(add(a, mul(add(b, mul(a, -1)), r.uniform(-2, 2))), 1);
    q[3] = r.integer(0, 1) ? r.vector(-10, 10) : q[r.integer(0, 2)];
    return q;
}

// Small grids: exact binary steps (exact differences) or decimal steps (rounded).
Quad grid(Random& r) {
    const bool binary = r.integer(0, 1) == 0;
    const double step = binary ? std::ldexp(1.0, r.integer(-20, 20)) : 0.1 * r.integer(1, 9);
    const Point o = binary ? mul(Point{double(r.integer(-1000, 1000)), double(r.integer(-1000, 1000)), 0.0}, step)
                           : r.vector(-100, 100);
    Quad q;
    for (Point& p : q) p = add(o, Point{step * r.integer(0, 2), step * r.integer(0, 2), step * r.integer(0, 2)});
    return q;
}

// Coordinates drawn from a few values spread over the whole double range: exact ties with
// differences no double can hold.
Quad wild_pool(Random& r) {
    double pool[3][3];
    for (auto& axis : pool)
        for (double& v : axis) v = r.wild();
    Quad q;
    for (Point& p : q) p = {pool[0][r.integer(0, 2)], pool[1][r.integer(0, 2)], pool[2][r.integer(0, 2)]};
    return q;
}

// Each axis on its own power-of-two scale, up to 2^120 apart: the differences are exact
// doubles but span more than 62 bits, which is the expansion path's share.
Point anisotropic_scales(Random& r) {
    return {std::ldexp(1.0, r.integer(-60, 60)), std::ldexp(1.0, r.integer(-60, 60)),
            std::ldexp(1.0, r.integer(-60, 60))};
}
Point anisotropic_point(Random& r, const Point& scale) {
    const int bits = r.integer(0, 1) ? 2 : 20;  // tiny grids for ties, 20-bit integers for long expansions
    Point p;
    for (int k = 0; k < 3; ++k) p[k] = scale[k] * r.integer(-(1 << bits) + 1, (1 << bits) - 1);
    return p;
}

Quad orient3d_case(Random& r, int kind) {
    switch (kind) {
    case 0: return plane_nudged(r);
    case 1: return line_nudged(r);
    case 2: return grid(r);
    case 3: {  // any of the above at a tiny, huge or subnormal scale
        Quad q = r.integer(0, 1) ? plane_nudged(r) : grid(r);
        const int k = r.integer(0, 2) == 0 ? r.integer(-1060, -900) : r.integer(-400, 960);
        for (Point& p : q) p = scaled(p, k);
        return q;
    }
    case 4: return wild_pool(r);
    case 5: {
        Quad q;
        for (Point& p : q) p = {r.wild(), r.wild(), r.wild()};
        return q;
    }
    case 6: {
        const Point scale = anisotropic_scales(r);
        Quad q;
        for (Point& p : q) p = anisotropic_point(r, scale);
        return q;
    }
    default: {
        Quad q;
        for (Point& p : q) p = r.vector(-1, 1);
        return q;
    }
    }
}

TEST(Predicates, Orient3dMatchesExactArithmetic) {
    Random r(20240607);
    test::Reference ref;
    const int kPerKind[8] = {300000, 100000, 250000, 150000, 100000, 25000, 50000, 25000};  // 10^6 in all
    const char* kNames[8] = {"plane+ulps", "line+ulps", "small grids", "scaled 2^-1060..2^960", "wide-range ties",
                             "wide-range random", "anisotropic grids", "uniform"};
    Tally total;
    // The pair version sees each case in lane 0 beside the previous one in lane 1.
    Quad previous = orient3d_case(r, 7);
    int previous_want = ref.orient3d(previous[0].data(), previous[1].data(), previous[2].data(), previous[3].data());
    for (int kind = 0; kind < 8; ++kind) {
        Tally t;
        for (int i = 0; i < kPerKind[kind]; ++i) {
            const Quad q = orient3d_case(r, kind);
            const int want = ref.orient3d(q[0].data(), q[1].data(), q[2].data(), q[3].data());
            const int got = orient3d(q[0].data(), q[1].data(), q[2].data(), q[3].data());
            const int got_inline = orient3d_inline(q[0].data(), q[1].data(), q[2].data(), q[3].data());
            const double* const lanes[2][4] = {{q[0].data(), q[1].data(), q[2].data(), q[3].data()},
                                               {previous[0].data(), previous[1].data(), previous[2].data(),
                                                previous[3].data()}};
            int got_pair[2];
            orient3d_inline_pair(lanes, got_pair);
            EXPECT_EQ(got_pair[1], previous_want);
            previous = q;
            previous_want = want;
            ++t.cases;
            t.zeros += want == 0;
            t.naive_wrong += sign(naive_orient3d(q[0], q[1], q[2], q[3])) != want;
            if (got != want || got_inline != want || got_pair[0] != want) {
                if (++t.mismatches <= 5)
                    ADD_FAILURE() << kNames[kind] << ": got " << got << "/" << got_inline << "/" << got_pair[0] << ", want " << want
                                  << " for " << q[0][0] << " " << q[0][1] << " " << q[0][2] << " | " << q[1][0] << " "
                                  << q[1][1] << " " << q[1][2] << " | " << q[2][0] << " " << q[2][1] << " " << q[2][2]
                                  << " | " << q[3][0] << " " << q[3][1] << " " << q[3][2];
            }
        }
        t.print(kNames[kind]);
        total.cases += t.cases;
        total.zeros += t.zeros;
        total.naive_wrong += t.naive_wrong;
        total.mismatches += t.mismatches;
        EXPECT_EQ(t.mismatches, 0) << kNames[kind];
    }
    total.print("orient3d total");
    EXPECT_EQ(total.cases, 1000000);
    EXPECT_GT(total.zeros, 100000);
    EXPECT_GT(total.naive_wrong, 50000);
}

// ---------------------------------------------------------------------------------------
// insphere generators: five points.

using Quint = std::array<Point, 5>;

Quint sphere_nudged(Random& r) {
    const Point c = r.integer(0, 3) == 0 ? r.vector(-1e4, 1e4) : r.vector(-10, 10);
    const double radius = std::ldexp(r.uniform(1, 2), r.integer(-8, 4));
    Quint q;
    for (Point& p : q) p = r.nudge(add(c, mul(r.unit(), radius)), 2);
    return q;
}

// Integer points with |v|^2 = 50 (many of them), moved and scaled exactly: exactly co-spherical.
Quint integer_sphere(Random& r) {
    static const std::vector<Point> kShell = [] {
        std::vector<Point> s;
        for (int x = -7; x <= 7; ++x)
            for (int y = -7; y <= 7; ++y)
                for (int z = -7; z <= 7; ++z)
                    if (x * x + y * y + z * z == 50) s.push_back({double(x), double(y), double(z)});
        return s;
    }();
    const Point c{double(r.integer(-50, 50)), double(r.integer(-50, 50)), double(r.integer(-50, 50))};
    const int k = r.integer(-30, 30);
    Quint q;
    for (Point& p : q) p = scaled(add(c, kShell[r.integer(0, int(kShell.size()) - 1)]), k);
    return q;
}

// Corners of a box with arbitrary double bounds: exactly co-spherical, differences rounded.
Quint box_corners(Random& r) {
    const Point lo = r.vector(-10, 10), size = r.vector(0.01, 10);
    Quint q;
    for (Point& p : q)
        for (int k = 0; k < 3; ++k) p[k] = r.integer(0, 1) ? lo[k] : lo[k] + size[k];
    return q;
}

Quint flat_nudged(Random& r) {  // a flat tet: all five nearly coplanar
    const Quad a = plane_nudged(r);
    Quint q;
    for (int i = 0; i < 4; ++i) q[i] = a[i];
    q[4] = r.integer(0, 1) ? a[r.integer(0, 3)] : r.nudge(add(a[0], mul(add(a[1], mul(a[2], -1)), 0.5)), 2);
    return q;
}

Quint insphere_case(Random& r, int kind) {
    switch (kind) {
    case 0: return sphere_nudged(r);
    case 1: return integer_sphere(r);
    case 2: return box_corners(r);
    case 3: return flat_nudged(r);
    case 4: {  // tiny, huge, subnormal: the filter's window and the expansion window both bite
        Quint q = r.integer(0, 2) == 0 ? sphere_nudged(r) : (r.integer(0, 1) ? integer_sphere(r) : box_corners(r));
        const int k = r.integer(0, 2) == 0 ? r.integer(-1074, -900) : r.integer(-400, 960);
        for (Point& p : q) p = scaled(p, k);
        return q;
    }
    case 5: {
        double pool[3][3];
        for (auto& axis : pool)
            for (double& v : axis) v = r.wild();
        Quint q;
        for (Point& p : q) p = {pool[0][r.integer(0, 2)], pool[1][r.integer(0, 2)], pool[2][r.integer(0, 2)]};
        return q;
    }
    case 6: {
        const Point scale = anisotropic_scales(r);
        Quint q;
        for (Point& p : q) p = anisotropic_point(r, scale);
        return q;
    }
    default: {
        Quint q;
        for (Point& p : q) p = r.vector(-1, 1);
        return q;
    }
    }
}

TEST(Predicates, InsphereMatchesExactArithmetic) {
    Random r(77);
    test::Reference ref;
    const int kPerKind[8] = {300000, 200000, 150000, 100000, 150000, 25000, 50000, 25000};  // 10^6 in all
    const char* kNames[8] = {"sphere+ulps", "integer sphere", "box corners", "flat+ulps", "scaled 2^-1074..2^960",
                             "wide-range ties", "anisotropic grids", "uniform"};
    Tally total;
    for (int kind = 0; kind < 8; ++kind) {
        Tally t;
        for (int i = 0; i < kPerKind[kind]; ++i) {
            const Quint q = insphere_case(r, kind);
            const double* p[5] = {q[0].data(), q[1].data(), q[2].data(), q[3].data(), q[4].data()};
            const int want = ref.insphere(p[0], p[1], p[2], p[3], p[4]);
            const int got = insphere(p[0], p[1], p[2], p[3], p[4]);
            const int got_inline = insphere_inline(p[0], p[1], p[2], p[3], p[4]);
            ++t.cases;
            t.zeros += want == 0;
            t.naive_wrong += sign(naive_insphere(q)) != want;
            if (got != want || got_inline != want) {
                if (++t.mismatches <= 5) {
                    std::ostringstream os;
                    os.precision(17);
                    for (const Point& x : q) os << x[0] << " " << x[1] << " " << x[2] << " | ";
                    ADD_FAILURE() << kNames[kind] << ": got " << got << "/" << got_inline << ", want " << want
                                  << " for " << os.str();
                }
            }
        }
        t.print(kNames[kind]);
        total.cases += t.cases;
        total.zeros += t.zeros;
        total.naive_wrong += t.naive_wrong;
        total.mismatches += t.mismatches;
        EXPECT_EQ(t.mismatches, 0) << kNames[kind];
    }
    total.print("insphere total");
    EXPECT_EQ(total.cases, 1000000);
    EXPECT_GT(total.zeros, 100000);
    EXPECT_GT(total.naive_wrong, 50000);
}

// The second filter stage (from the monomials' permanent) on the cases the first one leaves: it
// never contradicts exact arithmetic, and it decides some of the near-ties of points a few ulps
// off a sphere (those of a front's rings) that would otherwise need exact arithmetic.
TEST(Predicates, InspherePermanentStageIsExactWhereItDecides) {
    Random r(78);
    test::Reference ref;
    int left = 0, decided = 0, wrong = 0;
    for (int i = 0; i < 400000; ++i) {
        const int kind = i % 8;
        const Quint q = insphere_case(r, kind);
        const double* p[5] = {q[0].data(), q[1].data(), q[2].data(), q[3].data(), q[4].data()};
        if (detail::insphere_filter(p[0], p[1], p[2], p[3], p[4]) != 0) continue;
        ++left;
        const int s = detail::insphere_filter_permanent(p[0], p[1], p[2], p[3], p[4]);
        if (s == 0) continue;
        ++decided;
        wrong += s != ref.insphere(p[0], p[1], p[2], p[3], p[4]);
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(left, 10000);
    EXPECT_GT(decided, left / 20) << decided << " of " << left;
}

TEST(Predicates, Orient2dMatchesExactArithmetic) {
    Random r(5);
    test::Reference ref;
    long zeros = 0;
    for (int i = 0; i < 200000; ++i) {
        const Quad q = orient3d_case(r, i % 7);
        const int axis_i = r.integer(0, 2), axis_j = (axis_i + r.integer(1, 2)) % 3;
        const int want = ref.orient2d(q[0].data(), q[1].data(), q[2].data(), axis_i, axis_j);
        zeros += want == 0;
        ASSERT_EQ(detail::orient2d(q[0].data(), q[1].data(), q[2].data(), axis_i, axis_j), want)
            << "case " << i << " axes " << axis_i << axis_j << ": " << std::hexfloat << q[0][axis_i] << " "
            << q[0][axis_j] << " | " << q[1][axis_i] << " " << q[1][axis_j] << " | " << q[2][axis_i] << " "
            << q[2][axis_j];
    }
    EXPECT_GT(zeros, 10000);
}

// ---------------------------------------------------------------------------------------
// The expansion primitives on their own: every result equals the exact rational value.

mpq_class value(int n, const double* e) {
    mpq_class v = 0;
    for (int i = 0; i < n; ++i) v += mpq_class(e[i]);
    return v;
}

// Components by increasing magnitude, none zero: what the predicates' sign() relies on.
bool well_formed(int n, const double* e) {
    for (int i = 0; i < n; ++i)
        if (e[i] == 0 || (i > 0 && !(std::fabs(e[i - 1]) < std::fabs(e[i])))) return false;
    return true;
}

TEST(Predicates, ExpansionArithmeticIsExact) {
    Random r(31);
    auto operand = [&] { return std::ldexp(r.uniform(-1, 1), r.integer(-100, 100)); };
    for (int trial = 0; trial < 20000; ++trial) {
        const double a = operand(), b = trial % 3 == 0 ? a * 0x1p-27 : operand();
        double x = 0, y = 0;
        detail::two_sum(a, b, x, y);
        ASSERT_EQ(mpq_class(x) + mpq_class(y), mpq_class(a) + mpq_class(b));
        detail::two_diff(a, b, x, y);
        ASSERT_EQ(mpq_class(x) + mpq_class(y), mpq_class(a) - mpq_class(b));
        detail::two_product(a, b, x, y);
        ASSERT_EQ(mpq_class(x) + mpq_class(y), mpq_class(a) * mpq_class(b));
    }
    for (int trial = 0; trial < 2000; ++trial) {
        // Two expansions grown from random doubles, then every operation on them.
        double e[64], f[64], t[64];
        int ne = 0, nf = 0;
        mpq_class ve = 0, vf = 0;
        for (int k = 0; k < 8; ++k) {
            const double g = operand(), h = operand();
            ve += mpq_class(g);
            vf -= mpq_class(h);
            int n = detail::expansion_sum(ne, e, 1, &g, t);
            std::copy(t, t + n, e);
            ne = n;
            n = detail::expansion_diff(nf, f, 1, &h, t);
            std::copy(t, t + n, f);
            nf = n;
        }
        ASSERT_EQ(value(ne, e), ve);
        ASSERT_EQ(value(nf, f), vf);
        ASSERT_TRUE(well_formed(ne, e) && well_formed(nf, f));
        double h[4096], scratch[8192];
        int n = detail::expansion_sum(ne, e, nf, f, h);
        ASSERT_EQ(value(n, h), ve + vf);
        ASSERT_EQ(detail::expansion_sign(n, h), sgn(ve + vf));
        const double s = operand();
        n = detail::expansion_scale(ne, e, s, h);
        ASSERT_EQ(value(n, h), ve * mpq_class(s));
        ASSERT_TRUE(well_formed(n, h));
        n = detail::expansion_product(ne, e, nf, f, h, scratch);
        ASSERT_EQ(value(n, h), ve * vf);
        ASSERT_TRUE(well_formed(n, h));
        const int compressed = detail::expansion_compress(n, h);
        ASSERT_LE(compressed, n);
        ASSERT_EQ(value(compressed, h), ve * vf);
        ASSERT_TRUE(well_formed(compressed, h));
        ASSERT_EQ(detail::expansion_sign(compressed, h), sgn(ve * vf));
    }
}

// ---------------------------------------------------------------------------------------
// Conventions, stated in predicates.hpp.

TEST(Predicates, SignConventions) {
    const Point o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    // (o, x, y) counter-clockwise seen from z: positive.
    EXPECT_EQ(orient3d(o.data(), x.data(), y.data(), z.data()), 1);
    EXPECT_EQ(orient3d(x.data(), o.data(), y.data(), z.data()), -1);
    EXPECT_EQ(orient3d(o.data(), x.data(), y.data(), Point{0.3, 0.3, 0}.data()), 0);
    // The circumcentre (1/2, 1/2, 1/2) is inside, far points and the opposite corner outside.
    const Point centre{0.5, 0.5, 0.5}, far{5, 5, 5}, corner{1, 1, 1}, on{1, 1, 0};
    EXPECT_EQ(insphere(o.data(), x.data(), y.data(), z.data(), centre.data()), 1);
    EXPECT_EQ(insphere(o.data(), x.data(), y.data(), z.data(), far.data()), -1);
    EXPECT_EQ(insphere(o.data(), x.data(), y.data(), z.data(), corner.data()), 0);  // cube corner: on the sphere
    EXPECT_EQ(insphere(o.data(), x.data(), y.data(), z.data(), on.data()), 0);
    // A negatively oriented tet flips the sign.
    EXPECT_EQ(insphere(x.data(), o.data(), y.data(), z.data(), centre.data()), -1);
    EXPECT_EQ(insphere(x.data(), o.data(), y.data(), z.data(), far.data()), 1);
}

TEST(Predicates, ExtremeMagnitudes) {
    // The same co-spherical and coplanar configurations at the ends of the double range.
    for (int k : {-1074, -1070, -1000, -600, -300, 0, 300, 600, 900, 1000}) {
        const double s = std::ldexp(1.0, k);
        const Point o{0, 0, 0}, x{s, 0, 0}, y{0, s, 0}, z{0, 0, s}, corner{s, s, s};
        EXPECT_EQ(orient3d(o.data(), x.data(), y.data(), z.data()), 1) << k;
        EXPECT_EQ(orient3d(o.data(), x.data(), y.data(), Point{s, s, 0}.data()), 0) << k;
        EXPECT_EQ(insphere(o.data(), x.data(), y.data(), z.data(), corner.data()), 0) << k;
        if (k <= 1020) {
            const Point far{4 * s, 4 * s, 4 * s};
            EXPECT_EQ(insphere(o.data(), x.data(), y.data(), z.data(), far.data()), -1) << k;
        }
    }
    // Offsets no difference can represent: 1e300 next to the smallest subnormal.
    const double big = 1e300, tiny = 0x1p-1074;
    const Point a{big, 0, 0}, b{big, tiny, 0}, c{big, 0, tiny}, d{big, tiny, tiny}, e{big + std::ldexp(big, -52), 0, 0};
    EXPECT_EQ(orient3d(a.data(), b.data(), c.data(), d.data()), 0);
    EXPECT_EQ(orient3d(a.data(), b.data(), c.data(), e.data()), -orient3d(b.data(), a.data(), c.data(), e.data()));
    EXPECT_NE(orient3d(a.data(), b.data(), c.data(), e.data()), 0);
}

}  // namespace
