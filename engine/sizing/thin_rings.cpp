#include "engine/sizing/thin_rings.hpp"

#include <algorithm>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh {
namespace {

// Apex height and tet size over the ring's thickness in front of a thinned ring. A taller apex
// left pipes a tenth of a radius from a face no room for their pyramids; smaller tets cost
// elements (all around the ring: its short steps make every outer quad small) for no better
// worst tet.
constexpr double kApexOverThickness = 0.6;
constexpr double kTetSizeOverThickness = 2.0;

}  // namespace

ThinRingShares thin_ring_shares(const HybridMesh& mesh, const SweepResult& sweep, double height_factor) {
    ThinRingShares out;
    const std::size_t n = sweep.outer_quad_scale.size();
    if (n == 0 || sweep.outer_quad_thickness.size() != n) return out;
    out.apex.assign(n, 1.0);
    out.tet_size.assign(n, 1.0);
    for (std::size_t q = 0; q < n; ++q) {
        if (!(sweep.outer_quad_scale[q] < 1.0)) continue;
        const index_t* c = sweep.outer_quads.data() + 4 * q;
        double h = 0;
        for (int k = 0; k < 4; ++k) h += 0.25 * norm(mesh.point(c[(k + 1) % 4]) - mesh.point(c[k]));
        if (!(h > 0)) continue;  // the pyramid phase refuses a collapsed quad with its own message
        const double t = sweep.outer_quad_thickness[q];
        out.apex[q] = std::min(1.0, kApexOverThickness * t / (height_factor * h));
        out.tet_size[q] = std::min(1.0, kTetSizeOverThickness * t / h);
    }
    return out;
}

}  // namespace tubemesh
