// orient3d and orient2d: filter, then the exact paths of exact.hpp.
#include <algorithm>
#include <cmath>

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

// Sign of det[p; q; r] (rows of exact differences) in expansions.
int orient3d_expansion(const double (&row)[3][3]) {
    const auto& [px, py, pz] = row[0];
    const auto& [qx, qy, qz] = row[1];
    const auto& [rx, ry, rz] = row[2];
    const Expansion<4> qr = cross_difference(qx, ry, rx, qy);
    const Expansion<4> pr = cross_difference(px, ry, rx, py);
    const Expansion<4> pq = cross_difference(px, qy, qx, py);
    return ((qr * pz - pr * qz) + pq * rz).sign();
}

template <int N>
std::optional<int> orient3d_bigint(const ScaledInput& in) {
    using Int = BigInt<N>;
    Int m[9];
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) m[3 * r + k] = in.integer<N>(3 * (r + 1) + k) - in.integer<N>(k);
    return determinant_sign(m, 3);
}

template <int N>
std::optional<int> orient2d_bigint(const ScaledInput& in) {
    using Int = BigInt<N>;
    const Int m[4] = {in.integer<N>(2) - in.integer<N>(0), in.integer<N>(3) - in.integer<N>(1),
                      in.integer<N>(4) - in.integer<N>(0), in.integer<N>(5) - in.integer<N>(1)};
    return determinant_sign(m, 2);
}

// As filters.hpp: n = 4 roundings (2 differences, product, difference), P <= 2 mi mj, so the
// error is at most 8u (1 + 6u) mi mj with the bound's own two roundings.
constexpr double kOrient2dBound = 9.0 * 0x1p-53;
constexpr double kOrient2dMin = 0x1p-480, kOrient2dMax = 0x1p480;

}  // namespace

int orient3d_exact(const double* a, const double* b, const double* c, const double* d) {
    const double* rows[3] = {b, c, d};
    const Differences<3, 3> diff(rows, a, kXYZ);
    if (!diff.finite) return 0;
    if (diff.integral) return determinant3(diff.x[0], diff.x[1], diff.x[2]).sign();
    if (diff.exact && diff.in_window(0x1p-300, 0x1p300)) return orient3d_expansion(diff.d);
    const double* points[4] = {a, b, c, d};
    const ScaledInput in(points, 4, 3, kXYZ);
    return bigint_sign(in.span_bits(), 3, [&]<int N>() { return orient3d_bigint<N>(in); });
}

int orient2d(const double* a, const double* b, const double* c, int i, int j) {
    const double bi = b[i] - a[i], bj = b[j] - a[j], ci = c[i] - a[i], cj = c[j] - a[j];
    const double det = bi * cj - bj * ci;
    // std::max, not std::fmax (a libm call): a NaN makes det NaN, and the comparisons abstain.
    const double mi = std::max(std::fabs(bi), std::fabs(ci)), mj = std::max(std::fabs(bj), std::fabs(cj));
    if (std::min(mi, mj) >= kOrient2dMin && std::max(mi, mj) <= kOrient2dMax) {
        const int s = decided_sign(det, kOrient2dBound * (mi * mj));
        if (s != 0) return s;
    }
    const double* rows[2] = {b, c};
    const int axes[2] = {i, j};
    const Differences<2, 2> diff(rows, a, axes);
    if (!diff.finite) return 0;
    if (diff.integral) return cross_difference(diff.x[0][0], diff.x[1][1], diff.x[1][0], diff.x[0][1]).sign();
    if (diff.exact && diff.in_window(kOrient2dMin, kOrient2dMax))
        return cross_difference(diff.d[0][0], diff.d[1][1], diff.d[1][0], diff.d[0][1]).sign();
    const double* points[3] = {a, b, c};
    const ScaledInput in(points, 3, 2, axes);
    return bigint_sign(in.span_bits(), 2, [&]<int N>() { return orient2d_bigint<N>(in); });
}

}  // namespace detail

int orient3d(const double* a, const double* b, const double* c, const double* d) {
    const int s = detail::orient3d_filter(a, b, c, d);
    return s != 0 ? s : detail::orient3d_exact(a, b, c, d);
}

}  // namespace tubemesh::predicates
