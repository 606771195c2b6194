#pragma once
// Two Vec3 at once, one per SSE2 lane, with vec3_ops.hpp's operations in the same order: each
// lane gives the bits vec3_ops gives (no fused multiply-add, no reassociation), so a hot loop
// can evaluate two elements at a time and still decide exactly as the scalar code.
// TUBEMESH_VEC3_PAIR is 1 where SSE2 is available (every x86-64), 0 elsewhere: callers keep
// their scalar loop for that case.
#if defined(__SSE2__)
#define TUBEMESH_VEC3_PAIR 1
#include <emmintrin.h>

#include "engine/core/vec3.hpp"

namespace tubemesh {

struct Vec3Pair {
    __m128d x, y, z;
};

// Lane 0 from a, lane 1 from b.
inline __m128d pair_of(double a, double b) { return _mm_set_pd(b, a); }
inline Vec3Pair pair_of(const Vec3& a, const Vec3& b) { return {pair_of(a.x, b.x), pair_of(a.y, b.y), pair_of(a.z, b.z)}; }
inline Vec3Pair broadcast(const Vec3& a) { return {_mm_set1_pd(a.x), _mm_set1_pd(a.y), _mm_set1_pd(a.z)}; }
inline double lane(__m128d v, int i) {
    alignas(16) double out[2];
    _mm_store_pd(out, v);
    return out[i];
}
inline Vec3 lane(const Vec3Pair& v, int i) { return {lane(v.x, i), lane(v.y, i), lane(v.z, i)}; }

inline Vec3Pair operator+(const Vec3Pair& a, const Vec3Pair& b) {
    return {_mm_add_pd(a.x, b.x), _mm_add_pd(a.y, b.y), _mm_add_pd(a.z, b.z)};
}
inline Vec3Pair operator-(const Vec3Pair& a, const Vec3Pair& b) {
    return {_mm_sub_pd(a.x, b.x), _mm_sub_pd(a.y, b.y), _mm_sub_pd(a.z, b.z)};
}
inline Vec3Pair operator*(__m128d s, const Vec3Pair& a) { return {_mm_mul_pd(s, a.x), _mm_mul_pd(s, a.y), _mm_mul_pd(s, a.z)}; }
inline __m128d dot(const Vec3Pair& a, const Vec3Pair& b) {
    return _mm_add_pd(_mm_add_pd(_mm_mul_pd(a.x, b.x), _mm_mul_pd(a.y, b.y)), _mm_mul_pd(a.z, b.z));
}
inline Vec3Pair cross(const Vec3Pair& a, const Vec3Pair& b) {
    return {_mm_sub_pd(_mm_mul_pd(a.y, b.z), _mm_mul_pd(a.z, b.y)), _mm_sub_pd(_mm_mul_pd(a.z, b.x), _mm_mul_pd(a.x, b.z)),
            _mm_sub_pd(_mm_mul_pd(a.x, b.y), _mm_mul_pd(a.y, b.x))};
}
inline __m128d norm2(const Vec3Pair& a) { return dot(a, a); }

}  // namespace tubemesh
#else
#define TUBEMESH_VEC3_PAIR 0
#endif
