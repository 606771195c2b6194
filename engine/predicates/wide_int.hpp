#pragma once
// Fixed-width two's-complement integers of L 64-bit limbs, for the exact tier that runs when
// the coordinate differences of a predicate, on a common power-of-two scale, are integers
// below 2^62. Then every intermediate of orient3d and insphere has a known width (128 bits for
// 2x2 minors and lifted coordinates, 192 for 3x3 minors, 320 for insphere) and the arithmetic
// is a fixed, branch-light sequence of limb operations: an order of magnitude faster than
// expansions or BigInt on full-mantissa input, which is what near-degenerate meshes produce.
#include <cstdint>

#include "engine/predicates/bigint.hpp"  // uint128_t

namespace tubemesh::predicates::detail {

template <int L>
struct Wide {
    std::uint64_t limb[L];  // little-endian, two's complement

    static Wide of(std::int64_t v) {
        Wide r;
        r.limb[0] = static_cast<std::uint64_t>(v);
        for (int i = 1; i < L; ++i) r.limb[i] = v < 0 ? ~std::uint64_t{0} : 0;
        return r;
    }
    bool negative() const { return (limb[L - 1] >> 63) != 0; }
    int sign() const {
        if (negative()) return -1;
        for (int i = 0; i < L; ++i)
            if (limb[i] != 0) return 1;
        return 0;
    }
    Wide negated() const {
        Wide r;
        std::uint64_t carry = 1;
        for (int i = 0; i < L; ++i) {
            const uint128_t t = static_cast<uint128_t>(~limb[i]) + carry;
            r.limb[i] = static_cast<std::uint64_t>(t);
            carry = static_cast<std::uint64_t>(t >> 64);
        }
        return r;
    }
    friend Wide operator+(const Wide& a, const Wide& b) {
        Wide r;
        std::uint64_t carry = 0;
        for (int i = 0; i < L; ++i) {
            const uint128_t t = static_cast<uint128_t>(a.limb[i]) + b.limb[i] + carry;
            r.limb[i] = static_cast<std::uint64_t>(t);
            carry = static_cast<std::uint64_t>(t >> 64);
        }
        return r;
    }
    friend Wide operator-(const Wide& a, const Wide& b) { return a + b.negated(); }
};

// The exact product; the caller's bounds guarantee it fits in A + B limbs.
template <int A, int B>
Wide<A + B> operator*(const Wide<A>& a, const Wide<B>& b) {
    if constexpr (A == 1 && B == 1) {  // the most frequent product: one hardware multiply
        __extension__ typedef __int128 int128_t;
        const auto p = static_cast<uint128_t>(static_cast<int128_t>(static_cast<std::int64_t>(a.limb[0])) *
                                              static_cast<std::int64_t>(b.limb[0]));
        return Wide<2>{{static_cast<std::uint64_t>(p), static_cast<std::uint64_t>(p >> 64)}};
    }
    const Wide<A> ma = a.negative() ? a.negated() : a;
    const Wide<B> mb = b.negative() ? b.negated() : b;
    Wide<A + B> r;
    for (int i = 0; i < A + B; ++i) r.limb[i] = 0;
    for (int i = 0; i < A; ++i) {
        std::uint64_t carry = 0;
        for (int j = 0; j < B; ++j) {
            const uint128_t t = static_cast<uint128_t>(ma.limb[i]) * mb.limb[j] + r.limb[i + j] + carry;
            r.limb[i + j] = static_cast<std::uint64_t>(t);
            carry = static_cast<std::uint64_t>(t >> 64);
        }
        r.limb[i + B] = carry;
    }
    return a.negative() != b.negative() ? r.negated() : r;
}

// Integers below 2^62 in magnitude, the input of this tier.
using W1 = Wide<1>;

// a * b - c * d, exact in 128 bits for |a|, |b|, |c|, |d| < 2^62.
inline Wide<2> cross_difference(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) {
    return W1::of(a) * W1::of(b) - W1::of(c) * W1::of(d);
}

// det[[x0 y0 z0], [x1 y1 z1], [x2 y2 z2]] for entries below 2^62: the 2x2 minors are below 2^125,
// the determinant below 6 * 2^186 < 2^189, inside 192 bits.
inline Wide<3> determinant3(const std::int64_t (&r0)[3], const std::int64_t (&r1)[3], const std::int64_t (&r2)[3]) {
    const Wide<2> m12 = cross_difference(r1[0], r2[1], r2[0], r1[1]);
    const Wide<2> m02 = cross_difference(r0[0], r2[1], r2[0], r0[1]);
    const Wide<2> m01 = cross_difference(r0[0], r1[1], r1[0], r0[1]);
    return (W1::of(r0[2]) * m12 - W1::of(r1[2]) * m02) + W1::of(r2[2]) * m01;
}

}  // namespace tubemesh::predicates::detail
