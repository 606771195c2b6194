#include "engine/tets/refine.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include "engine/delaunay/insertion_order.hpp"
#include "engine/delaunay/triangulation.hpp"
#include "engine/tets/control_space.hpp"
#include "engine/tets/interior_points.hpp"

namespace tubemesh::tets {
namespace {

using Clock = std::chrono::steady_clock;

// Hilbert order over the batch's bounding cube: each kernel part walks along one stretch.
void sort_along_curve(std::vector<Candidate>& c) {
    if (c.size() < 2) return;
    double lo[3] = {c[0].p[0], c[0].p[1], c[0].p[2]}, hi[3] = {lo[0], lo[1], lo[2]};
    for (const Candidate& q : c)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], q.p[a]);
            hi[a] = std::max(hi[a], q.p[a]);
        }
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300});
    const double scale = double((1u << 16) - 1) / extent;
    std::vector<std::pair<std::uint64_t, index_t>> key(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) {
        std::uint32_t g[3];
        for (int a = 0; a < 3; ++a) g[a] = static_cast<std::uint32_t>((c[i].p[a] - lo[a]) * scale);
        key[i] = {delaunay::hilbert_key(g[0], g[1], g[2], 16), static_cast<index_t>(i)};
    }
    std::sort(key.begin(), key.end());
    std::vector<Candidate> sorted(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) sorted[i] = c[key[i].second];
    c.swap(sorted);
}

}  // namespace

RefineStats refine_interior(TetDomain& domain, const ControlSpace& space, const RefineOptions& options) {
    const auto t0 = Clock::now();
    if (domain.tets.size() == 0) throw Error("refinement: the tet domain has no tetrahedra");
    const unsigned threads = options.threads ? options.threads : static_cast<unsigned>(tbb::info::default_concurrency());
    const unsigned parts = options.partitions ? options.partitions : threads;
    RefineStats stats;
    const index_t first_new = domain.point_count();

    tbb::task_arena arena(static_cast<int>(threads));
    arena.execute([&] {
        delaunay::Triangulation tri;
        tri.adopt(domain.xyz, std::move(domain.tets));
        domain.tets = delaunay::TetStore();
        // Points in the mesh (inserted), for the distance test; kernel ids follow domain.xyz.
        GrowingPoints live(domain.xyz);
        TooBigMemo memo;
        ProposalMemo proposals;
        // h at every point, by kernel id: the front's and Steiner points' now, each inserted
        // point's from its candidate.
        std::vector<double> sizes = point_sizes(domain.xyz, space);
        const FarLattice lattice{options.lattice_spacing, options.lattice_clearance};
        for (; stats.rounds < options.max_rounds; ++stats.rounds) {
            const MeshView view{tri.store(), domain.xyz, sizes};
            const std::vector<index_t> faces = active_faces(view, options.size_tolerance, memo);
            stats.too_big_left = static_cast<index_t>(faces.size());
            if (faces.empty()) break;
            std::vector<Candidate> cand = propose_points(view, faces, space, proposals, lattice);
            stats.candidates += cand.size();
            const std::vector<index_t> keep = select_points(cand, live, options.reject_factor);
            stats.rejected_close += cand.size() - keep.size();
            if (keep.empty()) break;
            std::vector<Candidate> batch(keep.size());
            for (std::size_t i = 0; i < keep.size(); ++i) batch[i] = cand[keep[i]];
            sort_along_curve(batch);

            const index_t base = tri.point_count();
            std::vector<double> xyz(3 * batch.size());
            std::vector<index_t> ids(batch.size());
            for (std::size_t i = 0; i < batch.size(); ++i) {
                std::copy(batch[i].p, batch[i].p + 3, xyz.begin() + 3 * i);
                ids[i] = base + static_cast<index_t>(i);
            }
            tri.add_points(xyz, ids);
            domain.xyz.insert(domain.xyz.end(), xyz.begin(), xyz.end());
            for (const Candidate& c : batch) sizes.push_back(c.h);
            for (std::size_t i = 0; i < batch.size(); ++i) tri.set_walk_start(ids[i], batch[i].tet);
            tri.reserve_tets(std::size_t{tri.store().size()} + 8 * batch.size() + 1024);
            const std::size_t blocked_before = tri.blocked().size(), dup_before = tri.duplicates().size();
            tri.insert(ids, parts, options.min_points_per_part);
            // Only inserted points count as existing for the next round's distance test.
            std::vector<std::uint8_t> dead(batch.size(), 0);
            for (std::size_t k = blocked_before; k < tri.blocked().size(); ++k) dead[tri.blocked()[k] - base] = 1;
            for (std::size_t k = dup_before; k < tri.duplicates().size(); ++k) dead[tri.duplicates()[k].first - base] = 1;
            std::size_t added = 0;
            for (std::size_t i = 0; i < batch.size(); ++i)
                if (!dead[i]) {
                    live.append(std::span<const double>(xyz).subspan(3 * i, 3));
                    ++added;
                }
            if (added == 0) break;
        }
        stats.size_tests = memo.tests;
        stats.proposals_reused = proposals.reused_total.load();
        const delaunay::KernelCounters& k = tri.counters();
        stats.blocked = k.blocked;
        stats.shrunk_cavities = k.shrunk;
        stats.kernel_conflicts = k.conflicts;
        stats.duplicates = tri.duplicates().size();
        domain.tets = tri.finish();

        // Drop the points the kernel skipped: renumber the new points densely, in order.
        const index_t n = domain.point_count();
        std::vector<std::uint8_t> used(n, 0);
        for (index_t v : domain.tets.vertices()) used[v] = 1;
        std::vector<index_t> to(n, kNoIndex);
        index_t next = first_new;
        for (index_t v = 0; v < first_new; ++v) to[v] = v;
        for (index_t v = first_new; v < n; ++v)
            if (used[v]) {
                to[v] = next;
                std::copy_n(domain.xyz.begin() + 3 * std::size_t{v}, 3, domain.xyz.begin() + 3 * std::size_t{next});
                ++next;
            }
        domain.xyz.resize(3 * std::size_t{next});
        for (index_t t = 0; t < domain.tets.size(); ++t)
            for (int i = 0; i < 4; ++i) domain.tets.vertex(t)[i] = to[domain.tets.vertex(t)[i]];
        stats.inserted = next - first_new;
    });
    stats.tets = domain.tets.size();
    stats.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return stats;
}

}  // namespace tubemesh::tets
