#pragma once
// Four Vec3 at once, one per AVX lane, with vec3_ops.hpp's operations in the same order: as
// vec3_pair.hpp, each lane gives the bits vec3_ops gives (AVX has no fused multiply-add). The
// build does not assume AVX: every function here carries the target itself, and a caller (also
// marked TUBEMESH_AVX) runs only where has_avx() says so. TUBEMESH_VEC3_QUAD is 0 off x86-64.
#if defined(__x86_64__) && defined(__GNUC__)
#define TUBEMESH_VEC3_QUAD 1
#include <immintrin.h>

#include "engine/core/vec3.hpp"

#define TUBEMESH_AVX [[gnu::target("avx")]]

namespace tubemesh {

inline bool has_avx() {
    static const bool avx = __builtin_cpu_supports("avx");
    return avx;
}

struct Vec3Quad {
    __m256d x, y, z;
};

// Lane i from p[i].
TUBEMESH_AVX inline Vec3Quad quad_of(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return {_mm256_set_pd(d.x, c.x, b.x, a.x), _mm256_set_pd(d.y, c.y, b.y, a.y), _mm256_set_pd(d.z, c.z, b.z, a.z)};
}
TUBEMESH_AVX inline double lane(__m256d v, int i) {
    alignas(32) double out[4];
    _mm256_store_pd(out, v);
    return out[i];
}
TUBEMESH_AVX inline Vec3 lane(const Vec3Quad& v, int i) { return {lane(v.x, i), lane(v.y, i), lane(v.z, i)}; }

TUBEMESH_AVX inline Vec3Quad operator+(const Vec3Quad& a, const Vec3Quad& b) {
    return {_mm256_add_pd(a.x, b.x), _mm256_add_pd(a.y, b.y), _mm256_add_pd(a.z, b.z)};
}
TUBEMESH_AVX inline Vec3Quad operator-(const Vec3Quad& a, const Vec3Quad& b) {
    return {_mm256_sub_pd(a.x, b.x), _mm256_sub_pd(a.y, b.y), _mm256_sub_pd(a.z, b.z)};
}
TUBEMESH_AVX inline Vec3Quad operator*(__m256d s, const Vec3Quad& a) {
    return {_mm256_mul_pd(s, a.x), _mm256_mul_pd(s, a.y), _mm256_mul_pd(s, a.z)};
}
TUBEMESH_AVX inline __m256d dot(const Vec3Quad& a, const Vec3Quad& b) {
    return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a.x, b.x), _mm256_mul_pd(a.y, b.y)), _mm256_mul_pd(a.z, b.z));
}
TUBEMESH_AVX inline Vec3Quad cross(const Vec3Quad& a, const Vec3Quad& b) {
    return {_mm256_sub_pd(_mm256_mul_pd(a.y, b.z), _mm256_mul_pd(a.z, b.y)),
            _mm256_sub_pd(_mm256_mul_pd(a.z, b.x), _mm256_mul_pd(a.x, b.z)),
            _mm256_sub_pd(_mm256_mul_pd(a.x, b.y), _mm256_mul_pd(a.y, b.x))};
}
TUBEMESH_AVX inline __m256d norm2(const Vec3Quad& a) { return dot(a, a); }

}  // namespace tubemesh
#else
#define TUBEMESH_VEC3_QUAD 0
#endif
