#pragma once
// Semi-static floating-point filters for orient3d and insphere: the determinant in plain doubles
// and an a-priori bound on its rounding error from the largest coordinate differences. They
// return +1 or -1 when the sign is certain, 0 when the exact code must decide.
//
// Error bounds. u = 2^-53. With the standard model fl(x op y) = (x op y)(1 + d), |d| <= u, the
// computed determinant is a sum of monomials in the exact coordinate differences, each
// multiplied by at most n factors (1 + d_i); so its error is at most gamma_n * P, gamma_n =
// nu / (1 - nu), P = the sum of the monomials' absolute values. n counts the roundings on the
// longest path from an input difference to the result; P is bounded by the maxima mx, my, mz
// of the absolute differences in each coordinate (computed differences are within a factor
// (1 - u) of the exact ones).
//   orient3d: n = 8 (3 differences, product and difference in a 2x2 minor, product, 2 sums),
//     P <= 6 mx my mz: error <= 48u (1 + 15u) mx my mz including the rounding of the bound's
//     own three products. kOrient3dBound = 49u.
//   insphere: n = 16 (5 differences, 2 in the 2x2 minor, 3 in the 3x3 minor, 3 in the lifted
//     coordinate, 1 product, 2 final sums), P <= 4 rows * 3 squares * 6 = 72 m^2 mx my mz with
//     m = max(mx, my, mz): error <= 1152u (1 + 26u) m^2 mx my mz. kInsphereBound = 1153u.
// The spare u (about 1/50 and 1/1150 of the bound) also absorbs what the model above leaves out,
// the absolute error (at most 2^-1075 each) of products that fall in the subnormal range. That
// is why the filters only decide when every maximum lies in a window: above it something could
// overflow (orient3d: 6 m^3 < 2^1023; insphere: 72 m^5 < 2^1023), below it the subnormal errors
// could exceed the spare u. Outside the window, or for NaN, the filter abstains.
//
// Contraction: a fused multiply-add only removes a rounding from a path, so these bounds stay
// valid when a caller's flags let the compiler contract; that is what makes it safe to inline
// them into code built without -ffp-contract=off (predicates_inline.hpp). Reassociation is not
// safe, hence the -ffast-math check.
#include <algorithm>
#include <cfloat>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#if defined(__FAST_MATH__)
#error "tubemesh predicates: the floating-point filters are not valid under -ffast-math"
#endif

