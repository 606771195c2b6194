#pragma once
// A finite double as an exact dyadic m * 2^e, read from its bits (frexp/ldexp are library
// calls, and this runs a dozen times per exact predicate).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace tubemesh::predicates::detail {

// x = m * 2^e with m odd (or m = 0, e = 0), |m| < 2^53. `top` is the exponent of the highest
// set bit of |x|, so every bit of x lies in [e, top].
struct Dyadic {
    std::int64_t m = 0;
    int e = 0;
    int top = 0;
};

// x must be finite.
inline Dyadic dyadic(double x) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    const int biased = static_cast<int>((bits >> 52) & 0x7FF);
    std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
    if (biased != 0) mantissa |= std::uint64_t{1} << 52;  // normal: implicit leading bit
    if (mantissa == 0) return {};
    int e = (biased == 0 ? 1 : biased) - 1075;  // value = mantissa * 2^e
    const int zeros = std::countr_zero(mantissa);
    mantissa >>= zeros;
    e += zeros;
    const int top = e + 63 - std::countl_zero(mantissa);
    const auto m = static_cast<std::int64_t>(mantissa);
    return {(bits >> 63) != 0 ? -m : m, e, top};
}

// The finite values v[0..n) as integers on one power-of-two scale, if all fit below 2^bits in
// magnitude (bits <= 62); false otherwise. The scale is positive, so signs of determinants of
// these integers are the signs for the doubles.
//
// With t the exponent of the largest |v|, they fit exactly when every v is a multiple of
// 2^(t + 1 - bits). For t < bits (the usual case) multiplying by 2^(bits - 1 - t) >= 1 is then
// exact, every product an integer below 2^bits, and no nonzero product is below 1: so the
// values fit exactly when every product survives a round trip through int64 unchanged. Larger
// or subnormal maxima are read bit by bit instead.
inline bool to_common_integers(const double* v, int n, int bits, std::int64_t* out) {
    double largest = 0;
    for (int i = 0; i < n; ++i) largest = std::max(largest, std::fabs(v[i]));
    const int biased = static_cast<int>(std::bit_cast<std::uint64_t>(largest) >> 52);  // sign bit is 0
    const int shift = bits - 1 - (biased - 1023);
    if (biased != 0 && shift >= 0 && shift <= 1023) {
        const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(shift + 1023) << 52);
        double fractions = 0;  // the sum of the products' distances to their truncations: 0 iff all are integers
        for (int i = 0; i < n; ++i) {
            const double w = v[i] * scale;
            const auto x = static_cast<std::int64_t>(w);
            fractions += std::fabs(w - static_cast<double>(x));
            out[i] = x;
        }
        return fractions == 0;
    }
    if (largest == 0) {
        for (int i = 0; i < n; ++i) out[i] = 0;
        return true;
    }
    Dyadic d[16];
    int emin = 0, top = 0;
    bool any = false;
    for (int i = 0; i < n; ++i) {
        d[i] = dyadic(v[i]);
        if (d[i].m == 0) continue;
        emin = any && emin < d[i].e ? emin : d[i].e;
        top = any && top > d[i].top ? top : d[i].top;
        any = true;
    }
    if (any && top - emin + 1 > bits) return false;  // |v| < 2^(top + 1), so |v| 2^-emin < 2^(top + 1 - emin)
    for (int i = 0; i < n; ++i) out[i] = d[i].m == 0 ? 0 : d[i].m * (std::int64_t{1} << (d[i].e - emin));
    return true;
}

}  // namespace tubemesh::predicates::detail
