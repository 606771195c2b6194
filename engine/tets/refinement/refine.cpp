#include "engine/tets/refinement/refine.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "engine/core/timing.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/delaunay/insertion_order.hpp"
#include "engine/delaunay/triangulation.hpp"
#include "engine/sizing/control_space.hpp"
#include "engine/tets/refinement/interior_points.hpp"

namespace tubemesh::tets {
namespace {

// Which of the points base, base + 1, ... (count of them) the kernel skipped in the insert() calls
// since it listed `blocked_before` blocked points and `dup_before` duplicates.
std::vector<std::uint8_t> skipped_points(const delaunay::Triangulation& tri, index_t base, std::size_t count,
                                         std::size_t blocked_before, std::size_t dup_before) {
    std::vector<std::uint8_t> dead(count, 0);
    for (std::size_t k = blocked_before; k < tri.blocked().size(); ++k) dead[tri.blocked()[k] - base] = 1;
    for (std::size_t k = dup_before; k < tri.duplicates().size(); ++k) dead[tri.duplicates()[k].first - base] = 1;
    return dead;
}

// The far field's lattice nodes inserted at once (RefineOptions::far_field_first), in BRIO
// rounds so that the first cavities, which reach across the unrefined core, are few. Their h is
// the far size; nodes outside the region or behind a concave part of the front are skipped by
// the kernel (the advancing front reaches them later). Returns the points inserted.
std::uint64_t insert_far_field(delaunay::Triangulation& tri, GrowingPoints& live, std::vector<double>& sizes,
                               std::vector<index_t>& sources, const ControlSpace& space, const FarLattice& lattice,
                               unsigned parts, const RefineOptions& options, const Pulse& pulse) {
    double lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
        lo[d] = std::numeric_limits<double>::infinity();
        hi[d] = -lo[d];
    }
    const std::span<const double> pts = tri.points();
    for (std::size_t i = 0; 3 * i < pts.size(); ++i)
        for (int d = 0; d < 3; ++d) {
            lo[d] = std::min(lo[d], pts[3 * i + d]);
            hi[d] = std::max(hi[d], pts[3 * i + d]);
        }
    // The region's volume, summed in tet order (the decision below must not depend on threads):
    // a box with more than 8 times the region's nodes (a thin or slanted solid) is left to the
    // advancing front, which never proposes a node outside the region.
    double volume = 0;
    const delaunay::TetStore& tets = tri.store();
    for (index_t t = 0; t < tets.size(); ++t) {
        const index_t* v = tets.vertex(t);
        if (v[0] == delaunay::kFreeSlot) continue;
        const auto at = [&](index_t i) { return Vec3{pts[3 * std::size_t{i}], pts[3 * std::size_t{i} + 1], pts[3 * std::size_t{i} + 2]}; };
        volume += std::abs(tet_volume(at(v[0]), at(v[1]), at(v[2]), at(v[3])));
    }
    const double a = lattice.spacing * space.far_size();
    const double region_nodes = a > 0 ? 2 * volume / (a * a * a) : 0;
    const std::vector<double> nodes = far_lattice_points(lo, hi, space, lattice, 8 * region_nodes + 1024);
    beat(pulse);
    const std::size_t m = nodes.size() / 3;
    if (m == 0) return 0;
    std::vector<double> x(m), y(m), z(m);
    for (std::size_t i = 0; i < m; ++i) {
        x[i] = nodes[3 * i];
        y[i] = nodes[3 * i + 1];
        z[i] = nodes[3 * i + 2];
    }
    const delaunay::InsertionOrder order = delaunay::brio_hilbert_order(x, y, z);
    const index_t base = tri.point_count();
    std::vector<double> xyz(3 * m);
    std::vector<index_t> ids(m);
    for (std::size_t k = 0; k < m; ++k) {
        const index_t i = order.order[k];
        xyz[3 * k] = x[i];
        xyz[3 * k + 1] = y[i];
        xyz[3 * k + 2] = z[i];
        ids[k] = base + static_cast<index_t>(k);
    }
    tri.add_points(xyz, ids);
    sizes.insert(sizes.end(), m, space.far_size());
    sources.insert(sources.end(), m, kNoIndex);
    tri.reserve_tets(std::size_t{tri.store().size()} + 8 * m + 1024);
    const std::size_t blocked_before = tri.blocked().size(), dup_before = tri.duplicates().size();
    const std::span<const index_t> all(ids);
    for (std::size_t r = 0; r + 1 < order.round_begin.size(); ++r) {
        tri.insert(all.subspan(order.round_begin[r], order.round_begin[r + 1] - order.round_begin[r]), parts,
                   options.min_points_per_part);
        beat(pulse);
        if (options.round_done) options.round_done(tri.live_tets());
    }
    const std::vector<std::uint8_t> dead = skipped_points(tri, base, m, blocked_before, dup_before);
    std::vector<double> in;
    in.reserve(xyz.size());
    for (std::size_t k = 0; k < m; ++k)
        if (!dead[k]) in.insert(in.end(), {xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]});
    live.append(in);
    return in.size() / 3;
}

}  // namespace

