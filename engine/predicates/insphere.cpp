// insphere: filter, then the exact paths of exact.hpp.
//
// The determinant. With rows A = a - e, ..., D = d - e and lifted coordinates la = |A|^2, ...,
//   det5[[a, |a|^2, 1], ..., [e, |e|^2, 1]] = det4[[A, la], [B, lb], [C, lc], [D, ld]]
// (translate by e, a column operation, then expand along e's row [0 0 0 0 1]), and expanding
// along the lifted column,
//   det4 = -la det[B;C;D] + lb det[A;C;D] - lc det[A;B;D] + ld det[A;B;C].
// For a positive tet with e at its circumcentre all lifts equal r^2, so det4 =
// r^2 det4[[A,1],...] = -r^2 det[b-a, c-a, d-a] < 0: inside is negative. insphere returns the
// sign of -det4 = la det[B;C;D] - lb det[A;C;D] + lc det[A;B;D] - ld det[A;B;C], positive inside.
#include "engine/predicates/bigint.hpp"
#include "engine/predicates/differences.hpp"
#include "engine/predicates/exact.hpp"
#include "engine/predicates/expansion.hpp"
#include "engine/predicates/filters.hpp"
#include "engine/predicates/predicates.hpp"
#include "engine/predicates/wide_int.hpp"

namespace tubemesh::predicates {

namespace detail {

namespace {

constexpr int kXYZ[3] = {0, 1, 2};

// The insphere sign from rows of integer differences below 2^62: 2x2 minors < 2^125, 3x3
// minors < 2^189, lifts < 2^126, the determinant < 2^317, all inside their widths.
int insphere_integers(const std::int64_t (&row)[4][3]) {
    const auto& [ax, ay, az] = row[0];
    const auto& [bx, by, bz] = row[1];
    const auto& [cx, cy, cz] = row[2];
    const auto& [dx, dy, dz] = row[3];
    const Wide<2> ab = cross_difference(ax, by, bx, ay), ac = cross_difference(ax, cy, cx, ay);
    const Wide<2> ad = cross_difference(ax, dy, dx, ay), bc = cross_difference(bx, cy, cx, by);
    const Wide<2> bd = cross_difference(bx, dy, dx, by), cd = cross_difference(cx, dy, dx, cy);
    const Wide<3> bcd = (W1::of(bz) * cd - W1::of(cz) * bd) + W1::of(dz) * bc;
    const Wide<3> acd = (W1::of(az) * cd - W1::of(cz) * ad) + W1::of(dz) * ac;
    const Wide<3> abd = (W1::of(az) * bd - W1::of(bz) * ad) + W1::of(dz) * ab;
    const Wide<3> abc = (W1::of(az) * bc - W1::of(bz) * ac) + W1::of(cz) * ab;
    auto lift = [](std::int64_t x, std::int64_t y, std::int64_t z) {
        return (W1::of(x) * W1::of(x) + W1::of(y) * W1::of(y)) + W1::of(z) * W1::of(z);
    };
    return ((lift(ax, ay, az) * bcd - lift(bx, by, bz) * acd) + (lift(cx, cy, cz) * abd - lift(dx, dy, dz) * abc))
        .sign();
}

// The same from rows of exact double differences in the expansion window.
int insphere_expansion(const double (&row)[4][3]) {
    const auto& [ax, ay, az] = row[0];
    const auto& [bx, by, bz] = row[1];
    const auto& [cx, cy, cz] = row[2];
    const auto& [dx, dy, dz] = row[3];
    // Compressing the intermediates keeps full-mantissa input at a few components per value
    // instead of the worst-case lengths, which would set the cost of every later product.
    auto minor = [](double a, double b, double c, double d) { return cross_difference(a, b, c, d).compress(); };
    const Expansion<4> ab = minor(ax, by, bx, ay), ac = minor(ax, cy, cx, ay), ad = minor(ax, dy, dx, ay);
    const Expansion<4> bc = minor(bx, cy, cx, by), bd = minor(bx, dy, dx, by), cd = minor(cx, dy, dx, cy);
    const Expansion<24> bcd = ((cd * bz - bd * cz) + bc * dz).compress();
    const Expansion<24> acd = ((cd * az - ad * cz) + ac * dz).compress();
    const Expansion<24> abd = ((bd * az - ad * bz) + ab * dz).compress();
    const Expansion<24> abc = ((bc * az - ac * bz) + ab * cz).compress();
    auto lift = [](double x, double y, double z) {
        return ((product(x, x) + product(y, y)) + product(z, z)).compress();
    };
    const Expansion<288> ta = (lift(ax, ay, az) * bcd).compress(), tb = (lift(bx, by, bz) * acd).compress();
    const Expansion<288> tc = (lift(cx, cy, cz) * abd).compress(), td = (lift(dx, dy, dz) * abc).compress();
    return ((ta - tb) + (tc - td)).sign();
}

template <int N>
std::optional<int> insphere_bigint(const ScaledInput& in) {
    using Int = BigInt<N>;
    Int m[16];
    for (int r = 0; r < 4; ++r) {
        Int lift;
        for (int k = 0; k < 3; ++k) {
            const Int diff = in.integer<N>(3 * r + k) - in.integer<N>(12 + k);
            m[4 * r + k] = diff;
            lift = lift + diff * diff;
        }
        m[4 * r + 3] = lift;
    }
    const std::optional<int> s = determinant_sign(m, 4);
    return s ? std::optional<int>(-*s) : std::nullopt;
}

}  // namespace

int insphere_exact(const double* a, const double* b, const double* c, const double* d, const double* e) {
    // Near-ties among a structured front's points often pass the tighter bound: exact
    // arithmetic only for the rest.
    if (const int s = insphere_filter_permanent(a, b, c, d, e)) return s;
    const double* rows[4] = {a, b, c, d};
    const Differences<4, 3> diff(rows, e, kXYZ);
    if (!diff.finite) return 0;
    if (diff.integral) return insphere_integers(diff.x);
    if (diff.exact && diff.in_window(0x1p-160, 0x1p160)) return insphere_expansion(diff.d);
    const double* points[5] = {a, b, c, d, e};
    const ScaledInput in(points, 5, 3, kXYZ);
    return bigint_sign(in.span_bits(), 5, [&]<int N>() { return insphere_bigint<N>(in); });
}

}  // namespace detail

int insphere(const double* a, const double* b, const double* c, const double* d, const double* e) {
    const int s = detail::insphere_filter(a, b, c, d, e);
    return s != 0 ? s : detail::insphere_exact(a, b, c, d, e);
}

}  // namespace tubemesh::predicates
