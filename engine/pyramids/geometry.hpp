#pragma once
// The distances the suitability criteria measure (point-triangle here; segment-segment and
// the Vec3 arithmetic in engine/core/vec3_ops.hpp), plus axis-aligned boxes used to skip far-away pairs
// before any distance or exact test. Inline: they run in the innermost loops.
//
// These are *measurements* in double, compared against thresholds of the order of h: a
// rounding error of 1e-16 h cannot change an outcome that matters. Every yes/no question
// about incidence (does this edge cross that face?) goes to the exact predicates instead.
#include <algorithm>
#include <cmath>

#include "engine/core/vec3_ops.hpp"  // Vec3 arithmetic, segment_segment_distance2

namespace tubemesh::pyramids {

struct Box {
    Vec3 lo{}, hi{};

    static Box around(const Vec3& c, double r) { return {{c.x - r, c.y - r, c.z - r}, {c.x + r, c.y + r, c.z + r}}; }
    static Box of(const Vec3& a) { return {a, a}; }
    void add(const Vec3& p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    void add(const Box& b) {
        add(b.lo);
        add(b.hi);
    }
    // Without branches (& not &&): the inner loops test many boxes and half of them pass.
    bool overlaps(const Box& b) const {
        return (lo.x <= b.hi.x) & (b.lo.x <= hi.x) & (lo.y <= b.hi.y) & (b.lo.y <= hi.y) & (lo.z <= b.hi.z) &
               (b.lo.z <= hi.z);
    }
    Vec3 centre() const { return 0.5 * (lo + hi); }
    // p in the closed box: box_distance2(*this, p) == 0.
    bool contains(const Vec3& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
    }
};

// Squared distance between two boxes (0 when they overlap): a lower bound of the distance
// between anything inside them, so "box distance >= d" proves "distance >= d".
inline double box_distance2(const Box& a, const Box& b) {
    // The positive one of the two differences, or 0 where the intervals overlap (both <= 0);
    // as max operations, which the inner loops run without branches.
    auto gap = [](double alo, double ahi, double blo, double bhi) {
        return std::max(std::max(alo - bhi, blo - ahi), 0.0);
    };
    const double dx = gap(a.lo.x, a.hi.x, b.lo.x, b.hi.x);
    const double dy = gap(a.lo.y, a.hi.y, b.lo.y, b.hi.y);
    const double dz = gap(a.lo.z, a.hi.z, b.lo.z, b.hi.z);
    return dx * dx + dy * dy + dz * dz;
}

inline double box_distance2(const Box& a, const Vec3& p) { return box_distance2(a, Box::of(p)); }

// The point of the closed triangle abc nearest to p (Ericson, Real-Time Collision Detection,
// 5.1.5: Voronoi regions of the vertices, edges and face). A degenerate triangle falls
// through to its edges, which is the right answer.
inline Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double denom = va + vb + vc;
    if (!(denom > 0)) {  // degenerate (collinear) triangle: nearest point of its three edges
        auto seg = [&](const Vec3& s, const Vec3& e) {
            const Vec3 d = e - s;
            const double l2 = norm2(d);
            return s + (l2 > 0 ? std::clamp(dot(p - s, d) / l2, 0.0, 1.0) : 0.0) * d;
        };
        const Vec3 q[3] = {seg(a, b), seg(b, c), seg(c, a)};
        int best = 0;
        for (int k = 1; k < 3; ++k)
            if (distance2(p, q[k]) < distance2(p, q[best])) best = k;
        return q[best];
    }
    return a + (vb / denom) * ab + (vc / denom) * ac;
}

// Squared distance from p to the closed triangle abc.
inline double point_triangle_distance2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    return distance2(p, closest_point_on_triangle(p, a, b, c));
}

}  // namespace tubemesh::pyramids
