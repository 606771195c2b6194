// Compiled with -ffp-contract=off (see engine/CMakeLists.txt): the filter's error bound assumes
// every product and difference is rounded on its own.
#include "engine/surface/uv_predicates.hpp"

#include <cmath>

#include "engine/predicates/predicates.hpp"

namespace tubemesh::surface {

int orient2d(Uv a, Uv b, Uv c) {
    const double left = (b.u - a.u) * (c.v - a.v);
    const double right = (b.v - a.v) * (c.u - a.u);
    const double det = left - right;
    // Shewchuk's ccwerrboundA for this evaluation order: (3 + 16 eps) eps.
    constexpr double eps = 0x1p-53;
    constexpr double bound = (3.0 + 16.0 * eps) * eps;
    if (std::abs(det) > bound * (std::abs(left) + std::abs(right))) return det > 0 ? 1 : -1;
    // det[b-a, c-a, d-a] with d - a = (0, 0, 1) is exactly the 2D determinant above.
    const double pa[3] = {a.u, a.v, 0.0}, pb[3] = {b.u, b.v, 0.0}, pc[3] = {c.u, c.v, 0.0};
    const double pd[3] = {a.u, a.v, 1.0};
    return predicates::orient3d(pa, pb, pc, pd);
}

}  // namespace tubemesh::surface
