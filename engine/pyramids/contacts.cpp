#include "engine/pyramids/contacts.hpp"

#include <algorithm>

#include "engine/core/vec3_ops.hpp"
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

// The closed triangle abc and the segment pq lie on two sides of a plane, the triangle's own or
// one through an edge perpendicular to it, the segment farther from it than 1e-9 of the scene's
// size (the largest distance from a): so they do not meet. Rounding in these few operations is
// below 1e-14 of that size, so the computed planes separate them as the exact ones would. False
// when undecided, as always for a flat triangle. It spares segment_triangle the exact path for
// the ring edges that continue a pyramid's base edges in a line, in its lateral faces' planes.
bool separated(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
    constexpr double kMargin2 = 1e-18;
    const Vec3 ab = b - a, ac = c - a;
    const Vec3 n = cross(ab, ac);
    const double nn = norm2(n);
    if (!(nn > kMargin2 * norm2(ab) * norm2(ac))) return false;
    const double scale2 = std::max(std::max(norm2(p - a), norm2(q - a)), std::max(norm2(ab), norm2(ac)));
    // p and q strictly on the side of the plane through u with normal m that m points away from.
    const auto behind = [&](const Vec3& u, const Vec3& m) {
        const double sp = dot(p - u, m), sq = dot(q - u, m), limit = kMargin2 * scale2 * norm2(m);
        return sp < 0 && sq < 0 && sp * sp > limit && sq * sq > limit;
    };
    if (behind(a, n) || behind(a, -1.0 * n)) return true;
    // n x (edge) points into the triangle from each edge (n = ab x ac: the triangle turns about n).
    return behind(a, cross(n, ab)) || behind(b, cross(n, c - b)) || behind(c, cross(n, a - c));
}

// The segment shares no node with the triangle.
[[gnu::noinline]] bool contact_unshared(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
    return !separated(p, q, a, b, c) && predicates::segment_triangle(p, q, a, b, c) != predicates::Contact::None;
}

// The segment s-other shares node s with the closed triangle (s, b, c), not known to leave its
// plane: it meets the triangle elsewhere exactly when it lies in that plane and points into it.
[[gnu::noinline]] bool contact_beyond_shared(const Vec3& s, const Vec3& other, const Vec3& b, const Vec3& c,
                                             const NewPyramid& y) {
    if (leaves_angle(s, other, b, c)) return false;
    if (predicates::orient3d(s, b, c, other) != 0) return false;
    for (const Vec3& x : y.p)
        if (predicates::orient3d(s, b, c, x) != 0) return overlaps_beyond_shared(s, other, b, c, x);
    return true;  // a flat triangle: refuse
}

int corner_of(index_t n, const std::array<index_t, 3>& it) {
    if (n == kNoIndex) return -1;
    return n == it[0] ? 0 : n == it[1] ? 1 : n == it[2] ? 2 : -1;
}

}  // namespace

bool improper_contact(index_t ip, const Vec3& p, index_t iq, const Vec3& q, const std::array<index_t, 3>& it,
                      const std::array<const Vec3*, 3>& t, const NewPyramid& y) {
    const int cp = corner_of(ip, it), cq = corner_of(iq, it);
    if (cp >= 0 && cq >= 0) return false;  // the segment is an edge of the triangle
    if (cp < 0 && cq < 0) return contact_unshared(p, q, *t[0], *t[1], *t[2]);
    // Sharing one node, the segment meets the triangle's plane only there unless it lies in
    // that plane; then it meets the triangle elsewhere when it points into it. (s, b, c) is the
    // triangle turned to start at the shared node: the same orientation.
    const int shared = cp >= 0 ? cp : cq;
    const Vec3& other = cp >= 0 ? q : p;
    const Vec3& s = *t[shared];
    const Vec3& b = *t[shared == 2 ? 0 : shared + 1];
    const Vec3& c = *t[shared == 0 ? 2 : shared - 1];
    if (surely_off_plane(s, b, c, other)) return false;
    return contact_beyond_shared(s, other, b, c, y);
}

}  // namespace tubemesh::pyramids
