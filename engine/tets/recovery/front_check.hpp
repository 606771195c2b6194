#pragma once
// Checks that a tet front is a closed, manifold, consistently oriented triangle surface before
// recovery starts, so a bad front fails with a message naming the triangles at fault instead
// of a recovery that cannot succeed. (Self-intersections show up during recovery, as front
// elements that cross.)
#include <array>
#include <span>
#include <utility>
#include <vector>

#include "engine/core/types.hpp"

namespace tubemesh::tets {

// The front's edges (u < v) and triangles (point ids in increasing order), each sorted: the
// recovery looks them up (FrontLocks) without building sets of its own.
struct FrontElements {
    std::vector<std::pair<index_t, index_t>> edges;
    std::vector<std::array<index_t, 3>> triangles;
};

// Throws tubemesh::Error when a triangle repeats a point or names a point >= point_count,
// when an edge belongs to one triangle (open front) or to more than two (non-manifold), when
// two triangles run along their common edge in the same direction (inconsistent orientation),
// or when two triangles have the same three points. The sorts run in parallel; every key is
// distinct, so the result and the error reported do not depend on the thread count.
FrontElements check_front(std::span<const index_t> front, index_t point_count);

}  // namespace tubemesh::tets
