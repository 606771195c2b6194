// Simulation of Simplicity (Edelsbrunner and Mücke 1990) for orient3d and insphere.
//
// The scheme. orient3d is -sign det4 of the rows [p, 1], insphere -sign det5 of the rows
// [p, h, 1] with h = |p|^2 (insphere.cpp). Every point i gets infinitesimal perturbations: its
// coordinates x, y, z are moved by delta(i, x), delta(i, y), delta(i, z) and its lifted
// coordinate h by omega(i). All these parameters are ordered by size, and each is infinitely
// smaller than any product of larger ones (as eps^(2^k) for the k-th). The order, largest first:
//   omega(i) for all points by decreasing global index, then
//   delta(i, x), delta(i, y), delta(i, z) for all points by decreasing global index.
// So the point with the largest index carries the dominant perturbation, and lifting is
// perturbed before position: for a tet that is not flat, the co-spherical tie of insphere is
// decided like a regular triangulation with infinitesimal weights (Geogram, CGAL), by
// orient3d of the four points other than the one with the largest index, then the next, ...
// Only when all five points are coplanar do the position perturbations take over, and they
// are the same as orient3d_sos's: both predicates are exact predicates of one perturbed
// weighted point set (positions p + delta, lifted heights |p|^2 + omega), so a Delaunay
// triangulation built from them is that set's regular triangulation, consistent everywhere.
//
// The perturbed determinant is a polynomial in the parameters. Its terms are indexed by sets S
// of perturbed matrix entries with distinct rows and distinct columns; the coefficient of S is
// +-(the minor of the unperturbed matrix without S's rows and columns). Since the parameters
// are powers eps^(2^k), ordering the terms by size is ordering S by the binary number with
// bit k for the k-th parameter: the sign is the sign of the first nonzero coefficient in that
// order. The constant "1" column is never perturbed, so the first S covering every perturbed
// column leaves the 1x1 minor [1]: the sequence always ends with a nonzero term, and the
// result is never 0 for distinct indices, even for coincident points.
//
// With the rows sorted by decreasing index, the k-th parameter of a predicate call is a fixed
// entry, so the terms of each predicate are a table computed at compile time: 17 for orient3d
// after the determinant, most calls stopping at the first (a 2D orientation); 78 for insphere,
// where a tet that is not flat stops within the first five (the orient3d of the lifting terms).
#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <utility>

#include "engine/predicates/bigint.hpp"
#include "engine/predicates/exact.hpp"
#include "engine/predicates/predicates.hpp"

