#pragma once
// Fixed-width two's-complement integers of L 64-bit limbs, for the exact tier that runs when
// the coordinate differences of a predicate, on a common power-of-two scale, are integers
// below 2^62. Then every intermediate of orient3d and insphere has a known width (128 bits for
// 2x2 minors and lifted coordinates, 192 for 3x3 minors, 320 for insphere) and the arithmetic
// is a fixed, branch-light sequence of limb operations: an order of magnitude faster than
// expansions or BigInt on full-mantissa input, which is what near-degenerate meshes produce.
#include <cstdint>

#if defined(__x86_64__)
#include <x86intrin.h>
#endif

#include "engine/predicates/bigint.hpp"  // uint128_t

namespace tubemesh::predicates::detail {

// x + y + carry_in, carry out in `carry`: one add-with-carry instruction where the target has it
// (the 128-bit formulation below compiles to several).
inline std::uint64_t add_carry(std::uint64_t x, std::uint64_t y, unsigned char& carry) {
#if defined(__x86_64__)
    unsigned long long r;
    carry = _addcarry_u64(carry, x, y, &r);
    return r;
#else
    const uint128_t t = static_cast<uint128_t>(x) + y + carry;
    carry = static_cast<unsigned char>(t >> 64);
    return static_cast<std::uint64_t>(t);
#endif
}
// x - y - borrow_in, borrow out in `borrow`.
inline std::uint64_t sub_borrow(std::uint64_t x, std::uint64_t y, unsigned char& borrow) {
#if defined(__x86_64__)
    unsigned long long r;
    borrow = _subborrow_u64(borrow, x, y, &r);
    return r;
#else
    const uint128_t t = static_cast<uint128_t>(x) - y - borrow;
    borrow = static_cast<unsigned char>((t >> 64) & 1);
    return static_cast<std::uint64_t>(t);
#endif
}

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
    Wide negated() const { return Wide{} - *this; }
    friend Wide operator+(const Wide& a, const Wide& b) {
        Wide r;
        unsigned char carry = 0;
        for (int i = 0; i < L; ++i) r.limb[i] = add_carry(a.limb[i], b.limb[i], carry);
        return r;
    }
    friend Wide operator-(const Wide& a, const Wide& b) {
        Wide r;
        unsigned char borrow = 0;
        for (int i = 0; i < L; ++i) r.limb[i] = sub_borrow(a.limb[i], b.limb[i], borrow);
        return r;
    }
};

// The exact product; the caller's bounds guarantee it fits in A + B limbs. The limbs read as
// unsigned are a + 2^(64A) [a < 0] and b + 2^(64B) [b < 0]; their product, less
// 2^(64A) b [a < 0] and 2^(64B) a [b < 0], is a b modulo 2^(64(A+B)): schoolbook on the limbs
// and two masked subtractions, no negation of operands or result.
template <int A, int B>
[[gnu::always_inline]] inline Wide<A + B> operator*(const Wide<A>& a, const Wide<B>& b) {
    __extension__ typedef __int128 int128_t;
    if constexpr (A == 1 && B == 1) {  // the most frequent product: one hardware multiply
        const auto p = static_cast<uint128_t>(static_cast<int128_t>(static_cast<std::int64_t>(a.limb[0])) *
                                              static_cast<std::int64_t>(b.limb[0]));
        return Wide<2>{{static_cast<std::uint64_t>(p), static_cast<std::uint64_t>(p >> 64)}};
    } else if constexpr (A == 1 && B == 2) {
        // z (b1 2^64 + b0) = (z b1 + floor(z b0 / 2^64)) 2^64 + (z b0 mod 2^64), with z b0 and
        // z b1 signed products that fit in 128 bits.
        const auto z = static_cast<std::int64_t>(a.limb[0]);
        const auto low = static_cast<int128_t>(static_cast<uint128_t>(a.limb[0]) * b.limb[0] -
                                               (z < 0 ? static_cast<uint128_t>(b.limb[0]) << 64 : 0));
        const int128_t high = static_cast<int128_t>(z) * static_cast<std::int64_t>(b.limb[1]) + (low >> 64);
        return Wide<3>{{static_cast<std::uint64_t>(low), static_cast<std::uint64_t>(high),
                        static_cast<std::uint64_t>(static_cast<uint128_t>(high) >> 64)}};
    } else {
        Wide<A + B> r;
        for (int i = 0; i < B; ++i) r.limb[i] = 0;
#pragma GCC unroll 8
        for (int i = 0; i < A; ++i) {
            std::uint64_t carry = 0;
#pragma GCC unroll 8
            for (int j = 0; j < B; ++j) {
                const uint128_t t = static_cast<uint128_t>(a.limb[i]) * b.limb[j] + r.limb[i + j] + carry;
                r.limb[i + j] = static_cast<std::uint64_t>(t);
                carry = static_cast<std::uint64_t>(t >> 64);
            }
            r.limb[i + B] = carry;
        }
        const auto subtract_shifted = [&r](const std::uint64_t* limb, int count, int shift, std::uint64_t mask) {
            unsigned char borrow = 0;
            for (int i = 0; i < count; ++i) r.limb[shift + i] = sub_borrow(r.limb[shift + i], limb[i] & mask, borrow);
        };
        subtract_shifted(b.limb, B, A, 0 - static_cast<std::uint64_t>(a.negative()));
        subtract_shifted(a.limb, A, B, 0 - static_cast<std::uint64_t>(b.negative()));
        return r;
    }
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
