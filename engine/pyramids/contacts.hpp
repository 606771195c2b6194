#pragma once
// Exact incidence between a segment and a triangle that may share nodes with it, for the
// criteria "new edges do not intersect visible elements" and "new triangles do not
// intersect visible edges". The answers are exact: decided by the exact predicates, or, where
// a segment leaves a shared node away from the triangle by far more than rounding, by that.
#include <array>

#include "engine/core/types.hpp"
#include "engine/core/vec3_ops.hpp"
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

// The plane of a triangle (a, b, c), to tell points surely off it: surely_off(s, x) is true only
// where orient3d(a, b, c, x) != 0, for s a node of the triangle (so on the plane exactly): x
// lies off the plane by more than 1e-9 of |b - a| |c - a| |x - s| (the determinant's own
// scale), decided in double. The rounding error of the normal and of the dot product is below
// 1e-14 of that scale, so the computed sign is the exact one. False (undecided) otherwise, and
// where a squared length leaves [1e-150, 1e150], out of reach of underflow and overflow. Made
// once, it serves every segment leaving a node of the triangle: the common case of the
// shared-node contact, which then cannot happen.
class PlaneFilter {
public:
    PlaneFilter(const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 ab = b - a, ac = c - a;
        n_ = cross(ab, ac);
        const double bb = norm2(ab), cc = norm2(ac);
        usable_ = in_range(bb) && in_range(cc);
        k_ = kMargin2 * bb * cc;
    }
    bool surely_off(const Vec3& s, const Vec3& x) const {
        const Vec3 v = x - s;
        const double d = dot(n_, v), vv = norm2(v);
        return usable_ && in_range(vv) && d * d > k_ * vv;
    }

private:
    static constexpr double kMargin2 = 1e-18;
    static bool in_range(double l2) { return l2 >= 1e-150 && l2 <= 1e150; }
    Vec3 n_;
    double k_;
    bool usable_;
};

// x surely off the plane of s, b, c (orient3d(s, b, c, x) != 0), as PlaneFilter decides it.
inline bool surely_off_plane(const Vec3& s, const Vec3& b, const Vec3& c, const Vec3& x) {
    return PlaneFilter(s, b, c).surely_off(s, x);
}

}  // namespace tubemesh::pyramids
