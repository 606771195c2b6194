#include "engine/pyramids/batches.hpp"

#include <algorithm>

namespace tubemesh::pyramids {

void Batcher::colour(std::span<const index_t> order, const Adjacency& neighbours, Adjacency& out) {
    index_t colours = 0;
    for (index_t i : order) {
        for (index_t j : neighbours.row(i))
            if (colour_[j] != kNoIndex) seen_[colour_[j]] = i;
        index_t c = 0;
        while (c < colours && seen_[c] == i) ++c;
        if (c == colours) {
            ++colours;
            seen_.resize(std::max<std::size_t>(seen_.size(), colours), kNoIndex);
            seen_[c] = kNoIndex;
        }
        colour_[i] = c;
    }
    // Counting sort by colour keeps each batch in the pass's order.
    out.offset.assign(colours + 1, 0);
    for (index_t i : order) ++out.offset[colour_[i] + 1];
    for (index_t c = 0; c < colours; ++c) out.offset[c + 1] += out.offset[c];
    out.items.resize(order.size());
    std::vector<std::size_t> next(out.offset.begin(), out.offset.end() - 1);
    for (index_t i : order) out.items[next[colour_[i]]++] = i;
    for (index_t i : order) colour_[i] = kNoIndex;
}

}  // namespace tubemesh::pyramids
