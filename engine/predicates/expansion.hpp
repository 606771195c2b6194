#pragma once
// Exact floating-point expansion arithmetic after Shewchuk, "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates" (1997). A real number is held exactly as a
// sum of doubles ordered by increasing magnitude whose bits do not overlap; its sign is the sign
// of the last (largest) component. An empty expansion is zero.
//
// The algorithms are exact only for round-to-nearest-even IEEE doubles evaluated without extended
// precision and without fused multiply-add contraction (this target is built with
// -ffp-contract=off), and only while no product underflows or overflows: callers check that
// their operands lie in a window that rules this out (see exact.hpp) and fall back to BigInt
// otherwise.
#include <cfloat>
#include <cmath>

namespace tubemesh::predicates::detail {

static_assert(FLT_EVAL_METHOD == 0, "expansion arithmetic needs plain double evaluation (SSE2, not x87)");

// x = fl(a + b) and x + y == a + b exactly.
inline void two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    const double b_in_x = x - a;  // the part of b that made it into x
    const double a_in_x = x - b_in_x;
    y = (a - a_in_x) + (b - b_in_x);
}

// As two_sum, three operations cheaper, when |a| >= |b| (or a == 0).
inline void fast_two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    y = b - (x - a);
}

// x = fl(a - b) and x + y == a - b exactly.
inline void two_diff(double a, double b, double& x, double& y) {
    x = a - b;
    const double b_in_x = a - x;
    const double a_in_x = x + b_in_x;
    y = (a - a_in_x) + (b_in_x - b);
}

// x = fl(a * b) and x + y == a * b exactly (no underflow, |a|, |b| < 2^995 for the split).
inline void two_product(double a, double b, double& x, double& y) {
    x = a * b;
#if defined(__FMA__)
    // An explicit fma is one correctly rounded operation, so this is exact; it is not the
    // contraction -ffp-contract=off forbids.
    y = std::fma(a, b, -x);
#else
    // Dekker: split each factor into two 26-bit halves whose pairwise products are exact.
    constexpr double kSplitter = 134217729.0;  // 2^27 + 1
    const double ca = kSplitter * a;
    const double a_hi = ca - (ca - a);
    const double a_lo = a - a_hi;
    const double cb = kSplitter * b;
    const double b_hi = cb - (cb - b);
    const double b_lo = b - b_hi;
    const double err1 = x - a_hi * b_hi;
    const double err2 = err1 - a_lo * b_hi;
    const double err3 = err2 - a_hi * b_lo;
    y = a_lo * b_lo - err3;
#endif
}

// h = e + f, zero components dropped. h has room for ne + nf components and must not alias
// e or f. Returns the length of h.
int expansion_sum(int ne, const double* e, int nf, const double* f, double* h);

// h = e - f, as expansion_sum.
int expansion_diff(int ne, const double* e, int nf, const double* f, double* h);

// h = e * b, zero components dropped. h has room for 2 ne components and must not alias e.
int expansion_scale(int ne, const double* e, double b, double* h);

// h = e * f. h has room for 2 ne nf components; scratch for 4 ne nf (reused between calls).
int expansion_product(int ne, const double* e, int nf, const double* f, double* h, double* scratch);

// Rewrites e in place as an equal expansion with as few components as two sweeps find
// (Shewchuk's compress, his Theorem 23: the result is nonadjacent, so still a valid input to
// the functions above). Products of full-mantissa numbers otherwise drag along dozens of tiny
// components whose count, not their value, sets the cost of every later product.
int expansion_compress(int n, double* e);

inline int expansion_sign(int n, const double* e) { return n == 0 ? 0 : (e[n - 1] > 0 ? 1 : -1); }

// A fixed-capacity expansion on the stack. The capacity is the worst case the operation that
// produced it can need, so the operators below cannot overflow the buffer.
template <int N>
struct Expansion {
    double c[N];
    int n = 0;
    int sign() const { return expansion_sign(n, c); }
    Expansion& compress() {
        n = expansion_compress(n, c);
        return *this;
    }
};

// a * b of two doubles.
inline Expansion<2> product(double a, double b) {
    Expansion<2> r;
    two_product(a, b, r.c[1], r.c[0]);
    r.n = r.c[0] != 0 ? 2 : 1;
    if (r.n == 2) return r;
    r.c[0] = r.c[1];
    r.n = r.c[0] != 0 ? 1 : 0;
    return r;
}

// a * b - c * d of four doubles.
inline Expansion<4> cross_difference(double a, double b, double c, double d) {
    const Expansion<2> ab = product(a, b), cd = product(c, d);
    Expansion<4> r;
    r.n = expansion_diff(ab.n, ab.c, cd.n, cd.c, r.c);
    return r;
}

template <int N, int M>
Expansion<N + M> operator+(const Expansion<N>& e, const Expansion<M>& f) {
    Expansion<N + M> r;
    r.n = expansion_sum(e.n, e.c, f.n, f.c, r.c);
    return r;
}

template <int N, int M>
Expansion<N + M> operator-(const Expansion<N>& e, const Expansion<M>& f) {
    Expansion<N + M> r;
    r.n = expansion_diff(e.n, e.c, f.n, f.c, r.c);
    return r;
}

template <int N>
Expansion<2 * N> operator*(const Expansion<N>& e, double b) {
    Expansion<2 * N> r;
    r.n = expansion_scale(e.n, e.c, b, r.c);
    return r;
}

template <int N, int M>
Expansion<2 * N * M> operator*(const Expansion<N>& e, const Expansion<M>& f) {
    Expansion<2 * N * M> r;
    double scratch[4 * N * M];
    r.n = expansion_product(e.n, e.c, f.n, f.c, r.c, scratch);
    return r;
}

}  // namespace tubemesh::predicates::detail
