#include "engine/pyramids/wedge.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/mesh/edge_key.hpp"
#include "engine/core/vec3_ops.hpp"

namespace tubemesh::pyramids {

namespace {

// The part of v perpendicular to the unit vector e.
Vec3 across(const Vec3& v, const Vec3& e) { return v - dot(v, e) * e; }

}  // namespace

BoundaryEdges::BoundaryEdges(std::span<const index_t> triangles) {
    edges_.reserve(triangles.size());
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const index_t n = triangles[t + k];
            if (n >= on_boundary_.size()) on_boundary_.resize(std::size_t{n} + 1 + on_boundary_.size() / 2, false);
            on_boundary_[n] = true;
            edges_.emplace_back(edge_key(n, triangles[t + (k + 1) % 3]), triangles[t + (k + 2) % 3]);
        }
    std::sort(edges_.begin(), edges_.end());
}

index_t BoundaryEdges::opposite(index_t a, index_t b) const {
    const auto on = [&](index_t n) { return n < on_boundary_.size() && on_boundary_[n]; };
    if (!on(a) || !on(b)) return kNoIndex;
    const std::uint64_t key = edge_key(a, b);
    const auto first = std::lower_bound(edges_.begin(), edges_.end(), std::pair{key, index_t{0}});
    if (first == edges_.end() || first->first != key) return kNoIndex;
    const auto next = first + 1;
    if (next != edges_.end() && next->first == key) return kNoIndex;
    return first->second;
}

ApexPlacement place_apex(const HybridMesh& mesh, const index_t* quad, const Vec3& centroid, const Vec3& normal,
                         double h, const BoundaryEdges& boundary, const PyramidOptions& opt, double max_shift) {
    ApexPlacement paper{{0, 0, 0}, opt.height_factor * h, false};
    if (!(opt.wedge_degrees > 0)) return paper;
    const double angle = opt.wedge_degrees * std::numbers::pi / 180.0;
    const double cos_target = std::cos(angle), sin_target = std::sin(angle);
    ApexPlacement placed{{0, 0, 0}, opt.wedge_height_factor * h, true};
    bool narrow = false;
    for (int k = 0; k < 4; ++k) {
        const index_t a = quad[k], b = quad[(k + 1) % 4];
        const index_t s = boundary.opposite(a, b);
        if (s == kNoIndex) continue;
        const Vec3 pa = mesh.point(a), pb = mesh.point(b);
        const Vec3 mid = 0.5 * (pa + pb);
        const Vec3 e = (1.0 / norm(pb - pa)) * (pb - pa);
        // In the plane across the edge: u along the quad away from the edge, n up; the
        // boundary triangle leaves the edge in direction t.
        Vec3 u = across(centroid - mid, e);
        const double depth = norm(u);  // half the quad's length across the edge
        if (!(depth > 0)) continue;
        u = (1.0 / depth) * u;
        const Vec3 t3 = across(mesh.point(s) - mid, e);
        const double tu = dot(t3, u), tn = dot(t3, normal), tl = std::hypot(tu, tn);
        if (!(tl > 0)) continue;
        // Wedge of the paper's apex, at (depth, height_factor h) from the edge.
        const double wedge_cos = (tu * depth + tn * paper.height) / (tl * std::hypot(depth, paper.height));
        if (wedge_cos <= cos_target) continue;
        narrow = true;
        // The ray at the target angle from t, turned towards u; the apex at the lowered height
        // must lie beyond it: depth + shift >= height · ru / rn.
        const double ru = (tu * cos_target + tn * sin_target) / tl, rn = (tn * cos_target - tu * sin_target) / tl;
        const double most = max_shift * 2.0 * depth;
        const double shift = rn > 0 ? std::clamp(placed.height * ru / rn - depth, 0.0, most) : most;
        placed.shift = placed.shift + shift * u;
    }
    return narrow ? placed : paper;
}

}  // namespace tubemesh::pyramids
