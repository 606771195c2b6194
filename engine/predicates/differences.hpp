#pragma once
// The coordinate differences of one predicate call in the forms the exact paths need
// (exact.hpp): as doubles with a flag saying whether they are exact, and, when possible, as
// integers below 2^62 on a common power-of-two scale.
#include <cmath>
#include <cstdint>

#include "engine/predicates/dyadic.hpp"
#include "engine/predicates/expansion.hpp"

namespace tubemesh::predicates::detail {

template <int Rows, int Dims>
struct Differences {
    double d[Rows][Dims] = {};          // fl(row - base)
    std::int64_t x[Rows][Dims] = {};    // row - base, scaled to integers, when `integral`
    bool finite = true;                 // false: NaN or infinity in the input, nothing else is set
    bool exact = true;                  // d holds the exact differences
    bool integral = false;              // x is valid

    Differences(const double* const* rows, const double* base, const int (&axes)[Dims]) {
        // x * 0 is 0 for finite x and NaN for infinity or NaN: one test for all the inputs.
        double zeros = 0;
        for (int r = 0; r <= Rows; ++r)
            for (int k = 0; k < Dims; ++k) zeros += (r < Rows ? rows[r] : base)[axes[k]] * 0.0;
        finite = zeros == 0;
        if (!finite) return;
        double tails = 0;  // the sum of the differences' rounding errors' magnitudes: 0 iff all are exact
        for (int r = 0; r < Rows; ++r)
            for (int k = 0; k < Dims; ++k) {
                double tail = 0;
                two_diff(rows[r][axes[k]], base[axes[k]], d[r][k], tail);
                tails += std::fabs(tail);
            }
        exact = tails == 0;
        if (exact) {
            integral = to_common_integers(&d[0][0], Rows * Dims, 62, &x[0][0]);
            return;
        }
        // Inexact differences of coordinates below 2^61 are integers below 2^62.
        double c[(Rows + 1) * Dims];
        std::int64_t ci[(Rows + 1) * Dims];
        for (int r = 0; r <= Rows; ++r)
            for (int k = 0; k < Dims; ++k) c[r * Dims + k] = (r < Rows ? rows[r] : base)[axes[k]];
        integral = to_common_integers(c, (Rows + 1) * Dims, 61, ci);
        if (!integral) return;
        for (int r = 0; r < Rows; ++r)
            for (int k = 0; k < Dims; ++k) x[r][k] = ci[r * Dims + k] - ci[Rows * Dims + k];
    }

    // Every difference is 0 or within [lo, hi] in magnitude: the expansion window.
    bool in_window(double lo, double hi) const {
        for (int r = 0; r < Rows; ++r)
            for (int k = 0; k < Dims; ++k) {
                const double m = std::fabs(d[r][k]);
                if (m != 0 && !(m >= lo && m <= hi)) return false;
            }
        return true;
    }
};

}  // namespace tubemesh::predicates::detail
