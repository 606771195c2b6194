#pragma once
// Node tag -> point index for the MSH reader. Gmsh's tags are usually dense (a direct table),
// but any positive 64-bit tags are legal; sparse ones fall back to binary search.
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "engine/core/types.hpp"

namespace tubemesh::io {

class NodeTagMap {
public:
    // `sorted_tags`: ascending and distinct; point i has tag sorted_tags[i].
    explicit NodeTagMap(std::vector<std::uint64_t> sorted_tags) : tags_(std::move(sorted_tags)) {
        const std::uint64_t n = tags_.size();
        // A table no bigger than a few times the node count: the tags come from the file,
        // so their size must not decide the allocation on their own.
        if (!tags_.empty() && tags_.back() <= 4 * n + 1024) {
            table_.assign(tags_.back() + 1, kNoIndex);
            for (std::size_t i = 0; i < tags_.size(); ++i) table_[tags_[i]] = static_cast<index_t>(i);
            tags_.clear();
            tags_.shrink_to_fit();
        }
    }

    // kNoIndex when no node has this tag.
    index_t find(std::uint64_t tag) const {
        if (!table_.empty()) return tag < table_.size() ? table_[tag] : kNoIndex;
        const auto it = std::lower_bound(tags_.begin(), tags_.end(), tag);
        return it != tags_.end() && *it == tag ? static_cast<index_t>(it - tags_.begin()) : kNoIndex;
    }

private:
    std::vector<std::uint64_t> tags_;
    std::vector<index_t> table_;
};

}  // namespace tubemesh::io
