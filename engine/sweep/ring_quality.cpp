#include "engine/sweep/ring_quality.hpp"

#include <algorithm>
#include <array>

#include "engine/quality/quality.hpp"
#include "engine/sweep/ring_cells.hpp"

namespace tubemesh::sweep {

void RingQuality::add(const RingQuality& later) {
    min_jacobian = std::min(min_jacobian, later.min_jacobian);
    sum_jacobian += later.sum_jacobian;
    max_condition = std::max(max_condition, later.max_condition);
    sum_condition += later.sum_condition;
    if (folded_layer < 0) folded_layer = later.folded_layer;
}

RingQuality measure_layers(const TubePlan& plan, std::span<const Vec3> nodes, int first, int last) {
    RingQuality q;
    const RingCells cells{0, static_cast<index_t>(plan.n), static_cast<index_t>(plan.layers), plan.turn};
    for (index_t i = static_cast<index_t>(first); i < static_cast<index_t>(last); ++i)
        for (index_t j = 0; j < cells.layers; ++j)
            for (index_t k = 0; k < cells.n; ++k) {
                const std::array<index_t, 8> ids = cells.hex(i, j, k);
                std::array<Vec3, 8> hex;
                for (std::size_t v = 0; v < 8; ++v) hex[v] = nodes[ids[v]];
                const HexQuality h = hex_quality(hex);
                q.min_jacobian = std::min(q.min_jacobian, h.scaled_jacobian);
                q.sum_jacobian += h.scaled_jacobian;
                q.max_condition = std::max(q.max_condition, h.condition);
                q.sum_condition += h.condition;
                if (!(h.scaled_jacobian > 0) && q.folded_layer < 0) q.folded_layer = static_cast<int>(i);
            }
    return q;
}

}  // namespace tubemesh::sweep
