#pragma once
// Exact incidence between a segment and a triangle that may share nodes with it, for the
// criteria "new edges do not intersect visible elements" and "new triangles do not
// intersect visible edges". The answers are exact: decided by the exact predicates, or, where
// a segment leaves a shared node away from the triangle by far more than rounding, by that.
#include <array>

#include "engine/core/types.hpp"
#include "engine/pyramids/geometry.hpp"
#include "engine/pyramids/new_pyramid.hpp"

namespace tubemesh::pyramids {

// Segment pq against the closed triangle t (node ids it, points t), where meeting at a
// shared node is allowed: true when they meet anywhere else (touching included). Segment
// ends with id kNoIndex are new nodes and share nothing. `y`, the candidate pyramid, supplies
// a point off the triangle's plane for the coplanar case: it is not flat, so one of its
// nodes is off any plane.
bool improper_contact(index_t ip, const Vec3& p, index_t iq, const Vec3& q, const std::array<index_t, 3>& it,
                      const std::array<const Vec3*, 3>& t, const NewPyramid& y);

}  // namespace tubemesh::pyramids
