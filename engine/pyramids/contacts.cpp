#include "engine/pyramids/contacts.hpp"

#include "engine/mesh/vec3_ops.hpp"
#include "engine/predicates/predicates.hpp"

namespace tubemesh::pyramids {

namespace {

// Segment S-Q and triangle (S, B, C) share S and lie in one plane: do they meet beyond S?
// Exactly when the direction S->Q lies in the closed angle BSC. In-plane orientations are
// the signs of orient3d with a fourth point X off the plane: all of them are then measured
// against the same "up", so comparing them with the triangle's own sign is exact.
bool overlaps_beyond_shared(const Vec3& s, const Vec3& q, const Vec3& b, const Vec3& c, const Vec3& x) {
    const int t = predicates::orient3d(s, b, c, x);
    const int sbq = predicates::orient3d(s, b, q, x);
    const int sqc = predicates::orient3d(s, q, c, x);
    return sbq * t >= 0 && sqc * t >= 0;
}

// Direction s->q makes an obtuse angle with both sides of the proper triangle's angle at s,
// so it lies outside that angle: inside it, q - s = a (b - s) + c (c - s) with a, c >= 0, and
// both dot products negative would break Cauchy-Schwarz. Decided in floating point only with
// a margin (1e-9 relative) far above the rounding of these few operations; false (undecided)
// otherwise, and for a flat or tiny triangle, which the exact path refuses. On straight rings
// the ring's edges continue each other in a line, coplanar with the pyramids' lateral faces,
// and would each take the exact path.
bool leaves_angle(const Vec3& s, const Vec3& q, const Vec3& b, const Vec3& c) {
    const Vec3 v = q - s, sb = b - s, sc = c - s;
    const double vb = dot(v, sb), vc = dot(v, sc);
    if (!(vb < 0 && vc < 0)) return false;
    constexpr double kMargin2 = 1e-18;
    const double vv = norm2(v), bb = norm2(sb), cc = norm2(sc);
    return vb * vb > kMargin2 * vv * bb && vc * vc > kMargin2 * vv * cc && norm2(cross(sb, sc)) > kMargin2 * bb * cc;
}

}  // namespace

bool improper_contact(index_t ip, const Vec3& p, index_t iq, const Vec3& q, const std::array<index_t, 3>& it,
                      const std::array<const Vec3*, 3>& t, const NewPyramid& y) {
    auto corner_of = [&](index_t n) {
        if (n == kNoIndex) return -1;
        for (int k = 0; k < 3; ++k)
            if (n == it[k]) return k;
        return -1;
    };
    const int cp = corner_of(ip), cq = corner_of(iq);
    if (cp >= 0 && cq >= 0) return false;  // the segment is an edge of the triangle
    const Vec3 &ra = *t[0], &rb = *t[1], &rc = *t[2];
    if (cp < 0 && cq < 0) return predicates::segment_triangle(p, q, ra, rb, rc) != predicates::Contact::None;
    // Sharing one node, the segment meets the triangle's plane only there unless it lies in
    // that plane; then it meets the triangle elsewhere when it points into it.
    const int shared = cp >= 0 ? cp : cq;
    const Vec3& other = cp >= 0 ? q : p;
    const Vec3& s = *t[shared];
    const Vec3& b = *t[(shared + 1) % 3];
    const Vec3& c = *t[(shared + 2) % 3];
    if (leaves_angle(s, other, b, c)) return false;
    if (predicates::orient3d(ra, rb, rc, other) != 0) return false;
    for (const Vec3& x : y.p)
        if (predicates::orient3d(ra, rb, rc, x) != 0) return overlaps_beyond_shared(s, other, b, c, x);
    return true;  // a flat triangle: refuse
}

}  // namespace tubemesh::pyramids
