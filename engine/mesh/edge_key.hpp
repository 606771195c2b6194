#pragma once
// One key per undirected edge (a, b) of point ids, for sorting and hashing edges: the smaller
// id in the high 32 bits.
#include <cstdint>

#include "engine/core/types.hpp"

namespace tubemesh {

inline std::uint64_t edge_key(index_t a, index_t b) {
    return a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
}

}  // namespace tubemesh
