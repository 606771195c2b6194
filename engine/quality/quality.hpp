#pragma once
// Element quality measures (docs/architecture.md, "Quality measures"), per element and per mesh.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "engine/core/pulse.hpp"
#include "engine/mesh/hybrid_mesh.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/core/vec3_pair.hpp"

namespace tubemesh {

// Tetrahedron collapse (paper, Table 1): at each vertex, the distance to the opposite face's
// plane over the square root of that face's area; the minimum of the four divided by the
// regular tet's value. 1 for a regular tet, 0 for a flat one, negative when inverted.
// Inline: the tet optimisation evaluates it millions of times on small stars.
//
// The signed distance from p_i to the plane of face i is 3V / A_i, so the value at vertex i
// is 3V / A_i^(3/2), with 3V = det / 2 and det = 6V the signed orientation determinant. Its
// minimum over the vertices is at the largest face when V > 0 and at the smallest one when
// V < 0 (the most negative value), so only one face area is needed.

// The regular tet's value, edge a: height a·sqrt(2/3) over sqrt(sqrt(3)/4·a²). a cancels, so
// this is exact and not the rounded 1.2408 of the paper (folded to a constant when inlined).
inline double regular_tet_collapse_scale() { return std::sqrt(2.0 / 3.0) / std::sqrt(std::sqrt(3.0) / 4.0); }

// The collapse from 3V and the four faces' 4·area² values (in any order): for callers that
// already hold some of them (the smoothing keeps the face opposite a moving point).
inline double tet_collapse_from(double three_volume, const std::array<double, 4>& area4) {
    const double regular = regular_tet_collapse_scale();
    const auto [a, b, c, d] = area4;
    const double area = 0.5 * std::sqrt(three_volume < 0 ? std::min({a, b, c, d}) : std::max({a, b, c, d}));
    // V < 0 implies every face has an area; a zero area here means V = 0 and the four
    // points collinear or coincident: a flat tet.
    if (!(area > 0)) return 0.0;
    return three_volume / (area * std::sqrt(area)) / regular;
}

inline double tet_collapse(const std::array<Vec3, 4>& p) {
    const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
    const double three_volume = 0.5 * dot(e1, cross(e2, e3));
    // Four times the squared face areas, face i opposite vertex i.
    return tet_collapse_from(three_volume, {norm2(cross(p[2] - p[1], p[3] - p[1])), norm2(cross(e2, e3)),
                                            norm2(cross(e1, e3)), norm2(cross(e1, e2))});
}

#if TUBEMESH_VEC3_PAIR
// tet_collapse_from and tet_collapse for two tets at once, one per lane: the same operations in
// the same order, so each lane holds the scalar function's bits.
inline __m128d tet_collapse_from_pair(__m128d three_volume, __m128d f0, __m128d f1, __m128d f2, __m128d f3) {
    // std::max({f0..f3}) keeps r unless r < f: maxpd(f, r) is (f > r ? f : r), NaNs included;
    // std::min({..}) takes f when f < r: minpd(f, r).
    const __m128d largest = _mm_max_pd(f3, _mm_max_pd(f2, _mm_max_pd(f1, f0)));
    const __m128d smallest = _mm_min_pd(f3, _mm_min_pd(f2, _mm_min_pd(f1, f0)));
    const __m128d negative = _mm_cmplt_pd(three_volume, _mm_setzero_pd());
    const __m128d chosen = _mm_or_pd(_mm_and_pd(negative, smallest), _mm_andnot_pd(negative, largest));
    const __m128d area = _mm_mul_pd(_mm_set1_pd(0.5), _mm_sqrt_pd(chosen));
    const __m128d value = _mm_div_pd(_mm_div_pd(three_volume, _mm_mul_pd(area, _mm_sqrt_pd(area))),
                                     _mm_set1_pd(regular_tet_collapse_scale()));
    return _mm_and_pd(_mm_cmpgt_pd(area, _mm_setzero_pd()), value);  // 0 where !(area > 0)
}

inline __m128d tet_collapse_pair(const std::array<Vec3Pair, 4>& p) {
    const Vec3Pair e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
    const __m128d three_volume = _mm_mul_pd(_mm_set1_pd(0.5), dot(e1, cross(e2, e3)));
    return tet_collapse_from_pair(three_volume, norm2(cross(p[2] - p[1], p[3] - p[1])), norm2(cross(e2, e3)),
                                  norm2(cross(e1, e3)), norm2(cross(e1, e2)));
}
#endif

// Hexahedron: scaled Jacobian J_m (minimum over the 8 corners of det(e1,e2,e3)/(|e1||e2||e3|))
// and condition number (maximum over the corners of |A|·|A^-1|/3, Frobenius norms;
// +infinity at a corner whose Jacobian determinant is not positive: degenerate or inverted).
// A = [e1 e2 e3], the edges from the corner, right-handed for a valid hex in VTK order.
struct HexQuality {
    double scaled_jacobian;
    double condition;
};
HexQuality hex_quality(const std::array<Vec3, 8>& p);

// Pyramid: Verdict's pyramid scaled Jacobian (see quality.cpp for the formula).
// 1 for the all-edges-equal pyramid, 0.891 for the paper's ideal apex, 0 when flat and
// negative when inverted (Verdict clamps to 0; the sign is kept here as for tets and hexes).
double pyramid_scaled_jacobian(const std::array<Vec3, 5>& p);

// One measure over one element kind: count, min, mean, max and a 10-class histogram over
// [lo, hi] (values below lo fall in class 0, above hi in class 9) as in the paper's Fig. 7.
// An empty kind has count 0 and min = mean = max = 0. One infinite hex condition number
// makes the mean and max infinite: such a mesh is not fit for analysis.
struct MeasureSummary {
    index_t count = 0;
    double min = 0, mean = 0, max = 0;
    double lo = 0, hi = 1;
    std::array<index_t, 10> histogram{};
};

struct QualitySummary {
    MeasureSummary tet_collapse;            // classes over [0, 1]
    MeasureSummary pyramid_jacobian;        // classes over [0, 1]
    MeasureSummary hex_scaled_jacobian;     // classes over [0, 1]
    MeasureSummary hex_condition;           // classes over [1, 4]
    // The standard measures (standard_measures.hpp, Verdict's definitions). The pyramid's is
    // pyramid_jacobian above, which is already Verdict's.
    MeasureSummary tet_scaled_jacobian;     // classes over [0, 1]
    MeasureSummary tet_min_dihedral;        // degrees, classes over [0, 90]
    MeasureSummary tet_aspect_ratio;        // classes over [1, 4]
    MeasureSummary hex_verdict_jacobian;    // classes over [0, 1]
};

// The primary measure of every cell of one kind (tet collapse, pyramid scaled Jacobian,
// hex scaled Jacobian), in cell order. Parallel over cells (oneTBB).
std::vector<double> cell_quality(const HybridMesh& mesh, CellKind kind);

// Hex condition numbers in cell order. Parallel over cells.
std::vector<double> hex_condition_numbers(const HybridMesh& mesh);

// A measure that one kind or all kinds have, per cell in cell order; NaN for the cells of a
// kind the measure does not apply to. Parallel over cells.
enum class CellMeasure {
    Primary,         // the paper's: tet collapse, pyramid and hex scaled Jacobian (cell_quality)
    ScaledJacobian,  // Verdict's, every kind
    MinDihedral,     // tets, degrees
    AspectRatio,     // tets
    Condition,       // hexes
};
std::vector<double> cell_measure(const HybridMesh& mesh, CellKind kind, CellMeasure measure);

// All four summaries. Parallel over cells; the result does not depend on the thread count.
// `pulse` is called between the measures (engine/core/pulse.hpp).
QualitySummary summarize_quality(const HybridMesh& mesh, const Pulse& pulse = {});

}  // namespace tubemesh
