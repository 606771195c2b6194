#pragma once
// Signed big integers on the stack, the last resort of the exact predicates (exact.hpp): for
// coordinates spanning more bits than the 62-bit integer path holds, whose differences are not
// doubles or lie where an expansion product could underflow or overflow. Every double is an
// integer multiple of a power of two, so all coordinates of one predicate, multiplied by the
// same power of two, become integers and the determinant's sign can be computed in integer
// arithmetic with no condition on the range.
//
// N 64-bit limbs of capacity. Callers first try a small N chosen from the input's bit span; an
// operation that would need more limbs than N marks its result as overflowed (the mark
// propagates) instead of writing past the buffer, and the caller retries with kLargeLimbs,
// which holds any finite input (2^-1074 next to 2^1023).
#include <algorithm>
#include <bit>
#include <cassert>
#include <cstdint>
#include <optional>

#include "engine/predicates/dyadic.hpp"

namespace tubemesh::predicates::detail {

__extension__ typedef unsigned __int128 uint128_t;  // __extension__: GCC/Clang builtin under -Wpedantic

template <int N>
class BigInt {
public:
    BigInt() = default;
    // Copies only the limbs in use: most values are far below the capacity.
    BigInt(const BigInt& o) : n_(o.n_), neg_(o.neg_), overflow_(o.overflow_) {
        std::copy(o.limb_, o.limb_ + o.n_, limb_);
    }
    BigInt& operator=(const BigInt& o) {
        n_ = o.n_;
        neg_ = o.neg_;
        overflow_ = o.overflow_;
        std::copy(o.limb_, o.limb_ + o.n_, limb_);
        return *this;
    }
    explicit BigInt(std::int64_t v) {
        neg_ = v < 0;
        const std::uint64_t m = neg_ ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
        if (m != 0) limb_[n_++] = m;
    }

    // m * 2^shift with m > 0.
    static BigInt shifted(std::uint64_t m, int shift, bool negative) {
        BigInt r;
        r.neg_ = negative;
        const int whole = shift / 64, part = shift % 64;
        if (whole + 2 > N) return overflowed();
        std::fill(r.limb_, r.limb_ + whole, std::uint64_t{0});
        r.limb_[whole] = m << part;
        r.limb_[whole + 1] = part == 0 ? 0 : m >> (64 - part);
        r.n_ = whole + 2;
        r.trim();
        return r;
    }

    int sign() const { return n_ == 0 ? 0 : (neg_ ? -1 : 1); }
    // Some operation leading to this value needed more than N limbs: the value is meaningless.
    bool overflow() const { return overflow_; }

    friend BigInt operator-(const BigInt& a) {
        BigInt r = a;
        r.neg_ = a.n_ != 0 && !a.neg_;
        return r;
    }
    friend BigInt operator+(const BigInt& a, const BigInt& b) { return add(a, b, b.neg_); }
    friend BigInt operator-(const BigInt& a, const BigInt& b) { return add(a, b, !b.neg_); }

    friend BigInt operator*(const BigInt& a, const BigInt& b) {
        BigInt r;
        if (a.overflow_ || b.overflow_ || a.n_ + b.n_ > N) return overflowed();
        if (a.n_ == 0 || b.n_ == 0) return r;
        std::fill(r.limb_, r.limb_ + a.n_ + b.n_, std::uint64_t{0});
        for (int i = 0; i < a.n_; ++i) {
            std::uint64_t carry = 0;
            for (int j = 0; j < b.n_; ++j) {
                const uint128_t t = static_cast<uint128_t>(a.limb_[i]) * b.limb_[j] + r.limb_[i + j] + carry;
                r.limb_[i + j] = static_cast<std::uint64_t>(t);
                carry = static_cast<std::uint64_t>(t >> 64);
            }
            r.limb_[i + b.n_] = carry;
        }
        r.n_ = a.n_ + b.n_;
        r.neg_ = a.neg_ != b.neg_;
        r.trim();
        return r;
    }

private:
    static BigInt overflowed() {
        BigInt r;
        r.overflow_ = true;
        return r;
    }

    void trim() {
        while (n_ > 0 && limb_[n_ - 1] == 0) --n_;
        if (n_ == 0) neg_ = false;
    }

    // -1, 0, +1 as |a| <, ==, > |b|.
    static int compare_magnitude(const BigInt& a, const BigInt& b) {
        if (a.n_ != b.n_) return a.n_ < b.n_ ? -1 : 1;
        for (int i = a.n_ - 1; i >= 0; --i)
            if (a.limb_[i] != b.limb_[i]) return a.limb_[i] < b.limb_[i] ? -1 : 1;
        return 0;
    }

