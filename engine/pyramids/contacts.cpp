#include "engine/pyramids/contacts.hpp"

#include "engine/predicates/predicates.hpp"

namespace tubemesh::pyramids {

namespace {

using P3 = std::array<double, 3>;

P3 raw(const Vec3& v) { return {v.x, v.y, v.z}; }

// Segment S-Q and triangle (S, B, C) share S and lie in one plane: do they meet beyond S?
// Exactly when the direction S->Q lies in the closed angle BSC. In-plane orientations are
// the signs of orient3d with a fourth point X off the plane: all of them are then measured
// against the same "up", so comparing them with the triangle's own sign is exact.
bool overlaps_beyond_shared(const P3& s, const P3& q, const P3& b, const P3& c, const P3& x) {
    const int t = predicates::orient3d(s.data(), b.data(), c.data(), x.data());
    const int sbq = predicates::orient3d(s.data(), b.data(), q.data(), x.data());
    const int sqc = predicates::orient3d(s.data(), q.data(), c.data(), x.data());
    return sbq * t >= 0 && sqc * t >= 0;
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
    const P3 rp = raw(p), rq = raw(q), ra = raw(*t[0]), rb = raw(*t[1]), rc = raw(*t[2]);
    if (cp < 0 && cq < 0)
        return predicates::segment_triangle(rp.data(), rq.data(), ra.data(), rb.data(), rc.data()) !=
               predicates::Contact::None;
    // Sharing one node, the segment meets the triangle's plane only there unless it lies in
    // that plane; then it meets the triangle elsewhere when it points into it.
    const int shared = cp >= 0 ? cp : cq;
    const P3& other = cp >= 0 ? rq : rp;
    if (predicates::orient3d(ra.data(), rb.data(), rc.data(), other.data()) != 0) return false;
    const std::array<const P3*, 3> r{&ra, &rb, &rc};
    const P3& s = *r[shared];
    const P3& b = *r[(shared + 1) % 3];
    const P3& c = *r[(shared + 2) % 3];
    for (const Vec3& v : y.p) {
        const P3 x = raw(v);
        if (predicates::orient3d(ra.data(), rb.data(), rc.data(), x.data()) != 0)
            return overlaps_beyond_shared(s, other, b, c, x);
    }
    return true;  // a flat triangle: refuse
}

}  // namespace tubemesh::pyramids
