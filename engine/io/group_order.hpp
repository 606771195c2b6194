#pragma once
// Elements of one block sorted by group (region or surface group) id, stably: writers emit
// one run per group without scanning the whole block once per group.
#include <cstddef>
#include <span>
#include <vector>

#include "engine/core/types.hpp"

namespace tubemesh::io {

struct GroupOrder {
    std::vector<index_t> order;      // element indices, grouped; mesh order within a group
    std::vector<std::size_t> start;  // group g owns order[start[g], start[g + 1])

    std::span<const index_t> group(std::size_t g) const {
        return std::span<const index_t>(order).subspan(start[g], start[g + 1] - start[g]);
    }
};

// Counting sort; every id must be < group_count (validate_layout() guarantees it).
inline GroupOrder order_by_group(const std::vector<index_t>& ids, std::size_t group_count) {
    GroupOrder g;
    g.start.assign(group_count + 1, 0);
    for (index_t id : ids) ++g.start[id + 1];
    for (std::size_t k = 0; k < group_count; ++k) g.start[k + 1] += g.start[k];
    g.order.resize(ids.size());
    std::vector<std::size_t> next(g.start.begin(), g.start.end() - 1);
    for (std::size_t i = 0; i < ids.size(); ++i) g.order[next[ids[i]]++] = static_cast<index_t>(i);
    return g;
}

}  // namespace tubemesh::io