    // a + (b with sign b_negative).
    static BigInt add(const BigInt& a, const BigInt& b, bool b_negative) {
        BigInt r;
        if (a.overflow_ || b.overflow_) return overflowed();
        if (a.neg_ == b_negative) {
            const BigInt& big = a.n_ >= b.n_ ? a : b;
            const BigInt& small = a.n_ >= b.n_ ? b : a;
            if (big.n_ + 1 > N) return overflowed();
            std::uint64_t carry = 0;
            for (int i = 0; i < big.n_; ++i) {
                const uint128_t t = static_cast<uint128_t>(big.limb_[i]) + (i < small.n_ ? small.limb_[i] : 0) + carry;
                r.limb_[i] = static_cast<std::uint64_t>(t);
                carry = static_cast<std::uint64_t>(t >> 64);
            }
            r.limb_[big.n_] = carry;
            r.n_ = big.n_ + 1;
            r.neg_ = a.neg_;
        } else {
            const int c = compare_magnitude(a, b);
            if (c == 0) return r;
            const BigInt& big = c > 0 ? a : b;
            const BigInt& small = c > 0 ? b : a;
            std::uint64_t borrow = 0;
            for (int i = 0; i < big.n_; ++i) {
                const std::uint64_t s = i < small.n_ ? small.limb_[i] : 0;
                const std::uint64_t d = big.limb_[i] - s - borrow;
                borrow = (big.limb_[i] < s || (big.limb_[i] == s && borrow != 0)) ? 1 : 0;
                r.limb_[i] = d;
            }
            r.n_ = big.n_;
            r.neg_ = c > 0 ? a.neg_ : b_negative;
        }
        r.trim();
        return r;
    }

    std::uint64_t limb_[N];  // only the first n_ are meaningful
    int n_ = 0;
    bool neg_ = false;
    bool overflow_ = false;
};

// The coordinates of one predicate call as integers on a common scale 2^-emin, and the limb
// count that any determinant of degree <= 6 in them needs.
class ScaledInput {
public:
    // Collects the coordinates; n <= kMaxValues.
    static constexpr int kMaxValues = 15;
    ScaledInput(const double* const* points, int count, int dimensions, const int* axes) {
        for (int p = 0; p < count; ++p)
            for (int k = 0; k < dimensions; ++k) add(points[p][axes[k]]);
    }

    // Bits of the largest coordinate over the smallest bit of any coordinate.
    int span_bits() const { return has_nonzero_ ? top_ - emin_ + 1 : 0; }

    template <int N>
    BigInt<N> integer(int i) const {
        const Dyadic& d = values_[i];
        if (d.m == 0) return BigInt<N>();
        return BigInt<N>::shifted(static_cast<std::uint64_t>(d.m < 0 ? -d.m : d.m), d.e - emin_, d.m < 0);
    }

private:
    void add(double x) {
        assert(count_ < kMaxValues);
        const Dyadic d = dyadic(x);
        values_[count_++] = d;
        if (d.m == 0) return;
        emin_ = has_nonzero_ ? std::min(emin_, d.e) : d.e;
        top_ = has_nonzero_ ? std::max(top_, d.top) : d.top;
        has_nonzero_ = true;
    }

    Dyadic values_[kMaxValues];
    int count_ = 0;
    int emin_ = 0, top_ = 0;
    bool has_nonzero_ = false;
};

// Limb capacities. kSmallLimbs covers spans of a few hundred bits. kLargeLimbs covers any
// finite input: coordinates are integers below 2^2098, differences below 2^2099 (33 limbs),
// lifted coordinates below 2^4200 (66 limbs), 3x3 minors of differences below 2^6300 (99 limbs);
// the largest product, lift times minor, needs 165 limbs and the sums after it one more.
inline constexpr int kSmallLimbs = 24;
inline constexpr int kLargeLimbs = 176;

// Whether a determinant of the given degree in integers of `span` bits is worth trying in
// kSmallLimbs (one limb per started 64 bits of each factor, plus carries).
inline bool fits_small(int span, int degree) { return degree * ((span + 1 + 63) / 64) + 4 <= kSmallLimbs; }

// Sign of the n x n determinant m (row-major, n <= 5), or nullopt when Int overflowed: Laplace
// expansion over column prefixes, each minor of the first k columns on a row subset computed
// once from the smaller ones.
template <class Int>
std::optional<int> determinant_sign(const Int* m, int n) {
    assert(n >= 1 && n <= 5);
    Int minor[32];  // indexed by row subset; minor[s] uses the first popcount(s) columns
    minor[0] = Int(1);
    const unsigned full = (1u << n) - 1;
    for (unsigned s = 1; s <= full; ++s) {
        const int k = std::popcount(s);
        const int column = k - 1;
        Int sum;
        int position = 0;  // rank of row r within s: Laplace sign (-1)^(position + column)
        for (int r = 0; r < n; ++r) {
            if (!(s & (1u << r))) continue;
            const Int term = m[r * n + column] * minor[s & ~(1u << r)];
            sum = ((position + column) % 2 == 0) ? sum + term : sum - term;
            ++position;
        }
        minor[s] = sum;
    }
    if (minor[full].overflow()) return std::nullopt;
    return minor[full].sign();
}

// Runs evaluate<N>() with N = kSmallLimbs when the span suggests it fits, and with kLargeLimbs
// when it does not or when the small attempt overflowed.
template <class Evaluate>
int bigint_sign(int span, int degree, Evaluate evaluate) {
    if (fits_small(span, degree))
        if (const std::optional<int> s = evaluate.template operator()<kSmallLimbs>()) return *s;
    const std::optional<int> s = evaluate.template operator()<kLargeLimbs>();
    assert(s && "kLargeLimbs holds any finite input");
    return s.value_or(0);
}

}  // namespace tubemesh::predicates::detail