namespace tubemesh::predicates::detail {

static_assert(FLT_EVAL_METHOD == 0, "the filters' error bounds assume plain double evaluation");

inline constexpr double kOrient3dBound = 49.0 * 0x1p-53;
inline constexpr double kOrient3dMin = 0x1p-330, kOrient3dMax = 0x1p330;
inline constexpr double kInsphereBound = 1153.0 * 0x1p-53;
inline constexpr double kInsphereMin = 0x1p-200, kInsphereMax = 0x1p200;

// +1 or -1 when |det| > bound, else 0 (also for NaN). Branch-free: the sign of random input is
// a coin toss, and a mispredicted branch costs as much as the whole filter.
inline int decided_sign(double det, double bound) { return int(det > bound) - int(det < -bound); }

inline double max3(double a, double b, double c) { return std::max(a, std::max(b, c)); }
inline double min3(double a, double b, double c) { return std::min(a, std::min(b, c)); }
inline double abs_max3(double a, double b, double c) { return max3(std::fabs(a), std::fabs(b), std::fabs(c)); }

// Sign of det[b-a, c-a, d-a] when certain, else 0.
inline int orient3d_filter(const double* a, const double* b, const double* c, const double* d) {
    const double px = b[0] - a[0], py = b[1] - a[1], pz = b[2] - a[2];
    const double qx = c[0] - a[0], qy = c[1] - a[1], qz = c[2] - a[2];
    const double rx = d[0] - a[0], ry = d[1] - a[1], rz = d[2] - a[2];
    // Expansion along z; the 2x2 minors are in x and y.
    const double det = (pz * (qx * ry - rx * qy) - qz * (px * ry - rx * py)) + rz * (px * qy - qx * py);
    const double mx = abs_max3(px, qx, rx), my = abs_max3(py, qy, ry), mz = abs_max3(pz, qz, rz);
    if (!(min3(mx, my, mz) >= kOrient3dMin && max3(mx, my, mz) <= kOrient3dMax)) return 0;
    const double bound = kOrient3dBound * ((mx * my) * mz);
    return decided_sign(det, bound);
}

#if defined(__SSE2__)
// orient3d_filter for two quadruples at once, one per SSE2 lane (p[l] = {a, b, c, d} of lane l):
// the same operations, so the same answers, written to sign[0] and sign[1].
inline void orient3d_filter_pair(const double* const p[2][4], int sign[2]) {
    const auto diff = [&](int v, int k) {
        return _mm_sub_pd(_mm_set_pd(p[1][v][k], p[0][v][k]), _mm_set_pd(p[1][0][k], p[0][0][k]));
    };
    const __m128d px = diff(1, 0), py = diff(1, 1), pz = diff(1, 2);
    const __m128d qx = diff(2, 0), qy = diff(2, 1), qz = diff(2, 2);
    const __m128d rx = diff(3, 0), ry = diff(3, 1), rz = diff(3, 2);
    const auto mul = [](__m128d x, __m128d y) { return _mm_mul_pd(x, y); };
    const auto sub = [](__m128d x, __m128d y) { return _mm_sub_pd(x, y); };
    const __m128d det = _mm_add_pd(sub(mul(pz, sub(mul(qx, ry), mul(rx, qy))), mul(qz, sub(mul(px, ry), mul(rx, py)))),
                                   mul(rz, sub(mul(px, qy), mul(qx, py))));
    const __m128d sign_bit = _mm_set1_pd(-0.0);
    const auto abs = [&](__m128d x) { return _mm_andnot_pd(sign_bit, x); };
    // std::max(a, b) is (a < b ? b : a) = maxpd(b, a); std::min(a, b) is (b < a ? b : a) = minpd(b, a).
    const auto max3v = [](__m128d a, __m128d b, __m128d c) { return _mm_max_pd(_mm_max_pd(c, b), a); };
    const auto min3v = [](__m128d a, __m128d b, __m128d c) { return _mm_min_pd(_mm_min_pd(c, b), a); };
    const __m128d mx = max3v(abs(px), abs(qx), abs(rx)), my = max3v(abs(py), abs(qy), abs(ry)),
                  mz = max3v(abs(pz), abs(qz), abs(rz));
    const __m128d in_window = _mm_and_pd(_mm_cmpge_pd(min3v(mx, my, mz), _mm_set1_pd(kOrient3dMin)),
                                         _mm_cmple_pd(max3v(mx, my, mz), _mm_set1_pd(kOrient3dMax)));
    const __m128d bound = mul(_mm_set1_pd(kOrient3dBound), mul(mul(mx, my), mz));
    const int positive = _mm_movemask_pd(_mm_and_pd(in_window, _mm_cmpgt_pd(det, bound)));
    const int negative = _mm_movemask_pd(_mm_and_pd(in_window, _mm_cmplt_pd(det, _mm_xor_pd(bound, sign_bit))));
    for (int l = 0; l < 2; ++l) sign[l] = ((positive >> l) & 1) - ((negative >> l) & 1);
}
#endif

// The insphere determinant's rows relative to e, their lifted determinant and per-axis extents,
// shared by both filter stages.
struct InsphereRows {
    double ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz;
    double la, lb, lc, ld;  // the rows' squared lengths
    double det, mx, my, mz;
};
inline InsphereRows insphere_rows(const double* a, const double* b, const double* c, const double* d,
                                  const double* e) {
    InsphereRows r;
    r.ax = a[0] - e[0], r.ay = a[1] - e[1], r.az = a[2] - e[2];
    r.bx = b[0] - e[0], r.by = b[1] - e[1], r.bz = b[2] - e[2];
    r.cx = c[0] - e[0], r.cy = c[1] - e[1], r.cz = c[2] - e[2];
    r.dx = d[0] - e[0], r.dy = d[1] - e[1], r.dz = d[2] - e[2];
    const double ab = r.ax * r.by - r.bx * r.ay, ac = r.ax * r.cy - r.cx * r.ay, ad = r.ax * r.dy - r.dx * r.ay;
    const double bc = r.bx * r.cy - r.cx * r.by, bd = r.bx * r.dy - r.dx * r.by, cd = r.cx * r.dy - r.dx * r.cy;
    const double bcd = (r.bz * cd - r.cz * bd) + r.dz * bc;
    const double acd = (r.az * cd - r.cz * ad) + r.dz * ac;
    const double abd = (r.az * bd - r.bz * ad) + r.dz * ab;
    const double abc = (r.az * bc - r.bz * ac) + r.cz * ab;
    r.la = (r.ax * r.ax + r.ay * r.ay) + r.az * r.az, r.lb = (r.bx * r.bx + r.by * r.by) + r.bz * r.bz;
    r.lc = (r.cx * r.cx + r.cy * r.cy) + r.cz * r.cz, r.ld = (r.dx * r.dx + r.dy * r.dy) + r.dz * r.dz;
    r.det = (r.la * bcd - r.lb * acd) + (r.lc * abd - r.ld * abc);
    r.mx = std::max(abs_max3(r.ax, r.bx, r.cx), std::fabs(r.dx));
    r.my = std::max(abs_max3(r.ay, r.by, r.cy), std::fabs(r.dy));
    r.mz = std::max(abs_max3(r.az, r.bz, r.cz), std::fabs(r.dz));
    return r;
}

// Sign of the insphere determinant (see insphere.cpp) when certain, else 0.
inline int insphere_filter(const double* a, const double* b, const double* c, const double* d, const double* e) {
    const InsphereRows r = insphere_rows(a, b, c, d, e);
    const double m = max3(r.mx, r.my, r.mz);
    if (!(min3(r.mx, r.my, r.mz) >= kInsphereMin && m <= kInsphereMax)) return 0;
    const double bound = kInsphereBound * ((m * m) * ((r.mx * r.my) * r.mz));
    return decided_sign(r.det, bound);
}

// A second, tighter stage of insphere_filter for the cases it leaves: the same determinant with
// the bound from its monomials' absolute values (the permanent P) instead of 72 m^2 mx my mz.
// Error <= gamma_16 P_exact <= 16u (1 + 50u) P for the computed P (it rounds down by at most
// 25u relative); kInspherePermanentBound = 17u leaves u P of spare, which absorbs the absolute
// error of subnormal intermediates as long as the bound is at least 2^-250: inside the window
// every difference is below 2^200, so each such error (at most 2^-1075) grows to at most 2^-470.
inline constexpr double kInspherePermanentBound = 17.0 * 0x1p-53;
inline constexpr double kInspherePermanentMin = 0x1p-250;
inline int insphere_filter_permanent(const double* a, const double* b, const double* c, const double* d,
                                     const double* e) {
    const InsphereRows r = insphere_rows(a, b, c, d, e);
    if (!(min3(r.mx, r.my, r.mz) >= kInsphereMin && max3(r.mx, r.my, r.mz) <= kInsphereMax)) return 0;
    const double ax = r.ax, ay = r.ay, az = r.az, bx = r.bx, by = r.by, bz = r.bz;
    const double cx = r.cx, cy = r.cy, cz = r.cz, dx = r.dx, dy = r.dy, dz = r.dz;
    const double la = r.la, lb = r.lb, lc = r.lc, ld = r.ld, det = r.det;
    // The 2x2 minors' permanents, then the 3x3 ones, each with absolute values.
    const auto p2 = [](double x0, double y1, double x1, double y0) {
        return std::fabs(x0 * y1) + std::fabs(x1 * y0);
    };
    const double pab = p2(ax, by, bx, ay), pac = p2(ax, cy, cx, ay), pad = p2(ax, dy, dx, ay);
    const double pbc = p2(bx, cy, cx, by), pbd = p2(bx, dy, dx, by), pcd = p2(cx, dy, dx, cy);
    const double pbcd = (std::fabs(bz) * pcd + std::fabs(cz) * pbd) + std::fabs(dz) * pbc;
    const double pacd = (std::fabs(az) * pcd + std::fabs(cz) * pad) + std::fabs(dz) * pac;
    const double pabd = (std::fabs(az) * pbd + std::fabs(bz) * pad) + std::fabs(dz) * pab;
    const double pabc = (std::fabs(az) * pbc + std::fabs(bz) * pac) + std::fabs(cz) * pab;
    const double permanent = (la * pbcd + lb * pacd) + (lc * pabd + ld * pabc);
    const double bound = kInspherePermanentBound * permanent;
    if (!(bound >= kInspherePermanentMin)) return 0;
    return decided_sign(det, bound);
}

}  // namespace tubemesh::predicates::detail
