#include "engine/sizing/curvature_sizes.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh {

namespace {

constexpr int kSteps = 8;

// The normal's turn per unit length from a to b on the face; 0 where it cannot be told.
double curvature_between(const SurfaceMap& map, Uv a, Uv b) {
    const Vec3 pa = map.point(a), pb = map.point(b);
    const Vec3 na = map.normal(a), nb = map.normal(b);
    const double step = norm(pb - pa);
    if (!(step > 0) || norm(na) == 0 || norm(nb) == 0) return 0;
    return norm(nb - na) / step;
}

// One normal on a 3 x 3 grid: the face is taken for a plane and costs nothing more.
bool looks_planar(const SurfaceMap& map, const ParamRange& u, const ParamRange& v) {
    const Vec3 n0 = map.normal({u.lo, v.lo});
    for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 2; ++j)
            if (norm(map.normal({u.lo + i * (u.hi - u.lo) / 2, v.lo + j * (v.hi - v.lo) / 2}) - n0) > 1e-12) return false;
    return true;
}

}  // namespace

void add_curvature_sources(const SurfaceMap& map, double max_size, std::vector<SizeSource>& out) {
    const ParamRange u = map.u_range(), v = map.v_range();
    const double du = (u.hi - u.lo) / kSteps, dv = (v.hi - v.lo) / kSteps;
    if (!(du > 0) || !(dv > 0) || looks_planar(map, u, v)) return;
    for (int i = 0; i <= kSteps; ++i)
        for (int j = 0; j <= kSteps; ++j) {
            const Uv at{u.lo + i * du, v.lo + j * dv};
            // Step inwards at the far ends so both samples lie in the parameter box.
            const Uv along_u{at.u + (i < kSteps ? du : -du), at.v}, along_v{at.u, at.v + (j < kSteps ? dv : -dv)};
            const double k = std::max(curvature_between(map, at, along_u), curvature_between(map, at, along_v));
            if (!(k > 0) || !std::isfinite(k)) continue;
            const double size = kCurvatureSize / k;
            if (size < max_size) out.push_back({map.point(at), size});
        }
}

}  // namespace tubemesh
