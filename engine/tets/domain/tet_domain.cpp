#include "engine/tets/domain/tet_domain.hpp"

#include <algorithm>
#include <cstdint>

namespace tubemesh::tets {

RecoveredTets recovered_tets(const TetDomain& d) { return {d.tets.clone(), d.point_count()}; }

std::vector<index_t> drop_unused_points(TetDomain& d, index_t first) {
    const index_t n = d.point_count();
    std::vector<std::uint8_t> used(n, 0);
    for (index_t v : d.tets.vertices()) used[v] = 1;
    std::vector<index_t> to(n, kNoIndex);
    index_t next = first;
    for (index_t v = 0; v < first; ++v) to[v] = v;
    for (index_t v = first; v < n; ++v)
        if (used[v]) {
            to[v] = next;
            std::copy_n(d.xyz.begin() + 3 * std::size_t{v}, 3, d.xyz.begin() + 3 * std::size_t{next});
            ++next;
        }
    d.xyz.resize(3 * std::size_t{next});
    for (index_t t = 0; t < d.tets.size(); ++t)
        for (int i = 0; i < 4; ++i) d.tets.vertex(t)[i] = to[d.tets.vertex(t)[i]];
    return to;
}

}  // namespace tubemesh::tets
