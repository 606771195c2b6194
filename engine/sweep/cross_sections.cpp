#include "engine/sweep/cross_sections.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/core/vec3_ops.hpp"

namespace tubemesh::sweep {
namespace {

void copy_end(const TubePlan& plan, int e, int station, std::span<Vec3> nodes) {
    const std::size_t per_station = static_cast<std::size_t>((plan.layers + 1) * plan.n);
    const std::vector<Vec3>& end = plan.ends[static_cast<std::size_t>(e)].node;
    std::copy(end.begin(), end.end(), nodes.begin() + static_cast<std::ptrdiff_t>(per_station * station));
}

// Where node k of station i goes before it is projected onto the wall, and its direction.
struct WallTarget {
    Vec3 point;
    Vec3 dir;
};

WallTarget wall_target(const TubePlan& plan, const Station& st, double w0, double w1, std::size_t k) {
    const Vec3 binormal = cross(st.tangent, st.reference);
    const double a = plan.angle(static_cast<int>(k), st.s);
    const Vec3 dir = std::cos(a) * st.reference + std::sin(a) * binormal;
    const double wall_depth = w0 * plan.ends[0].depth[k] + w1 * plan.ends[1].depth[k];
    return {st.centre + st.radius * dir + wall_depth * st.tangent, dir};
}

}  // namespace

std::vector<WallStart> node0_feet(const TubePlan& plan) {
    std::vector<WallStart> out(static_cast<std::size_t>(plan.stations()));
    WallCursor cursor;
    for (int i = 1; i + 1 < plan.stations(); ++i) {
        const Station& st = plan.line.stations[static_cast<std::size_t>(i)];
        const WallFoot foot =
            plan.wall.project(wall_target(plan, st, plan.weight(0, st.s), plan.weight(1, st.s), 0).point, cursor);
        out[static_cast<std::size_t>(i)] = {foot, cursor};
    }
    return out;
}

double place_stations(const TubePlan& plan, int first, int last, std::span<const WallStart> node0,
                      std::span<Vec3> nodes, std::span<double> scales) {
    const std::size_t n = static_cast<std::size_t>(plan.n);
    const std::size_t per_station = (static_cast<std::size_t>(plan.layers) + 1) * n;
    std::vector<WallCursor> cursor(n);
    const auto& depth0 = plan.ends[0].depth;
    const auto& depth1 = plan.ends[1].depth;
    double correction = 0;
    for (int i = first; i < last; ++i) {
        if (i == 0 || i == plan.stations() - 1) {
            const int e = i == 0 ? 0 : 1;
            copy_end(plan, e, i, nodes);
            if (!scales.empty())
                std::copy(plan.end_scale[e].begin(), plan.end_scale[e].end(), scales.begin() + i * static_cast<std::ptrdiff_t>(n));
            continue;
        }
        const Station& st = plan.line.stations[static_cast<std::size_t>(i)];
        const double w0 = plan.weight(0, st.s), w1 = plan.weight(1, st.s);
        Vec3* out = nodes.data() + per_station * static_cast<std::size_t>(i);
        for (std::size_t k = 0; k < n; ++k) {
            const auto [target, dir] = wall_target(plan, st, w0, w1, k);
            const double wall_depth = w0 * depth0[k] + w1 * depth1[k];
            // Node 0's foot is found already; at a chunk's first station the neighbour's face
            // and uv are the best guess for the others.
            if (cursor[k].face < 0 && k > 0) cursor[k] = cursor[k - 1];
            WallFoot foot;
            if (k == 0) {
                foot = node0[static_cast<std::size_t>(i)].foot;
                cursor[0] = node0[static_cast<std::size_t>(i)].cursor;
            } else {
                foot = plan.wall.project(target, cursor[k]);
            }
            correction = std::max(correction, foot.distance);
            out[k] = foot.point;
            const double thin = plan.scale(st.s, dir);
            if (!scales.empty()) scales[static_cast<std::size_t>(i) * n + k] = thin;
            for (std::size_t j = 1; j <= static_cast<std::size_t>(plan.layers); ++j) {
                const double depth = w0 * depth0[j * n + k] + w1 * depth1[j * n + k] - wall_depth;
                const double offset = thin < 1.0 ? thin * plan.offsets[j] : plan.offsets[j];
                out[j * n + k] = foot.point + offset * dir + depth * st.tangent;
            }
        }
    }
    return correction / plan.radius;
}

}  // namespace tubemesh::sweep