RefineStats refine_interior(TetDomain& domain, const ControlSpace& space, const Parallelism& par,
                            const RefineOptions& options, std::vector<double>* sizes_out, const Pulse& pulse,
                            RecoveredTets* relax_base) {
    const auto t0 = Clock::now();
    if (domain.tets.size() == 0) throw Error("refinement: the tet domain has no tetrahedra");
    const unsigned parts = par.parts;
    RefineStats stats;
    const index_t first_new = domain.point_count();

    {
        delaunay::Triangulation tri;
        tri.set_pulse(pulse);
        // The kernel holds the domain's points and tets while it refines (kernel id = domain id).
        tri.adopt(std::move(domain.xyz), std::move(domain.tets));
        domain.xyz.clear();
        domain.tets = delaunay::TetStore();
        // Points in the mesh (inserted), for the distance test.
        GrowingPoints live(tri.points());
        TooBigMemo memo;
        ProposalMemo proposals;
        // h at every point, by kernel id, and the front node that decides it: the front's and
        // Steiner points' from the control space now, each inserted point's from its candidate.
        std::vector<index_t> sources = point_sources(tri.points(), space);
        std::vector<double> sizes(sources.size());
        for (std::size_t v = 0; v < sizes.size(); ++v)
            sizes[v] = std::min(space.far_size(), space.term(sources[v], tri.points().data() + 3 * v));
        const FarLattice lattice{options.lattice_spacing, options.lattice_clearance};
        if (options.far_field_first)
            stats.far_field_first = insert_far_field(tri, live, sizes, sources, space, lattice, parts, options, pulse);
        for (; stats.rounds < options.max_rounds; ++stats.rounds) {
            beat(pulse);
            const MeshView view{tri.store(), tri.points(), sizes, sources};
            // The round's batch: the kept candidates along the Hilbert curve over them (each walk
            // starts near its point). What chose them is freed before the kernel inserts them.
            std::vector<Candidate> batch;
            {
                std::vector<Candidate> cand;
                {
                    const std::vector<index_t> faces = active_faces(view, options.size_tolerance, memo);
                    beat(pulse);
                    stats.too_big_left = static_cast<index_t>(faces.size());
                    if (faces.empty()) break;
                    cand = propose_points(view, faces, space, proposals, lattice);
                }
                beat(pulse);
                stats.candidates += cand.size();
                const std::vector<index_t> keep = select_points(cand, live, options.reject_factor, &view);
                beat(pulse);
                stats.rejected_close += cand.size() - keep.size();
                if (keep.empty()) break;
                std::vector<double> kept_xyz(3 * keep.size());
                for (std::size_t i = 0; i < keep.size(); ++i) std::copy_n(cand[keep[i]].p, 3, kept_xyz.begin() + 3 * i);
                const std::vector<index_t> along = delaunay::curve_order(kept_xyz);
                batch.resize(keep.size());
                for (std::size_t i = 0; i < keep.size(); ++i) batch[i] = cand[keep[along[i]]];
            }

            const index_t base = tri.point_count();
            std::vector<double> xyz(3 * batch.size());
            std::vector<index_t> ids(batch.size());
            for (std::size_t i = 0; i < batch.size(); ++i) {
                std::copy(batch[i].p, batch[i].p + 3, xyz.begin() + 3 * i);
                ids[i] = base + static_cast<index_t>(i);
            }
            tri.add_points(xyz, ids);
            for (const Candidate& c : batch) {
                sizes.push_back(c.h);
                sources.push_back(c.source);
            }
            for (std::size_t i = 0; i < batch.size(); ++i) tri.set_walk_start(ids[i], batch[i].tet);
            batch = {};
            tri.reserve_tets(std::size_t{tri.store().size()} + 8 * ids.size() + 1024);
            const std::size_t blocked_before = tri.blocked().size(), dup_before = tri.duplicates().size();
            tri.insert(ids, parts, options.min_points_per_part);
            // Only inserted points count as existing for the next round's distance test.
            const std::vector<std::uint8_t> dead = skipped_points(tri, base, ids.size(), blocked_before, dup_before);
            std::size_t added = 0;
            for (std::size_t i = 0; i < ids.size(); ++i)
                if (!dead[i]) {
                    live.append(std::span<const double>(xyz).subspan(3 * i, 3));
                    ++added;
                }
            if (added == 0) break;
            if (options.round_done) options.round_done(tri.live_tets());
        }
        stats.size_tests = memo.tests;
        stats.proposals_reused = proposals.reused_total.load();
        const delaunay::KernelCounters& k = tri.counters();
        stats.blocked = k.blocked;
        stats.shrunk_cavities = k.shrunk;
        stats.kernel_conflicts = k.conflicts;
        stats.exact_insphere = k.exact_insphere;
        stats.exact_insphere_reused = k.exact_insphere_reused;
        stats.duplicates = tri.duplicates().size();
        domain.tets = tri.finish();
        domain.xyz = tri.take_points();

        // Drop the points the kernel skipped: renumber the new points densely, in order.
        const std::vector<index_t> to = drop_unused_points(domain, first_new);
        const index_t next = domain.point_count();
        if (sizes_out) {
            sizes_out->assign(next, 0.0);
            for (std::size_t v = 0; v < to.size(); ++v)
                if (to[v] != kNoIndex) (*sizes_out)[to[v]] = sizes[v];
        }
        stats.inserted = next - first_new;
        // The far field's points stay first among the new ones (the renumbering keeps the order).
        if (relax_base) {
            if (relax_base->points != first_new)
                throw Error("refinement: the relaxation's mesh is not the one refinement started from");
            relax_base->in_place = static_cast<index_t>(stats.far_field_first);
        }
    }
    stats.tets = domain.tets.size();
    stats.seconds = seconds_since(t0);
    return stats;
}

}  // namespace tubemesh::tets
