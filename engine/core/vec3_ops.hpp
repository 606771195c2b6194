#pragma once
// Arithmetic on the mesh store's Vec3 and the few distances several modules measure. One copy,
// inline: these run in inner loops. Measurements in double only; yes/no incidence questions go
// to the exact predicates (engine/predicates).
#include <algorithm>
#include <cmath>

#include "engine/core/vec3.hpp"

namespace tubemesh {

// The point at p[0..2] of an interleaved xyz array (the Delaunay and tet stores keep their
// points so, for the predicates).
inline Vec3 vec3_at(const double* p) { return {p[0], p[1], p[2]}; }

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec3 operator*(const Vec3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
// Divides each coordinate (not a multiplication by 1 / s: the last bit differs).
inline Vec3 operator/(const Vec3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }
inline Vec3& operator+=(Vec3& a, const Vec3& b) { return a = a + b; }
inline Vec3& operator-=(Vec3& a, const Vec3& b) { return a = a - b; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm2(const Vec3& a) { return dot(a, a); }
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline double distance2(const Vec3& a, const Vec3& b) { return norm2(a - b); }
// det[a b c] = a · (b × c): positive when (a, b, c) is right-handed.
inline double det3(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }
// a / |a|; a zero vector stays zero.
inline Vec3 normalized(const Vec3& a) {
    const double n2 = norm2(a);
    return n2 > 0 ? a / std::sqrt(n2) : a;
}
inline bool all_finite(const Vec3& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
// Per coordinate, as std::min and std::max (the box of a point set).
inline Vec3 min_each(const Vec3& a, const Vec3& b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
inline Vec3 max_each(const Vec3& a, const Vec3& b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }
// det[b - a, c - a, d - a] / 6 in plain double: positive for a tet in topology.hpp's order. A
// measure, not a decision (decisions use engine/predicates).
inline double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return dot(b - a, cross(c - a, d - a)) / 6;
}

// Squared distance between the closed segments p1q1 and p2q2 (Ericson, Real-Time Collision
// Detection 5.1.9), with the degenerate (point-like and parallel) cases handled by clamping.
inline double segment_segment_distance2(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
    const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = norm2(d1), e = norm2(d2), f = dot(d2, r);
    double s = 0, t = 0;
    if (a <= 0 && e <= 0) return norm2(r);
    if (a <= 0) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = dot(d1, r);
        if (e <= 0) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = dot(d1, d2);
            const double denom = a * e - b * b;
            s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1) {
                t = 1;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return distance2(p1 + s * d1, p2 + t * d2);
}

}  // namespace tubemesh
