#include "engine/sizing/tet_size_caps.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "engine/core/vec3_ops.hpp"

namespace tubemesh {

TetSizeCaps::TetSizeCaps(const HybridMesh& mesh, std::span<const index_t> outer_quads, double far_size,
                         double gradation, double surface_growth, std::span<const double> quad_scale) {
    if (!(gradation >= 1.0)) throw Error("the tet gradation must be at least 1");
    if (!(surface_growth > 0) || !std::isfinite(surface_growth))
        throw Error("the surface size growth must be positive");
    if (outer_quads.size() < 4) return;
    std::vector<SizeSource> quads;
    quads.reserve(outer_quads.size() / 4);
    for (std::size_t q = 0; q + 3 < outer_quads.size(); q += 4) {
        Vec3 c{0, 0, 0};
        double edges = 0;
        for (int k = 0; k < 4; ++k) {
            const Vec3 p = mesh.point(outer_quads[q + k]);
            c = c + 0.25 * p;
            edges += norm(p - mesh.point(outer_quads[q + (k + 1) % 4]));
        }
        // A collapsed quad anchors nothing; the pyramid phase refuses it with its own message.
        const std::size_t index = q / 4;
        const double thin = index < quad_scale.size() ? quad_scale[index] : 1.0;
        if (edges > 0) quads.push_back({c, thin < 1.0 ? thin * 0.25 * edges : 0.25 * edges});
    }
    if (quads.empty()) return;
    volume_ = std::make_unique<SizeField>(SizeFieldOptions{far_size, std::max(gradation - 1.0, surface_growth)},
                                          std::move(quads));
}

TetSizeCaps::~TetSizeCaps() = default;

std::string too_large_warning(std::size_t left, int passes, std::optional<double> worst_tet) {
    if (left == 0 || (worst_tet && *worst_tet >= kPoorTet)) return "";
    std::string text = "surface: " + std::to_string(left) + " triangles are still more than " +
                       std::to_string(int(kTooLarge)) + " times the tet size beside them after " +
                       std::to_string(passes) + " passes";
    if (worst_tet) {
        char collapse[32];
        std::snprintf(collapse, sizeof collapse, "%.3g", *worst_tet);
        text += std::string(" and the worst tet's collapse is ") + collapse;
    } else {
        text += "; the tets on them may be flat";
    }
    return text + " (a smaller --size or a larger --gradation avoids it)";
}

std::vector<SizeSource> TetSizeCaps::caps(const HybridMesh& mesh, index_t first_triangle) const {
    const FaceBlock& tris = mesh.block(FaceKind::Tri);
    const index_t triangles = static_cast<index_t>(tris.nodes.size() / 3);
    if (!volume_ || first_triangle >= triangles) return {};
    const index_t n = triangles - first_triangle;
    std::vector<double> cap(n, 0.0);  // 0: the triangle is fine
    std::vector<Vec3> centroid(n);
    tbb::parallel_for(index_t{0}, n, [&](index_t i) {
        const index_t* t = &tris.nodes[3 * (first_triangle + i)];
        const Vec3 a = mesh.point(t[0]), b = mesh.point(t[1]), c = mesh.point(t[2]);
        const Vec3 sum = a + b + c;
        const Vec3 m{sum.x / 3, sum.y / 3, sum.z / 3};
        const double mean_edge = (norm(a - b) + norm(b - c) + norm(c - a)) / 3;
        if (volume_->below(m, mean_edge / kTooLarge)) {
            cap[i] = kCapped * volume_->at(m);
            centroid[i] = m;
        }
    });
    std::vector<SizeSource> out;
    for (index_t i = 0; i < n; ++i)
        if (cap[i] > 0) out.push_back({centroid[i], cap[i]});
    return out;
}

}  // namespace tubemesh
