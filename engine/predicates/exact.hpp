#pragma once
// Exact signs behind the filters, and the helpers the symbolic perturbation and the intersection
// tests share. Internal to the predicates target.
//
// Each exact predicate takes the cheapest of these paths that is provably exact:
//  1. Small integers. The coordinate differences are doubles (two_diff leaves no tail) that,
//     on a common power-of-two scale, are integers below 2^62; or failing that the coordinates
//     themselves are integers below 2^61 on a common scale. Then fixed-width integers of 128 to
//     320 bits hold every intermediate (wide_int.hpp). This is the usual case: nearby points
//     have exact differences (Sterbenz), and a local configuration spans few bits.
//  2. Expansions. The differences are doubles in a window where no expansion product can
//     underflow or overflow, but span more than 62 bits.
//  3. BigInt on the coordinates: exact for any finite input.
// The expansion windows: every product of `degree` differences has its lowest bit at or above
// (2^-53 |d|min)^degree, which must stay >= 2^-1074, and the largest expansion component must
// stay below 2^995 for Dekker's split. orient2d (degree 2): [2^-480, 2^480]; orient3d
// (degree 3): [2^-300, 2^300]; insphere (degree 5): [2^-160, 2^160].
//
// Coordinates must be finite; for NaN or infinity the exact functions return 0.

namespace tubemesh::predicates::detail {

// Sign of det[b-a, c-a, d-a], computed exactly (no filter).
int orient3d_exact(const double* a, const double* b, const double* c, const double* d);

// Sign of the insphere determinant (positive: e inside the sphere of the positive tet abcd),
// computed exactly (no filter).
int insphere_exact(const double* a, const double* b, const double* c, const double* d, const double* e);

// Sign of det[b-a, c-a] for the points projected on coordinates (i, j): +1 when a, b, c turn
// counter-clockwise in the (i, j) plane. Filtered and exact.
int orient2d(const double* a, const double* b, const double* c, int i, int j);

}  // namespace tubemesh::predicates::detail