namespace tubemesh::predicates {

namespace {

using detail::BigInt;

constexpr int kLift = 3;  // column of h; x, y, z are 0, 1, 2; the constant column comes last

// One term: the perturbed entries' rows and columns (bit masks) and the sign of its coefficient
// relative to the complementary minor.
struct Term {
    std::uint8_t rows = 0;
    std::uint8_t columns = 0;
    std::int8_t sign = 1;
};

// Entry perturbed by the parameter with bit k: for the lifted matrix the first `rows` bits are
// the omegas, then 3 deltas per row; rows are in order of decreasing index.
template <int Rows, bool Lifted>
constexpr void parameter_entry(int k, int& row, int& column) {
    if (Lifted && k < Rows) {
        row = k;
        column = kLift;
        return;
    }
    const int delta = Lifted ? k - Rows : k;
    row = delta / 3;
    column = delta % 3;
}

// Visits the valid S in increasing binary order with their coefficient signs, up to the first
// that perturbs every perturbable column (its minor is [1]).
template <int Rows, bool Lifted, class Visit>
constexpr void for_each_term(Visit visit) {
    constexpr int kParameters = Lifted ? 4 * Rows : 3 * Rows;
    constexpr int kColumns = Lifted ? 4 : 3;
    for (std::uint32_t set = 1; set < (1u << kParameters); ++set) {
        Term t;
        int column_of_row[Rows] = {};
        int index_sum = 0;
        bool valid = true;
        for (int k = 0; k < kParameters && valid; ++k) {
            if (!(set & (1u << k))) continue;
            int row = 0, column = 0;
            parameter_entry<Rows, Lifted>(k, row, column);
            valid = !(t.rows & (1u << row)) && !(t.columns & (1u << column));
            t.rows = static_cast<std::uint8_t>(t.rows | (1u << row));
            t.columns = static_cast<std::uint8_t>(t.columns | (1u << column));
            column_of_row[row] = column;
            index_sum += row + column;
        }
        if (!valid) continue;
        // Generalised Laplace expansion: (-1)^(sum of rows + columns) times the sign of the
        // permutation that pairs the perturbed rows, in order, with their columns.
        int inversions = 0;
        for (int r1 = 0; r1 < Rows; ++r1)
            for (int r2 = r1 + 1; r2 < Rows; ++r2)
                if ((t.rows & (1u << r1)) && (t.rows & (1u << r2)) && column_of_row[r1] > column_of_row[r2])
                    ++inversions;
        t.sign = static_cast<std::int8_t>((index_sum + inversions) % 2 == 0 ? 1 : -1);
        visit(t);
        if (std::popcount(static_cast<unsigned>(t.columns)) == kColumns) return;
    }
}

template <int Rows, bool Lifted>
constexpr int term_count() {
    int n = 0;
    for_each_term<Rows, Lifted>([&](const Term&) { ++n; });
    return n;
}

template <int Rows, bool Lifted>
constexpr auto make_terms() {
    std::array<Term, term_count<Rows, Lifted>()> terms{};
    int n = 0;
    for_each_term<Rows, Lifted>([&](const Term& t) { terms[n++] = t; });
    return terms;
}

// Sign of a minor with columns `columns` (among x, y, z, h) followed by the constant column,
// in exact integer arithmetic: the general case, only reached when five points are coplanar.
template <int N>
std::optional<int> lifted_minor_sign(int k, const int* columns, const detail::ScaledInput& in) {
    using Int = BigInt<N>;
    Int m[25];
    for (int r = 0; r < k; ++r) {
        for (int c = 0; c + 1 < k; ++c) {
            if (columns[c] != kLift) {
                m[r * k + c] = in.integer<N>(3 * r + columns[c]);
                continue;
            }
            Int lift;
            for (int axis = 0; axis < 3; ++axis) {
                const Int x = in.integer<N>(3 * r + axis);
                lift = lift + x * x;
            }
            m[r * k + c] = lift;
        }
        m[r * k + k - 1] = Int(1);
    }
    return detail::determinant_sign(m, k);
}

// Sign of the minor of [x y z (h) 1] on the rows in `row_mask` and the columns in `column_mask`
// plus the constant column. The cases without h are the classic predicates of lower dimension.
int minor_sign(const double* const* points, unsigned row_mask, unsigned column_mask) {
    const double* rows[5];
    int k = 0;
    for (int r = 0; r < 5; ++r)
        if (row_mask & (1u << r)) rows[k++] = points[r];
    int columns[4];
    int c = 0;
    for (int col = 0; col < 4; ++col)
        if (column_mask & (1u << col)) columns[c++] = col;
    assert(c + 1 == k);
    if (!(column_mask & (1u << kLift))) {
        switch (c) {
        case 0: return 1;
        case 1: {  // det[[u0 1], [u1 1]] = u0 - u1
            const double u0 = rows[0][columns[0]], u1 = rows[1][columns[0]];
            return u0 > u1 ? 1 : (u0 < u1 ? -1 : 0);
        }
        case 2: return detail::orient2d(rows[0], rows[1], rows[2], columns[0], columns[1]);
        case 3: return -orient3d(rows[0], rows[1], rows[2], rows[3]);  // det4[[p 1]] = -orient3d
        default: break;
        }
    }
    for (int r = 0; r < k; ++r)
        for (int axis = 0; axis < 3; ++axis)
            if (!std::isfinite(rows[r][axis])) return 0;
    constexpr int kAxes[3] = {0, 1, 2};
    const detail::ScaledInput in(rows, k, 3, kAxes);
    return detail::bigint_sign(in.span_bits(), 4, [&]<int N>() { return lifted_minor_sign<N>(k, columns, in); });
}

// Sign of the first nonzero term after the unperturbed determinant.
template <int Rows, bool Lifted>
int perturbed_sign(const double* const* sorted) {
    static constexpr auto kTerms = make_terms<Rows, Lifted>();
    constexpr unsigned kAllRows = (1u << Rows) - 1, kAllColumns = Lifted ? 0xFu : 0x7u;
    for (const Term& t : kTerms) {
        const int m = minor_sign(sorted, kAllRows & ~t.rows, kAllColumns & ~t.columns);
        if (m != 0) return t.sign * m;
    }
    assert(false && "the last term's minor is [1]");
    return 0;
}

// Sorts the points by decreasing index; returns the permutation's sign, 0 if two indices are equal.
template <int Rows>
int sort_by_index(const double** points, std::uint32_t* index) {
    int parity = 1;
    for (int i = 1; i < Rows; ++i)
        for (int j = i; j > 0 && index[j - 1] <= index[j]; --j) {
            if (index[j - 1] == index[j]) return 0;
            std::swap(index[j - 1], index[j]);
            std::swap(points[j - 1], points[j]);
            parity = -parity;
        }
    for (int i = 1; i < Rows; ++i)
        if (index[i - 1] == index[i]) return 0;
    return parity;
}

}  // namespace

int orient3d_sos(const double* a, const double* b, const double* c, const double* d, std::uint32_t ia,
                 std::uint32_t ib, std::uint32_t ic, std::uint32_t id) {
    const int s = orient3d(a, b, c, d);
    if (s != 0) return s;
    const double* points[4] = {a, b, c, d};
    std::uint32_t index[4] = {ia, ib, ic, id};
    const int parity = sort_by_index<4>(points, index);
    if (parity == 0) return 0;
    // orient3d = -sign det4 and det4(given order) = parity * det4(sorted).
    return -parity * perturbed_sign<4, false>(points);
}

namespace {

// insphere_sos once the unperturbed sign s is known.
int insphere_perturbed(int s, const double* a, const double* b, const double* c, const double* d, const double* e,
                       std::uint32_t ia, std::uint32_t ib, std::uint32_t ic, std::uint32_t id, std::uint32_t ie) {
    if (s != 0) return s;
    const double* points[5] = {a, b, c, d, e};
    std::uint32_t index[5] = {ia, ib, ic, id, ie};
    const int parity = sort_by_index<5>(points, index);
    if (parity == 0) return 0;
    return -parity * perturbed_sign<5, true>(points);
}

}  // namespace

int insphere_sos(const double* a, const double* b, const double* c, const double* d, const double* e,
                 std::uint32_t ia, std::uint32_t ib, std::uint32_t ic, std::uint32_t id, std::uint32_t ie) {
    return insphere_perturbed(insphere(a, b, c, d, e), a, b, c, d, e, ia, ib, ic, id, ie);
}

int insphere_sos_unfiltered(const double* a, const double* b, const double* c, const double* d, const double* e,
                            std::uint32_t ia, std::uint32_t ib, std::uint32_t ic, std::uint32_t id,
                            std::uint32_t ie) {
    return insphere_perturbed(detail::insphere_exact(a, b, c, d, e), a, b, c, d, e, ia, ib, ic, id, ie);
}

}  // namespace tubemesh::predicates
