#pragma once
// What the smoothing's parallel moves stand on: the point -> tets incidence of a TetDomain and
// the greedy colouring of points in index order (no two points of one colour share a tet).
// Both are built in parallel over fixed chunks and give the same arrays as the serial loops
// they replaced, for any thread count (tests/tets_smoothing_test.cpp checks the colouring
// against the serial greedy).
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/core/uninit_vector.hpp"
#include "engine/tets/domain/tet_domain.hpp"

namespace tubemesh::tets {

// Point -> tets incidence as offsets + indices, tets in increasing order for every point.
struct Incidence {
    std::vector<index_t> offsets;
    UninitVector<index_t> tets;  // filled in parallel: no serial zeroing first
    std::span<const index_t> of(index_t p) const { return {tets.data() + offsets[p], offsets[p + 1] - offsets[p]}; }
};

// A counting sort of the vertex rows by point, over fixed chunks of the rows.
Incidence build_incidence(const TetDomain& dom);

// Greedy colouring of `points` (increasing) in that order: each point takes the smallest
// colour no point before it in `points` that shares a tet with it has. Returns the points of
// each colour, in increasing order. `colour` has one entry per point, kNoIndex on entry and
// again on return.
std::vector<std::vector<index_t>> colour_points(const TetDomain& dom, const Incidence& inc,
                                                std::span<const index_t> points,
                                                std::vector<std::uint32_t>& colour);

}  // namespace tubemesh::tets
