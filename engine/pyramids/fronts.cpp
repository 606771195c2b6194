#include "engine/pyramids/fronts.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include "engine/pyramids/wedge.hpp"
#include "engine/quality/quality.hpp"

namespace tubemesh::pyramids {

namespace {

std::string where(const Vec3& p) {
    return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
}

Front make_front(const HybridMesh& mesh, const index_t* q, index_t index, const BoundaryEdges& boundary,
                 const PyramidOptions& opt, double scale = 1.0, bool thin_ring = false) {
    Front f;
    for (int k = 0; k < 4; ++k) {
        f.node[k] = q[k];
        f.corner[k] = mesh.point(q[k]);
    }
    const auto& c = f.corner;
    f.centroid = 0.25 * (c[0] + c[1] + c[2] + c[3]);
    f.h = 0.25 * (norm(c[1] - c[0]) + norm(c[2] - c[1]) + norm(c[3] - c[2]) + norm(c[0] - c[3]));
    // The cross product of the diagonals is twice the quad's vector area: it is the
    // best-fit normal of a non-planar (bilinear) quad too, where the paper's AB x AD would
    // depend on which corner is A.
    const Vec3 area = cross(c[2] - c[0], c[3] - c[1]);
    const double length = norm(area);
    if (!(length > 1e-12 * f.h * f.h) || !(f.h > 0))
        throw Error("pyramids: front quad " + std::to_string(index) + " near " + where(f.centroid) +
                    " is degenerate (zero area); the ring's outer quads must be proper quadrilaterals");
    f.normal = (1.0 / length) * area;
    f.height = opt.height_factor * f.h;
    f.spacing = f.h;
    f.shift = {0, 0, 0};
    f.ideal = f.centroid + f.height * f.normal;
    const double ideal_quality = pyramid_scaled_jacobian({c[0], c[1], c[2], c[3], f.ideal});
    f.quality_floor = std::min(opt.min_quality, opt.min_quality_ratio * ideal_quality);
    // An apex placed for a wedge may not score below min_quality, nor below the paper's apex
    // where that scores less (an elongated quad): the pyramid would become the mesh's worst
    // element instead of the tet. Nor may MN lean past max_angle (possible with non-default
    // wedge_* options only): every try node on the line M -> N would fail the angle test.
    const auto at = [&](const ApexPlacement& apex) { return (f.centroid + apex.shift) + apex.height * f.normal; };
    const auto usable = [&](const ApexPlacement& apex) {
        if (!apex.wedge) return false;
        const bool upright =
            std::atan2(norm(apex.shift), apex.height) * 180 / std::numbers::pi < opt.max_angle_degrees;
        return upright &&
               pyramid_scaled_jacobian({c[0], c[1], c[2], c[3], at(apex)}) >= std::min(opt.min_quality, ideal_quality);
    };
    std::optional<Vec3> wide;  // the second, wider-shifted wedge apex, when there is one
    if (scale < 1.0) {
        // Lowered for a facing front (apart_scales): on the normal line, the quality floor
        // still the paper apex's.
        f.height *= scale;
        f.ideal = f.centroid + f.height * f.normal;
        f.lowered = true;
        // Over a thin ring the gap ahead is thin too: a flat pyramid is the one that fits, so
        // the floor is the lowered apex's, not the paper's.
        if (thin_ring) f.spacing = scale * f.h;
        if (thin_ring)
            f.quality_floor = std::min(opt.min_quality, opt.min_quality_ratio * pyramid_scaled_jacobian(
                                                                                  {c[0], c[1], c[2], c[3], f.ideal}));
    } else {
        const ApexPlacement apex = place_apex(mesh, q, f.centroid, f.normal, f.h, boundary, opt, opt.wedge_max_shift);
        if (usable(apex)) {
            f.shift = apex.shift;
            f.height = apex.height;
            f.ideal = at(apex);
            f.wedge = true;
        }
        // Only a quad whose wedge is narrow has a placement to widen (place_apex decides that
        // before it looks at the shift's bound).
        if (apex.wedge && opt.wedge_wide_shift > opt.wedge_max_shift) {
            const ApexPlacement second =
                place_apex(mesh, q, f.centroid, f.normal, f.h, boundary, opt, opt.wedge_wide_shift);
            if (usable(second)) wide = at(second);
        }
    }
    f.wide = wide.value_or(f.ideal);
    f.ideal_quality = f.wedge || f.lowered ? pyramid_scaled_jacobian({c[0], c[1], c[2], c[3], f.ideal}) : ideal_quality;
    // Over a thin ring the room ahead is the spacing, not h: nodes farther than the paper's
    // radius scaled to it make pyramids that lean out of that room.
    f.candidate_radius = opt.search_radius_factor * f.spacing;
    // Try nodes lie between M and N, at most |MN|·(1 - Rate_K) from N.
    const double lowest_rate = std::pow(opt.relax_rate, std::max(opt.try_nodes, 0));
    const double lift = f.wedge ? norm(f.ideal - f.centroid) : f.height;
    double reach = std::max(f.candidate_radius, lift * (1.0 - lowest_rate));
    for (const Vec3& p : c) reach = std::max(reach, norm(p - f.ideal));
    reach = std::max(reach, norm(f.wide - f.ideal));  // the second apex's pyramid too
    // A hair more than the exact bound, so that rounding in the bound itself cannot matter.
    f.reach = reach * (1.0 + 1e-9);
    f.query_radius = f.reach + opt.distance_factor * f.spacing * (1.0 + 1e-9);  // the largest threshold
    return f;
}

bool shares_node(const Front& f, const Front& g) {
    for (index_t a : f.node)
        for (index_t b : g.node)
            if (a == b) return true;
    return false;
}

// Apexes at a + l·b apart (l the common scale of the heights): the largest l in [lowest, 1]
// that puts them `want` apart; when none does, whichever of lowest and 1 leaves them farther
// apart (1 where lowering brings them closer). At l = 1 they are nearer than `want`.
double apart_scale(const Vec3& a, const Vec3& b, double want, double lowest) {
    const double aa = norm2(a), ab = dot(a, b), bb = norm2(b);
    if (bb > 0) {
        const double disc = ab * ab - bb * (aa - want * want);
        if (disc >= 0) {
            const double root = (-ab - std::sqrt(disc)) / bb;  // where the too-near stretch begins
            if (root >= lowest && root <= 1.0) return root;
        }
    }
    const auto d2 = [&](double l) { return aa + 2 * l * ab + l * l * bb; };
    return d2(lowest) > d2(1.0) ? lowest : 1.0;
}

// Per front, the scale of its ideal height that PyramidOptions::apart_factor asks for (1:
// none), decided from the unscaled fronts only, so it does not depend on the order of work.
// A front with an apex placed for a wedge keeps it, and the fronts near it see it there.
std::vector<double> apart_scales(std::span<const Front> fronts, const IdealApexes& apexes, const PyramidOptions& opt) {
    const std::size_t n = fronts.size();
    std::vector<double> scale(n, 1.0);
    if (!(opt.apart_factor > 0) || n < 2) return scale;
    double largest_h = 0;
    for (const Front& f : fronts) largest_h = std::max(largest_h, f.h);
    const auto keeps_apex = [](const Front& f) { return f.wedge || has_wide(f); };
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t>& r) {
        std::vector<std::pair<index_t, double>> hits;
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            const Front& f = fronts[i];
            if (keeps_apex(f)) continue;
            // Every pair's distance asked for below is within this (rings of very different
            // sizes would otherwise make the small fronts search as far as the largest asks).
            const double radius = opt.apart_factor * 0.5 * (f.h + largest_h);
            apexes.index.within_unordered(f.ideal, radius, hits);
            for (const auto& [j, d2] : hits) {
                const Front& g = fronts[j];
                if (j == i || shares_node(f, g)) continue;
                const double want = opt.apart_factor * 0.5 * (f.h + g.h);
                if (!(d2 < want * want)) continue;
                // f's apex at M_f + l·H_f·n_f; g's lowered alike, or at N_g when it keeps it.
                const Vec3 from = keeps_apex(g) ? g.ideal : g.centroid;
                const Vec3 b = keeps_apex(g) ? f.height * f.normal : f.height * f.normal - g.height * g.normal;
                scale[i] = std::min(scale[i], apart_scale(f.centroid - from, b, want, opt.apart_lowest));
            }
        }
    });
    return scale;
}

}  // namespace

