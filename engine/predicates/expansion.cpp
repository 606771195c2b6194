#include "engine/predicates/expansion.hpp"

#include <algorithm>
#include <cmath>

namespace tubemesh::predicates::detail {

namespace {

// Shewchuk's fast expansion sum (his Theorem 13): merge both inputs by magnitude, then run one
// accumulator through them; each step leaves behind the exact rounding error, which can only be
// smaller than everything still to come. Inputs must be strongly nonoverlapping, which the
// outputs of two_sum, two_product, this function and expansion_scale are under
// round-to-nearest-even. `sign` is +1 to add f, -1 to subtract it (negation is exact).
int merge_sum(int ne, const double* e, int nf, const double* f, double sign, double* h) {
    if (nf == 0) {
        std::copy(e, e + ne, h);
        return ne;
    }
    if (ne == 0) {
        for (int j = 0; j < nf; ++j) h[j] = sign * f[j];
        return nf;
    }
    int i = 0, j = 0, n = 0;
    auto next_smallest = [&]() {
        if (j == nf || (i < ne && std::fabs(e[i]) < std::fabs(f[j]))) return e[i++];
        return sign * f[j++];
    };
    double low = next_smallest();
    double q = 0, err = 0;
    fast_two_sum(next_smallest(), low, q, err);  // the second is the larger by the merge order
    if (err != 0) h[n++] = err;
    while (i < ne || j < nf) {
        two_sum(q, next_smallest(), q, err);
        if (err != 0) h[n++] = err;
    }
    if (q != 0) h[n++] = q;
    return n;
}

}  // namespace

int expansion_sum(int ne, const double* e, int nf, const double* f, double* h) {
    return merge_sum(ne, e, nf, f, 1.0, h);
}

int expansion_diff(int ne, const double* e, int nf, const double* f, double* h) {
    return merge_sum(ne, e, nf, f, -1.0, h);
}

// Shewchuk's scale-expansion (his Theorem 19): each component's product is split into a high
// and a low part, and both are folded into the running sum in order of magnitude.
int expansion_scale(int ne, const double* e, double b, double* h) {
    if (ne == 0 || b == 0) return 0;
    int n = 0;
    double q = 0, err = 0;
    two_product(e[0], b, q, err);
    if (err != 0) h[n++] = err;
    for (int i = 1; i < ne; ++i) {
        double p_hi = 0, p_lo = 0, s = 0;
        two_product(e[i], b, p_hi, p_lo);
        two_sum(q, p_lo, s, err);
        if (err != 0) h[n++] = err;
        fast_two_sum(p_hi, s, q, err);
        if (err != 0) h[n++] = err;
    }
    if (q != 0) h[n++] = q;
    return n;
}

// Distributes the shorter factor over the longer one: fewer, longer partial products keep the
// number of merge passes small.
int expansion_product(int ne, const double* e, int nf, const double* f, double* h, double* scratch) {
    if (ne < nf) {
        std::swap(ne, nf);
        std::swap(e, f);
    }
    if (nf == 0) return 0;
    double* partial = scratch;          // 2 ne
    double* other = scratch + 2 * ne;   // 2 ne nf
    double* acc = h;
    int n = expansion_scale(ne, e, f[0], acc);
    for (int j = 1; j < nf; ++j) {
        const int np = expansion_scale(ne, e, f[j], partial);
        n = expansion_sum(n, acc, np, partial, other);
        std::swap(acc, other);
    }
    if (acc != h) std::copy(acc, acc + n, h);
    return n;
}

// Top-down sweep: fold each smaller component into the running sum, keeping the running sum
// aside whenever a nonzero error splits off. Bottom-up sweep: the same from the small end,
// which pushes the remaining overlaps upward.
int expansion_compress(int n, double* e) {
    if (n < 2) return n;
    int bottom = n - 1;
    double q = e[n - 1];
    for (int i = n - 2; i >= 0; --i) {
        double sum = 0, err = 0;
        fast_two_sum(q, e[i], sum, err);
        if (err != 0) {
            e[bottom--] = sum;
            q = err;
        } else {
            q = sum;
        }
    }
    e[bottom] = q;
    int top = 0;
    q = e[bottom];
    for (int i = bottom + 1; i < n; ++i) {
        double sum = 0, err = 0;
        fast_two_sum(e[i], q, sum, err);
        if (err != 0) e[top++] = err;
        q = sum;
    }
    if (q != 0 || top == 0) e[top++] = q;
    return q == 0 && top == 1 ? 0 : top;
}

}  // namespace tubemesh::predicates::detail
