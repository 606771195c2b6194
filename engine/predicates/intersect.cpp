// Segment/triangle and triangle/triangle contact, decided with orient3d and, for coplanar
// configurations, orient2d in a coordinate plane.
//
// Coplanar pieces are projected by dropping one coordinate. That is exact (no arithmetic) and
// preserves every intersection as long as the common plane is not parallel to the dropped axis,
// i.e. the plane's normal has a nonzero component there; orient2d of three points of the plane
// in that coordinate plane is exactly that component's sign, so the choice is exact too.
#include <cmath>
#include <utility>

#include "engine/predicates/exact.hpp"
#include "engine/predicates/predicates.hpp"

namespace tubemesh::predicates {

namespace {

using detail::orient2d;

// A coordinate plane (i, j) = all axes but one.
struct Plane2 {
    int i = 0, j = 1;
};

constexpr Plane2 kPlanes[3] = {{0, 1}, {1, 2}, {2, 0}};

// The coordinate plane in which the triangle projects without degenerating; false for a
// degenerate (collinear) triangle, whose normal is exactly zero.
bool triangle_plane(const double* a, const double* b, const double* c, Plane2& plane) {
    for (const Plane2& p : kPlanes)
        if (orient2d(a, b, c, p.i, p.j) != 0) {
            plane = p;
            return true;
        }
    return false;
}

// A coordinate plane onto which a known coplanar (or collinear) point set projects one-to-one.
Plane2 common_plane(const double* const* pts, int n) {
    Plane2 plane;
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
            for (int c = b + 1; c < n; ++c)
                if (triangle_plane(pts[a], pts[b], pts[c], plane)) return plane;
    // Collinear: keep an axis along which the points differ, so the line does not project to a point.
    for (int k = 0; k < 3; ++k)
        for (int a = 1; a < n; ++a)
            if (pts[a][k] != pts[0][k]) return {k, (k + 1) % 3};
    return plane;  // all points coincide
}

// Closed segments pq and rs, collinear or not, in the plane (i, j).
bool segments_meet_2d(const double* p, const double* q, const double* r, const double* s, Plane2 pl) {
    const int o1 = orient2d(p, q, r, pl.i, pl.j), o2 = orient2d(p, q, s, pl.i, pl.j);
    const int o3 = orient2d(r, s, p, pl.i, pl.j), o4 = orient2d(r, s, q, pl.i, pl.j);
    if (o1 * o2 > 0 || o3 * o4 > 0) return false;
    if (o1 != 0 || o2 != 0 || o3 != 0 || o4 != 0) return true;
    // All on one line: they meet iff their extents overlap along both axes (along the axis the
    // line is not perpendicular to, that is equivalent to overlapping on the line).
    for (int k : {pl.i, pl.j}) {
        if (std::fmax(p[k], q[k]) < std::fmin(r[k], s[k])) return false;
        if (std::fmax(r[k], s[k]) < std::fmin(p[k], q[k])) return false;
    }
    return true;
}

// x in the closed triangle abc, which is not degenerate in the plane.
bool point_in_triangle_2d(const double* x, const double* a, const double* b, const double* c, Plane2 pl) {
    const int o = orient2d(a, b, c, pl.i, pl.j);
    return orient2d(a, b, x, pl.i, pl.j) * o >= 0 && orient2d(b, c, x, pl.i, pl.j) * o >= 0 &&
           orient2d(c, a, x, pl.i, pl.j) * o >= 0;
}

// Whether the closed convex hulls of u[0..nu) and v[0..nv) (1 to 3 points each, possibly
// degenerate) meet in the plane: some pair of sides meets, or one hull holds a vertex of the
// other (the only way to meet without sides crossing is containment).
bool hulls_meet_2d(const double* const* u, int nu, const double* const* v, int nv, Plane2 pl) {
    auto side = [](const double* const* w, int n, int k, const double*& s0, const double*& s1) {
        s0 = w[k];
        s1 = w[(k + 1) % n];
    };
    const int su = nu == 3 ? 3 : 1, sv = nv == 3 ? 3 : 1;  // a point or a segment is its own side
    for (int k = 0; k < su; ++k)
        for (int l = 0; l < sv; ++l) {
            const double *p = nullptr, *q = nullptr, *r = nullptr, *s = nullptr;
            side(u, nu, k, p, q);
            side(v, nv, l, r, s);
            if (segments_meet_2d(p, q, r, s, pl)) return true;
        }
    if (nu == 3 && orient2d(u[0], u[1], u[2], pl.i, pl.j) != 0 && point_in_triangle_2d(v[0], u[0], u[1], u[2], pl))
        return true;
    if (nv == 3 && orient2d(v[0], v[1], v[2], pl.i, pl.j) != 0 && point_in_triangle_2d(u[0], v[0], v[1], v[2], pl))
        return true;
    return false;
}

// The two extreme points of a collinear triple (a degenerate triangle's hull).
void collinear_extent(const double* a, const double* b, const double* c, const double*& lo, const double*& hi) {
    const double* pts[3] = {a, b, c};
    lo = hi = a;
    for (int k = 0; k < 3; ++k) {
        if (a[k] == b[k] && a[k] == c[k]) continue;
        for (const double* p : pts) {
            if (p[k] < lo[k]) lo = p;
            if (p[k] > hi[k]) hi = p;
        }
        return;  // along a line, the order on one varying axis is the order on the line
    }
}

// Segment pq against a degenerate triangle abc (a segment or a point): Touching or None.
Contact segment_degenerate_triangle(const double* p, const double* q, const double* a, const double* b,
                                    const double* c) {
    if (orient3d(p, q, a, b) != 0 || orient3d(p, q, b, c) != 0 || orient3d(p, q, a, c) != 0) return Contact::None;
    const double* all[5] = {p, q, a, b, c};
    const double* seg[2] = {p, q};
    const double* tri[3] = {a, b, c};
    return hulls_meet_2d(seg, 2, tri, 3, common_plane(all, 5)) ? Contact::Touching : Contact::None;
}

// A proper crossing of the plane has vertices strictly on both sides.
bool straddles(int s0, int s1, int s2) {
    return (s0 > 0 || s1 > 0 || s2 > 0) && (s0 < 0 || s1 < 0 || s2 < 0);
}

// Index of a vertex strictly on its side alone (the others on the opposite side or on the plane).
int lone_vertex(const int* s) {
    for (int k = 0; k < 3; ++k)
        if (s[k] != 0 && s[(k + 1) % 3] != s[k] && s[(k + 2) % 3] != s[k]) return k;
    return -1;
}

}  // namespace

Contact segment_triangle(const double* p, const double* q, const double* a, const double* b, const double* c) {
    Plane2 plane;
    if (!triangle_plane(a, b, c, plane)) return segment_degenerate_triangle(p, q, a, b, c);
    const int sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
    if (sp * sq > 0) return Contact::None;
    const double* tri[3] = {a, b, c};
    if (sp == 0 && sq == 0) {
        const double* seg[2] = {p, q};
        return hulls_meet_2d(seg, 2, tri, 3, plane) ? Contact::Touching : Contact::None;
    }
    if (sp == 0 || sq == 0) {  // one endpoint on the plane: the only candidate contact
        const double* on_plane[1] = {sp == 0 ? p : q};
        return hulls_meet_2d(on_plane, 1, tri, 3, plane) ? Contact::Touching : Contact::None;
    }
    // pq crosses the plane at an interior point X; the line pq passes through the triangle iff
    // it sees the three edges turning the same way, and through an edge or vertex on a zero.
    const int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
    if ((s1 > 0 || s2 > 0 || s3 > 0) && (s1 < 0 || s2 < 0 || s3 < 0)) return Contact::None;
    return s1 != 0 && s2 != 0 && s3 != 0 ? Contact::Crossing : Contact::Touching;
}

// Non-coplanar triangles that both cross each other's plane properly meet on the line L where
// the planes cross, in two intervals: T1's from edge ab to edge ac, T2's from de to df, once
// each is rotated so that a (d) is alone on its side and a (d) is on the positive side of the
// other plane. With t measured along n1 x n2 (n1 = (b-a)x(c-a), n2 = (e-d)x(f-d)), the sign of
// t(X_dy) - t(X_ax) for x in {b, c}, y in {e, f} is orient3d(a, x, d, y): the tet (a, x, d, y)
// has volume (Y - X) . ((y-d) x (x-a)) for any X on line ax and Y on line dy, and
// (n1 x n2) . ((y-d) x (x-a)) = (n1 . (y-d)) (n2 . (x-a)) > 0 in this configuration. The same
// identities give t(X_ac) < t(X_ab) and t(X_de) < t(X_df). The relative interiors of the
// intervals lie in the triangles' interiors, so: overlap of open intervals = Crossing, of
// closed intervals only = Touching.
Contact triangle_triangle(const double* a, const double* b, const double* c, const double* d, const double* e,
                          const double* f) {
    Plane2 plane1, plane2;
    const bool flat1 = !triangle_plane(a, b, c, plane1), flat2 = !triangle_plane(d, e, f, plane2);
    if (flat1 || flat2) {
        // A degenerate triangle is a segment or a point with no interior: contact is Touching.
        const double *lo = nullptr, *hi = nullptr;
        if (flat1) {
            collinear_extent(a, b, c, lo, hi);
            return segment_triangle(lo, hi, d, e, f) == Contact::None ? Contact::None : Contact::Touching;
        }
        collinear_extent(d, e, f, lo, hi);
        return segment_triangle(lo, hi, a, b, c) == Contact::None ? Contact::None : Contact::Touching;
    }
    int s2[3] = {orient3d(a, b, c, d), orient3d(a, b, c, e), orient3d(a, b, c, f)};  // T2 against plane 1
    if (s2[0] * s2[1] > 0 && s2[1] * s2[2] > 0) return Contact::None;
    int s1[3] = {orient3d(d, e, f, a), orient3d(d, e, f, b), orient3d(d, e, f, c)};  // T1 against plane 2
    if (s1[0] * s1[1] > 0 && s1[1] * s1[2] > 0) return Contact::None;
    const double* t1[3] = {a, b, c};
    const double* t2[3] = {d, e, f};
    if (s2[0] == 0 && s2[1] == 0 && s2[2] == 0)
        return hulls_meet_2d(t1, 3, t2, 3, plane1) ? Contact::Touching : Contact::None;
    // A triangle that only touches the other's plane meets it in its vertices on that plane.
    if (!straddles(s1[0], s1[1], s1[2]) || !straddles(s2[0], s2[1], s2[2])) {
        const bool first = !straddles(s1[0], s1[1], s1[2]);
        const int* s = first ? s1 : s2;
        const double* const* touching = first ? t1 : t2;
        const double* on_plane[3];  // 1 or 2 used; sized 3 so the compiler sees every access in bounds
        int n = 0;
        for (int k = 0; k < 3; ++k)
            if (s[k] == 0) on_plane[n++] = touching[k];
        return hulls_meet_2d(on_plane, n, first ? t2 : t1, 3, first ? plane2 : plane1) ? Contact::Touching
                                                                                      : Contact::None;
    }
    // Canonical form. Rotations keep each triangle's orientation; swapping two vertices of one
    // triangle negates the signs of the other triangle's vertices against its plane.
    int k = lone_vertex(s1);
    const double* A = t1[k];
    const double* B = t1[(k + 1) % 3];
    const double* C = t1[(k + 2) % 3];
    int l = lone_vertex(s2);
    const double* D = t2[l];
    const double* E = t2[(l + 1) % 3];
    const double* F = t2[(l + 2) % 3];
    if (s1[k] < 0) std::swap(E, F);
    if (s2[l] < 0) std::swap(B, C);
    const int left = orient3d(A, B, D, E);   // sign of t(X_de) - t(X_ab): T2's start against T1's end
    const int right = orient3d(A, C, D, F);  // sign of t(X_df) - t(X_ac): T2's end against T1's start
    if (left < 0 && right > 0) return Contact::Crossing;
    if (left <= 0 && right >= 0) return Contact::Touching;
    return Contact::None;
}

}  // namespace tubemesh::predicates