IdealApexes::IdealApexes(std::span<const Front> fronts)
    : x(coordinate(fronts, &Vec3::x)), y(coordinate(fronts, &Vec3::y)), z(coordinate(fronts, &Vec3::z)),
      index(x, y, z) {}

std::vector<double> IdealApexes::coordinate(std::span<const Front> fronts, double Vec3::*c) {
    std::vector<double> out;
    out.reserve(fronts.size());
    for (const Front& f : fronts) out.push_back(f.ideal.*c);
    return out;
}

std::vector<Front> make_fronts(const HybridMesh& mesh, std::span<const index_t> quads,
                               std::span<const index_t> boundary_triangles, const PyramidOptions& opt,
                               std::unique_ptr<IdealApexes>* apexes, std::span<const double> room) {
    // Without wedge placement nobody asks which quad edges lie on a boundary triangle.
    const BoundaryEdges boundary(opt.wedge_degrees > 0 ? boundary_triangles : std::span<const index_t>{});
    const std::size_t n = quads.size() / 4;
    std::vector<Front> fronts(n);
    const auto room_of = [&](std::size_t i) { return i < room.size() ? std::min(room[i], 1.0) : 1.0; };
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        const double thin = room_of(i);
        fronts[i] = make_front(mesh, quads.data() + 4 * i, static_cast<index_t>(i), boundary, opt, thin, thin < 1.0);
    });
    // Facing fronts lowered together (PyramidOptions::apart_factor).
    auto index = std::make_unique<IdealApexes>(fronts);
    const std::vector<double> scale = apart_scales(fronts, *index, opt);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        if (scale[i] < 1.0) {
            const double thin = room_of(i);
            fronts[i] = make_front(mesh, quads.data() + 4 * i, static_cast<index_t>(i), boundary, opt,
                                   thin * scale[i], thin < 1.0);
        }
    });
    if (apexes) {
        const bool lowered = std::any_of(scale.begin(), scale.end(), [](double l) { return l < 1.0; });
        *apexes = lowered ? std::make_unique<IdealApexes>(fronts) : std::move(index);
    }
    return fronts;
}

