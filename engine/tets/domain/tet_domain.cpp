#include "engine/tets/domain/tet_domain.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <span>

#include <tbb/parallel_for.h>

#include "engine/core/ordered_compact.hpp"

namespace tubemesh::tets {

RecoveredTets recovered_tets(const TetDomain& d) { return {d.tets.clone(), d.point_count()}; }

std::vector<index_t> drop_unused_points(TetDomain& d, index_t first) {
    const index_t n = d.point_count();
    // Threads may flag one point at once, always with 1: relaxed stores suffice.
    std::vector<std::uint8_t> used(n, 0);
    const std::span<const index_t> rows = d.tets.vertices();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size(), 16384), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t k = r.begin(); k < r.end(); ++k)
            std::atomic_ref<std::uint8_t>(used[rows[k]]).store(1, std::memory_order_relaxed);
    });
    std::vector<index_t> to(n, kNoIndex);
    std::iota(to.begin(), to.begin() + first, index_t{0});
    // The kept points' new places, in order, written to a new array (in place, a chunk could
    // overwrite a point the chunk before it has not moved yet).
    std::vector<double> xyz;
    ordered_compact(
        n - first, [&](std::size_t i) { return used[first + i] != 0; },
        [&](std::size_t count) {
            xyz.resize(3 * (std::size_t{first} + count));
            std::copy_n(d.xyz.begin(), 3 * std::size_t{first}, xyz.begin());
        },
        [&](std::size_t i, std::size_t k) {
            const std::size_t v = first + i, next = first + k;
            to[v] = static_cast<index_t>(next);
            std::copy_n(d.xyz.begin() + 3 * v, 3, xyz.begin() + 3 * next);
        });
    d.xyz.swap(xyz);
    tbb::parallel_for(tbb::blocked_range<index_t>(0, d.tets.size(), 4096), [&](const tbb::blocked_range<index_t>& r) {
        for (index_t t = r.begin(); t < r.end(); ++t)
            for (int i = 0; i < 4; ++i) d.tets.vertex(t)[i] = to[d.tets.vertex(t)[i]];
    });
    return to;
}

}  // namespace tubemesh::tets
