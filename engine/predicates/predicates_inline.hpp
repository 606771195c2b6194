#pragma once
// orient3d and insphere with the floating-point filter inlined into the caller, for inner loops
// (Delaunay insertion, cavity search). Same results as predicates.hpp's orient3d and insphere:
// only the exact fallback is a call. Safe in code compiled without -ffp-contract=off (see the
// contraction note in filters.hpp); refuses to compile under -ffast-math.
#include "engine/predicates/filters.hpp"
#include "engine/predicates/predicates.hpp"

namespace tubemesh::predicates {

namespace detail {
int orient3d_exact(const double* a, const double* b, const double* c, const double* d);
int insphere_exact(const double* a, const double* b, const double* c, const double* d, const double* e);
}  // namespace detail

inline int orient3d_inline(const double* a, const double* b, const double* c, const double* d) {
    const int s = detail::orient3d_filter(a, b, c, d);
    return s != 0 ? s : detail::orient3d_exact(a, b, c, d);
}

// orient3d_inline of two quadruples (p[l] = {a, b, c, d} of lane l), written to sign[0] and
// sign[1]: the same signs, the two filters evaluated at once.
inline void orient3d_inline_pair(const double* const p[2][4], int sign[2]) {
#if defined(__SSE2__)
    detail::orient3d_filter_pair(p, sign);
#else
    sign[0] = sign[1] = 0;
#endif
    for (int l = 0; l < 2; ++l)
        if (sign[l] == 0) sign[l] = detail::orient3d_exact(p[l][0], p[l][1], p[l][2], p[l][3]);
}

inline int insphere_inline(const double* a, const double* b, const double* c, const double* d, const double* e) {
    const int s = detail::insphere_filter(a, b, c, d, e);
    return s != 0 ? s : detail::insphere_exact(a, b, c, d, e);
}

}  // namespace tubemesh::predicates
