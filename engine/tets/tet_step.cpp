#include "engine/tets/tet_step.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_sort.h>

#include "engine/core/ordered_compact.hpp"
#include "engine/core/timing.hpp"
#include "engine/core/vec3_ops.hpp"

namespace tubemesh::tets {
namespace {

// The pyramid apexes that only pyramids (as apex) and tets hold, for the smoothing to move.
void mark_movable_apexes(const HybridMesh& mesh, const std::vector<index_t>& to_domain, double floor, TetDomain& dom) {
    if (!(floor > 0 && floor <= 1)) throw Error("tet step: the apexes' pyramid floor must lie in (0, 1]");
    std::vector<std::uint8_t> held(mesh.point_count(), 0);
    for (index_t v : mesh.block(CellKind::Hex).nodes) held[v] = 1;
    for (const FaceBlock& b : mesh.faces)
        for (index_t v : b.nodes) held[v] = 1;
    const std::vector<index_t>& pyramids = mesh.block(CellKind::Pyramid).nodes;
    for (std::size_t c = 0; c + 4 < pyramids.size(); c += 5)
        for (int k = 0; k < 4; ++k) held[pyramids[c + k]] = 1;
    // (apex, base) of every pyramid whose apex may move, by apex, each apex's in pyramid order.
    std::vector<std::pair<index_t, std::array<index_t, 4>>> tops;
    for (std::size_t c = 0; c + 4 < pyramids.size(); c += 5) {
        const index_t apex = pyramids[c + 4];
        if (held[apex] || to_domain[apex] == kNoIndex) continue;
        std::array<index_t, 4> base;
        for (int k = 0; k < 4; ++k) base[k] = to_domain[pyramids[c + k]];
        // The base corners are nodes of the pyramid's side triangles, so front points.
        if (std::find(base.begin(), base.end(), kNoIndex) == base.end()) tops.push_back({to_domain[apex], base});
    }
    std::stable_sort(tops.begin(), tops.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    dom.apex_rank.assign(dom.front_points, kNoIndex);
    dom.apex_at = {0};
    dom.apex_bases.clear();
    dom.apex_floor = floor;
    for (const auto& [apex, base] : tops) {
        if (dom.apex_rank[apex] == kNoIndex) {
            if (!dom.apex_bases.empty()) dom.apex_at.push_back(static_cast<index_t>(dom.apex_bases.size()));
            dom.apex_rank[apex] = static_cast<index_t>(dom.apex_at.size() - 1);
        }
        dom.apex_bases.push_back(base);
    }
    if (!dom.apex_bases.empty()) dom.apex_at.push_back(static_cast<index_t>(dom.apex_bases.size()));
}

// Surface nodes inside one flat face: every front triangle around them is a boundary triangle
// of one surface group, and their fan lies in one plane. Nodes of cells, of CAD edges (two
// groups meet) and of curved faces stay.
void mark_sliding_points(const HybridMesh& mesh, std::span<const index_t> front, const std::vector<index_t>& to_domain,
                         const std::vector<index_t>& to_mesh, TetDomain& dom) {
    const index_t n = mesh.point_count();
    constexpr index_t kMixed = kNoIndex - 1;
    std::vector<index_t> group(n, kNoIndex);  // the one surface group around a node, or kMixed
    std::vector<index_t> surface_count(n, 0), front_count(n, 0);
    for (CellKind kind : {CellKind::Hex, CellKind::Pyramid})
        for (index_t v : mesh.block(kind).nodes) group[v] = kMixed;
    for (index_t v : mesh.block(FaceKind::Quad).nodes) group[v] = kMixed;
    const FaceBlock& tris = mesh.block(FaceKind::Tri);
    for (std::size_t t = 0; t < tris.group.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const index_t v = tris.nodes[3 * t + k];
            if (group[v] == kNoIndex) group[v] = tris.group[t];
            else if (group[v] != tris.group[t]) group[v] = kMixed;
            ++surface_count[v];
        }
    // Each front point's triangles, as (domain point, front triangle) sorted by point.
    std::vector<std::pair<index_t, index_t>> fans;
    fans.reserve(front.size());
    for (std::size_t t = 0; t < front.size() / 3; ++t)
        for (int k = 0; k < 3; ++k) {
            ++front_count[front[3 * t + k]];
            fans.push_back({to_domain[front[3 * t + k]], static_cast<index_t>(t)});
        }
    tbb::parallel_sort(fans.begin(), fans.end());  // distinct pairs: one order
    dom.slide_rank.assign(dom.front_points, kNoIndex);
    dom.slide_normal.clear();
    dom.slide_offset.clear();
    for (std::size_t i = 0, j = 0; i < fans.size(); i = j) {
        const index_t p = fans[i].first;
        while (j < fans.size() && fans[j].first == p) ++j;
        const index_t node = to_mesh[p];
        // All the node's front triangles are its boundary triangles, of one group.
        if (group[node] == kNoIndex || group[node] == kMixed || surface_count[node] != front_count[node]) continue;
        const Vec3 here = mesh.point(node);
        Vec3 sum{0, 0, 0};
        double longest = 0;
        for (std::size_t k = i; k < j; ++k) {
            const index_t* f = front.data() + 3 * std::size_t{fans[k].second};
            sum = sum + cross(mesh.point(f[1]) - mesh.point(f[0]), mesh.point(f[2]) - mesh.point(f[0]));
            for (int c = 0; c < 3; ++c) longest = std::max(longest, norm(mesh.point(f[c]) - here));
        }
        const double len = norm(sum);
        if (!(len > 0)) continue;
        // A plane at x, y or z = c: the unit axis exactly (1/len * len may round to 1 - 2^-53), so
        // a slid point keeps its coordinate c to the last bit.
        const auto sign = [](double c) { return c > 0 ? 1.0 : c < 0 ? -1.0 : 0.0; };
        const bool on_axis = (sum.x == 0) + (sum.y == 0) + (sum.z == 0) == 2;
        const Vec3 normal = on_axis ? Vec3{sign(sum.x), sign(sum.y), sign(sum.z)} : (1.0 / len) * sum;
        // Flat: no fan corner off the plane by more than a rounding error of the edges.
        bool flat = true;
        for (std::size_t k = i; k < j && flat; ++k)
            for (int c = 0; c < 3; ++c)
                if (std::abs(dot(mesh.point(front[3 * std::size_t{fans[k].second} + c]) - here, normal)) > 1e-9 * longest)
                    flat = false;
        if (!flat) continue;
        dom.slide_rank[p] = static_cast<index_t>(dom.slide_normal.size());
        dom.slide_normal.push_back(normal);
        dom.slide_offset.push_back(dot(normal, here));
    }
    if (dom.slide_normal.empty()) dom.slide_rank.clear();
}

}  // namespace

TetStepStats build_tets(HybridMesh& mesh, std::span<const index_t> front, index_t region, const Parallelism& par,
                        const TetStepOptions& options) {
    const auto t0 = Clock::now();
    TetStepStats stats;
    if (front.empty() || front.size() % 3 != 0) throw Error("tet step: the front is empty or not made of triangles");
    stats.threads = par.threads;
    stats.partitions = par.parts;
    stats.front_triangles = static_cast<index_t>(front.size() / 3);

    // Compact the front's nodes to domain ids 0..k-1 in order of first use (deterministic).
    const index_t n = mesh.point_count();
    std::vector<index_t> to_domain(n, kNoIndex);
    std::vector<index_t> to_mesh;
    std::vector<double> xyz;
    std::vector<index_t> local;
    local.reserve(front.size());
    for (index_t v : front) {
        if (v >= n) throw Error("tet step: a front node id is out of range");
        if (to_domain[v] == kNoIndex) {
            to_domain[v] = static_cast<index_t>(to_mesh.size());
            to_mesh.push_back(v);
            xyz.insert(xyz.end(), {mesh.x[v], mesh.y[v], mesh.z[v]});
        }
        local.push_back(to_domain[v]);
    }

    TetDomain domain = recover_boundary(xyz, local, par, options.recovery, &stats.recovery, options.pulse);
    if (options.part_done) options.part_done();
    beat(options.pulse);
    // Three serial steps side by side: the movable points' tables (written into the domain), the
    // copy of the recovered tets and the control space (both only read it).
    RecoveredTets recovered;  // the relaxation inserts the interior points again into this mesh
    std::optional<ControlSpace> control;
    ControlSpaceOptions co;
    co.far_size = options.far_size;
    co.gradation = options.gradation;
    tbb::parallel_invoke(
        [&] {
            if (options.move_apexes) mark_movable_apexes(mesh, to_domain, options.apex_floor, domain);
            if (options.slide_surface) mark_sliding_points(mesh, front, to_domain, to_mesh, domain);
        },
        [&] {
            if (options.relaxation.iterations > 0) recovered = recovered_tets(domain);
        },
        [&] { control.emplace(domain, co); });
    const ControlSpace& space = *control;
    // The domain holds its own copies now: free these before the refinement grows it.
    xyz = {};
    local = {};
    to_domain = {};
    beat(options.pulse);

    std::vector<double> sizes;
    stats.refine =
        refine_interior(domain, space, par, options.refine, options.relaxation.iterations > 0 ? &sizes : nullptr,
                        options.pulse, options.relaxation.iterations > 0 ? &recovered : nullptr);
    control.reset();  // only the refinement asks the control space
    if (options.relaxation.iterations > 0) {
        stats.relaxation = relax_points(domain, std::move(recovered), sizes, par, options.relaxation, options.pulse);
        recovered = RecoveredTets();
    }
    if (options.part_done) options.part_done();  // refinement and relaxation

    stats.optimise = optimise(domain, options.optimise, options.pulse);
    if (options.part_done) options.part_done();

    // Apexes and surface points the smoothing moved: their new places.
    if (domain.front_moves())
        tbb::parallel_for(tbb::blocked_range<index_t>(0, domain.front_points, 4096), [&](const tbb::blocked_range<index_t>& r) {
            for (index_t p = r.begin(); p < r.end(); ++p)
                if (domain.movable(p)) {
                    const double* q = domain.point(p);
                    mesh.x[to_mesh[p]] = q[0];
                    mesh.y[to_mesh[p]] = q[1];
                    mesh.z[to_mesh[p]] = q[2];
                }
        });
    // Append: points after the front's become new mesh points, in domain order.
    const index_t domain_points = domain.point_count();
    to_mesh.resize(domain_points, kNoIndex);
    // Recovery keeps the ids of Steiner points it removed again: only points of tets are added.
    // Threads may flag one point at once, always with 1: relaxed stores suffice.
    std::vector<std::uint8_t> used(domain_points, 0);
    tbb::parallel_for(tbb::blocked_range<index_t>(0, domain.tets.size(), 4096), [&](const tbb::blocked_range<index_t>& r) {
        for (index_t t = r.begin(); t < r.end(); ++t) {
            const index_t* v = domain.tets.vertex(t);
            for (int k = 0; k < 4; ++k) std::atomic_ref<std::uint8_t>(used[v[k]]).store(1, std::memory_order_relaxed);
        }
    });
    const index_t first_new = mesh.point_count(), front_points = domain.front_points;
    stats.new_points = static_cast<index_t>(ordered_compact(
        domain_points - front_points, [&](std::size_t i) { return used[front_points + i] != 0; },
        [&](std::size_t count) {
            mesh.x.resize(first_new + count);
            mesh.y.resize(first_new + count);
            mesh.z.resize(first_new + count);
        },
        [&](std::size_t i, std::size_t k) {
            const index_t p = front_points + static_cast<index_t>(i), to = first_new + static_cast<index_t>(k);
            const double* q = domain.point(p);
            to_mesh[p] = to;
            mesh.x[to] = q[0];
            mesh.y[to] = q[1];
            mesh.z[to] = q[2];
        }));
    CellBlock& tets = mesh.block(CellKind::Tet);
    const std::size_t first_tet = tets.region.size();
    tets.nodes.resize(tets.nodes.size() + 4 * std::size_t{domain.tets.size()});
    tets.region.resize(first_tet + domain.tets.size(), region);
    tbb::parallel_for(tbb::blocked_range<index_t>(0, domain.tets.size(), 4096), [&](const tbb::blocked_range<index_t>& r) {
        for (index_t t = r.begin(); t < r.end(); ++t) {
            const index_t* v = domain.tets.vertex(t);
            for (int k = 0; k < 4; ++k) tets.nodes[4 * (first_tet + t) + k] = to_mesh[v[k]];
        }
    });
    stats.tets = domain.tets.size();
    stats.seconds = seconds_since(t0);
    return stats;
}

}  // namespace tubemesh::tets
