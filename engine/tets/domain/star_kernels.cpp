#include "engine/tets/domain/star_kernels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "engine/core/vec3_ops.hpp"
#include "engine/core/vec3_pair.hpp"
#include "engine/core/vec3_quad.hpp"
#include "engine/predicates/predicates_inline.hpp"
#include "engine/quality/quality.hpp"
#include "engine/tets/domain/tet_neighbourhood.hpp"

namespace tubemesh::tets {

namespace {

// A tet's collapse is 3V / A^(3/2) over the regular tet's, A its largest face area, so
// d ln q = d(3V) / 3V - 1.5 dA / A; only the faces through p have areas that move.

// The first of the four faces (kTetFaceToward order) with the largest area of star tet k, and
// the face opposite p (where p is a corner of the largest face, u and w are its other two).
struct LargestFace {
    int face = 0, u = -1, w = -1;
};
LargestFace with_corners(const StarCorners& star, std::size_t k, int largest) {
    LargestFace l{largest};
    const int lp = star.at[k];
    if (largest != lp)
        for (int i : kTetFaceToward[largest])
            if (i != lp) (l.u < 0 ? l.u : l.w) = i;
    return l;
}

// d ln q / dp of star tet k.
Vec3 log_collapse_gradient(const StarCorners& star, std::size_t k_star) {
    const int lp = star.at[k_star];
    const std::array<Vec3, 4>& c = star.corners[k_star];
    const auto& f = kTetFaceToward[lp];
    const Vec3& opposite = star.opposite[k_star].n;  // toward p
    const double three_volume = 0.5 * dot(c[lp] - c[f[0]], opposite);
    // The largest face and its area (the face opposite p's is known).
    int largest = 0;
    double area2 = -1;
    for (int k = 0; k < 4; ++k) {
        const auto& h = kTetFaceToward[k];
        const double a2 = k == lp ? star.opposite[k_star].area4 : norm2(cross(c[h[1]] - c[h[0]], c[h[2]] - c[h[0]]));
        if (a2 > area2) {
            area2 = a2;
            largest = k;
        }
    }
    Vec3 d_ln = (0.5 / three_volume) * opposite;
    if (largest != lp) {
        // p is a corner (c[lp], u, w) of the largest face: dA/dp = (u - w) x n / 2, n the
        // face's unit normal.
        const LargestFace l = with_corners(star, k_star, largest);
        const Vec3 n = cross(c[l.u] - c[lp], c[l.w] - c[lp]);
        const double len = norm(n);
        if (len > 0) {
            const double area = 0.5 * len;
            d_ln = d_ln - (1.5 / area) * (0.5 / len) * cross(c[l.u] - c[l.w], n);
        }
    }
    return d_ln;
}

#if TUBEMESH_VEC3_PAIR
// log_collapse_gradient of star tets k and k + 1, one per lane: the same operations in the same
// order (the face opposite p is computed as the others are, which gives its stored area).
void log_collapse_gradient_pair(const StarCorners& star, std::size_t k, Vec3 out[2]) {
    const auto& c0 = star.corners[k];
    const auto& c1 = star.corners[k + 1];
    const int lp[2] = {star.at[k], star.at[k + 1]};
    const auto corner = [&](int i0, int i1) { return pair_of(c0[i0], c1[i1]); };
    const Vec3Pair at_p = corner(lp[0], lp[1]);
    const Vec3Pair opposite = pair_of(star.opposite[k].n, star.opposite[k + 1].n);
    const __m128d three_volume = _mm_mul_pd(
        _mm_set1_pd(0.5), dot(at_p - corner(kTetFaceToward[lp[0]][0], kTetFaceToward[lp[1]][0]), opposite));
    // The first strict maximum from -1, as the scalar loop keeps it.
    __m128d area2 = _mm_set1_pd(-1), largest = _mm_setzero_pd();
    for (int f = 0; f < 4; ++f) {
        const auto& h = kTetFaceToward[f];
        const Vec3Pair a = corner(h[0], h[0]);
        const __m128d a2 = norm2(cross(corner(h[1], h[1]) - a, corner(h[2], h[2]) - a));
        const __m128d larger = _mm_cmpgt_pd(a2, area2);
        area2 = _mm_or_pd(_mm_and_pd(larger, a2), _mm_andnot_pd(larger, area2));
        largest = _mm_or_pd(_mm_and_pd(larger, _mm_set1_pd(f)), _mm_andnot_pd(larger, largest));
    }
    const Vec3Pair d_ln = _mm_div_pd(_mm_set1_pd(0.5), three_volume) * opposite;
    const LargestFace l[2] = {with_corners(star, k, static_cast<int>(lane(largest, 0))),
                              with_corners(star, k + 1, static_cast<int>(lane(largest, 1)))};
    const bool moves[2] = {l[0].face != lp[0], l[1].face != lp[1]};
    out[0] = lane(d_ln, 0);
    out[1] = lane(d_ln, 1);
    if (!moves[0] && !moves[1]) return;
    // A lane whose largest face is opposite p takes any corners here and ignores the result.
    const auto other = [&](int lane_index, int i) { return moves[lane_index] ? i : (lp[lane_index] + 1) % 4; };
    const Vec3Pair u = corner(other(0, l[0].u), other(1, l[1].u)), w = corner(other(0, l[0].w), other(1, l[1].w));
    const Vec3Pair n = cross(u - at_p, w - at_p);
    const __m128d len = _mm_sqrt_pd(norm2(n));
    const __m128d area = _mm_mul_pd(_mm_set1_pd(0.5), len);
    const Vec3Pair moved =
        d_ln - _mm_mul_pd(_mm_div_pd(_mm_set1_pd(1.5), area), _mm_div_pd(_mm_set1_pd(0.5), len)) * cross(u - w, n);
    for (int i = 0; i < 2; ++i)
        if (moves[i] && lane(len, i) > 0) out[i] = lane(moved, i);
}
#endif

}  // namespace

Vec3 ascent_direction(const StarCorners& star, std::span<const double> collapse) {
    Vec3 g{0, 0, 0};
    const std::size_t n = star.corners.size();
    std::size_t k = 0;
#if TUBEMESH_VEC3_PAIR
    for (; k + 1 < n; k += 2) {
        if (!(collapse[k] > 0) && !(collapse[k + 1] > 0)) continue;
        Vec3 d_ln[2];
        log_collapse_gradient_pair(star, k, d_ln);
        for (int i = 0; i < 2; ++i)
            if (collapse[k + i] > 0) g = g + collapse[k + i] * d_ln[i];
    }
#endif
    for (; k < n; ++k)
        if (collapse[k] > 0) g = g + collapse[k] * log_collapse_gradient(star, k);
    return g;
}

bool none_inverted(const TetDomain& dom, index_t p, std::span<const index_t> star, const Vec3& x) {
    const double moved[3] = {x.x, x.y, x.z};
    const auto corners = [&](index_t t, const double* c[4]) {
        const index_t* v = dom.tets.vertex(t);
        for (int i = 0; i < 4; ++i) c[i] = v[i] == p ? moved : dom.point(v[i]);
    };
    // Two tets per filter evaluation; the signs are exact either way.
    std::size_t k = 0;
    for (; k + 1 < star.size(); k += 2) {
        const double* c[2][4];
        corners(star[k], c[0]);
        corners(star[k + 1], c[1]);
        int sign[2];
        predicates::orient3d_inline_pair(c, sign);
        if (sign[0] <= 0 || sign[1] <= 0) return false;
    }
    if (k < star.size()) {
        const double* c[4];
        corners(star[k], c);
        if (predicates::orient3d_inline(c[0], c[1], c[2], c[3]) <= 0) return false;
    }
    return true;
}

// Where p would make tet t regular over its opposite face: above the face's centroid, at the
// regular tet's height for the face's mean edge length, on p's side.
Vec3 regular_apex(const TetDomain& dom, index_t t, index_t p) {
    const index_t* v = dom.tets.vertex(t);
    const int lp = local_index(dom, t, p);
    const auto& f = kTetFaceToward[lp];
    const Vec3 a = point_vec(dom, v[f[0]]), b = point_vec(dom, v[f[1]]), c = point_vec(dom, v[f[2]]);
    const Vec3 normal = cross(b - a, c - a);  // toward p: (a, b, c, p) is positive
    const double len = norm(normal);
    const Vec3 centroid = (1.0 / 3.0) * (a + b + c);
    if (!(len > 0)) return centroid;
    const double edge = (norm(b - a) + norm(c - b) + norm(a - c)) / 3.0;
    return centroid + (std::sqrt(2.0 / 3.0) * edge / len) * normal;
}

void gather_star_corners(const TetDomain& dom, index_t p, std::span<const index_t> star, StarCorners& out,
                         bool with_faces) {
    const std::size_t n = star.size();
    out.corners.resize(n);
    out.at.resize(n);
    // Raw pointers: a store through `at` (bytes) could alias anything and force reloads.
    std::array<Vec3, 4>* corners = out.corners.data();
    std::uint8_t* at = out.at.data();
    for (std::size_t k = 0; k < n; ++k) {
        const index_t* v = dom.tets.vertex(star[k]);
        std::uint8_t where = 0;
        for (int i = 0; i < 4; ++i) {
            corners[k][i] = point_vec(dom, v[i]);
            if (v[i] == p) where = static_cast<std::uint8_t>(i);
        }
        at[k] = where;
    }
    if (!with_faces) return;
    out.opposite.resize(n);
    // Tets 1, 2, ... also in pairs (tet 0, the old worst, is evaluated alone: most trials stop there).
    const std::size_t pairs = n > 1 ? (n - 1) / 2 : 0;
    out.paired.resize(pairs * StarCorners::kPairStride);
    StarCorners::Opposite* opposite = out.opposite.data();
    double* paired = out.paired.data();
    for (std::size_t k = 0; k < n; ++k) {
        const auto& f = kTetFaceToward[at[k]];
        StarCorners::Opposite& o = opposite[k];
        o.a = corners[k][f[0]];
        o.b = corners[k][f[1]];
        o.c = corners[k][f[2]];
        o.n = cross(o.b - o.a, o.c - o.a);
        o.area4 = norm2(o.n);
        if (k == 0 || (k - 1) / 2 >= pairs) continue;  // tet 0, or the last of an even count: alone
        double* lane = paired + (k - 1) / 2 * StarCorners::kPairStride + (k - 1) % 2;
        const double values[13] = {o.a.x, o.a.y, o.a.z, o.b.x, o.b.y, o.b.z, o.c.x,
                                   o.c.y, o.c.z, o.n.x, o.n.y, o.n.z, o.area4};
        for (int i = 0; i < 13; ++i) lane[2 * i] = values[i];
    }
}

Vec3 star_centroid(const StarCorners& star) {
    Vec3 centroid{0, 0, 0};
    for (std::size_t k = 0; k < star.corners.size(); ++k)
        for (int i = 0; i < 4; ++i)
            if (i != star.at[k]) centroid = centroid + star.corners[k][i];
    return (1.0 / (3.0 * static_cast<double>(star.corners.size()))) * centroid;
}

#if TUBEMESH_VEC3_QUAD
namespace {

// det (6V) and circumcentre of star tets k .. k + 3 as odt_target's scalar loop computes them.
TUBEMESH_AVX void circumcentres_quad(const StarCorners& star, std::size_t k, double det[4], Vec3 centre[4]) {
    Vec3Quad p[4];
    for (int i = 0; i < 4; ++i)
        p[i] = quad_of(star.corners[k][i], star.corners[k + 1][i], star.corners[k + 2][i], star.corners[k + 3][i]);
    const Vec3Quad a = p[0];
    const Vec3Quad b = p[1] - a, c = p[2] - a, d = p[3] - a;
    const __m256d det6 = dot(b, cross(c, d));
    const Vec3Quad at = a + _mm256_div_pd(_mm256_set1_pd(0.5), det6) *
                                (norm2(b) * cross(c, d) + norm2(c) * cross(d, b) + norm2(d) * cross(b, c));
    _mm256_storeu_pd(det, det6);
    for (int i = 0; i < 4; ++i) centre[i] = lane(at, i);
}

}  // namespace
#endif

Vec3 odt_target(const StarCorners& star, const Vec3& fallback, std::span<const double> weight) {
    Vec3 sum{0, 0, 0};
    double total = 0;
    // Tet k with 6V = det and circumcentre `centre`, in tet order.
    const auto add = [&](std::size_t k, double det, const Vec3& centre) {
        if (!(det > 0)) return;
        const double w = weight.empty() ? det : det * weight[k];
        sum = sum + w * centre;
        total += w;
    };
    const std::size_t n = star.corners.size();
    std::size_t k = 0;
#if TUBEMESH_VEC3_QUAD
    if (has_avx())
        for (; k + 3 < n; k += 4) {
            double det[4];
            Vec3 centre[4];
            circumcentres_quad(star, k, det, centre);
            for (int i = 0; i < 4; ++i) add(k + i, det[i], centre[i]);
        }
#endif
#if TUBEMESH_VEC3_PAIR
    // Two tets at a time, the same operations per lane as the scalar loop below.
    for (; k + 1 < n; k += 2) {
        const auto& c0 = star.corners[k];
        const auto& c1 = star.corners[k + 1];
        const Vec3Pair a = pair_of(c0[0], c1[0]);
        const Vec3Pair b = pair_of(c0[1], c1[1]) - a, c = pair_of(c0[2], c1[2]) - a, d = pair_of(c0[3], c1[3]) - a;
        const __m128d det = dot(b, cross(c, d));
        const Vec3Pair centre = a + _mm_div_pd(_mm_set1_pd(0.5), det) *
                                        (norm2(b) * cross(c, d) + norm2(c) * cross(d, b) + norm2(d) * cross(b, c));
        add(k, lane(det, 0), lane(centre, 0));
        add(k + 1, lane(det, 1), lane(centre, 1));
    }
#endif
    for (; k < n; ++k) {
        const auto& corner = star.corners[k];
        const Vec3 a = corner[0];
        const Vec3 b = corner[1] - a, c = corner[2] - a, d = corner[3] - a;
        const double det = dot(b, cross(c, d));
        if (!(det > 0)) continue;
        add(k, det, a + (0.5 / det) * (norm2(b) * cross(c, d) + norm2(c) * cross(d, b) + norm2(d) * cross(b, c)));
    }
    return total > 0 ? (1.0 / total) * sum : fallback;
}

namespace {

// tet_collapse of (a, b, c, x) from the fixed face's data: the same measure, rounded a little
// differently (3V from n instead of from the edges at a corner).
double collapse_with(const StarCorners::Opposite& o, const Vec3& x) {
    const Vec3 xa = o.a - x, xb = o.b - x, xc = o.c - x;
    return tet_collapse_from(-0.5 * dot(xa, o.n),
                             {o.area4, norm2(cross(xa, xb)), norm2(cross(xb, xc)), norm2(cross(xc, xa))});
}

#if TUBEMESH_VEC3_PAIR
// collapse_with for two tets at once (a pair block of StarCorners::paired), written to q[0..1]:
// the same operations in the same order per lane, so the same bits as collapse_with.
void collapse_with_pair(const double* block, const Vec3& at_x, double q[2]) {
    const auto load = [&](int i) { return _mm_loadu_pd(block + 2 * i); };
    const Vec3Pair x = broadcast(at_x);
    const Vec3Pair xa = Vec3Pair{load(0), load(1), load(2)} - x, xb = Vec3Pair{load(3), load(4), load(5)} - x,
                   xc = Vec3Pair{load(6), load(7), load(8)} - x;
    const __m128d three_volume = _mm_mul_pd(_mm_set1_pd(-0.5), dot(xa, Vec3Pair{load(9), load(10), load(11)}));
    _mm_storeu_pd(q, tet_collapse_from_pair(three_volume, load(12), norm2(cross(xa, xb)), norm2(cross(xb, xc)),
                                            norm2(cross(xc, xa))));
}
#endif

#if TUBEMESH_VEC3_QUAD
// collapse_with_pair for two pair blocks at once (tets in lane order low 0, low 1, high 0,
// high 1): the same operations per lane, so the same bits.
TUBEMESH_AVX void collapse_with_quad(const double* low, const double* high, const Vec3& at_x, double q[4]) {
    __m256d v[13];  // the 13 numbers of the four faces, lane by lane (no lambda: it would lose the target)
    for (int i = 0; i < 13; ++i) v[i] = _mm256_set_m128d(_mm_loadu_pd(high + 2 * i), _mm_loadu_pd(low + 2 * i));
    const Vec3Quad x = quad_of(at_x, at_x, at_x, at_x);
    const Vec3Quad xa = Vec3Quad{v[0], v[1], v[2]} - x, xb = Vec3Quad{v[3], v[4], v[5]} - x,
                   xc = Vec3Quad{v[6], v[7], v[8]} - x;
    const __m256d three_volume = _mm256_mul_pd(_mm256_set1_pd(-0.5), dot(xa, Vec3Quad{v[9], v[10], v[11]}));
    const __m256d f0 = v[12], f1 = norm2(cross(xa, xb)), f2 = norm2(cross(xb, xc)), f3 = norm2(cross(xc, xa));
    // As tet_collapse_from_pair: maxpd(f, r) and minpd(f, r) are std::max's and std::min's picks.
    const __m256d largest = _mm256_max_pd(f3, _mm256_max_pd(f2, _mm256_max_pd(f1, f0)));
    const __m256d smallest = _mm256_min_pd(f3, _mm256_min_pd(f2, _mm256_min_pd(f1, f0)));
    const __m256d zero = _mm256_setzero_pd();
    const __m256d chosen = _mm256_blendv_pd(largest, smallest, _mm256_cmp_pd(three_volume, zero, _CMP_LT_OQ));
    const __m256d area = _mm256_mul_pd(_mm256_set1_pd(0.5), _mm256_sqrt_pd(chosen));
    const __m256d value = _mm256_div_pd(_mm256_div_pd(three_volume, _mm256_mul_pd(area, _mm256_sqrt_pd(area))),
                                        _mm256_set1_pd(regular_tet_collapse_scale()));
    _mm256_storeu_pd(q, _mm256_and_pd(_mm256_cmp_pd(area, zero, _CMP_GT_OQ), value));  // 0 where !(area > 0)
}

#endif

}  // namespace

StarQuality star_quality(const StarCorners& star, const Vec3& x, double give_up) {
    StarQuality s;
    // Adds tet k's q; false when the caller stops there.
    const auto add = [&](double q) {
        s.worst = std::min(s.worst, q);
        s.sum += q;
        return !(q <= give_up);
    };
    const std::size_t n = star.corners.size();
    std::size_t k = 0;
    if (k < n && !add(collapse_with(star.opposite[k++], x))) return s;
#if TUBEMESH_VEC3_PAIR
    std::size_t j = 0;
#if TUBEMESH_VEC3_QUAD
    if (has_avx())
        for (; k + 3 < n; j += 2, k += 4) {
            double q[4];
            collapse_with_quad(star.paired.data() + j * StarCorners::kPairStride,
                               star.paired.data() + (j + 1) * StarCorners::kPairStride, x, q);
            if (!add(q[0]) || !add(q[1]) || !add(q[2]) || !add(q[3])) return s;
        }
#endif
    for (; k + 1 < n; ++j, k += 2) {
        double q[2];
        collapse_with_pair(star.paired.data() + j * StarCorners::kPairStride, x, q);
        if (!add(q[0]) || !add(q[1])) return s;
    }
#endif
    for (; k < n; ++k)
        if (!add(collapse_with(star.opposite[k], x))) break;
    return s;
}

}  // namespace tubemesh::tets
