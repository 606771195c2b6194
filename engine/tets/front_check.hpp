#pragma once
// Checks that a tet front is a closed, manifold, consistently oriented triangle surface before
// recovery starts, so a bad front fails with a message naming the triangles at fault instead
// of a recovery that cannot succeed. (Self-intersections show up during recovery, as front
// elements that cross.)
#include <span>
#include <utility>
#include <vector>

#include "engine/core/types.hpp"

namespace tubemesh::tets {

// Throws tubemesh::Error when a triangle repeats a point or names a point >= point_count,
// when an edge belongs to one triangle (open front) or to more than two (non-manifold), when
// two triangles run along their common edge in the same direction (inconsistent orientation),
// or when two triangles have the same three points. Returns the front's edges (u < v), sorted.
std::vector<std::pair<index_t, index_t>> check_front(std::span<const index_t> front, index_t point_count);

}  // namespace tubemesh::tets
