#pragma once
// Exact incidence between a segment and a triangle that may share nodes with it, for the
// criteria "new edges do not intersect visible elements" and "new triangles do not
// intersect visible edges". The answers are exact: decided by the exact predicates, or, where
// a segment leaves a shared node away from the triangle by far more than rounding, by that.
#include <array>

#include "engine/core/types.hpp"
#include "engine/mesh/vec3_ops.hpp"
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

// True only where orient3d(s, b, c, x) != 0: x lies off the plane of s, b, c by more than 1e-9
// of |b - s| |c - s| |x - s| (the determinant's own scale), decided in double. Its rounding
// error is below 1e-14 of that scale, so the computed sign is the exact one. False (undecided)
// otherwise, and where a squared length leaves [1e-150, 1e150], out of reach of underflow and
// overflow. The common case of the shared-node contact: a segment leaving a node of the
// triangle out of its plane.
inline bool surely_off_plane(const Vec3& s, const Vec3& b, const Vec3& c, const Vec3& x) {
    constexpr double kMargin2 = 1e-18, kLow = 1e-150, kHigh = 1e150;
    const Vec3 sb = b - s, sc = c - s, v = x - s;
    const double d = dot(cross(sb, sc), v);
    const double bb = norm2(sb), cc = norm2(sc), vv = norm2(v);
    const bool in_range = (bb >= kLow) & (bb <= kHigh) & (cc >= kLow) & (cc <= kHigh) & (vv >= kLow) & (vv <= kHigh);
    return in_range && d * d > kMargin2 * bb * cc * vv;
}

}  // namespace tubemesh::pyramids