Adjacency front_neighbours(std::span<const Front> fronts, const IdealApexes* apexes) {
    Adjacency adj;
    const std::size_t n = fronts.size();
    adj.offset.assign(n + 1, 0);
    if (n == 0) return adj;
    double largest_query = 0, largest_reach = 0;
    for (const Front& f : fronts) {
        largest_query = std::max(largest_query, f.query_radius);
        largest_reach = std::max(largest_reach, f.reach);
    }

    std::unique_ptr<IdealApexes> own;
    if (!apexes) apexes = (own = std::make_unique<IdealApexes>(fronts)).get();

    // Rows found block by block, each block's rows back to back in its own buffer; offsets
    // then place them.
    constexpr std::size_t kBlock = 256;
    std::vector<std::vector<index_t>> found((n + kBlock - 1) / kBlock);
    tbb::parallel_for(std::size_t{0}, found.size(), [&](std::size_t b) {
        std::vector<std::pair<index_t, double>> hits;
        std::vector<index_t>& out = found[b];
        for (std::size_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
            const Front& f = fronts[i];
            const double radius = std::max(f.query_radius + largest_reach, largest_query + f.reach);
            apexes->index.within_unordered(f.ideal, radius, hits);
            const std::size_t row = out.size();
            for (const auto& [j, d2] : hits) {
                if (j == i) continue;
                const Front& g = fronts[j];
                const double reach = std::max(f.query_radius + g.reach, g.query_radius + f.reach);
                if (d2 < reach * reach) out.push_back(j);
            }
            std::sort(out.begin() + static_cast<std::ptrdiff_t>(row), out.end());
            adj.offset[i + 1] = out.size() - row;
        }
    });
    for (std::size_t i = 0; i < n; ++i) adj.offset[i + 1] += adj.offset[i];
    adj.items.resize(adj.offset[n]);
    tbb::parallel_for(std::size_t{0}, found.size(), [&](std::size_t b) {
        std::copy(found[b].begin(), found[b].end(), adj.items.begin() + static_cast<std::ptrdiff_t>(adj.offset[b * kBlock]));
    });
    return adj;
}

}  // namespace tubemesh::pyramids
