// The integer tier of the exact predicates on its own: fixed-width two's-complement arithmetic
// (wide_int.hpp) against GMP, and the conversion of doubles to integers on one power-of-two
// scale (dyadic.hpp) against the bit-span rule read with frexp.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "engine/predicates/dyadic.hpp"
#include "engine/predicates/wide_int.hpp"

namespace {

using tubemesh::predicates::detail::Wide;

template <int L>
mpz_class value(const Wide<L>& w) {
    mpz_class v = 0;
    for (int i = L - 1; i >= 0; --i) {
        v <<= 64;
        v += mpz_class(static_cast<unsigned long>(w.limb[i]));
    }
    if (w.negative()) v -= mpz_class(1) << (64 * L);
    return v;
}

// v reduced into the L-limb two's-complement range, as limb arithmetic wraps.
template <int L>
mpz_class wrapped(mpz_class v) {
    const mpz_class modulus = mpz_class(1) << (64 * L), half = mpz_class(1) << (64 * L - 1);
    v %= modulus;  // sign of the dividend
    if (v < 0) v += modulus;
    if (v >= half) v -= modulus;
    return v;
}

// Limbs that hit the carry and sign edges often: 0, all ones, the sign bit alone, its
// complement, small values, or anything.
template <int L>
Wide<L> operand(std::mt19937_64& rng) {
    static constexpr std::uint64_t kEdges[] = {0, ~std::uint64_t{0}, std::uint64_t{1} << 63, ~(std::uint64_t{1} << 63),
                                               1, 2};
    Wide<L> w;
    const int style = static_cast<int>(rng() % 4);
    for (int i = 0; i < L; ++i) {
        const std::uint64_t r = rng();
        w.limb[i] = style == 0 ? kEdges[r % 6] : (style == 1 && r % 3 == 0 ? kEdges[(r >> 8) % 6] : r);
    }
    if (style == 3) w = Wide<L>::of(static_cast<std::int64_t>(rng()) >> (rng() % 64));  // sign-extended
    return w;
}

template <int A, int B>
void check_product(std::mt19937_64& rng, int trials) {
    for (int t = 0; t < trials; ++t) {
        const Wide<A> a = operand<A>(rng);
        const Wide<B> b = operand<B>(rng);
        // Any A-limb by B-limb product fits in A + B limbs, so it is exact.
        ASSERT_EQ(value(a * b), value(a) * value(b)) << A << "x" << B << " limbs, trial " << t;
    }
}

template <int L>
void check_sums(std::mt19937_64& rng, int trials) {
    for (int t = 0; t < trials; ++t) {
        const Wide<L> a = operand<L>(rng), b = operand<L>(rng);
        ASSERT_EQ(value(a + b), wrapped<L>(value(a) + value(b))) << L << " limbs, trial " << t;
        ASSERT_EQ(value(a - b), wrapped<L>(value(a) - value(b))) << L << " limbs, trial " << t;
        ASSERT_EQ(value(a.negated()), wrapped<L>(-value(a))) << L << " limbs, trial " << t;
        ASSERT_EQ(a.sign(), sgn(value(a))) << L << " limbs, trial " << t;
    }
}

TEST(PredicatesIntegers, WideArithmeticMatchesGmp) {
    std::mt19937_64 rng(17);
    check_product<1, 1>(rng, 20000);
    check_product<1, 2>(rng, 20000);
    check_product<2, 1>(rng, 20000);
    check_product<1, 3>(rng, 20000);
    check_product<2, 2>(rng, 20000);
    check_product<2, 3>(rng, 20000);
    check_product<3, 2>(rng, 20000);
    check_sums<1>(rng, 20000);
    check_sums<2>(rng, 20000);
    check_sums<3>(rng, 20000);
    check_sums<5>(rng, 20000);
}

// The rule to_common_integers implements, read independently: all nonzero values fit below
// 2^bits on one scale iff the highest set bit over all of them minus the lowest is below bits.
bool fits_by_span(const std::vector<double>& v, int bits) {
    int top = 0, low = 0;
    bool any = false;
    for (double x : v) {
        if (x == 0) continue;
        int e = 0;
        double m = std::ldexp(std::frexp(std::fabs(x), &e), 53);  // |x| = m 2^(e - 53), m an integer
        int lowest = e - 53;
        while (std::fmod(m, 2.0) == 0) {
            m /= 2;
            ++lowest;
        }
        top = any ? std::max(top, e - 1) : e - 1;
        low = any ? std::min(low, lowest) : lowest;
        any = true;
    }
    return !any || top - low + 1 <= bits;
}

// Values with a chosen span of bits around the limit, at scales over the whole range (subnormal,
// tiny, ordinary, huge), with zeros of both signs mixed in.
std::vector<double> values_with_span(std::mt19937_64& rng, int n, int bits) {
    std::uniform_int_distribution<int> span_of(bits - 3, bits + 2), base_of(-1074, 900), bit(0, 1);
    const int span = std::max(1, span_of(rng));
    const int base = rng() % 4 == 0 ? base_of(rng) : static_cast<int>(rng() % 120) - 60;
    std::vector<double> v(n);
    for (double& x : v) {
        if (rng() % 8 == 0) {
            x = bit(rng) ? 0.0 : -0.0;
            continue;
        }
        // An integer of at most min(span, 53) bits placed so its bits stay within [base, base + span).
        const int width = std::min(span, 53);
        const std::uint64_t m = (rng() >> (64 - width)) | 1;
        const int shift = static_cast<int>(rng() % static_cast<unsigned>(span - width + 1));
        x = std::ldexp(static_cast<double>(m), base + shift) * (bit(rng) ? 1 : -1);
    }
    if (rng() % 2 == 0) {  // pin both ends of the span so it is exactly `span` bits
        v[0] = std::ldexp(1.0, base);
        v[1] = -std::ldexp(1.0, base + span - 1);
    }
    return v;
}

TEST(PredicatesIntegers, CommonScaleMatchesTheBitSpan) {
    std::mt19937_64 rng(23);
    int fitted = 0, refused = 0;
    for (int trial = 0; trial < 200000; ++trial) {
        const int bits = trial % 2 == 0 ? 62 : 61;
        const int n = 2 + static_cast<int>(rng() % 14);
        std::vector<double> v = values_with_span(rng, n, bits);
        if (trial % 50 == 0) v[rng() % n] = std::ldexp(1.0, 1000);  // a maximum beyond the fast scale
        std::int64_t out[16];
        const bool fits = tubemesh::predicates::detail::to_common_integers(v.data(), n, bits, out);
        ASSERT_EQ(fits, fits_by_span(v, bits)) << "trial " << trial;
        if (!fits) {
            ++refused;
            continue;
        }
        ++fitted;
        // One positive power-of-two ratio out / v for every nonzero value, |out| < 2^bits, and 0 for 0.
        mpq_class ratio = 0;
        for (int i = 0; i < n; ++i) {
            ASSERT_LT(std::fabs(static_cast<double>(out[i])), std::ldexp(1.0, bits)) << "trial " << trial;
            if (v[i] == 0) {
                ASSERT_EQ(out[i], 0) << "trial " << trial;
                continue;
            }
            const mpq_class r = mpq_class(mpz_class(static_cast<long>(out[i]))) / mpq_class(v[i]);
            if (ratio == 0) ratio = r;
            ASSERT_EQ(r, ratio) << "trial " << trial << " value " << i;
        }
        if (ratio != 0) {
            ASSERT_GT(ratio, 0);
            const mpz_class num = ratio.get_num(), den = ratio.get_den();
            ASSERT_TRUE(mpz_popcount(num.get_mpz_t()) == 1 && mpz_popcount(den.get_mpz_t()) == 1)
                << "trial " << trial;
        }
    }
    EXPECT_GT(fitted, 50000);
    EXPECT_GT(refused, 30000);
}

}  // namespace
